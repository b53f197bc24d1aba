"""Every public result prints one line with its key numbers and their units: the test reads
each ``name=value unit`` back from the ``repr`` and compares it with the object's attributes
(to the last digit printed), and checks that no number is printed unchecked."""

import re
from html.parser import HTMLParser

import numpy as np
import pytest

from skcable import cable, conductors, mooring, strand, study

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?"
VALUE = rf"\[{NUMBER}(?:, {NUMBER})*\]|\({NUMBER}(?:, {NUMBER})*\)|{NUMBER}\.\.{NUMBER}|{NUMBER}"
ITEM = re.compile(rf"(\w+)=({VALUE})(?: ([^\s,;:()=]+))?")


def parse(text: str) -> dict:
    """``name -> (list of printed number strings, is_range, unit)`` of every ``name=value unit``."""
    found = {}
    for name, value, unit in ITEM.findall(text):
        assert name not in found, f"{name} printed twice in {text}"
        if ".." in value:
            found[name] = (value.split(".."), True, unit)
        else:
            found[name] = (re.findall(NUMBER, value), False, unit)
    return found


def half_unit(printed: float, digits: int) -> float:
    """Half a unit of the last of ``digits`` significant digits: the rounding of a number
    printed with them (``%g`` drops trailing zeros: "2" is 2.00000 to 6 digits)."""
    return 0.5 * 10.0 ** (np.floor(np.log10(abs(printed))) - digits + 1) if printed else 0.0


def agrees(printed: str, actual: float, digits: int = 6) -> bool:
    value = float(printed)
    return abs(value - actual) <= 1.0001 * half_unit(value, digits)


def check_repr(result, spec: dict, digits: int = 6) -> str:
    """Assert that ``repr(result)`` is one line and prints exactly ``spec``'s names, each
    with its unit and the value of ``spec[name][1](result)`` (a list, or a range, of an
    array) to ``digits`` significant digits."""
    text = repr(result)
    assert "\n" not in text, text
    found = parse(text)
    assert set(found) == set(spec), f"printed {sorted(found)}, expected {sorted(spec)}: {text}"
    for name, (unit, of) in spec.items():
        printed, is_range, shown_unit = found[name]
        assert shown_unit == unit, f"{name}: unit {shown_unit!r}, expected {unit!r}: {text}"
        actual = np.ravel(np.asarray(of(result), dtype=float))
        if is_range:
            ends = agrees(printed[0], actual.min(), digits), agrees(printed[1], actual.max(), digits)
            assert all(ends), (name, text)
        else:
            assert len(printed) == actual.size, (name, text)
            pairs = zip(printed, actual, strict=True)
            assert all(agrees(p, a, digits) for p, a in pairs), (name, printed, actual)
    check_html(result, found)
    return text


class _Table(HTMLParser):
    """The rows of an HTML table: each row's cell texts; the caption."""

    def __init__(self):
        super().__init__()
        self.rows, self.caption, self._in = [], "", None

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th", "caption"):
            self._in = tag
            if tag != "caption":
                self.rows[-1].append("")

    def handle_endtag(self, tag):
        self._in = None

    def handle_data(self, data):
        if self._in == "caption":
            self.caption += data
        elif self._in:
            self.rows[-1][-1] += data


def check_html(result, found: dict) -> None:
    """Jupyter shows ``result`` as a table (issue 31): one row per quantity of its repr, its
    value and unit as printed there."""
    table = _Table()
    table.feed(result._repr_html_())
    assert table.rows[0] == ["quantity", "value", "unit"] and table.caption
    assert parse(", ".join(f"{n}={v} {u}".rstrip() for n, v, u in table.rows[1:])) == found


def attr(name):
    return lambda result: getattr(result, name)


def attrs(units: dict) -> dict:
    """The spec of attributes printed under their own names."""
    return {name: (unit, attr(name)) for name, unit in units.items()}


@pytest.fixture(scope="module")
def curve():
    model = strand.StrandModel(strand.preset("steel-9.5").damaged(2), 0.3, n_elements=16, slip="axis")
    return model.capacity_curve(n_steps=8)


def curve_spec(end="rupture", K_Leq=True):
    spec = {
        f"{end}_strain": ("", lambda c: c.strain[-1]),
        f"{end}_force": ("N", lambda c: c.force[-1]),
        "toughness": ("N", lambda c: np.trapezoid(c.force, c.strain)),  # the area under the curve
    }
    if K_Leq:
        spec["K_Leq"] = ("N", attr("K_Leq"))
    return spec


def test_capacity_curve_and_step(curve):
    assert curve.ruptured
    spec = curve_spec() | {
        "max_slip_fraction": ("", lambda c: np.max(c.slip_fraction)),
        "cutbacks": ("", attr("cutbacks")),
        "snaps": ("", lambda c: sum(s.shifted for s in c.steps)),
    }
    assert "slip 'axis', 8 steps, ruptured" in check_repr(curve, spec)
    stopped = curve.model.capacity_curve(max_strain=0.003, n_steps=4)
    spec = curve_spec("last") | {k: spec[k] for k in ("max_slip_fraction", "cutbacks", "snaps")}
    assert "not ruptured" in check_repr(stopped, spec)
    step_spec = {
        "strain": ("", attr("strain")),
        "force": ("N", attr("force")),
        "slip_fraction": ("", lambda s: np.mean(s.slipping.any(axis=0))),
        "peak_curvature": ("1/m", lambda s: np.abs(s.curvature).max()),
        "max_wire_strain": ("", lambda s: s.wire_strain.max()),
        "iterations": ("", attr("iterations")),
    }
    check_repr(curve.steps[2], step_spec)


def test_bending_cycles():
    s = strand.preset("steel-9.5")
    law = strand.LayerSlipLaw(s.section(), mu=0.5, tension=20e3)
    model = strand.StrandModel(s, 0.3, n_elements=16, slip=strand.StageSlip(law), axial="force")
    cycles = strand.bending_cycles(model, 0.006, force=20e3, n_steps=1, cycles=1)

    def loop_area(c):  # ∮ R dq of the cycle's polygon (the shoelace formula, clockwise positive)
        q, R = c.drive[c.branch > 0], c.reaction[c.branch > 0]
        q, R = np.append(c.amplitude, q), np.append(c.backbone[1][-1], R)
        return -0.5 * (np.dot(q[:-1], R[1:]) - np.dot(q[1:], R[:-1]))

    spec = {
        "amplitude": ("rad", attr("amplitude")),
        "energy_per_cycle": ("J", loop_area),
        "friction_per_cycle": ("J", lambda c: c.work[c.branch > 0].sum()),
        "inexact": ("", attr("inexact")),
        "unloaded": ("", attr("unloaded")),
    }
    assert check_repr(cycles, spec).startswith("BendingCycles(right v', 1 cycle, ")


def test_analysis_and_closed_form():
    analysis = strand.analyse(strand.preset("steel-9.5"), n_points=50)
    text = check_repr(analysis, {k: (u, lambda a, f=f: f(a.curve)) for k, (u, f) in curve_spec().items()})
    assert text.startswith("Analysis(closed form: ") and analysis.reason in text
    assert "'steel-9.5', 50 points" in check_repr(analysis.curve, curve_spec())


def test_section_and_bending_law():
    s = strand.preset("steel-9.5").damaged(1)
    section = s.section()
    spec = attrs({"area": "m²", "centroid": "m", "I_stick": "m⁴", "I_slip": "m⁴", "EA": "N"})
    check_repr(section, spec, digits=4)
    law = s.bending_law(mu=0.5, axial_strain=0.004)
    units = {"mu": "", "axial_strain": "", "EI_stick": "N·m²", "EI_slip": "N·m²", "M_rf": "N·m"}
    check_repr(law, attrs(units | {"kappa_m": "1/m"}), digits=4)


def test_change_of_state_and_thermal_catenary():
    states = conductors.change_of_state(
        np.array([300.0, 400.0]),
        0.0,
        EA=3e7,
        alpha=2.3e-5,
        w0=10.0,
        t0=15.0,
        sag0=6.0,
        w=[10.0, 25.0],
        t=[50, -5],
    )
    units = {"t": "°C", "w": "N/m", "H": "N", "sag": "m", "T_max": "N", "L0": "m"}
    assert "(catenary, 2 spans × 2 states: " in check_repr(states, attrs(units))
    windy = conductors.change_of_state(
        300.0, 0.0, EA=3e7, alpha=2.3e-5, w0=10.0, t0=15.0, sag0=6.0, w=10.0, t=50.0, wind=3.0
    )
    blowout = ("rad", lambda r: np.arctan2(r.wind, r.w))  # the resultant load's angle
    check_repr(windy, attrs(units | {"wind": "N/m"}) | {"blowout": blowout})
    hot = conductors.thermal_catenary(300.0, 0.0, 10.0, 3e7, length=301.0, alpha=2.3e-5, t=50.0, t0=15.0)
    units = {"H": "N", "V_A": "N", "V_B": "N", "T_A": "N", "T_B": "N", "sag": "m", "length": "m"}
    spec = attrs(units | {"stretched_length": "m"}) | {"k": ("", lambda r: 1 + 2.3e-5 * 35)}
    check_repr(hot, spec)


def test_tension_section():
    section = conductors.tension_section(
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
    )
    ruling = np.sqrt((250**3 + 450**3 + 300**3) / (250 + 450 + 300))  # the ruling span's formula
    units = {"t": "°C", "w": "N/m", "H": "N", "sag": "m", "swing": "m", "H_ruling": "N"}
    spec = attrs(units) | {"ruling_span": ("m", lambda s: ruling)}
    assert "(3 spans, 2 states: " in check_repr(section, spec)


def test_frequencies():
    f = conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0, n_modes=4)
    units = {"f_in_plane": "Hz", "f_out_of_plane": "Hz", "H": "N", "sag": "m", "lambda2": ""}
    assert "(4 modes: " in check_repr(f, attrs(units))
    beam = strand.beam_frequencies(1.0, 1e3, 1.0, 0.45, n_modes=3)
    spec = attrs({"f": "Hz", "EI": "N·m²", "N": "N", "length": "m", "mass_per_length": "kg/m"})
    assert "(clamped, 3 modes: " in check_repr(beam, spec)
    section = strand.preset("steel-9.5").section()
    both = strand.strand_bending_frequencies(section, N=1e3, length=1.0, mass_per_length=0.45, n_modes=3)
    spec = attrs({"f_stick": "Hz", "f_slip": "Hz", "EI_stick": "N·m²", "EI_slip": "N·m²"})
    check_repr(both, spec | {"drop": ("", lambda r: 1 - r.f_slip / r.f_stick)})


def test_funicular_polygons():
    poly = cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)])
    spec = attrs({"T": "N", "angles": "rad", "lengths": "m"}) | {"B": ("m", lambda r: [20, 2])}
    assert "(4 segments: " in check_repr(poly, spec)
    vertical = cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5))
    spec = attrs({"H": "N", "V_A": "N", "V_B": "N"}) | {
        "T": ("N", lambda r: np.hypot(r.H, np.diff(r.nodes[:, 1]) / np.diff(r.nodes[:, 0]) * r.H)),
        "B": ("m", lambda r: [10, -1]),
    }
    check_repr(vertical, spec)


def test_catenaries_on_arrays():
    spans = np.linspace(100.0, 900.0, 20)
    many = cable.catenary(spans, -20.0, 20.0, length=1.05 * spans)
    units = dict.fromkeys(("H", "V_A", "V_B", "T_A", "T_B", "length", "sag"), "")  # any consistent units
    assert "(20 scenes, constraint 'length': " in check_repr(many, attrs(units))
    two = cable.catenary(spans[:2], -20.0, 20.0, length=1.05 * spans[:2])
    check_repr(two, attrs(units))


def test_mooring_equilibrium():
    heading = np.radians([0.0, 120.0, 240.0])
    ring = np.column_stack([np.cos(heading), np.sin(heading), np.zeros(3)])
    body = mooring.RigidBody(
        20.0 * ring + [0.0, 0.0, -14.0],
        mass=8e6,
        volume=8.2e3,
        center_of_gravity=(0, 0, -5),
        metacentre=(0, 0, 10),
        waterplane_area=600.0,
    )
    leg = mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0)
    system = mooring.MooringSystem(body, [leg] * 3, 800.0 * ring + [0.0, 0.0, -200.0], depth=200.0)
    eq = system.equilibrium(force=(2e6, 0.0, 0.0))
    spec = attrs({"offset": "m", "angles": "rad", "heel": "rad"}) | {
        "T_fairlead": ("N", lambda e: np.linalg.norm(e.fairlead_forces, axis=1)),
        "min_eigenvalue": ("N/m", lambda e: np.min(e.eigenvalues)),
        "iterations": ("", lambda e: len(e.history) - 1),
    }
    assert "(3 lines: " in check_repr(eq, spec)


def test_study_table_header():
    cases = study.grid(span=[100.0, 200.0], sag=[5.0, -1.0], w=[10.0])
    table = study.run(study.cable_solve, cases, executor="serial", progress=False)
    head = repr(table).splitlines()[0]
    n, ok, failed = map(
        int, re.fullmatch(r"skcable study of cable_solve: (\d+) cases, (\d+) ok, (\d+) failed", head).groups()
    )
    assert (n, ok, failed) == (len(cases), (table.status == "ok").sum(), (table.status == "failed").sum())


def test_parser_reads_lists_ranges_and_units():
    found = parse("X(a=1.5 N, b=[1, 2e+03] m, c=0..19 Hz, d=(3, 4) N·m², n=7)")
    assert found == {
        "a": (["1.5"], False, "N"),
        "b": (["1", "2e+03"], False, "m"),
        "c": (["0", "19"], True, "Hz"),
        "d": (["3", "4"], False, "N·m²"),
        "n": (["7"], False, ""),
    }
    assert half_unit(85819.2, 6) == pytest.approx(0.05) and half_unit(1.01608e07, 6) == pytest.approx(50)
    assert agrees("85819.2", 85819.24) and not agrees("85819.2", 85819.26)
    assert agrees("2", 2.000004) and not agrees("2", 2.00001)  # "2" is 2.00000 to 6 digits
    assert agrees("0", 0.0) and not agrees("0", 1e-300)
