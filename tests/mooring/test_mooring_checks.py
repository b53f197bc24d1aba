"""Anchor and line checks, and the component library.

References: each line's closure at 30 digits with mpmath (`tests.mooring.mooring_reference`) for the
anchor loads, uplift, grounded length and largest tensions; published numbers for the library:
the breaking loads of offshore chain tabulated from DNV-OS-E302 by a chain maker, and the property
formulas of Orcina's OrcaFlex documentation, written in the test.
"""

import math

import numpy as np
import pytest

from skcable import mooring
from skcable.errors import InputError
from tests.mooring.mooring_reference import free_line, grounded_line


def _spread(line, radius=800.0, force=(1.2e6, 0.0, 0.0)):
    system = mooring.MooringSystem(depth=200.0)
    hull = system.add_body(
        mooring.RigidBody(mass=8e6, volume=8.2e3, metacentre=(0, 0, 10), waterplane_area=600.0)
    )
    for h in np.radians([0.0, 120.0, 240.0]):
        c, s = np.cos(h), np.sin(h)
        a = system.add_point([radius * c, radius * s, -200.0], fixed=True)
        system.add_line(line, a, system.add_point([20 * c, 20 * s, -14.0], body=hull))
    return system, system.equilibrium(force={hull: force})


def test_anchor_loads_and_grounded_lengths_against_the_closure():
    w, EA, L, mu = 2456.82, 1.2326e9, 850.0, 0.6
    line = mooring.Line([mooring.Segment(L, w, EA)], seabed=0.0, friction=mu)
    system, eq = _spread(line)
    anchors, lines = eq.anchor_loads(), eq.line_checks()
    assert len(anchors) == 3 and (anchors["lines"] == 1).all()
    for k, solved in enumerate(eq.lines):
        span, dh = solved.span, solved.dh
        H, V_B, H_A, L_B = grounded_line(span, dh, w, EA, L, mu, (solved.plane.H_B, solved.plane.V_B))
        assert anchors["horizontal"].iloc[k] == pytest.approx(H_A, rel=1e-10, abs=1e-6 * H)
        assert anchors["vertical"].iloc[k] == 0.0 and anchors["uplift_angle"].iloc[k] == 0.0
        assert lines["grounded_length"].iloc[k] == pytest.approx(L_B, rel=1e-10)
        assert lines["lower_angle"].iloc[k] == 0.0 and lines["lower_end"].iloc[k] == "a"
        assert lines["T_b"].iloc[k] == pytest.approx(math.hypot(H, V_B), rel=1e-10)


def test_uplift_of_a_taut_line():
    w, EA, L = 1000.0, 6.0e8, 770.0
    line = mooring.Line([mooring.Segment(L, w, EA)], seabed=0.0)
    system, eq = _spread(line, radius=760.0, force=(4e5, 0.0, 0.0))
    anchors, lines = eq.anchor_loads(), eq.line_checks()
    taut = int(np.argmax(anchors["uplift_angle"].to_numpy()))
    solved = eq.lines[taut]
    assert solved.model == "free"
    H, V_A, _ = free_line(solved.span, solved.dh, [(L, w, EA)], (solved.plane.H_B, solved.plane.V_B))
    # the line pulls its anchor up: V_A < 0 is the upward reaction's sign
    assert anchors["vertical"].iloc[taut] == pytest.approx(-V_A, rel=1e-9)
    assert anchors["uplift_angle"].iloc[taut] == pytest.approx(math.atan2(-V_A, H), rel=1e-9)
    assert lines["lower_angle"].iloc[taut] == pytest.approx(math.atan2(-V_A, H), rel=1e-9)
    assert lines["grounded_length"].iloc[taut] == 0.0


def test_segment_checks_against_the_mbl():
    chain, rope = mooring.component("studless chain R3"), mooring.component("polyester rope")
    segments = [chain.segment(300.0, 0.1), rope.segment(500.0, 0.16), chain.segment(100.0, 0.1)]
    system, eq = _spread(mooring.Line(segments, seabed=0.0), radius=820.0)
    table = eq.segment_checks(safety_factor=1.67)
    assert len(table) == 9
    mbl_chain = 0.0223 * 100.0**2 * (44 - 0.08 * 100.0) * 1e3  # DNV-OS-E302, R3, 100 mm
    assert table["mbl"].iloc[0] == pytest.approx(mbl_chain, rel=1e-14)
    for k, solved in enumerate(eq.lines):
        top = table[(table["line"] == k) & (table["segment"] == 2)].iloc[0]
        assert top["T_max"] == pytest.approx(solved.tension_b, rel=1e-12)  # a line's largest tension: at B
        assert top["utilisation"] == pytest.approx(1.67 * solved.tension_b / mbl_chain, rel=1e-12)
        assert bool(top["ok"]) == (1.67 * solved.tension_b <= mbl_chain)
    with pytest.raises(InputError) as err:
        eq.segment_checks(safety_factor=0.0)
    assert err.value.argument == "safety_factor"
    bare = _spread(mooring.Line([mooring.Segment(850.0, 2456.82, 1.2326e9)], seabed=0.0))[1]
    with pytest.raises(InputError) as err:
        bare.segment_checks(safety_factor=1.67)
    assert err.value.argument == "mbl"


@pytest.mark.parametrize(
    "grade, d_mm, kN",
    # a maker's proof and break test table of offshore chain (DNV-OS-E302): breaking load, kN
    [("R3", 34, 1065), ("R3", 70, 4196), ("R3S", 34, 1189), ("R4", 34, 1308), ("R4", 44, 2148)],
)
def test_chain_breaking_load_matches_the_tabulated(grade, d_mm, kN):
    for link in ("studless", "studlink"):
        mbl = mooring.component(f"{link} chain {grade}").properties(d_mm / 1000.0)["MBL"]
        assert mbl == pytest.approx(kN * 1e3, abs=1.0e3)  # the table gives whole kN


def test_component_formulas_and_weight_in_water():
    # Orcina's OrcaFlex documentation, "Chain": studless mass 19.9 d^2 te/m, EA 0.854e8 d^2 kN, OD 1.80 d
    p = mooring.component("studless chain R4").properties(0.12, rho=1025.0, g=9.81)
    assert p["mass"] == pytest.approx(19.9e3 * 0.12**2, rel=1e-14)
    assert p["EA"] == pytest.approx(0.854e11 * 0.12**2, rel=1e-14)
    assert p["w"] == pytest.approx(9.81 * (19.9e3 - 1025.0 * math.pi / 4 * 1.80**2) * 0.12**2, rel=1e-13)
    rope = mooring.component("polyester rope").properties(0.2)
    assert 0 < rope["w"] < 0.3 * 9.81 * rope["mass"]  # polyester barely sinks (density 1.38)
    assert mooring.component("nylon rope").properties(0.1)["MBL"] == pytest.approx(139357e3 * 0.01, rel=1e-14)
    assert set(mooring.components()) >= {"studlink chain R3", "six-strand wire rope, IWRC", "nylon rope"}


def test_users_add_their_own_components():
    mine = mooring.Component(
        "test fibre", 500.0, 2e9, lambda d: 3e8 * d * d, 0.9, source="A. Maker, Rope data sheet, 2024"
    )
    mooring.register_component(mine)
    assert mooring.component("test fibre") is mine
    seg = mine.segment(100.0, 0.1)
    assert seg.mbl == pytest.approx(3e6) and seg.EA == pytest.approx(2e7)
    with pytest.raises(InputError):
        mooring.register_component(mine)
    with pytest.raises(InputError) as err:
        mooring.component("no such rope")
    assert err.value.argument == "name"
    with pytest.raises(InputError) as err:
        mooring.component("studless chain R3").properties(0.6)
    assert err.value.argument == "diameter"


def test_a_line_between_two_points_refuses_a_sloped_plane_solution():
    """`LineBetween.block` moves an end along a seabed fixed in the line's plane; over a slope the
    seabed under a moving end would move too (the column ``-J_r - m (J_za + J_zb)``), so a sloped
    plane solution is refused rather than given a wrong stiffness."""
    from skcable.mooring.between_points import LineBetween

    line = mooring.Line([mooring.Segment(300.0, 1000.0, 1e9)])
    plane = mooring.line_in_plane(line, 250.0, 80.0, seabed=-5.0, seabed_slope=0.05)
    a, b = np.zeros(3), np.array([250.0, 0.0, 80.0])
    with pytest.raises(InputError, match="flat seabed") as err:
        LineBetween(line, a, b, plane, 250.0, (1.0, 0.0))
    assert err.value.argument == "plane"
