"""Every public MoorDyn input file of the corpus, read and solved (issue 33).

The corpus (``tests/data/moordyn``, sources in its ``SOURCES.md``): every input file under
MoorDyn's ``tests/``, ``example/`` and ``bench/`` (FloatingArrayDesign/MoorDyn) and MoorPy's
``tests/`` and ``examples/`` (NREL/MoorPy), and a sample of OpenFAST's regression tests (r-test).
Each file is read and solved once per module (`solved`); what each test asserts comes from
elsewhere:

- an independent **force balance** at every free point, rod and body, written here: the lines'
  forces on their ends plus the weights, buoyancies and forces of the file's own rows (a rod's
  weight at its middle and the buoyancy of its displaced volume, its sections' circular segments
  below the water line integrated along its axis here, at that volume's centre), a point on the
  seabed pressed into it;
- **MoorPy 1.3** (M. Hall, NREL): each line solved by MoorPy's catenary with its ends where the
  equilibrium put them (``Line.staticSolve``), its end tensions to 1e-4 (MoorPy's own tolerance),
  and MoorPy's own equilibrium (``System.solveEquilibrium``) where it converges, g = 9.80665 in
  both; where MoorPy has no answer or a wrong one (a line whose ends share a vertical, a
  weightless line), the closed form of a straight line decides: its tension changes by its
  weight ``w L`` from end to end, its stretched length is the distance of its ends.
"""

from __future__ import annotations

import contextlib
import functools
import io
import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError, PlausibilityWarning
from skcable.mooring.rod import RodBody

DATA = Path(__file__).resolve().parents[1] / "data" / "moordyn"
#: curve and settings files the inputs name, not inputs themselves
AUXILIARY = {"owc.dat", "syrope.dat", "SOURCES.md"}
#: FAST.Farm's turbine positions (the r-test case's FAST.Farm.fstf: WT_X, WT_Y, WT_Z)
TURBINES = {"SharedMooring2.dat": [(0.0, 0.0, 0.0), (1600.0, 0.0, 0.0)]}
#: MoorDyn-C refuses this one too: two rods numbered 3 ("Rod ID must be sequential")
REFUSED = {"MoorDyn/bench/Mooring/floating_rods.txt": (17, "ID")}
#: the files of the issue: MoorDyn's and MoorPy's (64 with line types, 3 of MoorDyn's without)
CORPUS = sorted(
    str(p.relative_to(DATA))
    for p in DATA.rglob("*")
    if p.is_file() and p.name not in AUXILIARY and p.parts[len(DATA.parts)] in ("MoorDyn", "MoorPy")
)
OTHERS = sorted(
    str(p.relative_to(DATA)) for p in DATA.rglob("*") if p.is_file() and p.parts[len(DATA.parts)] == "r-test"
)
#: files whose scene these statics do not solve yet, and why (the report says it)
UNSOLVED: dict[str, str] = {}


def test_the_corpus_is_the_issues_and_every_file_has_its_source():
    with_lines = [
        n
        for n in CORPUS
        if re.search(
            r"---.*(LINE TYPES|LINE DICTIONARY)",
            (DATA / n).read_text(encoding="utf-8", errors="replace").upper(),
        )
    ]
    assert len(with_lines) == 64 and len(CORPUS) == 67
    sources = (DATA / "SOURCES.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| (\S+) \| `([^`]+)` \| `([0-9a-f]{40})` \|$", sources, re.M)
    listed = {
        ("MoorDyn/" if r == "FloatingArrayDesign/MoorDyn" else "MoorPy/" if r == "NREL/MoorPy" else "r-test/")
        + p
        for r, p, _ in rows
    }
    files = {str(p.relative_to(DATA)) for p in DATA.rglob("*") if p.is_file() and p.name != "SOURCES.md"}
    assert listed == files


def solved(name):
    """``(model, equilibrium)`` of the file ``name``: read and solved once per module (its error,
    where it has one, raised again)."""
    outcome = _solved(name)
    if isinstance(outcome, Exception):
        raise outcome
    return outcome


@functools.cache
def _solved(name):
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("ignore", UserWarning)  # an option MoorDyn does not know warns
            warnings.simplefilter("always", mooring_warning())
            model = mooring.read_moordyn(DATA / name, turbines=TURBINES.get(Path(name).name))
            eq = model.equilibrium()
        FINDINGS[name] = [str(w.message) for w in caught if issubclass(w.category, mooring_warning())]
        return model, eq
    except Exception as exc:  # noqa: BLE001 - kept, raised by `solved`
        return exc


#: ``{file: [message]}``: the plausibility warnings of each file's equilibrium (`_solved`), judged by
#: `test_the_only_findings_are_anchors_pulled_up_as_a_recount_says`
FINDINGS: dict[str, list[str]] = {}


def uplift_angles(model, eq) -> dict:
    """``{fixed point index: angle (degrees)}`` of the net pull of its lines above the horizontal,
    at each fixed point on the seabed, summed here from the lines' end forces."""
    system = model.system
    pulls: dict = {}
    for k, line in zip(eq.line_indices, eq.lines, strict=True):
        handle = system.mooring_lines[k]
        for end, p in enumerate((handle.a, handle.b)):
            if p.kind == "fixed" and system.depth is not None and abs(p.position[2] + system.depth) < 1e-6:
                pulls[p.index] = pulls.get(p.index, 0.0) + np.asarray(line.end_forces[end])
    return {j: math.degrees(math.atan2(F[2], math.hypot(F[0], F[1]))) for j, F in pulls.items()}


def mooring_warning():
    from skcable.errors import PlausibilityWarning

    return PlausibilityWarning


def _point_loads(model):
    """``{system point index: own load (3,)}``: each point's weight, buoyancy and force, from the
    file's columns (a v1 row's FX FY FZ, an EXTERNAL LOADS row's Fext)."""
    system = model.system
    g, rho = system.g, system.rho
    return {p.index: np.array([0.0, 0.0, rho * g * p.volume - p.mass * g]) + p.force for p in system.points}


def _rod_loads(rod, a, b, rho, g):
    """A rod's weight (at its middle) and the buoyancy of its displaced volume as ``[(point of
    application, force)]``, from its ends ``a`` and ``b``: its cross-sections are discs of radius
    ``r`` normal to its axis, the still water line cuts each one ``y = z / cos β`` from its centre
    (``β`` the axis' inclination from the horizontal), and the part below is the circular segment
    ``r² acos(y/r) - y sqrt(r² - y²)``; its integral along the axis (scipy's ``quad``) is the
    volume, applied at its centre along the axis."""
    from scipy.integrate import quad

    length = float(np.linalg.norm(b - a))
    weight = rod.type.mass * g * length
    out = [(0.5 * (a + b), np.array([0.0, 0.0, -weight]))]
    r = 0.5 * rod.type.d
    cos_beta = float(np.hypot(*(b - a)[:2])) / length
    za, dz = float(a[2]), float(b[2] - a[2])

    def area(t):  # the submerged part of the section at t (m²)
        z = za + t * dz
        if cos_beta == 0.0:  # a vertical rod: each section wholly wet or dry
            return math.pi * r * r if z < 0.0 else 0.0
        y = min(max(z / cos_beta, -r), r)
        return r * r * math.acos(y / r) - y * math.sqrt(r * r - y * y)

    cuts = [(c - za) / dz for c in (-r * cos_beta, 0.0, r * cos_beta)] if dz != 0.0 else []
    points = [t for t in cuts if 0.0 < t < 1.0] or None
    options = dict(points=points, epsabs=1e-14 * r * r, epsrel=1e-13, limit=200)
    moment0 = quad(area, 0.0, 1.0, **options)[0]
    if moment0 > 0.0:
        centre = quad(lambda t: t * area(t), 0.0, 1.0, **options)[0] / moment0
        out.append((a + centre * (b - a), np.array([0.0, 0.0, rho * g * moment0 * length])))
    return out


def _balance(model, eq):
    """``[(what, net force (3,), net moment (3,) or None, scale)]`` at every free point and body:
    the independent sums of the module docstring (a rod body's moment about its end A)."""
    system = model.system
    P = {p.index: p.position for p in eq.points}
    loads = {k: [(P[k], f)] for k, f in _point_loads(model).items()}
    rods = [r for r in model.rods.values() if len(r.points) and r.points[0] is not r.points[1]]
    rod_lines = {id(r.handle) for r in rods if r.handle is not None}
    scale = max([abs(float(f[2])) for f in _point_loads(model).values()] + [1e-300])
    for k, line in zip(eq.line_indices, eq.lines, strict=True):
        handle = system.mooring_lines[k]
        if id(handle) in rod_lines:  # a rod fixed to a body: its loads come from `_rod_loads`
            continue
        for end, p in enumerate((handle.a, handle.b)):
            loads[p.index].append((P[p.index], np.asarray(line.end_forces[end])))
        scale = max(scale, float(np.linalg.norm(line.end_forces, axis=1).max()))
    for rod in rods:
        a, b = rod.points
        for where, force in _rod_loads(rod, P[a.index], P[b.index], system.rho, system.g):
            loads[a.index].append((where, force))  # on the rod's body, or its end A's point
    scale = max([scale] + [float(np.abs(f).max()) for items in loads.values() for _, f in items])
    scale = max([scale] + [b.mass * b.g + b.rho * b.g * b.volume for b in system.bodies])
    out = []
    for p in system.points:
        if p.kind == "free":
            net = sum((f for _, f in loads[p.index]), np.zeros(3))
            out.append((f"point {p.index}", net, None, scale, P[p.index]))
    pinned = set(system.held_dofs.tolist())
    for i, body in enumerate(system.bodies):
        state = eq.bodies[i]
        net, moment = np.zeros(3), np.zeros(3)
        for p in system.points:
            if p.body is body:
                for where, f in loads[p.index]:
                    net += f
                    moment += np.cross(where - state.offset, f)
        if not isinstance(body, RodBody):  # a rod's own loads are `_rod_loads`
            weight = np.array([0.0, 0.0, -body.mass * body.g])
            net += weight + np.array([0.0, 0.0, body.rho * body.g * body.volume])
            moment += np.cross(state.rotation @ body.center_of_gravity, weight)
        if system.layout.body_start[i] in pinned:  # the pin takes the force: the moment about it
            net = np.zeros(3)
        out.append((f"body {i}", net, moment, scale, state.offset))
    return out


def _line_check(model, eq, k, moorpy):
    """The line ``k`` of the file against MoorPy's catenary at its ends, or, where MoorPy has none or
    a wrong one, the straight line's closed form (module docstring)."""
    handle = model.lines[k]
    line = eq.lines[eq.line_indices.index(handle.index)]
    ours = np.linalg.norm(line.end_forces, axis=1)
    a, b = (eq.points[p.index].position for p in (handle.a, handle.b))
    segment = handle.model.segments[0]
    if line.model in ("vertical", "weightless"):
        if line.model == "weightless":
            d = float(np.linalg.norm(b - a))
            expected = (
                max(segment.EA * (d / segment.length - 1.0), 0.0) if segment.law.kind == "constant" else None
            )
            if expected is not None:
                np.testing.assert_allclose(ours, [expected, expected], rtol=1e-12, atol=1e-9 * segment.EA)
            return "closed form"
        low, high = sorted(ours)  # T at the top = T at the bottom + w L (the line straight, vertical)
        if line.state == "taut":
            assert abs(abs(ours[1] - ours[0]) - abs(segment.w) * segment.length) <= 1e-9 * max(high, 1.0)
            height = abs(float(b[2] - a[2]))
            T_low = min(ours) if segment.w > 0 else max(ours)
            stretched = segment.length * (1.0 + (T_low + 0.5 * abs(segment.w) * segment.length) / segment.EA)
            if segment.w < 0:
                stretched = segment.length * (
                    1.0 + (T_low - 0.5 * abs(segment.w) * segment.length) / segment.EA
                )
            assert stretched == pytest.approx(height, rel=1e-12)
        return "closed form"
    if moorpy is not None and line.model != "touchdown between the ends":
        # (MoorPy's catenary of a line touching the seabed between two suspended ends takes the
        # branch its start gives: its equilibrium decides, `test_moorpy_s_own_equilibrium`)
        ml = moorpy.lineList[k]
        ml.setEndPosition(a, 0)
        ml.setEndPosition(b, 1)
        with contextlib.redirect_stdout(io.StringIO()), np.errstate(all="ignore"):
            ml.staticSolve(tol=1e-10)
        if np.isfinite([ml.TA, ml.TB]).all():
            np.testing.assert_allclose(ours, [ml.TA, ml.TB], rtol=1e-4)
            return "MoorPy"
    if line.model == "free":  # MoorPy has no answer: Irvine's elastic catenary, solved here
        _irvine(line, segment, a, b)
        return "Irvine"
    return "balance only"


def _irvine(line, segment, a, b):
    """A free hanging line against H.M. Irvine's elastic catenary ("Cable Structures", 1981, eq.
    2.24), ``(H, V_b)`` solved here by scipy's ``fsolve`` from the line's own forces."""
    from scipy.optimize import fsolve

    w, L, EA = segment.w, segment.length, segment.EA
    span = float(np.hypot(*(b - a)[:2]))
    dz = float(b[2] - a[2])

    def ends(x):
        H, V = x
        Va = V - w * L
        X = H / w * (math.asinh(V / H) - math.asinh(Va / H)) + H * L / EA
        Z = H / w * (math.hypot(1.0, V / H) - math.hypot(1.0, Va / H)) + (V * L - 0.5 * w * L * L) / EA
        return [X - span, Z - dz]

    F = np.asarray(line.end_forces[1])
    H, V = fsolve(ends, [float(np.hypot(*F[:2])), -float(F[2])], xtol=1e-12)
    assert np.abs(ends([H, V])).max() <= 1e-9 * max(span, abs(dz), 1.0)
    T = np.linalg.norm(line.end_forces, axis=1)
    np.testing.assert_allclose(T, [math.hypot(H, V - w * L), math.hypot(H, V)], rtol=1e-9)


def _moorpy(name, model):
    """MoorPy's system of the file, g and the water density the file's, the depth MoorDyn's; None
    where MoorPy cannot read it (rods' ends, VIV columns, a Syrope EA, g = 0)."""
    moorpy = pytest.importorskip("moorpy")
    system = model.system
    try:
        with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ms = moorpy.System(file=str(DATA / name), depth=system.depth or 0.0, rho=system.rho, g=system.g)
            ms.depth = system.depth or 0.0
            ms.initialize()
    except Exception:  # noqa: BLE001 - MoorPy's own failure to read the file: the balance decides
        return None
    return ms


@pytest.mark.parametrize("name", CORPUS + OTHERS)
def test_every_file_reads_and_its_equilibrium_balances(name):
    if name in REFUSED:
        line, argument = REFUSED[name]
        with pytest.raises(InputError) as err:
            solved(name)
        assert err.value.line == line and err.value.argument == argument
        return
    if name in UNSOLVED:
        pytest.xfail(UNSOLVED[name])
    model, eq = solved(name)
    for what, net, moment, scale, where in _balance(model, eq):
        on_seabed = (
            model.system.depth is not None and abs(where[2] + model.system.depth) < 1e-9 * model.system.depth
        )
        if on_seabed and what.startswith("point"):  # the seabed pushes up: net down, none sideways
            assert net[2] <= 1e-8 * scale and np.abs(net[:2]).max() <= 1e-8 * scale, (what, net)
            continue
        assert np.abs(net).max() <= 1e-8 * scale, (what, net, scale)
        if moment is not None:
            arm = max(1.0, float(np.abs(where).max()))
            assert np.abs(moment).max() <= 1e-8 * scale * arm, (what, moment)


@pytest.mark.parametrize("name", [n for n in CORPUS + OTHERS if n not in REFUSED and n not in UNSOLVED])
def test_every_line_against_moorpy_or_the_straight_line(name):
    model, eq = solved(name)
    ms = _moorpy(name, model)
    judged = [_line_check(model, eq, k, ms) for k in range(len(model.lines))]
    assert len(judged) == len(model.lines)


#: files MoorPy 1.3 solves as the same system (its ``solveEquilibrium``, tol 1e-6 m); MoorPy solves
#: others differently: ``hanging_lines.txt``, ``test_dynamic_currents.txt`` (its catenary gives a
#: vertical line with a free end half its weight) and ``lifting.txt`` (a vertical line under a
#: weight: 0.0016 N), where the closed form decides (`_line_check`); ``SharedMooring2.dat`` (it makes
#: the turbines free bodies) and ``md_BdyExtLdDmpg`` (it reads no EXTERNAL LOADS), where the balance
#: decides
MOORPY_SOLVES = [
    "MoorDyn/tests/Mooring/body_tests/bodyDrag.txt",
    "MoorDyn/tests/Mooring/local_euler/hanging.txt",
    "MoorDyn/tests/Mooring/pendulum.txt",
    "MoorDyn/tests/Mooring/time_schemes.txt",
    "MoorPy/examples/MoordynSemiTautUpd.dat",
    "MoorPy/tests/case2.dat",
    "MoorPy/tests/case3.dat",
    "MoorPy/tests/case4.dat",
    "MoorPy/tests/case6.dat",
    "MoorPy/tests/case8.dat",
    "r-test/modules/moordyn/md_cable/moordyn.dat",
]


@pytest.mark.parametrize("name", MOORPY_SOLVES)
def test_moorpy_s_own_equilibrium(name):
    model, eq = solved(name)
    ms = _moorpy(name, model)
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert ms.solveEquilibrium(tol=1e-6, maxIter=1000)
    for k, handle in enumerate(model.lines):
        ours = np.linalg.norm(eq.lines[eq.line_indices.index(handle.index)].end_forces, axis=1)
        np.testing.assert_allclose(ours, [ms.lineList[k].TA, ms.lineList[k].TB], rtol=1e-4)


def test_a_point_hanging_below_its_anchor_weighs_m_g():
    """MoorDyn's pendulum: 1e5 kg on a line as dense as water, from a start 10 m aside; it hangs
    straight below the anchor, the line's tension at it m g (a line as dense as water: 1.6e-5 N/m
    of buoyancy, 1.6e-3 N along the line, below 1e-9 of m g)."""
    model, eq = solved("MoorDyn/tests/Mooring/pendulum.txt")
    (line,) = eq.lines
    assert line.model == "vertical" and line.state == "taut"  # to the tolerance: 1e-10 m g over m g / L
    assert eq.points[1].position[:2] == pytest.approx([0.0, 0.0], abs=1e-8)
    assert line.tension_b == pytest.approx(1e5 * 9.80665, rel=1e-9)
    model, eq = solved("MoorDyn/tests/Mooring/lifting.txt")  # 1e3 kg straight below from the start
    assert eq.lines[0].tension_b == pytest.approx(1e3 * 9.80665, rel=1e-9)


@pytest.mark.parametrize("upward", [False, True], ids=["a weight below", "a buoy above"])
def test_a_line_whose_ends_share_a_vertical_either_way_up(upward):
    """A weight hanging below an anchor, or a buoy held above one: the line hangs straight, its
    tension the point's net load at the point and that plus (minus) the line's weight at the anchor;
    its stretched length (Irvine's: ``L + (T_low L + w L²/2)/EA``) the height between them."""
    w, L, EA, load = 400.0, 80.0, 2e8, 5e5
    system = mooring.MooringSystem(depth=200.0, g=9.80665)
    anchor = system.add_point([10.0, 5.0, -200.0 if upward else -20.0], fixed=True)
    start = [12.0, 6.0, -125.0] if upward else [11.0, 4.0, -95.0]
    kind = dict(volume=load / (1025.0 * 9.80665)) if upward else dict(mass=load / 9.80665)
    point = system.add_point(start, **kind)
    ends = (anchor, point) if upward else (point, anchor)  # a below b, then b below a
    system.add_line(mooring.Line([mooring.Segment(L, w, EA)]), *ends)
    if upward:  # a buoy straight above its anchor pulls it up at 90°: a pile's load, said
        with pytest.warns(PlausibilityWarning, match=r"uplift_angle: is 90° at anchor point 0"):
            eq = system.equilibrium()
    else:
        eq = system.equilibrium()
    (line,) = eq.lines
    # to the equilibrium's tolerance (1e-10 of the load; its lateral stiffness T/L: 1e-8 m)
    assert line.model == "vertical" and eq.points[1].position[:2] == pytest.approx([10.0, 5.0], abs=1e-8)
    at_point = line.tension_b if upward else line.tension_a
    at_anchor = line.tension_a if upward else line.tension_b
    assert at_point == pytest.approx(load, rel=1e-10)
    assert at_anchor - at_point == pytest.approx(-w * L if upward else w * L, rel=1e-12)
    T_low = at_anchor if upward else at_point
    height = abs(eq.points[1].position[2] - anchor.position[2])
    assert L + (T_low * L + 0.5 * w * L * L) / EA == pytest.approx(height, rel=1e-13)


@pytest.mark.filterwarnings("default::skcable.errors.PlausibilityWarning")  # the command reports them
def test_the_command_runs_on_every_file_of_the_corpus(capsys):
    """``skcable mooring FILE`` on the 67 files: a result for every one MoorDyn reads (exit 0, or 5
    with the anchors pulled up named where the file's equilibrium has them: `FINDINGS`), a named
    refusal (exit 2) for the one it refuses; the unsolved ones loud (`UNSOLVED`). Each file's
    equilibrium is the module's (`solved`): the command's reading, its output and its errors are
    what this test runs."""
    from skcable import cli
    from skcable.mooring.equilibrium import warn_implausible
    from skcable.mooring.moordyn import MoorDynModel

    def cached(model, **options):  # each file solved once per module (`solved`), its findings warned
        eq = solved(str(Path(model.path).relative_to(DATA)))[1]
        warn_implausible(eq)
        return eq

    for name in CORPUS:
        if name not in UNSOLVED and name not in REFUSED:
            solved(name)  # solved before the command's equilibrium is the cached one
        with pytest.MonkeyPatch.context() as patch:
            if name not in UNSOLVED:
                patch.setattr(MoorDynModel, "equilibrium", cached)
            status = cli.main(["mooring", str(DATA / name), "--json"])
        out, err = capsys.readouterr()
        if name in REFUSED:
            assert status == cli.EXIT_USAGE and "line 17" in err, (name, err)
        elif name in UNSOLVED:  # loud: no convergence, or an equilibrium that says it is unstable
            assert (status != 0 or "unstable" in err) and err, name
        elif FINDINGS[name]:  # solved, with its findings named (`FINDINGS`)
            assert status == cli.EXIT_WARNINGS and all(m.split(":")[0] in err for m in FINDINGS[name]), (
                name,
                err,
            )
            assert '"lines"' in out
        else:
            assert status == 0, (name, err)
            assert '"lines"' in out


#: files whose equilibrium's net load has a round-off floor above the solver's tolerance (1e-10), and
#: that floor (of the force scale): ``BodiesAndRods.dat`` holds a rod pinned to a body by a tie of
#: 6.4e14 N/m (MoorDyn's 6e-8 m gap); moved by one ulp of its dofs its equilibrium's net load
#: scatters by 2e-8 to 7e-8. Read back, its tie starts closed (the pin where the file has it): one
#: Newton step lands in that noise, and the steps after it only sample it, as many as chance gives
#: (on main before the rods' water line, with the water density 1025 ± 0.03, 1 to 3 steps). The
#: tie also brings the scaled Jacobian near the conditioning threshold of the equilibrium's Newton
#: step: on the oldest numpy/scipy that pyproject.toml allows, the first step from the read-back
#: start was the least-squares one, taken by the watchdog with no gain (0.6696 -> 0.6696), and the
#: second landed in the noise (8e-9): the floor is reached within two steps.
NOISE_FLOOR = {"MoorDyn/tests/Mooring/BodiesAndRods.dat": 1e-7}


@pytest.mark.parametrize("name", [n for n in CORPUS + OTHERS if n not in REFUSED and n not in UNSOLVED])
def test_written_at_its_equilibrium_it_starts_there(name, tmp_path):
    """``write_moordyn(model, path, equilibrium=eq)``: read back, the same file but for the free
    points, bodies and turning rods, which start at the equilibrium: it takes no Newton step, or
    one (the positions written to their last digit; a file whose net load has a round-off floor
    above the tolerance, two at most to that floor: `NOISE_FLOOR`), and its points stay there."""
    model, eq = solved(name)
    path = mooring.write_moordyn(model, tmp_path / Path(name).name, equilibrium=eq)
    for aux in ("syrope.dat", "../owc.dat"):  # the files its line types name, beside it
        if (DATA / name).parent.joinpath(aux).is_file():
            target = path.parent / aux
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes((DATA / name).parent.joinpath(aux).read_bytes())
    again, _ = None, None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        again = mooring.read_moordyn(path, turbines=TURBINES.get(Path(name).name))
    with warnings.catch_warnings(record=True) as caught:  # the file's own findings (`FINDINGS`), again
        warnings.simplefilter("always", PlausibilityWarning)
        eq2 = again.equilibrium()
    assert sorted(str(w.message) for w in caught) == sorted(FINDINGS[name])
    if name in NOISE_FLOOR:  # its noise floor within two steps, and within it after (`NOISE_FLOOR`)
        reached = next((k for k, r in enumerate(eq2.history) if r <= NOISE_FLOOR[name]), None)
        assert reached is not None and reached <= 2, eq2.history
        assert max(eq2.history[reached:]) <= NOISE_FLOOR[name], eq2.history
    else:
        assert len(eq2.history) - 1 <= 1
    scale = max(1.0, max(float(np.abs(p.position).max()) for p in eq.points))
    for p, q in zip(eq.points, eq2.points, strict=True):
        np.testing.assert_allclose(q.position, p.position, rtol=0, atol=1e-9 * scale)
    unchanged = [k for k, (a, b) in enumerate(zip(model.text, again.text, strict=True)) if a == b]
    assert len(model.text) == len(again.text) and len(unchanged) >= len(model.text) - len(eq.points) - len(
        model.rods
    ) - len(model.bodies)


def test_rods_pinned_and_free_take_their_closed_forms():
    """MoorDyn's ``RodPinnedFloating.txt``: two rods lighter than water pinned at (0, 0, -5), one
    along x and one along y, stand straight up over their pin (their buoyancy's moment about it
    vanishes only there, the rod wholly below the water line); ``RodHanging.txt``: a rod hanging on
    two equal lines from symmetric anchors stays level, its lines' tensions equal and their vertical
    forces carrying its weight in water."""
    model, eq = solved("MoorDyn/tests/Mooring/RodPinnedFloating.txt")
    for rod in model.rods.values():
        a, b = (eq.points[p.index].position for p in rod.points)
        np.testing.assert_allclose(b - a, [0.0, 0.0, 1.0], atol=1e-9)
    model, eq = solved("MoorDyn/tests/Mooring/RodHanging.txt")
    rod = model.rods[1]
    a, b = (eq.points[p.index].position for p in rod.points)
    assert a[2] == pytest.approx(b[2], abs=1e-9) and float(np.linalg.norm(b - a)) == pytest.approx(
        20.0, rel=1e-12
    )
    lines = [eq.lines[eq.line_indices.index(h.index)] for h in model.lines]
    ends = [line.end_forces[1] for line in lines]  # their forces on the rod's ends
    assert np.linalg.norm(ends[0]) == pytest.approx(np.linalg.norm(ends[1]), rel=1e-9)
    system = model.system
    weight = (rod.type.mass - system.rho * math.pi / 4 * rod.type.d**2) * system.g * 20.0
    assert ends[0][2] + ends[1][2] == pytest.approx(weight, rel=1e-9)


@pytest.mark.parametrize("name", [n for n in CORPUS + OTHERS if n not in REFUSED and n not in UNSOLVED])
def test_the_only_findings_are_anchors_pulled_up_or_lines_overstretched_as_a_recount_says(name):
    """A public file's equilibrium warns only where an anchor on the seabed is pulled up beyond the
    5° of a drag anchor (a riser's base, a tension leg's pile: real, and named), exactly there (the
    angle recounted from the lines' end forces), or where a line is stretched beyond what a rope
    survives: MoorDyn's viscoelastic test stretches 1 m of polyester between points 2 m apart, a
    strain of at least 100 % by the chord alone."""
    model, eq = solved(name)
    angles = {j: a for j, a in uplift_angles(model, eq).items() if a > 5.0 + 1e-9}
    found = FINDINGS[name]
    uplifts = [m for m in found if m.startswith("uplift_angle:")]
    strains = [m for m in found if m.startswith("strain:")]
    assert len(uplifts) + len(strains) == len(found), found
    named = {int(re.search(r"at anchor point (\d+)", m)[1]): m for m in uplifts}
    assert sorted(named) == sorted(angles), (named, angles)
    for j, message in named.items():
        assert f"is {angles[j]:.3g}°" in message, (message, angles[j])
    system = model.system
    P = {p.index: p.position for p in eq.points}
    for message in strains:
        k = int(re.search(r"on line (\d+)", message)[1])
        handle = system.mooring_lines[k]
        chord = float(np.linalg.norm(P[handle.b.index] - P[handle.a.index]))
        length = sum(seg.length for seg in handle.model.segments)
        strain = float(re.search(r"a strain of ([0-9.e+-]+) %", message)[1]) / 100.0
        assert strain >= chord / length - 1.0 - 1e-9 and chord / length - 1.0 > 0.5, (message, chord, length)
