"""Record the numbers of every domain of the library (closed forms, BVPs, lines, moorings,
conductors, frequencies, strands) on ordinary scenes, so that a restructured library can be
checked against the code that produced them.

``python tests/pinned_library.py`` writes ``tests/data/pinned_library.json`` with the commit it
ran on; ``tests/test_pinned_library.py`` recomputes every case through the same functions
(``CASES`` below) and compares each array to 1e-12 of its largest entry. The scenes are ordinary
ones (no extreme ratios), where a change of operation order moves a result by round-off only.
``python tests/pinned_library.py GROUP CASE "reason"`` re-pins one case whose physics changed
(the file keeps the commit and the reason).
"""

from __future__ import annotations

import json
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "data" / "pinned_library.json"


def _forces(sol, names=("H", "V_A", "V_B", "T_A", "T_B", "length", "sag")):
    return {k: getattr(sol, k) for k in names if hasattr(sol, k)}


def catenary_cases():
    from skcable import cable

    out = {}
    for name, kw in [
        ("length", dict(length=850.0)),
        ("sag", dict(sag=40.0)),
        ("H", dict(H=12000.0)),
        ("low", dict(low=-30.0)),
        ("T_max", dict(T_max=30000.0)),
    ]:
        c = cable.catenary(800.0, -20.0, 20.0, **kw)
        out[f"catenary_{name}"] = dict(
            _forces(c), x_low=c.x_low, y=c.y(np.linspace(0, 800, 9)), T=c.T(np.linspace(0, 800, 9))
        )
    spans = np.linspace(100.0, 900.0, 7)
    c = cable.catenary(spans, 10.0, 15.0, length=spans * 1.02)
    out["catenary_array"] = _forces(c)
    c = cable.catenary(800.0, -20.0, 20.0, length=850.0)
    out["catenary_stiffness"] = dict(K=c.stiffness(), kG=cable.geometric_stiffness(c, EA=1e7))
    for name, kw in [("sag", dict(sag=20.0)), ("H", dict(H=300.0)), ("length", dict(length=205.0))]:
        p = cable.parabola(200.0, 5.0, 1.0, **kw)
        out[f"parabola_{name}"] = dict(_forces(p), y=p.y(np.linspace(0, 200, 5)))
    e = cable.elastic_catenary(800.0, -20.0, 20.0, 1e7, length=801.409)
    out["elastic"] = dict(_forces(e), K=e.stiffness(), y=e.y(np.linspace(0, 800, 5)))
    e = cable.elastic_catenary(np.array([600.0, 700.0]), 5.0, 12.0, 5e6, length=np.array([620.0, 720.0]))
    out["elastic_array"] = _forces(e)
    return out


def funicular_cases():
    from skcable import cable

    f = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    v = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    return {
        "funicular": dict(T=f.T, angles=f.angles, nodes=np.asarray(f.nodes)),
        "funicular_vertical": dict(H=v.H, V_A=v.V_A, V_B=v.V_B, nodes=np.asarray(v.nodes)),
    }


def seabed_cases():
    from skcable import cable

    out = {}
    for name, kw in [
        ("free", dict()),
        ("seabed", dict(seabed=0.0)),
        ("friction", dict(seabed=0.0, friction=0.5)),
    ]:
        m = cable.elastic_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, **kw)
        row = dict(_forces(m, ("H", "V_A", "V_B", "T_A", "T_B")), K=m.stiffness())
        if "seabed" in kw:
            row.update(H_A=m.H_A, grounded=m.length_on_seabed, x_touchdown=m.x_touchdown)
        out[f"seabed_{name}"] = row
    heap = cable.elastic_catenary(100.0, 150.0, 1000.0, 5e8, length=400.0, seabed=0.0)
    out["seabed_heap"] = dict(H=heap.H, V_B=heap.V_B)
    s = cable.sloped_seabed_catenary(800.0, 150.0, 1000.0, 5e8, length=850.0, seabed_slope=0.05, friction=0.3)
    out["sloped"] = dict(H=s.H, H_A=s.H_A, V_A=s.V_A, V_B=s.V_B, grounded=s.length_on_seabed)
    return out


def line_cases():
    from skcable import mooring
    from skcable.errors import PlausibilityWarning

    chain, wire = mooring.Segment(300.0, 1000.0, 5e8), mooring.Segment(250.0, 400.0, 2e8)
    line = mooring.Line([chain, wire, chain], [mooring.ClumpWeight(1, 2e4)], seabed=0.0, friction=0.5)
    r = line.solve(800.0, 150.0)
    table = r.tensions()
    out = {
        "line_clump": dict(
            H=r.H, V_A=r.V_A, V_B=r.V_B, K=r.stiffness(), T=table.select_dtypes("number").to_numpy()
        )
    }
    buoyed = mooring.Line([chain, wire, chain], [mooring.Buoy(2, 5e4)])
    with warnings.catch_warnings():  # pinned scenes: taut lines (104 % strain, an anchor lifted 18°)
        warnings.filterwarnings("ignore", "(strain|uplift_angle)", PlausibilityWarning)
        r = buoyed.solve(780.0, 350.0)
        out["line_buoy"] = dict(H=r.H, V_B=r.V_B, K=r.stiffness())
        l3 = mooring.line_3d(mooring.Line([chain], seabed=0.0), (0.0, 0.0, -200.0), (500.0, 300.0, -14.0))
    out["line_3d"] = dict(F_a=l3.force_on_anchor, F_b=l3.force_on_fairlead, K=l3.stiffness())
    return out


def mooring_cases():
    sys.path.insert(0, str(ROOT / "examples"))
    import spread_mooring

    rest, pushed = spread_mooring.solve()
    return {
        "mooring_rest": dict(position=rest.position, K=rest.stiffness()),
        "mooring_pushed": dict(
            position=pushed.position,
            K=pushed.stiffness(),
            K_lines=pushed.stiffness(lines_only=True),
            T=pushed.tensions().select_dtypes("number").to_numpy(),
        ),
    }


def bvp_cases():
    from skcable import bvp, mooring

    ice = bvp.DistributedLoad(qy=lambda x: -15.0 * ((x > 100) & (x < 220)))
    a = bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(3.0), ice], length=320.0)
    b = bvp.solve_bvp(800.0, -20.0, [bvp.DeckLoad(20.0), bvp.SelfWeight(5.0)], sag=60.0, EA=2e9)
    c = bvp.solve_bvp(
        300.0, 10.0, [bvp.SelfWeight(3.0), bvp.PointLoad(120.0, 500.0)], H=900.0, degree=3, n_elements=20
    )
    wind = bvp.DistributedLoad(qx=lambda x: 2.0 + 0.0 * x, qy=lambda x: -3.0 + 0.0 * x)
    d = bvp.solve_bvp(300.0, 10.0, [wind], length=320.0, EA=1e6, formulation="arc", n_elements=32)
    e = bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(3.0)], T_max=2000.0, formulation="arc", n_elements=32)
    f = bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(3.0)], low=-20.0, n_elements=32)
    xs = np.linspace(0.0, 300.0, 7)
    out = {
        "bvp_ice": dict(_forces(a), y=a.y(xs)),
        "bvp_deck": dict(_forces(b), y=b.y(np.linspace(0, 800, 7))),
        "bvp_point_p3": dict(_forces(c), y=c.y(xs)),
        "bvp_arc_wind": dict(H_A=d.H_A, H_B=d.H_B, V_A=d.V_A, V_B=d.V_B, length=d.length),
        "bvp_arc_tmax": dict(H=e.H, V_A=e.V_A, V_B=e.V_B, length=e.length),
        "bvp_low": dict(_forces(f)),
    }
    segs = [(300.0, 1000.0, 5e8), (250.0, 400.0, 2e8), (300.0, 1000.0, 5e8)]
    g = mooring.solve_line_bvp(800.0, 150.0, segs, seabed=lambda x: -0.02 * x)
    h = mooring.solve_line_bvp(800.0, 150.0, [(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.5, n_elements=80)
    k = mooring.solve_line_bvp(700.0, 250.0, segs, point_loads=[(300.0, 2e4)], n_elements=48)
    out["line_bvp_slope"] = dict(H=g.H, H_A=g.H_A, V_A=g.V_A, V_B=g.V_B)
    out["line_bvp_friction"] = dict(H=h.H, H_A=h.H_A, V_A=h.V_A, V_B=h.V_B)
    out["line_bvp_free"] = dict(H=k.H, H_A=k.H_A, V_A=k.V_A, V_B=k.V_B)
    sol = bvp.solve(1000.0, 0.0, [bvp.DeckLoad(100e3), bvp.SelfWeight(15e3)], sag=100.0, rtol=1e-3)
    out["choice"] = dict(H=sol.H, V_A=sol.V_A, error_estimate=sol.error_estimate)
    return out


def conductor_cases():
    from skcable import conductors, strand

    out = {}
    cs = conductors.change_of_state(
        300.0, 0.0, EA=3e7, alpha=2.3e-5, w0=10.0, t0=15.0, sag0=6.0, w=[10.0, 25.0], t=[50.0, -5.0]
    )
    out["change_of_state"] = dict(H=cs.H, sag=cs.sag)
    drake = conductors.Conductor.from_strand(strand.preset("acsr-drake"), damage=2)
    out["drake"] = dict(EA=drake.EA, w=drake.w, alpha=drake.alpha)
    table = drake.sag_tension_table(
        400.0, t0=15.0, H0=28e3, temperatures=[-20, 15, 75], load_cases={"ice": (0.0125, 0)}
    )
    out["drake_table"] = dict(values=table.select_dtypes("number").to_numpy())
    ts = conductors.tension_section(
        [250, 450, 300], EA=3e7, alpha=2.3e-5, w0=16, t0=15, H0=2e4, w=16, t=80,
        insulator_length=3.0, insulator_weight=700.0,
    )  # fmt: skip
    out["tension_section"] = dict(H=ts.H, sag=ts.sag)
    out["ruling_span"] = dict(value=conductors.ruling_span([250.0, 450.0, 300.0]))
    nf = conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0)
    out["natural_frequencies"] = dict(f_in=nf.f_in_plane, f_out=nf.f_out_of_plane)
    return out


def strand_cases():
    from skcable import strand

    s = strand.preset("steel-9.5").damaged(1)
    sec = s.section()
    law = s.bending_law(mu=0.5, axial_strain=0.004)
    kappa = np.linspace(0.0, 0.5, 6)
    fr = strand.strand_bending_frequencies(sec, N=1e3, length=1.0, mass_per_length=0.45)
    a = strand.analyse(s)
    model = strand.StrandModel(
        s, 1.0, n_elements=24, terms=[strand.ElasticFoundation(2e4), strand.TransverseLoad(qy=5.0)]
    )
    # solved to 1e-12 (the default 1e-9 is the accuracy of a step, not the pin's): the numbers are
    # the model's equations, whatever the stopping rule
    step = model.solve(0.003, tol=1e-12)
    free = strand.StrandModel(s, 1.0, n_elements=24, twist="free", slip="axis").solve(0.003, tol=1e-12)
    return {
        "section": dict(
            area=sec.area, EA=sec.EA, EI_stick=sec.EI_stick, EI_slip=sec.EI_slip, centroid=sec.centroid
        ),
        "bending_law": dict(kappa_m=law.kappa_m, M0=law.moment(kappa, axis=0), M1=law.moment(kappa, axis=1)),
        "strand_frequencies": dict(stick=fr.stick.f, slip=fr.slip.f),
        "analyse": dict(K_Leq=a.curve.K_Leq),
        "strand_terms_step": dict(force=step.force, dofs=step.dofs),
        "strand_free_twist_axis_slip": dict(force=free.force, dofs=free.dofs),
    }


CASES = {
    "catenary": catenary_cases,
    "funicular": funicular_cases,
    "seabed": seabed_cases,
    "line": line_cases,
    "mooring": mooring_cases,
    "bvp": bvp_cases,
    "conductor": conductor_cases,
    "strand": strand_cases,
}


def encode(value):
    """A JSON-ready nested list of floats (bools as 0/1), and its shape."""
    array = np.asarray(value, dtype=float)
    return {"shape": list(array.shape), "values": array.ravel().tolist()}


def run_all() -> dict:
    return {group: {case: {k: encode(v) for k, v in values.items()} for case, values in fn().items()}
            for group, fn in CASES.items()}  # fmt: skip


def repin(group: str, case: str, reason: str) -> None:
    """Recompute one case of one group and replace it in the file, every other number kept as
    recorded; the commit and the reason are appended to the file's ``repinned`` list."""
    data = json.loads(OUT.read_text())
    computed = CASES[group]()
    if case not in data["groups"].get(group, {}) or case not in computed:
        raise SystemExit(f"no case {case!r} in group {group!r}")
    data["groups"][group][case] = {k: encode(v) for k, v in computed[case].items()}
    commit = subprocess.run(
        ["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.strip()
    data.setdefault("repinned", []).append({"group": group, "case": case, "commit": commit, "reason": reason})
    OUT.write_text(json.dumps(data, indent=1) + "\n")
    print(f"re-pinned {group}.{case} in {OUT} at {commit[:10]}")


def main():
    if len(sys.argv) > 1:  # python tests/pinned_library.py GROUP CASE "reason"
        group, case, reason = sys.argv[1:4]
        repin(group, case, reason)
        return
    commit = subprocess.run(
        ["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.strip()
    data = {"commit": commit, "groups": run_all()}
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(data, indent=1) + "\n")
    print(f"wrote {OUT} ({sum(len(g) for g in data['groups'].values())} cases) at {commit[:10]}")


if __name__ == "__main__":
    main()
