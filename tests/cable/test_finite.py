"""Every public closed-form call returns finite, residual-checked numbers or raises
InputError / ConvergenceError (issue #14): never another exception, never a NaN or inf.

Arguments are drawn from a seeded grid of magnitudes 1e-300 ... 1e300 of
either sign and zero, plus values that are not numbers at all (NaN, inf,
strings, None, booleans, complex, empty arrays, ragged lists, arrays whose
shapes do not broadcast). Each target is called with one argument replaced
at a time, with random combinations, and with arrays.
"""

import mpmath as mp
import numpy as np
import pytest

from skcable import bvp, cable
from skcable.cable.solution import ACCEPT
from skcable.errors import ConvergenceError, InputError

#: These scenes exercise the solvers beyond plausible answers (lifted anchors, bodies out of the
#: water, extreme magnitudes): the answer checks (tests/test_plausible.py) are not what they test.
pytestmark = pytest.mark.filterwarnings(
    "ignore:(strain|uplift_angle|mu|friction)\\b:skcable.errors.PlausibilityWarning"
)

MAGNITUDES = [1e-300, 1e-150, 1e-20, 1e-3, 0.5, 1.0, 7.5, 1e3, 1e20, 1e150, 1e300]
NUMBERS = [0.0, *MAGNITUDES, *(-m for m in MAGNITUDES)]
NOT_NUMBERS = [
    float("nan"),
    float("inf"),
    -float("inf"),
    "3",
    None,
    True,
    1j,
    [],
    np.array([]),
    [1.0, None],
    [[1.0, 2.0], [3.0]],
    10**400,
    np.ones(3),  # does not broadcast with the (2,) arrays below
]
SHOWN = ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low", "x_vertex", "y_vertex")


def _finite_numbers(value, where):
    if isinstance(value, (tuple, list)):
        for i, item in enumerate(value):
            _finite_numbers(item, f"{where}[{i}]")
        return
    array = np.asarray(value, dtype=float)
    assert np.all(np.isfinite(array)), f"{where} = {value!r} is not finite"


def check_result(result):
    """All numbers finite; the solution's own residual within the solvers' acceptance."""
    if isinstance(result, cable.CableSolution):
        for name in SHOWN:
            if hasattr(type(result), name):
                _finite_numbers(getattr(result, name), name)
        fractions = np.array([0.0, 0.37, 1.0])
        shape = np.broadcast(result.span, result.dh, result.T_A).shape
        if shape:  # x broadcasts against the solution's shape
            points = [np.multiply.outer(fractions, np.broadcast_to(result.span, shape))]
        else:  # one x at a time: an array of x costs the elastic catenary a vectorised search
            points = [float(f * result.span) for f in fractions]
        for x in points:
            for method in ("y", "T", "slope"):
                _finite_numbers(getattr(result, method)(x), method)
    elif isinstance(result, cable.Funicular):
        for name in ("T", "angles", "nodes", "forces"):
            _finite_numbers(getattr(result, name), name)
    elif isinstance(result, cable.FunicularVertical):
        for name in ("H", "V_A", "V_B", "T", "nodes", "loads"):
            _finite_numbers(getattr(result, name), name)
    elif isinstance(result, cable.SlidingLoad):
        for name in ("H", "V_A", "T_A", "y_load"):
            _finite_numbers(getattr(result, name), name)
        check_result(result.arc)
    elif isinstance(result, (bvp.SelfWeight, bvp.DeckLoad)):
        _finite_numbers(result.w, "w")
        assert type(result.w) is float
    elif isinstance(result, bvp.PointLoad):
        _finite_numbers((result.x, result.P), "x, P")
    elif isinstance(result, bvp.DistributedLoad):
        pass
    else:
        _finite_numbers(result, "result")
    if hasattr(result, "residual"):
        residual = result.residual()
        assert residual <= ACCEPT, f"residual {residual!r} of {type(result).__name__}"


def outcome(call, *args, **kwargs):
    """'ok' or 'raised'; any other exception propagates and fails the test."""
    try:
        result = call(*args, **kwargs)
    except (InputError, ConvergenceError):
        return "raised"
    check_result(result)
    return "ok"


def _sliding(span, w, length, P):
    return cable.sliding_load(span, w, length, P)


def _stiffness(model, span, dh, w, H, EA):
    solution = model(span, dh, w, H=H)
    return cable.geometric_stiffness(solution, EA=EA)


def _anchor(span, dh, w, H, mu):
    return cable.anchor_block_weight(cable.catenary(span, dh, w, H=H), mu)


def _y_at(span, dh, w, H, x):
    c = cable.catenary(span, dh, w, H=H)
    return c.y(x), c.T(x), c.slope(x)


def _parabola_y_at(span, dh, w, H, x):
    p = cable.parabola(span, dh, w, H=H)
    return p.y(x), p.T(x), p.slope(x)


def _solve(span, dh, w, value, name):
    return bvp.solve(span, dh, bvp.SelfWeight(w), **{name: value})


def _solve_deck(span, dh, w, value, name):
    return bvp.solve(span, dh, bvp.DeckLoad(w), **{name: value})  # the parabola is exact: no BVP


#: target: (callable, valid base arguments, which of them are numbers to perturb)
TARGETS = {
    **{
        f"catenary-{name}": (
            lambda span, dh, w, value, name=name: cable.catenary(span, dh, w, **{name: value}),
            dict(span=100.0, dh=30.0, w=2.0, value=base),
        )
        for name, base in [("length", 120.0), ("sag", 10.0), ("H", 300.0), ("low", -10.0), ("T_max", 400.0)]
    },
    **{
        f"parabola-{name}": (
            lambda span, dh, w, value, name=name: cable.parabola(span, dh, w, **{name: value}),
            dict(span=100.0, dh=30.0, w=2.0, value=base),
        )
        for name, base in [("length", 120.0), ("sag", 10.0), ("H", 300.0), ("low", -10.0), ("T_max", 400.0)]
    },
    "elastic_catenary": (
        lambda span, dh, w, EA, length: cable.elastic_catenary(span, dh, w, EA, length=length),
        dict(span=100.0, dh=30.0, w=2.0, EA=1e6, length=120.0),
    ),
    "funicular": (
        lambda bx, by, length, px, py: cable.funicular(
            (bx, by), [length, 6.0, 6.0, 5.0], [(5.0, -75.0), (px, py), (5.0, -75.0)]
        ),
        dict(bx=20.0, by=2.0, length=5.0, px=10.0, py=-100.0),
    ),
    "funicular_vertical-through": (
        lambda span, dh, x, P, yd: cable.funicular_vertical(
            span, dh, [(1.0, 50.0), (x, P), (7.0, 40.0)], through=(3.0, yd)
        ),
        dict(span=10.0, dh=-1.0, x=3.0, P=30.0, yd=-5.0),
    ),
    "funicular_vertical-H": (
        lambda span, dh, x, P, H: cable.funicular_vertical(span, dh, [(1.0, 50.0), (x, P), (x, 40.0)], H=H),
        dict(span=10.0, dh=-1.0, x=3.0, P=30.0, H=28.0),
    ),
    "geometric_stiffness-catenary": (
        lambda span, dh, w, H, EA: _stiffness(cable.catenary, span, dh, w, H, EA),
        dict(span=100.0, dh=30.0, w=2.0, H=300.0, EA=1e6),
    ),
    "geometric_stiffness-parabola": (
        lambda span, dh, w, H, EA: _stiffness(cable.parabola, span, dh, w, H, EA),
        dict(span=100.0, dh=30.0, w=2.0, H=300.0, EA=1e6),
    ),
    "geometric_stiffness_series": (cable.geometric_stiffness_series, dict(span=2.0, w=0.5, H=10.0)),
    "capstan": (cable.capstan, dict(T0=100.0, mu=0.3, angle=3.0)),
    "membrane_tension": (cable.membrane_tension, dict(p=2e5, R=1.5)),
    "smooth_surface_reaction": (cable.smooth_surface_reaction, dict(T=10.0, R_n=2.0, q_N=1.0)),
    "sphere_parallel": (cable.sphere_parallel, dict(q=3.0, R=2.0, latitude=0.6)),
    "ring_on_rod": (cable.ring_on_rod, dict(dh=5.0, w=2.0, length=100.0, mu=0.4)),
    "anchor_block_weight": (_anchor, dict(span=100.0, dh=0.0, w=1.0, H=50.0, mu=0.5)),
    "sliding_load": (_sliding, dict(span=100.0, w=1.0, length=110.0, P=20.0)),
    "catenary-methods": (_y_at, dict(span=100.0, dh=30.0, w=2.0, H=300.0, x=40.0)),
    "parabola-methods": (_parabola_y_at, dict(span=100.0, dh=30.0, w=2.0, H=300.0, x=40.0)),
    "SelfWeight": (bvp.SelfWeight, dict(w=1.0)),
    "DeckLoad": (bvp.DeckLoad, dict(w=1.0)),
    "PointLoad": (bvp.PointLoad, dict(x=1.0, P=2.0)),
    "solve-catenary": (
        lambda span, dh, w, value: _solve(span, dh, w, value, "sag"),
        dict(span=200.0, dh=0.0, w=1.0, value=20.0),
    ),
    "solve-parabola": (
        lambda span, dh, w, value: _solve_deck(span, dh, w, value, "H"),
        dict(span=200.0, dh=0.0, w=1.0, value=300.0),
    ),
}
#: T_max constraints cost ~2 ms a call (a bracketed minimum first): fewer random draws
SLOW = {"catenary-T_max": 20, "solve-catenary": 60, "sliding_load": 60}


@pytest.mark.parametrize("target", sorted(TARGETS))
@pytest.mark.filterwarnings("ignore::skcable.errors.PlausibilityWarning")  # extremes by design
def test_one_argument_at_a_time(target):
    call, base = TARGETS[target]
    assert outcome(call, **base) == "ok", "the base call must be valid"
    for name in base:
        values = NOT_NUMBERS + NUMBERS
        if "T_max" in target:
            values = NOT_NUMBERS + NUMBERS[::3]
        for value in values:
            outcome(call, **{**base, name: value})


@pytest.mark.parametrize("target", sorted(TARGETS))
def test_random_combinations_of_magnitudes(target):
    call, base = TARGETS[target]
    rng = np.random.default_rng(14)
    for _ in range(SLOW.get(target, 120)):
        draw = {name: float(rng.choice(NUMBERS)) for name in base}
        outcome(call, **draw)


#: one number per argument: arrays are refused, naming the argument
SCALAR_ONLY = ("SelfWeight", "DeckLoad", "PointLoad", "sliding_load", "funicular", "solve")


@pytest.mark.parametrize("target", sorted(TARGETS))
def test_arrays(target):
    call, base = TARGETS[target]
    if target.startswith(SCALAR_ONLY):
        for name in base:
            assert outcome(call, **{**base, name: np.array([1.0, 2.0]) * base[name]}) == "raised", name
        return
    if target.endswith("methods"):  # an array of x against a scalar solution
        assert outcome(call, **{**base, "x": np.array([[0.0, 40.0], [100.0, 250.0]])}) == "ok"
        return
    rng = np.random.default_rng(3)
    # a valid array call, each argument a (2,)-array around its base value
    arrays = {name: np.array([value, value * 1.01]) for name, value in base.items()}
    assert outcome(call, **arrays) == "ok"
    # broadcasting: (2, 1) against (2,) is fine, (3,) against (2,) is refused naming an argument
    first = next(iter(base))
    assert outcome(call, **{**arrays, first: arrays[first][:, None]}) == "ok"
    assert outcome(call, **{**arrays, first: np.ones(3)}) == "raised"
    assert outcome(call, **{**arrays, first: np.ones((0,))}) == "raised"
    # random magnitudes, as arrays of 8
    for _ in range(10):
        draw = {name: rng.choice(NUMBERS, size=8) for name in base}
        outcome(call, **draw)


def test_bad_input_names_the_argument():
    cases = [
        (lambda: cable.catenary("3", 30.0, 1.0, H=1.0), "span"),
        (lambda: cable.catenary(100.0, None, 1.0, H=1.0), "dh"),
        (lambda: cable.catenary(100.0, 30.0, True, H=1.0), "w"),
        (lambda: cable.catenary(100.0, 30.0, 1.0, H=[1.0, None]), "H"),
        (lambda: cable.catenary(np.ones(2), np.ones(3), 1.0, H=1.0), "dh"),
        (lambda: cable.catenary(np.ones(0), 30.0, 1.0, H=1.0), "span"),
        (lambda: cable.catenary(100.0, 30.0, 1.0, H=1e-300), "H"),  # tensions overflow
        (lambda: cable.catenary(100.0, 30.0, 1.0, H=1e307), "H"),  # span/(2a) underflows
        (lambda: cable.parabola(100.0, 30.0, 1.0, H=1e-300), "H"),
        (lambda: bvp.SelfWeight("3"), "w"),
        (lambda: bvp.SelfWeight(np.array([1.0, 2.0])), "w"),
        (lambda: bvp.DeckLoad(None), "w"),
        (lambda: bvp.PointLoad("1", 2.0), "x"),
        (lambda: cable.capstan(1e300, 10.0, 100.0), "T0, mu, angle"),
        (lambda: cable.sphere_parallel(1.0, 1.0, 1e-320), "q, R, latitude"),
        (lambda: cable.geometric_stiffness_series(1e-300, 1.0, 1.0), "span, w, H"),
        (lambda: cable.funicular_vertical(10.0, 0.0, [(5.0, 1.0), (5.0, "2")], H=1.0), "loads"),
        (lambda: cable.funicular((20.0, 2.0), [5.0, 6.0], [(0.0, 0.0)]), "loads"),
        (lambda: cable.catenary(100.0, 30.0, 2.0, H=300.0).y(1e20), "x"),
        (lambda: cable.catenary(100.0, 30.0, 2.0, H=300.0).points(-1), "n"),
    ]
    for call, argument in cases:
        with pytest.raises(InputError) as info:
            call()
        assert info.value.argument == argument, (info.value.argument, str(info.value))
        assert isinstance(info.value, ValueError)


def test_extreme_but_representable_results_are_right():
    # 40-digit values of the closed forms; each has an intermediate beyond the float range
    mp.mp.dps = 40
    assert cable.capstan(1e-300, 10.0, 100.0) == pytest.approx(
        float(mp.mpf("1e-300") * mp.exp(1000)), rel=1e-13
    )
    T, Q = cable.sphere_parallel(1e-300, 1e300, 0.6)  # T = qR cos²/sin, Q = q/sin
    assert T == pytest.approx(float(mp.cos(mp.mpf(0.6)) ** 2 / mp.sin(mp.mpf(0.6))), rel=1e-14)
    assert Q == pytest.approx(float(mp.mpf("1e-300") / mp.sin(mp.mpf(0.6))), rel=1e-14)
    # k = 3H/(2 span) + 12 H³/(w² span³): the first term alone, then the second (xi² underflows)
    assert cable.geometric_stiffness_series(1e300, 1e300, 1.0) == pytest.approx(1.5e-300, rel=1e-14)
    assert cable.geometric_stiffness_series(1.0, 1e-300, 1e-100) == pytest.approx(1.2e301, rel=1e-14)
    assert cable.membrane_tension(1e-300, 1e300) == pytest.approx(1.0, rel=1e-15)
