"""The edge-input regime: a valid call with one argument replaced by an edge value (zero, a
negative, a subnormal, 1e308, ±inf, NaN, a bool, None, a string, a list, an array, a complex,
a wrong shape).

No oracle of the value: every returned number must be finite, and a refusal must be an
`InputError` naming an argument of the call, or a `ConvergenceError` with a history. Where the
edge value is invalid in itself (NaN, ±inf, None, a string, a bool, a complex, an empty list) or
beyond any physical magnitude (1e308, 1e-300, subnormals) the refusal must name the argument
that was replaced: the rest of the call is valid (D8). Moderate values (0, -1, a float32, a
list or array that broadcasts) may change the scene's regime, and then any argument of the
call may be named. Anything else is untyped (D7).
"""

from __future__ import annotations

from tests.fuzz.harness import Case
from tests.fuzz.scenes import pick

__all__ = ["REGIMES", "TARGETS", "EDGES"]

#: Edge values, as Python source in the harness's namespace.
EDGES = (
    "0.0",
    "-1.0",
    "5e-324",
    "1e-300",
    "1e308",
    "inf",
    "-inf",
    "nan",
    "True",
    "None",
    "'1'",
    "[1.0, 2.0]",
    "np.array([1.0, 2.0])",
    "1j",
    "[]",
    "np.float32(1.5)",
    "-5e-324",
    "2.5e-308",
)

_NF = "conductors.natural_frequencies(300.0, 0.0, 15.0, 3e7, H=2e4, n_modes=2)"
_SECTION = "strand.preset('steel-9.5').damaged(1).section()"
_BODY = (
    "mooring.RigidBody([(20.0, 0.0, -10.0), (-10.0, 17.32, -10.0), (-10.0, -17.32, -10.0)], "
    "waterplane_area=500.0)"
)
_ANCHORS = "[(800.0, 0.0, -200.0), (-400.0, 692.8, -200.0), (-400.0, -692.8, -200.0)]"
_CHAIN = "mooring.Line([mooring.Segment(850.0, 1000.0, 5e8)], seabed=0.0)"

#: (label, call template, {argument: valid value}); each argument is replaced in turn.
TARGETS = (
    (
        "elastic_catenary",
        "cable.elastic_catenary(span={span}, dh={dh}, w={w}, EA={EA}, length={length})",
        {"span": "800.0", "dh": "200.0", "w": "1000.0", "EA": "5e8", "length": "850.0"},
    ),
    (
        "elastic_catenary/seabed",
        "cable.elastic_catenary(span={span}, dh={dh}, w={w}, EA={EA}, length={length}, seabed={seabed}, "
        "friction={friction})",
        {
            "span": "800.0",
            "dh": "200.0",
            "w": "1000.0",
            "EA": "5e8",
            "length": "850.0",
            "seabed": "0.0",
            "friction": "0.3",
        },
    ),
    (
        "sloped_seabed_catenary",
        "cable.sloped_seabed_catenary(span={span}, dh={dh}, w={w}, EA={EA}, length={length}, "
        "seabed_slope={seabed_slope}, friction={friction})",
        {
            "span": "800.0",
            "dh": "250.0",
            "w": "1000.0",
            "EA": "5e8",
            "length": "850.0",
            "seabed_slope": "0.05",
            "friction": "0.3",
        },
    ),
    (
        "Line.solve",
        "mooring.Line([mooring.Segment({length}, {w}, {EA}), mooring.Segment(300.0, 200.0, 3e8)], "
        "[mooring.ClumpWeight(1, {weight})], seabed={seabed}, friction={friction}).solve({span}, {dh})",
        {
            "length": "600.0",
            "w": "1000.0",
            "EA": "5e8",
            "weight": "2e4",
            "seabed": "0.0",
            "friction": "0.5",
            "span": "800.0",
            "dh": "200.0",
        },
    ),
    (
        "line_3d",
        "mooring.line_3d({model}, {anchor}, {fairlead})",
        {"model": _CHAIN, "anchor": "[800.0, 0.0, -200.0]", "fairlead": "[20.0, 0.0, -10.0]"},
    ),
    (
        "MooringSystem.equilibrium",
        "mooring.MooringSystem({body}, {lines}, {anchors}).equilibrium(force={force}, tol={tol}, "
        "max_iter={max_iter})",
        {
            "body": _BODY,
            "lines": f"[{_CHAIN}] * 3",
            "anchors": _ANCHORS,
            "force": "(1e5, 0.0, 0.0)",
            "tol": "1e-10",
            "max_iter": "60",
        },
    ),
    (
        "change_of_state",
        "conductors.change_of_state({span}, {dh}, EA={EA}, alpha={alpha}, w0={w0}, t0={t0}, H0={H0}, w={w}, "
        "t={t}, "
        "wind={wind})",
        {
            "span": "300.0",
            "dh": "10.0",
            "EA": "3e7",
            "alpha": "2e-5",
            "w0": "15.0",
            "t0": "15.0",
            "H0": "2e4",
            "w": "20.0",
            "t": "80.0",
            "wind": "5.0",
        },
    ),
    (
        "change_of_state/sag0",
        "conductors.change_of_state({span}, {dh}, EA={EA}, alpha={alpha}, w0={w0}, t0={t0}, "
        "sag0={sag0}, w={w}, t={t}, model='parabola')",
        {
            "span": "300.0",
            "dh": "10.0",
            "EA": "3e7",
            "alpha": "2e-5",
            "w0": "15.0",
            "t0": "15.0",
            "sag0": "8.0",
            "w": "20.0",
            "t": "80.0",
        },
    ),
    (
        "sag_tension_table",
        "conductors.sag_tension_table({span}, {dh}, EA={EA}, alpha={alpha}, w0={w0}, t0={t0}, H0={H0}, "
        "temperatures={temperatures}, load_cases={load_cases})",
        {
            "span": "300.0",
            "dh": "0.0",
            "EA": "3e7",
            "alpha": "2e-5",
            "w0": "15.0",
            "t0": "15.0",
            "H0": "2e4",
            "temperatures": "[-5.0, 15.0, 80.0]",
            "load_cases": "{'bare': (15.0, 0.0), 'ice': (25.0, 8.0)}",
        },
    ),
    (
        "tension_section",
        "conductors.tension_section({spans}, {dh}, EA={EA}, alpha={alpha}, w0={w0}, t0={t0}, H0={H0}, w={w}, "
        "t={t}, "
        "insulator_length={insulator_length}, insulator_weight={insulator_weight})",
        {
            "spans": "[300.0, 400.0, 250.0]",
            "dh": "0.0",
            "EA": "3e7",
            "alpha": "2e-5",
            "w0": "15.0",
            "t0": "15.0",
            "H0": "2e4",
            "w": "15.0",
            "t": "60.0",
            "insulator_length": "3.0",
            "insulator_weight": "700.0",
        },
    ),
    (
        "natural_frequencies",
        "conductors.natural_frequencies({span}, {dh}, {w}, {EA}, H={H}, n_modes={n_modes}, g={g})",
        {"span": "300.0", "dh": "10.0", "w": "15.0", "EA": "3e7", "H": "2e4", "n_modes": "3", "g": "9.81"},
    ),
    (
        "strand_bending_frequencies",
        "strand.strand_bending_frequencies({section}, {N}, {length}, {mass_per_length}, axis={axis}, "
        "n_modes={n_modes})",
        {
            "section": _SECTION,
            "N": "1e3",
            "length": "1.0",
            "mass_per_length": "0.5",
            "axis": "0",
            "n_modes": "3",
        },
    ),
    ("strand.damaged", "strand.preset({name}).damaged({n}).section()", {"name": "'steel-9.5'", "n": "2"}),
    (
        "solve_line_bvp",
        "mooring.solve_line_bvp({span}, {dh}, [({length}, {w}, {EA})], seabed={seabed}, friction={friction}, "
        "n_elements={n_elements}, rtol={rtol}, max_iter={max_iter})",
        {
            "span": "800.0",
            "dh": "200.0",
            "length": "850.0",
            "w": "1000.0",
            "EA": "5e8",
            "seabed": "0.0",
            "friction": "0.3",
            "n_elements": "32",
            "rtol": "1e-10",
            "max_iter": "50",
        },
    ),
    (
        "io.write_mode_shapes",
        "io.write_mode_shapes({result}, {path})",
        {"result": _NF, "path": "'/tmp/skcable_fuzz_modes.vtu'"},
    ),
    (
        "io.cable_mesh",
        "io.cable_mesh({solution}, {n})",
        {"solution": "cable.elastic_catenary(800.0, 200.0, 1000.0, 5e8, length=850.0)", "n": "51"},
    ),
)

#: Edges that may change the scene's regime rather than invalidate the argument.
MODERATE = ("0.0", "-1.0", "np.float32(1.5)", "[1.0, 2.0]", "np.array([1.0, 2.0])")

#: Arguments whose domain holds 0: a subnormal or 1e-300 there is a zero, no outsized value.
ZERO_OK = (
    "dh",
    "seabed",
    "friction",
    "seabed_slope",
    "alpha",
    "t",
    "t0",
    "wind",
    "N",
    "insulator_length",
    "insulator_weight",
    "weight",
    "tol",
)
TINY_EDGES = ("5e-324", "-5e-324", "1e-300", "2.5e-308")

#: (target, argument) whose domain holds negative values: a line segment's ``w`` (a buoyant
#: segment). A negative subnormal there is a buoyant segment of no weight, a change of regime.
NEGATIVE_OK = (("Line.solve", "w"), ("solve_line_bvp", "w"))

#: Arguments for which None is a valid choice (another argument may then be the one missing).
OPTIONAL = ("seabed", "H", "sag", "H0", "sag0", "start", "n_elements")

#: A path edge must not write: only values that name no writable file.
_PATH_EDGES = (
    "None",
    "5",
    "1.5",
    "True",
    "[]",
    "''",
    "'/nonexistent-fuzz-dir/x.vtu'",
    "'modes.txt'",
    "b'x.vtu'",
)


def edge(rng) -> Case:
    """One target, one argument, one edge value."""
    label, template, args = TARGETS[int(rng.integers(len(TARGETS)))]
    name = pick(rng, list(args))
    value = pick(rng, _PATH_EDGES if name == "path" else EDGES)
    call = dict(args)
    call[name] = value
    expr = template.format(**call)
    # "constraint": the library's name for "exactly one of" its keywords (H or sag, ...)
    extra = {"segments", "attachments", "joint", "weight", "buoyancy", "start", "position", "constraint"}
    if label.startswith("change_of_state"):  # the signature's other keywords (H0 or sag0, model)
        extra |= {"H0", "sag0", "model", "wind"}
    names = frozenset(args) | extra
    # the fields of a segment given as a tuple are the argument ``segments``
    wanted = (name, "segments") if label == "solve_line_bvp" and name in ("length", "w", "EA") else (name,)
    moderate = (
        value in MODERATE
        or (value == "None" and name in OPTIONAL)
        or (value in TINY_EDGES and name in ZERO_OK)
        or (value == "-5e-324" and (label, name) in NEGATIVE_OK)
    )
    return Case(
        f"edges/{label}",
        expr,
        names,
        None,
        None,
        must_name=None if moderate else wanted,
        note=f"{name}={value}",
    )


REGIMES = {"edges": edge}
