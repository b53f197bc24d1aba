"""Bad input to the strand geometry, materials, sections and bending law raises
InputError naming the argument; nothing is silently reinterpreted."""

import numpy as np
import pytest

from skcable import strand
from skcable.errors import InputError

S = strand.preset("steel-9.5")
STEEL = strand.material("steel")
D = 3.1e-3
MAT = dict(E_e=2e11, E_p=1e9, eps_y=0.0053, eps_y1=0.005, eps_y2=0.006, eps_rupture=0.08)


def raises(argument, call):
    with pytest.raises(InputError) as info:
        call()
    assert info.value.argument == argument, str(info.value)
    return info.value


# --- Layer -------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "argument, kwargs",
    [
        ("phase", dict(phase=np.nan)),
        ("phase", dict(phase=np.inf)),
        ("phase", dict(phase="0")),
        ("phase", dict(phase=np.array([0.0, 0.1]))),
        ("wire_diameter", dict(wire_diameter=np.nan)),
        ("wire_diameter", dict(wire_diameter="3.1e-3")),
        ("wire_diameter", dict(wire_diameter=True)),
        ("wire_diameter", dict(wire_diameter=np.array([]))),
        ("wire_diameter", dict(wire_diameter=[D, D])),
        ("wire_diameter", dict(wire_diameter=0.0)),
        ("count", dict(count=True)),
        ("count", dict(count=6.0)),
        ("count", dict(count="6")),
        ("count", dict(count=0)),
        ("lay_angle", dict(lay_angle=np.nan)),
        ("lay_angle", dict(lay_angle="0.1")),
        ("lay_angle", dict(lay_angle=np.pi / 2)),
        ("direction", dict(direction=1.0)),
        ("direction", dict(direction=True)),
        ("direction", dict(direction=2)),
    ],
)
def test_layer_refuses(argument, kwargs):
    args = dict(count=6, wire_diameter=D, lay_angle=0.13) | kwargs
    raises(argument, lambda: strand.Layer(**args))


@pytest.mark.parametrize("value", [np.nan, np.inf, -1.0, "0.1", True, np.array([0.1])])
def test_layer_refuses_bad_lay_length(value):
    raises("lay_length", lambda: strand.Layer(6, D, lay_length=value))


def test_layer_keeps_numpy_numbers_as_plain_python_ones():
    layer = strand.Layer(np.int64(6), np.float32(D), lay_angle=np.float64(0.13), direction=np.int8(-1))
    assert type(layer.count) is int and type(layer.direction) is int
    assert type(layer.wire_diameter) is float and layer.wire_diameter == float(np.float32(D))


# --- Strand ------------------------------------------------------------------------------
def test_strand_refuses_bad_parts():
    layer = S.layers[0]
    raises("core_diameter", lambda: strand.Strand(np.nan, (layer,), STEEL))
    raises("core_diameter", lambda: strand.Strand("3e-3", (layer,), STEEL))
    raises("layers", lambda: strand.Strand(D, layer, STEEL))  # a Layer, not a tuple of them
    raises("layers", lambda: strand.Strand(D, (), STEEL))
    raises("layers", lambda: strand.Strand(D, (layer, "layer"), STEEL))
    raises("material", lambda: strand.Strand(D, (layer,), "steel"))
    raises("name", lambda: strand.Strand(D, (layer,), STEEL, name=7))
    assert strand.Strand(D, [layer], STEEL).layers == (layer,)  # a list is the same sequence


@pytest.mark.parametrize(
    "broken",
    [
        {(1, 0.5)},  # used to break nothing
        {(1, 2.0)},  # a float, even an integral one
        {(1.0, 2)},
        {(True, 2)},
        {(1, 6)},  # out of range
        {(1, -1)},  # no Python-style negative indices
        {(0, 0)},  # the core cannot break
        {(2, 0)},
        {(1, 2, 3)},
        {1},
        [(1, 2), (1, 2)],  # listed twice
        "(1, 2)",
        (1, 2),  # one pair instead of a list of pairs
    ],
)
def test_strand_refuses_bad_broken(broken):
    raises("broken", lambda: strand.Strand(D, S.layers, STEEL, broken=broken))


@pytest.mark.parametrize(
    "wires",
    [
        [(1, 2.7)],  # used to break wire 2
        [(1, 0.5)],  # used to break wire 0
        [(1, np.float64(2.0))],
        [(1, True)],
        [(1, 6)],
        [(1, -1)],
        [(2, 0)],
        [(0, 0)],
        [(1, 2), (1, 2)],
        [[1, 2, 3]],
        (1, 2),
        "12",
        7,
    ],
)
def test_damaged_refuses_bad_wires(wires):
    raises("wires", lambda: S.damaged(wires=wires))


def test_damaged_breaks_exactly_the_named_wires():
    # the intact flags follow (layer, index) exactly; numpy integers are integers
    s = S.damaged(wires=[(1, np.int64(2)), [1, 4]])
    assert s.broken == {(1, 2), (1, 4)}
    assert list(s.wires().intact) == [True, True, True, False, True, False, True]
    # adding breaks keeps the earlier ones; breaking one twice is refused
    assert S.damaged(wires=[(1, 0)]).damaged(wires=[(1, 3)]).broken == {(1, 0), (1, 3)}
    raises("wires", lambda: S.damaged(wires=[(1, 0)]).damaged(wires=[(1, 0)]))
    # a set gives the same strand as a list
    assert S.damaged(wires={(1, 2), (1, 4)}) == s


@pytest.mark.parametrize("n", [True, 1.0, "1", -1, 6, None])
def test_damaged_refuses_bad_n(n):
    if n is None:
        raises("n", lambda: S.damaged())  # neither n nor wires
    else:
        raises("n", lambda: S.damaged(n))
    raises("n", lambda: S.damaged(1, wires=[(1, 0)]))  # both


def test_damaged_n_on_a_damaged_strand_is_refused_and_zero_does_not_rotate():
    # damaged(n) rotates the outer layer: it would move wires already broken
    raises("n", lambda: S.damaged(wires=[(1, 3)]).damaged(1))
    raises("n", lambda: S.damaged(1).damaged(1))
    # no wire to place: the geometry is the strand's own, unrotated
    zero = S.damaged(0)
    assert zero.layers == S.layers and not zero.broken
    np.testing.assert_array_equal(zero.wires().psi, S.wires().psi)


@pytest.mark.parametrize("name", ["steel-99", ["steel-9.5"], None, 9.5])
def test_preset_refuses_unknown_names(name):
    raises("name", lambda: strand.preset(name))


# --- Material ----------------------------------------------------------------------------
@pytest.mark.parametrize(
    "argument, value",
    [
        ("E_e", np.nan),
        ("E_e", "2e11"),
        ("E_e", True),
        ("E_e", np.array([2e11, 2e11])),
        ("E_p", np.inf),
        ("E_p", "1e9"),
        ("eps_y", np.nan),
        ("eps_y1", "0.005"),
        ("eps_y2", np.inf),
        ("eps_rupture", np.nan),
        ("eps_rupture", np.array([])),
        ("poisson", np.nan),
        ("poisson", "0.3"),
        ("poisson", False),
    ],
)
def test_material_refuses(argument, value):
    raises(argument, lambda: strand.Material(**(MAT | {argument: value})))


@pytest.mark.parametrize("name", ["copper", ["steel"], None])
def test_material_preset_refuses_unknown_names(name):
    raises("name", lambda: strand.material(name))


@pytest.mark.parametrize("method", ["stress", "tangent", "secant"])
@pytest.mark.parametrize("strain", ["0.001", True, np.array(["0.001"]), [[0.001], [0.001, 0.002]], None])
def test_material_law_refuses_non_numbers(method, strain):
    raises("strain", lambda: getattr(STEEL, method)(strain))


@pytest.mark.parametrize("method", ["stress", "tangent", "secant"])
def test_material_law_is_element_wise_on_any_shape(method):
    law = getattr(STEEL, method)
    strain = np.linspace(-0.05, 0.05, 12).reshape(3, 4)
    out = law(strain)
    assert out.shape == (3, 4)
    np.testing.assert_array_equal(out.ravel(), [law(float(e)) for e in strain.ravel()])
    assert law(np.empty((0, 3))).shape == (0, 3)  # empty in, empty out (element-wise)
    assert np.isnan(law(np.nan))  # documented: not refused, propagated
