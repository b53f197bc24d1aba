"""Defects the fuzz finds that belong to other branches: how to recognise their outcomes, and a
probe each, rerun by every long run, that tells when the defect is fixed.

An outcome that matches an entry is still counted as a failure of its kind (the report lists
it under its defect); the CI test (`tests.test_fuzz`) accepts only failures that match an
entry, so that it stays green while their developers work, and fails on anything new.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from tests.fuzz import lines, moored, multi
from tests.fuzz.harness import Case, Outcome

__all__ = ["KNOWN", "Known", "match"]


@dataclass(frozen=True)
class Known:
    """A defect owned elsewhere: ``key`` (the issue's D-number, or F-number for a new one),
    ``issue``, ``branch``, ``summary``; the outcomes it explains (``regimes``: prefixes of the
    case's regime, ``kinds``, ``pattern``: a regular expression searched in the detail and the
    expression); ``probes``: builders of cases that fail while the defect lasts."""

    key: str
    issue: int
    branch: str
    summary: str
    regimes: tuple
    kinds: tuple
    pattern: str = ""
    probes: tuple = ()
    fixed: bool = False

    def explains(self, outcome: Outcome) -> bool:
        """Whether the defect explains ``outcome``; a fixed one explains nothing (its return is
        a new failure), its probes still rerun by the long run."""
        case = outcome.case
        return (
            not self.fixed
            and outcome.kind in self.kinds
            and any(case.regime.startswith(r) for r in self.regimes)
            and (not self.pattern or re.search(self.pattern, outcome.detail + " " + case.expr) is not None)
        )


def _edge(regime, expr, *names) -> Case:
    """An edge case whose refusal must name one of ``names``."""
    return Case(regime, expr, frozenset(names), None, None, must_name=names)


#: F3's example: a point body on six lines with clumps, slack in heaps at the start.
KNOWN_F3_SCENE = _MOORING_F3 = {
    "kind": "point",
    "fairleads": [(0.0, 0.0, -2.221810695577151)] * 6,
    "anchors": [
        (136.74149730579197, 21.24819491362879, -58.55003847276033),
        (89.19746485476111, 105.79950442228511, -58.55003847276033),
        (-71.8275837774875, 118.28153313685735, -58.55003847276033),
        (-138.26784656831626, -5.632537428018361, -58.55003847276033),
        (-66.86699269077785, -121.15497579963, -58.55003847276033),
        (94.01164071461393, -101.54572508315559, -58.55003847276033),
    ],
    "segments": [
        (76.79506627368482, 1072.4679662137207, 22042122508.80027),
        (85.5195703216612, 107.24679662137208, 11021061254.400135),
        (43.212457949198416, 1072.4679662137207, 22042122508.80027),
    ],
    "attachments": [("ClumpWeight", 1, 30953.8178852338)],
    "mass": 56264.80001532842,
    "volume": 81.6580246896911,
    "cog": (0.0, 0.0, -0.2457994440922225),
    "meta": (0.0, 0.0, 0.4127556377250041),
    "area": 2.005894635779188,
    "rho": 1025.0,
    "g": 9.81,
    "force": (-788.6121461981674, -1996.3757848378361, 0.0),
    "moment": (0.0, 0.0, 0.0),
    "depth": 58.55003847276033,
}

#: D4's last case (seed 26): 64 elements stopped with "no descent" at a merit of 1.8e-10
#: (tol 1e-10): a node at the touchdown with no push, the active set cycling.
KNOWN_D4_CYCLE = (
    [
        (144.1160206443183, 4.3671044446924245, 203962485.22061986),
        (55.34701010100797, 648.2549043307371, 813831488.8227067),
        (102.4253377866417, 13.51743236817562, 180843.2924765411),
        (30.244984952482323, 1194.7176670804631, 4983057203.274814),
    ],
    [("ClumpWeight", 1, 6495.485188278562)],
    0.0,
    0.0,
    201.14826261129866,
    132.8696946384012,
)


def _rigid(fairleads, anchors, segment, mass, volume, cog_z, meta_z, force, moment):
    """A rigid body's scene of `moored.random_scene`'s form, on one single-segment line per
    anchor, no waterplane, a flat seabed under the anchors."""
    return {
        "kind": "rigid",
        "fairleads": fairleads,
        "anchors": anchors,
        "segments": [segment],
        "attachments": [],
        "mass": mass,
        "volume": volume,
        "cog": (0.0, 0.0, cog_z),
        "meta": (0.0, 0.0, meta_z),
        "area": 0.0,
        "rho": 1025.0,
        "g": 9.81,
        "force": force,
        "moment": moment,
        "depth": -anchors[0][2],
    }


#: F3's last two cases (seed 26), bodies with no waterplane that heave 262 m (lines hanging
#: vertically at the start: x, y and yaw free, the roll and pitch moments unbalanced) and
#: 160 m (tensions falling a hundredfold, the residual scaled by them stood at 0.48).
KNOWN_F3_HEAVE_SCENES = (
    _rigid(
        [
            (6.17286138637317, -0.04931115455690552, -18.96490386095327),
            (-4.545968582061406, 4.176220652246626, -18.96490386095327),
            (-4.391866118194418, -4.337990466240852, -18.96490386095327),
        ],
        [
            (1481.6741587517458, -11.836174323705023, -391.419710336503),
            (-1091.1704885204285, 1002.4197587425163, -391.419710336503),
            (-1054.181218193423, -1041.249425903105, -391.419710336503),
        ],
        (1858.9610455318734, 171.28034734404466, 5806385399.563488),
        427991.158424685,
        459.22661263276007,
        -1.5060331695580718,
        1.2503244516536067,
        (0.0, -0.0, 0.0),
        (0.0, 0.0, 0.0),
    ),
    _rigid(
        [
            (8.252999323919887, 0.5753634608161066, -6.413382680059359),
            (1.929812156957603, 8.044803663951226, -6.413382680059359),
            (-7.702873121197526, -3.018076644387463, -6.413382680059359),
            (-2.78064238448509, -7.79173080145031, -6.413382680059359),
        ],
        [
            (1128.9812086999743, 78.70769279615584, -247.45988416070105),
            (263.9914988495458, 1100.5007764822883, -247.45988416070105),
            (-1053.7258838283342, -412.86224367595696, -247.45988416070105),
            (-380.3820740781668, -1065.8813011883365, -247.45988416070105),
        ],
        (1132.3110126115646, 406.020242977792, 321054820170.5122),
        89050.92105322532,
        167.06518684760385,
        0.5796011077285246,
        2.5394991717901636,
        (6643.010689451111, -116.1002421334383, 0.0),
        (0.0, 0.0, 4911.318082777067),
    ),
)

KNOWN = (
    Known(
        "D1",
        26,
        "closed",
        "a silent wrong H of the free elastic catenary (wL/H formed as a difference of rounded ratios)",
        ("elastic_catenary",),
        ("silent-wrong",),
        probes=(
            lambda: lines.free_case(
                [
                    0.2332264670872486,
                    -0.26928872264561327,
                    0.2670976622234697,
                    1037758168845.9086,
                    0.3288194802156623,
                ]
            ),
        ),
        fixed=True,
    ),
    Known(
        "D2",
        26,
        "closed",
        "a spurious 'Newton did not converge' of elastic_catenary, unit-dependent",
        ("elastic_catenary",),
        ("spurious-refusal",),
        probes=(
            lambda: lines.free_case(
                [
                    2.1958015558525883,
                    -0.8647353183964065,
                    8.075179402033653,
                    18565645.32965864,
                    2.344012229866921,
                ]
            ),
        ),
        fixed=True,
    ),
    Known(
        "D4",
        26,
        "linebvp",
        "solve_line_bvp fails on scenes Line.solve solves (taut lines, stagnating Newton; left: a line "
        "search with no descent just above the tolerance on a few meshes, about one scene in a thousand: "
        "the active set cycling at a touchdown node with no push, now held by the frozen steps)",
        ("solve_line_bvp", "edges/solve_line_bvp"),
        ("spurious-refusal",),
        probes=(
            lambda: multi.bvp_case(
                [(599.6939346579245, 56.07670748136184, 34001765662.077473)],
                [],
                0.0,
                0.0,
                603.4299455268164,
                106.88218088197465,
            ),
            lambda: multi.bvp_case(*KNOWN_D4_CYCLE),
        ),
        fixed=True,
    ),
    Known(
        "D5",
        26,
        "linebvp",
        "solve_line_bvp refuses a free line as a heap (judged by its uniform-weight start)",
        ("solve_line_bvp",),
        ("spurious-refusal",),
        r"heap",
        probes=(
            lambda: multi.bvp_case(
                [
                    (640.4312524203101, 14.848127473657213, 2536167.6286310744),
                    (849.2500712712057, 2703.66249904272, 6494901.897882393),
                ],
                [],
                -192.00556567930178,
                0.0,
                74.48396618457579,
                1334.9483700936419,
            ),
        ),
        fixed=True,
    ),
    Known(
        "F10",
        26,
        "linebvp",
        "solve_line_bvp refuses states it documents as outside its model (a slack stretch ending at a "
        "grounded point load; 'the discrete line is in compression ... give more elements') that Line.solve "
        "and the walk solve",
        ("solve_line_bvp",),
        ("spurious-refusal",),
        r"does not model that state|in compression",
        probes=(
            lambda: multi.bvp_case(
                [
                    (16.219963098358175, 0.8246341092730316, 41468.326653641845),
                    (57.236413980399746, 516.1222436728953, 9601662.282988938),
                    (13.541357352275917, 5.458639243704395, 28992.11862769992),
                ],
                [],
                0.0,
                0.0,
                32.95266515096135,
                64.42683566852091,
            ),
        ),
        fixed=True,
    ),
    Known(
        "F1",
        26,
        "moorings",
        "elastic_catenary(seabed=0) refuses taut lifted lines: 'SeabedCatenary: residual above 1e-09' "
        "(a check not sized to the round-off of a line with EA/(wL) ~ 1e11)",
        ("seabed",),
        ("spurious-refusal",),
        r"SeabedCatenary: residual",
        probes=(
            lambda: lines.seabed_case(
                [
                    1180.2124410413028,
                    1152.1040608081448,
                    3406.6014018524284,
                    1.2435462684617964e18,
                    1638.9125152052402,
                    0.0,
                    0.2325552160086822,
                ]
            ),
        ),
        fixed=True,
    ),
    Known(
        "F3",
        26,
        "moorings",
        "MooringSystem.equilibrium: 'the line search found no descent' from slack lines (heaps) where an "
        "independent solver finds the stable equilibrium (D3's class)",
        ("mooring",),
        ("spurious-refusal",),
        r"no descent|singular|stay slack|no convergence",
        probes=(
            lambda: moored.mooring_case(_MOORING_F3),
            *(lambda sc=sc: moored.mooring_case(sc) for sc in KNOWN_F3_HEAVE_SCENES),
        ),
        fixed=True,
    ),
    Known(
        "F6",
        26,
        "closed",
        "the closed forms name 'length' (or 'EA') where span = 1e308 or a subnormal EA is at fault "
        "(D8 in the closed forms: elastic_catenary, and through it the lines' solvers)",
        ("edges/elastic_catenary", "edges/sloped_seabed_catenary", "edges/Line.solve", "edges/line_3d"),
        ("untyped",),
        r"names '(length|EA|dh|w|span)' where '(span|EA|w|dh|length)'",
        probes=(
            lambda: _edge(
                "edges/elastic_catenary",
                "cable.elastic_catenary(span=1e308, dh=200.0, w=1000.0, EA=5e8, length=850.0)",
                "span",
            ),
            lambda: _edge(
                "edges/elastic_catenary",
                "cable.elastic_catenary(span=800.0, dh=200.0, w=1000.0, EA=2.5e-308, length=850.0)",
                "EA",
            ),
        ),
        fixed=True,
    ),
    Known(
        "F8",
        26,
        "moorings",
        "elastic_catenary(seabed=...) escapes as ZeroDivisionError or ValueError at extreme magnitudes "
        "(w = 1e-300 or 1e308, a subnormal length) (D7 in the seabed modules)",
        ("edges/elastic_catenary/seabed", "edges/Line.solve", "edges/line_3d", "edges/MooringSystem"),
        ("untyped",),
        r"ZeroDivisionError|ValueError|OverflowError",
        probes=(
            lambda: _edge(
                "edges/elastic_catenary/seabed",
                "cable.elastic_catenary(span=800.0, dh=200.0, "
                "w=1e-300, EA=5e8, length=850.0, seabed=0.0, friction=0.3)",
                "w",
            ),
            lambda: _edge(
                "edges/elastic_catenary/seabed",
                "cable.elastic_catenary(span=800.0, dh=200.0, "
                "w=1000.0, EA=5e8, length=5e-324, seabed=0.0, friction=0.3)",
                "length",
            ),
        ),
        fixed=True,
    ),
    Known(
        "F9",
        26,
        "moorings",
        "sloped_seabed_catenary names 'dh' where span or seabed_slope = 1e308 is at fault (D8 in the sloped "
        "seabed)",
        ("edges/sloped_seabed_catenary",),
        ("untyped",),
        r"names 'dh' where '(span|seabed_slope)'",
        probes=(
            lambda: _edge(
                "edges/sloped_seabed_catenary",
                "cable.sloped_seabed_catenary(span=1e308, dh=250.0, "
                "w=1000.0, EA=5e8, length=850.0, seabed_slope=0.05, friction=0.3)",
                "span",
            ),
        ),
        fixed=True,
    ),
    Known(
        "F7",
        26,
        "linebvp",
        "solve_line_bvp: a segment's EA given as a list escapes as ValueError; a subnormal EA names "
        "'length'; EA = inf is taken (the result holds EA = inf)",
        ("edges/solve_line_bvp",),
        ("untyped", "non-finite"),
        probes=(
            lambda: _edge(
                "edges/solve_line_bvp",
                "mooring.solve_line_bvp(800.0, 200.0, [(850.0, 1000.0, [1.0, 2.0])], seabed=0.0)",
                "EA",
                "segments",
            ),
        ),
        fixed=True,
    ),
)


def match(outcome: Outcome) -> Known | None:
    """The known defect that explains a failing ``outcome``, or None (a new defect)."""
    if not outcome.failed:
        return None
    for known in sorted(KNOWN, key=lambda k: not k.pattern):  # the specific ones first
        if known.explains(outcome):
            return known
    return None
