"""Results, curves and models pickle and unpickle to equal values, so that a study can ship
them between processes: every public result and model type, compared bit for bit (arrays,
floats, the state of every object reached from the result), its ``repr`` and, for a model,
what it computes after the round trip."""

import inspect
import math
import os
import pickle
import re
import struct
import tempfile

import numpy as np
import pandas as pd
import pytest

from skcable import bvp, cable, conductors, mooring, strand, study

# --- bit-for-bit comparison ---------------------------------------------------------------


def assert_same(a, b, path="result", seen=None):
    """``a`` and ``b`` hold the same values bit for bit: arrays (dtype, shape, bytes), floats
    (their bits: -0.0 is not 0.0), containers and the state of every object, recursively.
    An object pickled through ``__reduce__`` is compared by what it is rebuilt from."""
    seen = set() if seen is None else seen
    if (id(a), id(b)) in seen:
        return
    seen.add((id(a), id(b)))
    assert type(a) is type(b), f"{path}: {type(a).__name__} became {type(b).__name__}"
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape, f"{path}: {a.dtype}{a.shape} vs {b.dtype}{b.shape}"
        if a.dtype == object:
            for i, (x, y) in enumerate(zip(a.ravel(), b.ravel(), strict=True)):
                assert_same(x, y, f"{path}.flat[{i}]", seen)
        else:
            assert a.tobytes() == b.tobytes(), f"{path}: the arrays differ"
    elif isinstance(a, float | np.floating):
        assert struct.pack("d", a) == struct.pack("d", b), f"{path}: {a!r} vs {b!r}"
    elif isinstance(a, int | str | bytes | bool | complex | np.generic | type(None)):
        assert a == b, f"{path}: {a!r} vs {b!r}"
    elif isinstance(a, pd.DataFrame | pd.Series):
        check = (
            pd.testing.assert_frame_equal if isinstance(a, pd.DataFrame) else pd.testing.assert_series_equal
        )
        check(a, b, check_exact=True)
        assert_same(dict(a.attrs), dict(b.attrs), f"{path}.attrs", seen)
    elif isinstance(a, list | tuple):
        assert len(a) == len(b), f"{path}: length {len(a)} vs {len(b)}"
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            assert_same(x, y, f"{path}[{i}]", seen)
    elif isinstance(a, dict):
        assert list(a) == list(b), f"{path}: keys {list(a)} vs {list(b)}"
        for key in a:
            assert_same(a[key], b[key], f"{path}[{key!r}]", seen)
    elif isinstance(a, frozenset | set):
        assert a == b, f"{path}: {a!r} vs {b!r}"
    elif inspect.ismodule(a) or inspect.isroutine(a) or inspect.isclass(a):
        assert a is b, f"{path}: {a!r} vs {b!r}"  # pickled by reference
    elif type(a).__reduce__ is not object.__reduce__:  # rebuilt from what __reduce__ gives
        assert_same(a.__reduce__()[1:], b.__reduce__()[1:], f"{path}.__reduce__()", seen)
        assert_same(plain(a), plain(b), path, seen)
    else:
        assert_same(state(a), state(b), path, seen)


def state(obj) -> dict:
    """An object's instance state: its ``__dict__`` and its slots."""
    out = dict(vars(obj)) if hasattr(obj, "__dict__") else {}
    for cls in type(obj).__mro__:
        for name in getattr(cls, "__slots__", ()):
            if hasattr(obj, name):
                out[name] = getattr(obj, name)
    return out


def plain(obj) -> dict:
    """The public attributes of an object that are numbers, strings or arrays."""
    kinds = float | int | str | bool | np.ndarray | np.generic | type(None)
    return {k: v for k, v in state(obj).items() if not k.startswith("_") and isinstance(v, kinds)}


def round_trip(obj):
    return pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))


# --- the results and models -----------------------------------------------------------------

SPANS = np.array([800.0, 700.0])


def sloping_seabed(x):
    """A seabed falling 2 % away from the anchor (m): a module-level callable pickles."""
    return -0.02 * x


def sheared(z):
    """A current sheared towards the seabed (m/s at height z, m): a module function, so it pickles."""
    return (0.0, 0.8 * np.exp(np.asarray(z, dtype=float) / 100.0))


def line_in_sea(current):
    """`mooring.line_3d` of a chain-polyester line (the closed form with the rope's law), or of a chain
    in a current (the 3-D BVP: uniform, tabulated or sheared), its model report formed."""
    if current:
        flow = {
            True: (0.0, 0.8),
            "tabulated": bvp.TabulatedCurrent([0.0, 100.0, 200.0], [(0.0, 0.8), (0.0, 0.5), (0.0, 0.2)]),
            "sheared": bvp.ProfileCurrent(sheared),
        }[current]
        seg = mooring.Segment(500.0, 600.0, 4e8, diameter=0.1, cd_normal=1.2)
        solved = mooring.line_3d(mooring.Line([seg], current=flow), (0, 0, -200.0), (400.0, 0, -20.0))
    else:
        rope = mooring.axial.StrainTable([0.0, 0.01, 0.03], [0.0, 1e6, 2.5e6])
        segs = [mooring.Segment(100.0, 1500.0, 1e9), mooring.Segment(500.0, 50.0, rope)]
        solved = mooring.line_3d(mooring.Line(segs), (0, 0, -200.0), (550.0, 0, -20.0))
    assert solved.model.error >= 0.0
    return solved


def line():
    segments = [mooring.Segment(300.0, 1000.0, 5e8), mooring.Segment(250.0, 400.0, 2e8)]
    return mooring.Line(
        [*segments, mooring.Segment(300.0, 1000.0, 5e8)], [mooring.ClumpWeight(1, 2e4)], seabed=0.0
    )


def moored_system(point=False):
    heading = np.radians([0.0, 120.0, 240.0])
    ring = np.column_stack([np.cos(heading), np.sin(heading), np.zeros(3)])
    if point:
        body = mooring.PointBody(mass=8e6, volume=8.2e3, waterplane_area=600.0)
    else:
        body = mooring.RigidBody(
            20.0 * ring + [0.0, 0.0, -14.0], mass=8e6, volume=8.2e3, center_of_gravity=(0, 0, -5),
            metacentre=(0, 0, 10), waterplane_area=600.0,
        )  # fmt: skip
    leg = mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0)
    return mooring.MooringSystem(body, [leg] * 3, 800.0 * ring + [0.0, 0.0, -200.0], depth=200.0)


def network():
    """MoorPy's basicU: a U line between two anchors, two buoyant free points (built point by point)."""
    system = mooring.MooringSystem(depth=100.0)
    ends = [
        system.add_point([-200.0, 0.0, -100.0], fixed=True),
        system.add_point([-100.0, 0.0, -50.0], volume=50.0),
        system.add_point([100.0, 0.0, -40.0], volume=50.0),
        system.add_point([200.0, 0.0, -100.0], fixed=True),
    ]
    for L, a, b in zip((120.0, 250.0, 120.0), ends[:-1], ends[1:], strict=True):
        system.add_line(mooring.Line([mooring.Segment(L, 2456.82, 1.2326e9)]), a, b)
    return system


def moordyn_model():
    """A system written to a MoorDyn file and read back."""
    with tempfile.TemporaryDirectory() as folder:
        path = mooring.write_moordyn(network(), os.path.join(folder, "lines.dat"), diameter=0.12)
        return mooring.read_moordyn(path)


def strand_model(slip="axis", **options):
    return strand.StrandModel(strand.preset("steel-9.5").damaged(2), 0.3, n_elements=16, slip=slip, **options)


def stage_model():
    """A damaged 1x7 pulled by 15 kN, its layer law with history (both ends clamped but u(L))."""
    s = strand.preset("steel-9.5").damaged(1)
    law = strand.LayerSlipLaw(s.section(), mu=0.5, tension=15e3)
    return strand.StrandModel(s, 0.3, n_elements=16, slip=strand.StageSlip(law), axial="force")


def conductor_curves():
    from skcable.conductors import aa_coefficients

    psi = 6894.757293168361
    al = conductors.ComponentCurve(
        "aluminium", aa_coefficients([-1213.0, 44308.1, -14004.4, -37618.0, 30676.0]), 0.0045,
        64000.0 * psi * 100, 23e-6, compression_limit=0.0,
    )  # fmt: skip
    st = conductors.ComponentCurve(
        "steel", aa_coefficients([-69.3, 38629.0, -3998.1, -45713.0, 27892.0]), 0.0045, 37000.0 * psi * 100,
        11.5e-6,
    )  # fmt: skip
    return conductors.StressStrainModel((al, st), area=468.6e-6, t_ref=20.0)


def rating():
    linerate = pytest.importorskip("linerate")
    wire = linerate.Conductor(
        core_diameter=10.4e-3, conductor_diameter=28.1e-3, outer_layer_strand_diameter=4.44e-3,
        emissivity=0.8, solar_absorptivity=0.8, temperature1=25.0, temperature2=75.0,
        resistance_at_temperature1=7.283e-5, resistance_at_temperature2=8.688e-5,
        aluminium_cross_section_area=float("nan"), constant_magnetic_effect=1.0,
        current_density_proportional_magnetic_effect=0.0, max_magnetic_core_relative_resistance_increase=1.0,
    )  # fmt: skip
    towers = [linerate.Tower(latitude=50 + d, longitude=0.0, altitude=500.0) for d in (-0.0018, 0.0018)]
    span = linerate.Span(conductor=wire, start_tower=towers[0], end_tower=towers[1], num_conductors=1)
    weather = linerate.Weather(
        air_temperature=20.0, wind_direction=np.radians(80), wind_speed=1.66, ground_albedo=0.1,
        clearness_ratio=0.5,
    )  # fmt: skip
    return conductors.ThermalRating(span, weather, np.datetime64("2016-10-03T14:00"), standard="ieee738")


def drake():
    return conductors.Conductor.from_strand(strand.preset("acsr-drake"), damage=2)


X = np.linspace(0.0, 700.0, 9)


def along(c):
    """What a cable solution computes after the round trip: y and T along the span, and for
    one scene its profile, tensions and stiffness."""
    if np.ndim(c.span):
        return c.y(X[:, None] % c.span), c.T(X[:, None] % c.span), c.residual()
    return c.y(X % c.span), c.T(X % c.span), c.residual(), *profile(c)


def profile(c):
    """What a solution of the result protocol computes after the round trip: its profile,
    tensions and stiffness."""
    return c.profile(9), c.tensions(), c.stiffness()


def solves(model):
    """What a strand model computes after the round trip: one imposed strain."""
    return state(model.solve(0.003))


#: (name, factory, what to compute on the original and the copy, or None)
RESULTS = [
    ("catenary", lambda: cable.catenary(800.0, -20.0, 20.0, low=-30.0), along),
    ("catenary array", lambda: cable.catenary(SPANS, -20.0, 20.0, length=850.0), along),
    ("ring on rod", lambda: cable.ring_on_rod(5.0, 2.0, 100.0, 0.4), along),
    ("parabola", lambda: cable.parabola(200.0, 0.0, 1.0, sag=20.0), along),
    ("parabola array", lambda: cable.parabola(SPANS, 0.0, 1.0, sag=20.0), along),
    ("elastic catenary", lambda: cable.elastic_catenary(800.0, -20.0, 20.0, 1e12, length=801.409), along),
    ("elastic array", lambda: cable.elastic_catenary(SPANS, -20.0, 20.0, 1e9, length=850.0), along),
    (
        "seabed",
        lambda: cable.elastic_catenary(800.0, 150.0, 1e3, 5e8, length=850.0, seabed=0.0, friction=0.5),
        along,
    ),
    (
        "seabed array",
        lambda: cable.elastic_catenary(SPANS, 150.0, 1e3, 5e8, length=850.0, seabed=0.0),
        along,
    ),
    (
        "sloped seabed",
        lambda: cable.sloped_seabed_catenary(800.0, 150.0, 1e3, 5e8, length=850.0, seabed_slope=0.02),
        profile,
    ),
    ("funicular", lambda: cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]), None),
    (
        "funicular vertical",
        lambda: cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5)),
        None,
    ),
    ("sliding load", lambda: cable.sliding_load(100.0, 1.0, 110.0, 20.0), None),
    (
        "change of state",
        lambda: conductors.change_of_state(
            SPANS, 0.0, EA=3e7, alpha=2.3e-5, w0=10.0, t0=15.0, sag0=6.0, w=[10.0, 25.0], t=[50.0, -5.0]
        ),
        None,
    ),
    (
        "thermal catenary",
        lambda: conductors.thermal_catenary(
            SPANS, 0.0, 10.0, 3e7, length=851.0, alpha=2.3e-5, t=50.0, t0=15.0
        ),
        along,
    ),
    (
        "tension section",
        lambda: conductors.tension_section(
            [250, 450, 300],
            EA=3e7,
            alpha=2.3e-5,
            w0=16,
            t0=15,
            H0=2e4,
            w=16,
            t=[80, -5],
            insulator_length=3.0,
            insulator_weight=700.0,
        ),  # fmt: skip
        None,
    ),
    (
        "sag-tension table",
        lambda: drake().sag_tension_table(400.0, t0=15.0, H0=28e3, temperatures=[-20, 75]),
        None,
    ),
    (
        "natural frequencies",
        lambda: conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0, n_modes=3),
        None,
    ),
    ("BVP graph", lambda: bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(3.0)], length=320.0), along),
    (
        "BVP arc",
        lambda: bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(3.0)], length=320.0, formulation="arc"),
        lambda c: (
            [c.y(x) for x in X[:5] % c.span],
            *profile(c),
        ),  # y(x) one point at a time (arrays: see report)
    ),
    ("line solution", lambda: line().solve(800.0, 150.0), lambda r: (r.tensions(), r.stiffness())),
    (
        "line BVP",
        lambda: mooring.solve_line_bvp(800.0, 150.0, [(850.0, 1000.0, 5e8)], seabed=sloping_seabed),
        lambda r: (r.stiffness(), r.samples(11)),
    ),
    (
        "line 3-D",
        lambda: mooring.line_3d(line(), [800.0, 0.0, -150.0], [0.0, 0.0, 0.0]),
        lambda r: r.stiffness(),
    ),
    ("line in the sea, a rope's law", lambda: line_in_sea(False), lambda r: (r.stiffness(), r.profile(5))),
    ("line in the sea, a current", lambda: line_in_sea(True), lambda r: (r.stiffness(), r.profile(5))),
    ("line in a tabulated current", lambda: line_in_sea("tabulated"), lambda r: r.profile(5)),
    ("line in a sheared current", lambda: line_in_sea("sheared"), lambda r: r.profile(5)),
    (
        "line design",
        lambda: mooring.design_line(
            mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0, friction=0.5),
            [800.0, 0.0, -200.0],
            [20.0, 0.0, -14.0],
            target="pretension",
            value=1.2e6,
            depth=200.0,
        ),
        lambda r: (r.x, r.achieved),
    ),
    (
        "mooring equilibrium",
        lambda: moored_system().equilibrium(force=(2e6, 0.0, 0.0)),
        lambda r: r.stiffness(),
    ),
    ("mooring network equilibrium", lambda: network().equilibrium(), lambda r: r.stiffness()),
    (
        "line between",
        lambda: mooring.line_between(
            mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)]), [800, 0, -200], [0, 0, -14]
        ),
        lambda r: r.stiffness(),
    ),
    (
        "line in a plane",
        lambda: mooring.line_in_plane(line(), 800.0, 150.0, seabed=0.0),
        lambda r: (r.jacobian(), r.tensions()),
    ),
    (
        "line in a plane by the BVP",
        lambda: mooring.line_in_plane(line(), 800.0, 150.0, seabed=-10.0),
        lambda r: (r.jacobian(), r.tensions()),
    ),
    (
        "clamp stress",
        lambda: conductors.clamp_stress(strand.preset("acsr-drake").damaged(2), 0.5e-3, 28e3),
        None,
    ),
    (
        "residual strength",
        lambda: conductors.residual_strength(strand.preset("acsr-drake"), 2, rts=140.1e3),
        None,
    ),
    (
        "aeolian vibration",
        lambda: conductors.aeolian_vibration(
            strand.preset("acsr-drake"), 28e3, [10.0, 30.0], damping="foti", hours_per_year=[5.0, 5.0]
        ),
        lambda r: (r.to_frame().to_numpy(), r.life_years),
    ),
    ("section", lambda: strand.preset("steel-9.5").damaged(1).section(), None),
    (
        "bending law",
        lambda: strand.preset("steel-9.5").damaged(1).bending_law(mu=0.5, axial_strain=0.004),
        lambda law: law.moment(np.linspace(0.0, 0.5, 11), 0),
    ),
    (
        "layer slip law",
        lambda: strand.LayerSlipLaw(strand.preset("acsr-drake").damaged(2).section(), mu=0.7, tension=28e3),
        lambda law: (law.moment(np.linspace(0.0, 0.5, 11), 1), law.energy_per_cycle(0.2, 1)),
    ),
    ("stage law", lambda: strand.StageLaw(50.0, [950.0], [9.5]), lambda law: law.loop(0.03)),
    (
        "stage response",
        lambda: strand.StageLaw(50.0, [950.0], [9.5]).update([0.02, 0.0], np.zeros((2, 1))),
        None,
    ),
    ("curvature path", lambda: strand.StageLaw(50.0, [950.0], [9.5]).path([0.02, -0.02]), None),
    ("beam frequencies", lambda: strand.beam_frequencies(1.0, 1e3, 1.0, 0.45, n_modes=3), None),
    (
        "strand frequencies",
        lambda: strand.strand_bending_frequencies(
            strand.preset("steel-9.5").section(), N=1e3, length=1.0, mass_per_length=0.45, n_modes=3
        ),
        None,
    ),
    ("step result", lambda: strand_model().solve(0.003), None),
    (
        "bending cycles",
        lambda: strand.bending_cycles(stage_model(), 0.006, force=15e3, n_steps=1, cycles=1),
        lambda c: (c.energy_per_cycle, c.friction_per_cycle, c.masing_energy, c.loop(0)),
    ),
    (
        "capacity curve",
        lambda: strand_model().capacity_curve(n_steps=8),
        lambda c: (c.K_Leq, c.secant(0.002)),
    ),
    (
        "capacity curve, element slip",
        lambda: strand_model("element").capacity_curve(max_strain=0.006, n_steps=6),
        None,
    ),
    ("analysis, closed form", lambda: strand.analyse(strand.preset("steel-9.5"), n_points=20), None),
    (
        "analysis, FE",
        lambda: strand.analyse(strand.preset("steel-9.5").damaged(1), 0.3, n_elements=16, n_steps=8),
        None,
    ),
    (
        "study table",
        lambda: study.run(
            study.cable_solve,
            study.grid(span=[100.0, 200.0], sag=[5.0, -1.0], w=[10.0]),
            executor="serial",
            progress=False,
        ),
        None,
    ),  # fmt: skip
]

MODELS = [
    (
        "line BVP model",
        lambda: mooring.LineBVP([(850.0, 1000.0, 5e8)], seabed=0.0, friction=0.3, n_elements=32),
        lambda m: (lambda r: (r.H_B, r.V_B, r.stiffness()))(m.solve(780.0, 186.0)),
    ),
    ("strand", lambda: strand.preset("steel-9.5").damaged(1), lambda s: state(s.section())),
    ("multi-material strand", lambda: strand.preset("acsr-drake"), lambda s: state(s.section())),
    ("layer", lambda: strand.Layer(6, 3.1e-3, lay_length=0.15), None),
    ("wires", lambda: strand.preset("steel-9.5").damaged(1).wires(), None),
    ("material", lambda: strand.material("steel"), lambda m: m.stress(np.linspace(0.0, 0.05, 7))),
    ("strand model, stick", lambda: strand_model("none"), solves),
    ("strand model, axis slip", lambda: strand_model("axis"), solves),
    ("strand model, element slip", lambda: strand_model("element"), solves),
    (
        "strand model, stage slip",
        stage_model,
        lambda m: state(m.solve(force=15e3, prescribed={"right": {"v'": 0.004}})),
    ),
    ("strand model, annex E", lambda: strand_model(physics=[strand.AnnexE("element")], twist="free"), solves),
    (
        "strand model with terms",
        lambda: strand_model(
            terms=[
                strand.ElasticFoundation(2e4),
                strand.TransverseLoad(qy=5.0),
                strand.PointForce(0.1, fy=1.0),
                strand.PointMoment(0.2, mz=0.1),
                strand.NodalSpring(0.15, 1e3),
                strand.FollowerForce(0.2, 1.0),
                strand.TensionlessFoundation(1e4),
                strand.RigidCylinder((0.0, -0.01), 0.005, 1e5),
            ]
        ),  # fmt: skip
        solves,
    ),
    (
        "strand model, damage loads",
        lambda: strand_model(physics=[strand.HelicalWires("axis"), strand.SinusoidalDamageLoads()]),
        solves,
    ),
    ("strand layout", lambda: strand_model().layout, None),
    ("slip laws", lambda: [strand.Stick(0.4), strand.AxisSlip(0.3), strand.ElementSlip(0.2)], None),
    ("wire bending", lambda: strand.WireBending(), None),
    (
        "segment, clump, buoy",
        lambda: [mooring.Segment(1.0, 2.0, 3.0), mooring.ClumpWeight(1, 2.0), mooring.Buoy(1, 3.0)],
        None,
    ),
    ("line", line, lambda m: state(m.solve(800.0, 150.0))),
    ("mooring system", moored_system, lambda m: m.stiffness(np.zeros(6))),
    ("mooring network", network, lambda m: state(m.equilibrium())),
    ("line component", lambda: mooring.component("studless chain R3"), lambda c: c.properties(0.12)),
    ("MoorDyn model", moordyn_model, lambda m: state(m.system.equilibrium())),
    ("point body system", lambda: moored_system(point=True), lambda m: m.stiffness(np.zeros(3))),
    ("conductor", drake, lambda c: state(c.change_of_state(400.0, t0=15.0, H0=28e3, t=[50.0]))),
    ("BVP segment", lambda: mooring.BVPSegment(850.0, 1000.0, 5e8), None),
    (
        "cable loads",
        lambda: [
            bvp.SelfWeight(3.0),
            bvp.DeckLoad(2.0),
            bvp.PointLoad(10.0, 5.0),
            bvp.DistributedLoad(qy=np.sin),
        ],
        None,
    ),
    (
        "cable terms",
        lambda: [bvp.Buoyancy(0.01), bvp.WindDrag(10.0, 0.03), bvp.CurrentDrag(1.0, 0.1)],
        lambda terms: state(bvp.solve_bvp(300.0, 10.0, [bvp.SelfWeight(30.0), *terms], length=320.0)),
    ),
    ("stress-strain model", conductor_curves, lambda m: state(m)),
    (
        "creep law",
        lambda: conductors.CreepLaw(K=1.2e-5, phi=0.01, alpha=1.3, mu=0.16),
        lambda c: c.strain(30e6, 8.76e4, 15.0),
    ),
    ("Wöhler curve", lambda: conductors.WohlerCurve.safe_border_line(layers=2), None),
    ("thermal rating", rating, lambda r: r.temperature([600.0, 1000.0])),
]

#: Known failures, each to pass once the branch named lands (strict: an unexpected pass fails).
XFAIL: dict[str, str] = {}


def case(name, make, probe):
    if name not in XFAIL:
        return pytest.param(make, probe, id=name)
    known = pytest.mark.xfail(strict=True, reason=XFAIL[name], raises=(AttributeError, pickle.PicklingError))
    return pytest.param(make, probe, id=name, marks=known)


CASES = [case(*row) for row in RESULTS + MODELS]


@pytest.mark.parametrize(("make", "probe"), CASES)
def test_pickles_to_equal_values(make, probe):
    original = make()
    copy = round_trip(original)
    assert_same(original, copy)
    assert re.sub(" at 0x[0-9a-f]+", "", repr(copy)) == re.sub(" at 0x[0-9a-f]+", "", repr(original))
    if probe is not None:
        assert_same(probe(original), probe(copy), "computed")


#: Public classes that are neither results nor models: bases and protocols to subclass, and
#: the per-evaluation records handed to a term.
NOT_A_RESULT = {
    "CableSolution", "CableTerm", "CableState", "CableForce", "Term", "FieldTerm", "SectionTerm", "SlipLaw",
    "Step", "FieldAssembly", "StrandSupports", "Current", "SlipPoints",
}  # fmt: skip


def types_in(obj, seen=None) -> set:
    """The skcable types of ``obj`` and of everything its state holds, recursively."""
    seen = set() if seen is None else seen
    if id(obj) in seen:
        return set()
    seen.add(id(obj))
    found = {type(obj)} if type(obj).__module__.startswith("skcable") else set()
    if isinstance(obj, np.ndarray | pd.DataFrame | str | float | int):
        return found
    if isinstance(obj, list | tuple):
        parts = list(obj)
    elif isinstance(obj, dict):
        parts = list(obj.values())
    elif type(obj).__module__.startswith("skcable") and not inspect.isroutine(obj):
        parts = list(state(obj).values())
    else:
        parts = []
    for part in parts:
        found |= types_in(part, seen)
    return found


def test_every_public_result_and_model_is_pickled_above():
    made = set()
    for name, make, _ in RESULTS + MODELS:
        if name not in XFAIL:
            made |= types_in(make())
    public = {
        getattr(module, name)
        for module in (cable, bvp, mooring, conductors, strand)
        for name in module.__all__
        if inspect.isclass(getattr(module, name)) and name not in NOT_A_RESULT
    } | {study.StudyTable}
    missing = sorted(c.__name__ for c in public - made)
    assert not missing, f"public types that no factory above makes: {missing}"


def test_comparison_sees_one_bit():
    c = cable.catenary(SPANS, -20.0, 20.0, length=850.0)
    copy = round_trip(c)
    assert_same(c, copy)
    copy.H[0] = math.nextafter(copy.H[0], math.inf)
    with pytest.raises(AssertionError, match="H"):
        assert_same(c, copy)
    with pytest.raises(AssertionError):
        assert_same(0.0, -0.0)
