"""The plane line BVP and the line in space in its vertical plane: scenes of the differential survey
``benchmarks/line_bvp_planes.py`` (``--show SEED:SCENE`` prints each as Python).

`skcable.mooring.solve_line_bvp` and `skcable.mooring.line_bvp.space.solve_line_bvp_3d` share one
line law and their meshes' grading (on a seabed, graded by the closed-form start, then by the
line's turning) but not their drivers (the plane's first solve, friction and slack stretch; space's
starts, current and fitting): on a scene both solve, their end forces agree to the discretisation
errors of their meshes.
In space the anchor is at (0, 0, 0), the fairlead at (span, 0, dh), the seabed
``Plane(height, (slope, 0))``; the plane's ``(H_A, V_A, H_B, V_B)`` are space's
``force_on_anchor[[0, 2]] = (H_A, -V_A)`` and ``force_on_fairlead[[0, 2]] = (-H_B, -V_B)``.

`test_the_two_line_bvps_agree_on_the_surveys_scenes` holds twenty-two scenes both solve to 1e-6 of
the largest end force (the survey's threshold): seabeds sloping along the line (through the anchor
or below it), a flat seabed below the anchor, clump weights and buoys inside segments resting on
the seabed, weights varying along the line, friction; measured differences 2.3e-14 to 1.5e-7.
Each comment says what a driver failed before its fix: two (2:109, 2:216) the plane line failed
until its start on a straight slope through the anchor became the closed form on the slope
(`skcable.cable.sloped_seabed_catenary`, the line in space's), not the flat grounded line lifted
onto it; one (3:172) until its first solve tried the uniform mesh where the mesh graded by the
start fails; one (3:234) both failed until each tried the lifted line as well; one (5:126) the
line in space ended in compression until it graded its mesh by the line's turning; three (1:180,
2:217, 3:140) the line in space was 1.9e-3 to 1.4e-2 off on its uniform mesh until it graded its
meshes on a seabed as the plane line does (the survey's refinement of the uniform mesh moved it
to the plane line's answer: 6.0e-5 to 9.2e-7 off on four times the elements); three (1:162,
2:127, 2:177) with a buoy resting on the seabed were 1.6e-5 to 7.6e-3 apart until both
gradings took nodes at the ends of the arch it lifts (`skcable.mooring.line_bvp.mesh.arch_ends`);
one (1:79) the plane line failed until its first solves tried the line in space's first mesh;
one (2:243) the plane line's solution failed its equilibrium check until the polish held the
active set (`skcable.mooring.line_bvp.iterate.held_polish`); one (3:34) the line in space ended in
compression until, where its strategy fails, it solved the line in its vertical plane by the plane
line's strategy (`skcable.mooring.line_bvp.space.vertical_plane`): there the two agree to round-off,
one discrete line on one mesh.

Agreement is not correctness: on a coarse mesh both lines held one such buoy down alike
(`test_a_buoy_resting_on_the_seabed_lifts_its_arch_on_a_coarse_mesh`, against the same scene on
16 times the elements).
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pytest

from skcable import _plausible
from skcable.errors import ConvergenceError, InputError, ResolutionError, ResolutionWarning
from skcable.mooring import LineBVP, LineBVPSolution, solve_line_bvp
from skcable.mooring.bathymetry import Plane
from skcable.mooring.line_bvp.driver import LineBVPSolver
from skcable.mooring.line_bvp.inputs import scene
from skcable.mooring.line_bvp.resolution import solve_resolved
from skcable.mooring.line_bvp.space import LineBVP3D, LineBVP3DSolution, solve_line_bvp_3d

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
import line_bvp_planes as oracle_planes  # noqa: E402  (the survey's scenes, the oracle's input)
import line_energy_minimum as oracle  # noqa: E402

#: the survey's threshold of agreement, of the largest end force
TOLERANCE = 1e-6


class Scene(NamedTuple):
    """A survey scene: segments ``(length, w, EA)`` with ``w`` a number (N/m) or ``(w0, amplitude,
    wavelength, phase)`` (`varying`), point loads ``(s, P)``, seabed ``(height, slope)`` or None."""

    span: float
    dh: float
    segments: list
    point_loads: list
    seabed: tuple | None
    friction: float
    n_elements: int


def varying(w0, amplitude, wavelength, phase):
    """``w(s) = w0 (1 + amplitude sin(2π s/wavelength + phase))`` (N/m), the survey's weight
    varying along the line."""

    def w(s):
        return w0 * (1.0 + amplitude * np.sin(2.0 * np.pi * np.asarray(s) / wavelength + phase))

    return w


def solvers(sc: Scene, own_strategy=False):
    """``(plane, space)``: the scene's solves, callables of no argument (module docstring); with
    ``own_strategy``, the plane line's solver without its fallback on the line in space's strategy
    (`skcable.mooring.line_bvp.fallback`)."""
    segments = [(length, varying(*w) if isinstance(w, tuple) else w, EA) for length, w, EA in sc.segments]
    common = dict(point_loads=sc.point_loads, friction=sc.friction, n_elements=sc.n_elements)
    plane_bed: dict = {}
    space_bed = None
    if sc.seabed is not None:
        height, slope = sc.seabed
        space_bed = Plane(height, (slope, 0.0))
        plane_bed = dict(seabed=height)
        if slope != 0.0:
            plane_bed = dict(
                seabed=lambda x: height + slope * np.asarray(x),
                seabed_slope=lambda x: np.full(np.shape(x), slope),
            )
    ends = (0.0, 0.0, 0.0), (sc.span, 0.0, sc.dh)
    plane = lambda: solve_line_bvp(sc.span, sc.dh, segments, **plane_bed, **common)  # noqa: E731
    if own_strategy:
        bed = {"seabed": None, "seabed_slope": None, **plane_bed}
        plane = LineBVPSolver(scene(sc.span, sc.dh, segments, fit_touchdown=3, **bed, **common)).solve
    return (
        plane,
        lambda: solve_line_bvp_3d(*ends, segments, seabed=space_bed, **common),
    )


def plane_forces(plane):
    """The plane line's ``(H_A, V_A, H_B, V_B)`` as space's (module docstring)."""
    return np.array([plane.H_A, -plane.V_A, -plane.H_B, -plane.V_B])


def space_forces(space):
    """The line in space's end forces in its vertical plane (module docstring)."""
    assert abs(space.force_on_fairlead[1]) <= 1e-12 * space.T_B  # it stays in its plane
    return np.array([*space.force_on_anchor[[0, 2]], *space.force_on_fairlead[[0, 2]]])


def end_forces(sc: Scene):
    """The plane line's end forces and space's, mapped to the plane's (module docstring)."""
    plane, space = solvers(sc)
    return plane_forces(plane()), space_forces(space())


# fmt: off
AGREE = {
    # a rising slope (0.03), a clump inside the segment resting on it; measured 1.3e-13
    "2:128": Scene(72.59721747027211, 50.5784619660477, [(105.29816143781787, 1068.6278514431435, 654462810.1140933)], [(11.035329203892404, 9928.038693589726)], (0.0, 0.030253663857580076), 0.0, 256),  # noqa: E501
    # a falling slope (-0.057), a clump resting on it and a buoy, 64 elements; 3.1e-10
    "2:63": Scene(589.1404651714752, 546.2502548196321, [(953.4718246867014, 74.15656085281728, 11272132.040444456)], [(130.01707810210675, 1118.0107748284793), (744.5644532633052, -768.4963092669486)], (0.0, -0.056985246538177825), 0.0, 64),  # noqa: E501
    # a slope of 0.099, a weight varying ±47 %, a clump on the seabed; 2.2e-12
    "2:207": Scene(96.41321053763608, 21.863846549303744, [(102.51368143523452, (68.31511919867206, 0.469250907684044, 85.38142550222288, 5.577708152179122), 4230119257.886424)], [(47.612985926192636, 1186.8424966475543)], (0.0, 0.09926355205450985), 0.0, 256),  # noqa: E501
    # three segments, two of varying weight, a buoy on a falling slope; 2.0e-8
    "3:92": Scene(541.8900604057411, 203.01586229762708, [(488.6065071645146, (19.040531271364426, 0.16169330247597832, 162.88958283477365, 2.4714512923129623), 601068909.5394047), (63.63893053160398, 16.968390169812103, 1588694869.2270422), (149.8258526136109, (894.6630388749594, 0.14518629332418992, 435.41599508826147, 2.7072734353872265), 2476059333.843208)], [(237.37846428914378, -2318.2795697836386)], (0.0, -0.05398445517383972), 0.0, 256),  # noqa: E501
    # a buoy and a clump 15 m apart on a falling slope; 9.7e-11
    "3:204": Scene(1537.000878318417, 1535.143668758488, [(1197.482425905697, 21.608276841466697, 4710751377.936104), (1745.8361101748685, 18.66248226413691, 19057138.04349752)], [(1039.5844744951285, -1413.569165108074), (1054.998251542337, 3076.809852272384)], (0.0, -0.08750530433691511), 0.0, 256),  # noqa: E501
    # friction 0.6 on a rising slope (no slack stretch), weights varying, a clump; 2.5e-10
    "1:173": Scene(1008.1685821903866, 761.8148724506414, [(1049.4715426423293, (92.43379647759824, 0.381774725644153, 1630.0408698078859, 2.329458394757652), 3917482858.757249), (271.6406466758584, (78.32440876874492, 0.4883231028667477, 1671.0086028023663, 6.259947118760531), 42080938.8819897)], [(1086.8173840107809, 16861.94294127691)], (0.0, 0.07419324022883836), 0.6, 64),  # noqa: E501
    # a flat seabed 28 m below the anchor, a clump resting on it just past the landing; 2.7e-13
    "1:47": Scene(298.0386351917047, 288.48649557525715, [(541.3776759061628, 16.167325283734616, 7040252855.671788)], [(59.35096542404725, 1256.262885897471)], (-28.07717650637435, 0.0), 0.0, 256),  # noqa: E501
    # a slope below the anchor, a weight varying, a buoy on the seabed and a clump; 4.1e-9
    "2:103": Scene(1278.7414271866942, 624.599005694442, [(1470.8001118351485, (21.57973870412816, 0.17657192002522626, 1817.919687051525, 5.49121965766912), 533544516.8870285), (897.0941588985113, 73.20451173272482, 7092264773.924034)], [(1081.9631518605881, -984.430267591152), (1688.8897817880923, 21650.909029898463)], (-322.2909309685814, -0.07990214148456057), 0.0, 256),  # noqa: E501
    # a falling slope (-0.093) through the anchor, chain under a wire, 256 elements: the plane line
    # failed from its flat grounded start before the start on the slope; 8.6e-12
    "2:109": Scene(996.8666334542485, 181.12385918681088, [(872.807652892677, 924.2771221381778, 288692097.4389745), (309.223625149715, 22.461400595676867, 2745251350.2446804)], [], (0.0, -0.09326533352789533), 0.0, 256),  # noqa: E501
    # a clump inside a segment of varying weight on a falling slope, 256 elements: failed in the
    # plane before the start on the slope; 3.6e-13
    "2:216": Scene(957.8803706286196, 117.91940084553283, [(1105.5958054292175, (16.2524378320634, 0.13837515399400696, 1867.2228002823872, 5.37955773199594), 128055193.51766175)], [(895.782892664207, 300.1613144017629)], (0.0, -0.07971569413192899), 0.0, 256),  # noqa: E501
    # a slope (-0.088) below both ends, a weight varying ±10 % under a chain, a buoy: both lines
    # failed before they started from the uniform line touching down on the slope; 4.9e-13
    "2:56": Scene(1409.4172097836154, -53.215847802609275, [(1088.927512820654, (23.02003106203555, 0.09779856593718556, 1031.4084661703894, 3.0042985063325363), 44552580.22277516), (390.68089401193913, 1134.8798251894034, 205999945.14190117)], [(157.98340988301157, -47902.831063199665)], (-9.014801017963984, -0.08808902349809558), 0.0, 256),  # noqa: E501
    # a slope (-0.065) below both ends, three segments and a clump, 64 elements: as 2:56; 2.9e-10
    "1:103": Scene(1046.576713841768, -27.129755156540995, [(175.78338878754184, 20.955687263782682, 80642675.47835484), (242.30409911913938, 20.97268793613526, 220527620.14922205), (703.8830474254495, 66.16233702633271, 6132203355.937648)], [(98.45055019846845, 11585.19877156022)], (-33.177530335645606, -0.06513869917863027), 0.0, 64),  # noqa: E501
    # a slope below the anchor (-0.066), chain under a wire, 256 elements: the plane line failed on
    # the mesh graded by its start until its first solve tried the uniform mesh too; 3.3e-13
    "3:172": Scene(82.10856427503789, -2.8448158683969957, [(60.020823250453645, 983.8269844162455, 11349329.112749042), (25.048564461609107, 81.90826461628382, 166365802.86941996)], [], (-2.9490473395742454, -0.06564492858565593), 0.0, 256),  # noqa: E501
    # an anchor above a flat seabed, a rope landing on it, a buoy and a clump, 64 elements: the line
    # in space ended in compression on its uniform mesh (the landing's bend in one element) until
    # it graded its mesh by the line's turning as the plane line does; 4.6e-9
    "5:126": Scene(1922.2092475036493, 294.044509228659, [(494.89192333352344, 68.20312556629979, 66833930.27339349), (1775.8071179684848, 95.12563810673794, 912014998.0684423)], [(179.4679801391432, -28960.905299920803), (2103.0070315166067, 4535.555820946291)], (-55.54105296310373, 0.0), 0.0, 64),  # noqa: E501
    # a slope through the anchor, a weight varying +-47 %, a clump and a buoy of 73 and 92 kN: the
    # plane line failed from its start on the slope until it tried the uniform line lifted onto
    # the slope (switching by the tension); the line in space as well, on a mesh graded by that
    # start; 3.9e-12
    "3:234": Scene(720.8246891133476, 8.720188995417637, [(439.0475516232507, 875.5899328081308, 4594667007.771147), (103.57758309135652, (18.114687470739305, 0.47041778674158746, 1025.8479702200998, 1.4959240795939381), 1773500123.6117845), (234.86477799393015, 17.556572754682215, 836344294.352262)], [(171.49602873003803, 73063.35138591191), (516.707081104585, -92301.2053935098)], (0.0, -0.06787518350727702), 0.0, 64),  # noqa: E501
    # a flat seabed 27 m below the anchor, a weight varying +-16 %, 64 elements: the line in space
    # was 1.4e-2 of the largest force off on its uniform mesh (the landing's bend in one element;
    # on 4 times the elements 6.0e-5) until it graded its mesh from the start as the plane line
    # does; 4.8e-8
    "1:180": Scene(1673.3775969545588, 68.78822221302812, [(1770.4204098171263, (16.355186173293895, 0.15633141545904777, 625.231210775148, 1.828396669699145), 84360307.05301091)], [], (-26.786311588569824, 0.0), 0.0, 64),  # noqa: E501
    # chain, wire and rope on a flat seabed 1.4 m below the anchor, a clump on the chain, 256
    # elements: 4.8e-3 apart on space's uniform mesh (1.9e-4 on 4 times the elements); 3.4e-12
    "2:217": Scene(68.96862436925545, 2.822418904908874, [(17.667384016282316, 1180.8983179455745, 751321758.3370379), (42.740976814273395, 17.463870785674974, 754941478.673899), (12.561449108879362, 75.93188160646692, 8095573296.873058)], [(14.709064337621031, 1040.3926644059325)], (-1.370537941300455, 0.0), 0.0, 256),  # noqa: E501
    # a falling slope (-0.032) through the anchor, a clump on the second segment, 64 elements:
    # 1.9e-3 apart on space's uniform mesh (9.2e-7 on 4 times the elements); 4.9e-10
    "3:140": Scene(1175.4443507194756, 818.6305574786969, [(1548.0073463380697, 80.6837038178888, 6026221207.206553), (450.94426865580664, 68.63531752172263, 164908758.06173596)], [(1113.9380968528765, 2128.104285596925)], (0.0, -0.031951459312359695), 0.0, 64),  # noqa: E501
    # buoys resting on the seabed: the plane line's grading by the line's turning left the arch a
    # buoy lifts off the grounded line in one or two elements, or held the buoy down, until both
    # gradings took nodes at the arch's ends (`skcable.mooring.line_bvp.mesh.arch_ends`):
    # a low arch (0.14 m over 40 m) of a buoy near a clump, 1.6e-5 apart before; 9.5e-13
    "1:162": Scene(223.77074608392488, 62.89939084796257, [(32.886601379985, 20.61441103459703, 101380166.73397306), (137.12177586509273, 70.56314386521404, 106087226.46505192), (115.33259716669528, 72.59828653715647, 656273823.9351658)], [(68.91374051347343, -257.34741739282975), (126.65004318711226, 644.0422954003168)], (-15.257891045677004, 0.0), 0.0, 256),  # noqa: E501
    # a small buoy on a light rope on a flat seabed 8.9 m below the anchor, 64 elements: the plane
    # line held the buoy down (H 8 % low), 7.6e-3 apart before; 1.5e-7
    "2:127": Scene(252.63763042195094, 11.856537312336346, [(275.86486411754754, 20.497293534652815, 309459634.4891329)], [(115.84365879435217, -63.202928424368885), (147.83506783615294, 419.8540318084821)], (-8.876327226105044, 0.0), 0.0, 64),  # noqa: E501
    # a buoy on chain on a flat seabed 19 m below the anchor, 256 elements: 1.6e-3 apart before;
    # 2.1e-11
    "2:177": Scene(72.23392042200197, 8.160796484609474, [(56.27198648439684, 1077.815792681307, 822294507.4493213), (7.955996469465054, 1143.3844455906988, 197234758.63846344), (51.84086999824948, 918.4926731101724, 1311112298.8700743)], [(61.89245922702237, -1324.0930592580082)], (-19.452104843881312, 0.0), 0.0, 256),  # noqa: E501
    # a wire landing 2.5 m from an anchor 2.1 m above a flat seabed, a chain rising to the
    # fairlead, 64 elements: the plane line failed until its first solves tried the line in space's
    # first mesh (graded by the discrete start's turning); 4.1e-12
    "1:79": Scene(128.32334533690485, 2.7290709384430376, [(107.67220642256117, 92.55191212362412, 7234415615.430099), (26.64878423631918, 1019.4805269252205, 26021749.782621723)], [], (-2.091886822137727, 0.0), 0.0, 64),  # noqa: E501
    # chain, wire and rope on a falling slope (-0.097) through the anchor, 128 elements: the plane
    # line's solution failed its own equilibrium check (0.036 N/m against 1.2e-4 N/m: its polish
    # stopped at Newton's tolerance, full steps cycling between two active sets, a residual force
    # over an element of 0.36 mm) until the polish went on with the active set held; 3.0e-14
    "2:243": Scene(358.18673191695467, -5.830543329074647, [(236.6745059255771, 957.4474501241665, 18081727.20987222), (45.081749663018606, 889.5117815204349, 1322221115.355449), (106.87582599890182, 94.48276780275249, 53128222.37259287)], [], (0.0, -0.09723045454922863), 0.0, 128),  # noqa: E501
    # a chain, a rope and a wire of varying weights, a clump resting on a falling slope (-0.076):
    # the line in space ended in compression on every mesh until, where its strategy fails, it
    # took the plane line's solve in the vertical plane of its ends (Newton in space from it, on
    # its mesh: one discrete line, `skcable.mooring.line_bvp.space.vertical_plane`); 2.3e-14
    "3:34": Scene(1877.7795139969624, -84.61294874641233, [(520.0167112478808, 16.166116867964334, 4421865115.867061), (836.3738428092635, (17.200888381359942, 0.44334913330059644, 3539.867878397045, 3.5343588328418454), 264487313.8282214), (585.1610455735785, (19.79383818376042, 0.4589848800843584, 575.5423282269782, 2.39758898623215), 55040395.60102722)], [(1082.7444877803132, 1115.5051458202772)], (0.0, -0.07626227801550656), 0.0, 64)  # noqa: E501
}

#: scene 2:117: a heavy chain on a flat seabed, a clump and a 12.2 kN buoy resting on it, 64 elements
BUOY_ON_CHAIN = Scene(1422.863283919122, 35.392739838920384, [(935.5786615511254, 1175.149026436685, 170801084.4541431), (249.9588273225088, 17.074050209984847, 25027619.70865195), (339.37121662522213, 23.528349807072747, 15124508.934572434)], [(556.3000780546796, 23934.921645606984), (744.1155880173021, -12175.358440688813)], (-51.6886584842559, 0.0), 0.0, 64)  # noqa: E501

#: scene 3:19: a chain of weight varying ±35 % with a 439 N buoy resting on a nearly flat seabed, a
#: wire and a rope with a 4.3 kN clump at the fairlead, 64 elements
VARYING_BUOY = Scene(547.0656209506323, 40.79135265141903, [(119.09616191337666, (88.37852822079617, 0.3510624456859901, 558.7229516293593, 5.911863886973994), 128329797.95727485), (391.7939124775052, 19.004500942507942, 376344105.7181316), (73.80532552729484, 23.838925265329472, 30712212.744109597)], [(11.875576314419769, -438.653434422412), (561.4635931335204, 4299.899853231353)], (0.0, -0.00022106444514528867), 0.0, 64)  # noqa: E501
#: scene 3:160: a chain hanging almost vertically from a 10.3 kN clump, then a light rope, over a flat
#: seabed 7.1 m below the anchor, 64 elements
HANGING_TO_CLUMP = Scene(399.88638259698047, 2.3202982852674046, [(73.23715508631014, 1151.2050522936047, 342377713.3053049), (341.53988038717597, 19.835188621190447, 10534704.169814138)], [(24.145342086592702, 10272.346177262758)], (-7.0821617336914935, 0.0), 0.0, 64)  # noqa: E501
#: scene 3:53: a rope of weight varying ±40 % over 8.5 m lying on a slope of -0.089 from the anchor,
#: a wire and a rope of varying weights, 64 elements
SHORT_WAVES = Scene(67.18533890365998, 13.756802484604162, [(17.557197803261285, (77.74497416503118, 0.3953096037524316, 8.522705754265901, 2.6884084518422235), 33949710.67650141), (45.13058389690186, (66.65423243670861, 0.2894648595381882, 27.140585379945783, 0.5825843494581896), 333361802.1941017), (20.609741874591077, (17.85947802478008, 0.4829813687801935, 45.06744285993954, 5.780066458247716), 2352038966.858905)], [], (0.0, -0.08891523544311544), 0.0, 64)  # noqa: E501
#: scene 2:136: chain, wire and rope on a flat seabed, a 549 N buoy and a 688 N clump 0.55 m apart on
#: the chain, 64 elements
CLUMP_PAST_ARCH = Scene(125.81753795867601, 2.8498245385887344, [(19.448596158559198, 1055.4548292387067, 231228562.49157917), (44.252384437742585, 16.948186939103618, 19227949.56835867), (65.38018979633495, 89.2398842920646, 10183143.715478364)], [(4.217218385186116, -549.0474605264737), (4.765073772586564, 687.8583198756432)], (-0.42775369174513617, 0.0), 0.0, 64)  # noqa: E501
#: scene 1:121: a chain lying down a slope of -0.039 from its anchor and rising 58 m almost
#: vertically to its fairlead, its weight varying ±6 %, H = 54 N (``H/w`` = 4.7 cm), 256 elements
STANDING = Scene(716.4516934026433, 30.28559916504399, [(774.9085126795632, (1146.6478036881588, 0.05865373120637953, 426.2507574631828, 3.1430826863416947), 58046976.96603248)], [], (0.0, -0.0393226704244585), 0.0, 256)  # noqa: E501
#: scene 3:34: three segments, two of varying weight, a clump, on a slope of -0.076 through the
#: anchor, 64 elements: the line in space ends in compression (the plane line solves it)
SLOW_TOUCHDOWN = Scene(1791.7864374366995, -109.29601490166132, [(494.5395701885832, 1022.2352717783856, 97084181.99637), (687.6179975215059, 83.60271209047177, 19300672.331536077), (866.187803240909, 994.5795030119391, 70620732.4162754)], [], (-155.17755367866738, -0.08699683261135492), 0.0, 64)  # noqa: E501
SPACE_IN_COMPRESSION = Scene(578.5712723821961, -6.116117594660466, [(518.4002602327564, 17.52544424787615, 614519823.5361811), (88.60816212817235, (16.20649628512033, 0.4248794864216203, 223.52855790472205, 3.7940891473777625), 5061375889.040814)], [], (-13.022737878840323, -0.016921589467683656), 0.0, 64)  # noqa: E501
# fmt: on


@pytest.mark.parametrize("key", list(AGREE))
def test_the_two_line_bvps_agree_on_the_surveys_scenes(key):
    """Both solve; end forces within `TOLERANCE` of the largest (measured: module docstring)."""
    want, got = end_forces(AGREE[key])
    np.testing.assert_allclose(got, want, rtol=0, atol=TOLERANCE * np.abs(want).max())


def test_the_uniform_mesh_converges_to_the_graded_meshes_answer():
    """Scene 1:180 on the line in space's uniform mesh (``mesh="uniform"``, a line landing on a
    flat seabed 27 m below its anchor): off the plane line's answer on its graded mesh by 1.4e-2
    of the largest end force at 64 elements, 6.0e-5 at 256 and 9.8e-7 at 1024, converging to it,
    while the line in space on its graded 64 elements is within 4.8e-8
    (`test_the_two_line_bvps_agree_on_the_surveys_scenes`). The uniform meshes of 64 and 256
    elements warn that they do not resolve the bend where the line lands
    (`skcable.errors.ResolutionWarning`); 1024 does not."""
    sc = AGREE["1:180"]
    want, _ = end_forces(sc)
    segments = [(length, varying(*w), EA) for length, w, EA in sc.segments]
    off, warned = [], []
    for n in (64, 256, 1024):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ResolutionWarning)
            line = solve_line_bvp_3d(
                (0.0, 0.0, 0.0),
                (sc.span, 0.0, sc.dh),
                segments,
                seabed=sc.seabed[0],
                n_elements=n,
                mesh="uniform",
            )
        warned.append(bool(caught))
        assert line.problem.nodes_at is None  # uniform (but for the fitted nodes)
        got = np.array([*line.force_on_anchor[[0, 2]], *line.force_on_fairlead[[0, 2]]])
        off.append(np.abs(got - want).max() / np.abs(want).max())
    # converging to it (by 225 and 62 times at each fourfold refinement, measured)
    assert off[0] > 1e-3 and off[0] > 16 * off[1] > 256 * off[2] and off[2] < 1e-5
    # the resolution check: an element at the landing turns 1.1 rad (64), 0.67 rad (256), resolved
    assert warned == [True, True, False]


def test_a_buoy_resting_on_the_seabed_lifts_its_arch_on_a_coarse_mesh():
    """Scene 2:117: a heavy chain (w = 1175 N/m) on a flat seabed with a 12.2 kN buoy 744 m along
    it, which lifts an arch ``|P|/w`` = 10.4 m long off the seabed
    (`skcable.mooring.line_bvp.mesh.arch_ends`). On 64 elements both lines held the buoy down on
    the seabed, and agreed with each other: H = 670.3 N against 960.94 N on 1024 elements, 4.7e-3
    of the largest end force. With nodes at the arch's ends, both are within 1e-5 of the plane
    line on 1024 elements (measured 3.4e-6 plane, 4.9e-7 space; the two 1024-element lines agree
    within 3.1e-14). The resolution check flags the 64 elements (an element of 21 m at the arch
    turns 0.48 rad: `skcable.errors.ResolutionWarning`), on an answer that is close: its measure
    is empirical, and the table of docs/bvp.md counts such warnings."""
    sc = BUOY_ON_CHAIN
    reference, _ = end_forces(sc._replace(n_elements=1024))
    with pytest.warns(ResolutionWarning, match="turns 0.48 rad"):  # a bend 0.17, past the check's 0.14
        plane, space = end_forces(sc)
    for got in (plane, space):
        np.testing.assert_allclose(got, reference, rtol=0, atol=1e-5 * np.abs(reference).max())


def test_a_buoy_resting_on_a_line_of_varying_weight_lifts_its_arch():
    """Scene 3:19 (`VARYING_BUOY`): a 439 N buoy 11.9 m along a chain whose weight varies ±35 %
    along it, resting on a nearly flat seabed; its arch weighs the lift, about 5 m of chain. The
    arch's ends were taken under a uniform weight only: on 64 elements the plane line held the
    buoy down on the seabed (an element 11.9 m long, heavier than the lift), H = 35.3 N against
    the energy minimum's 75.04 N (7.5e-3 of the largest end force, silently; the line in space's
    first mesh, graded by its start, found the arch). With the arch's sides of equal moments about
    the buoy (`skcable.mooring.line_bvp.mesh.arch_ends`), both lines are within 1e-6 of the plane
    line on 1024 elements (measured 2.9e-8 each), and that one's
    H within 1e-3 of the energy minimum on 2000 nodes (`benchmarks/line_energy_minimum.py`, an
    oracle independent of both BVPs; measured 2.6e-4, the oracle's own discretisation: 75.69,
    74.95, 75.04 N on 500, 1000, 2000 nodes)."""
    reference, _ = end_forces(VARYING_BUOY._replace(n_elements=1024))
    plane, space = end_forces(VARYING_BUOY)
    for got in (plane, space):
        np.testing.assert_allclose(got, reference, rtol=0, atol=1e-6 * np.abs(reference).max())
    segments = tuple((length, oracle_planes.Varying(*w) if isinstance(w, tuple) else w, EA)
                     for length, w, EA in VARYING_BUOY.segments)  # fmt: skip
    sc = VARYING_BUOY
    minimum = oracle.energy_minimum(
        oracle_planes.Scene(sc.span, sc.dh, segments, tuple(sc.point_loads), sc.seabed), 2000
    )
    assert minimum.taut and abs(minimum.H_A - reference[0]) < 1e-3 * reference[0]


def test_a_mesh_that_does_not_resolve_a_bend_warns():
    """Scene 3:160 (`HANGING_TO_CLUMP`): a chain hanging almost vertically from a clump of 10.3 kN
    to a light rope, H = 12 N, its bend at the bottom a few centimetres in radius. On 64 elements
    both lines pass every check, and their V_A is 2.1e-2 off the line in space's on 1024 elements
    (the energy minimum on 1000, 2000, 4000 nodes: 8387, 8267, 8176 N, falling to the BVP's 8164.9
    N; the 64-element lines give 8333.6 N): an element of 1.4 m at the bend turns 0.89 rad within
    itself, and both warn (`skcable.errors.ResolutionWarning`, naming ``n_elements``). On 256
    elements both are within 1e-5 of the reference (measured 1.9e-6) and quiet (this project's
    pytest turns the warning into an error); ``n_elements="auto"`` takes those 256
    (`skcable.mooring.line_bvp.resolution`). A trial solve (inside a mooring system's equilibrium,
    `skcable._plausible.quiet`) does not warn."""
    reference = space_forces(solvers(HANGING_TO_CLUMP._replace(n_elements=1024))[1]())
    scale = np.abs(reference).max()
    mapped = (plane_forces, space_forces)
    for solve, forces in zip(solvers(HANGING_TO_CLUMP), mapped, strict=True):
        with pytest.warns(ResolutionWarning, match=r"the mesh's 64 elements .* do not resolve a bend"):
            coarse = forces(solve())
        assert np.abs(coarse - reference).max() > 1e-2 * scale
    for solve, forces in zip(
        solvers(HANGING_TO_CLUMP._replace(n_elements=256)), (plane_forces, space_forces), strict=True
    ):
        np.testing.assert_allclose(forces(solve()), reference, rtol=0, atol=1e-5 * scale)
    for solve, forces in zip(solvers(HANGING_TO_CLUMP._replace(n_elements="auto")), mapped, strict=True):
        auto = solve()  # quiet: 64 do not resolve the line, 256 do
        assert auto.n_elements == 256
        np.testing.assert_allclose(forces(auto), reference, rtol=0, atol=1e-5 * scale)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with _plausible.quiet():
            solvers(HANGING_TO_CLUMP)[1]()


def test_auto_elements_keep_the_coarser_line_where_a_refined_solve_fails():
    """``n_elements="auto"`` (`solve_resolved`) on scene 3:160 (`HANGING_TO_CLUMP`), whose 64
    elements do not resolve its bend: where the solve on 256 fails, or no time is left for it, the
    `ConvergenceError` keeps the line on 64 elements (``last``: converged and checked, the end
    forces of a solve asked for 64, flagged by the resolution check) and says so. Anything but a
    whole number or ``"auto"`` is refused, naming ``n_elements``."""
    sc = HANGING_TO_CLUMP
    segments, bed = list(sc.segments), dict(seabed=sc.seabed[0], point_loads=sc.point_loads)

    def on_64_only(n, seconds):
        if n > 64:
            raise ConvergenceError(f"no line on {n} elements", [1.0])
        with _plausible.quiet():
            return solve_line_bvp(sc.span, sc.dh, segments, n_elements=n, time_limit=seconds, **bed)

    with pytest.warns(ResolutionWarning):
        coarse = plane_forces(solve_line_bvp(sc.span, sc.dh, segments, n_elements=64, **bed))
    kept = r"\(n_elements='auto': on 256 elements; on 64 it converged, not resolved: error.last, checked\)"
    with pytest.raises(ConvergenceError, match=kept) as failed:
        solve_resolved(on_64_only, "auto", 60.0)
    kept = failed.value.last
    assert kept.n_elements == 64 and kept.unresolved()
    np.testing.assert_array_equal(plane_forces(kept), coarse)
    with pytest.raises(ConvergenceError, match="no time left of time_limit = 1e-09 s for 256") as failed:
        solve_resolved(lambda n, seconds: on_64_only(n, 60.0 if n == 64 else seconds), "auto", 1e-9)
    assert failed.value.history == failed.value.last.history  # the coarser line's
    np.testing.assert_array_equal(plane_forces(failed.value.last), coarse)
    for bad in ("fine", "AUTO", 0, 2.5):
        with pytest.raises(InputError, match="n_elements"):
            LineBVP(segments, n_elements=bad)


def test_auto_elements_say_what_the_coarser_solves_did():
    """What ``n_elements="auto"`` (`solve_resolved`) raises, with solves that fail by design: the
    first solve's failure unchanged; a solve in compression (`ResolutionError`) followed by one on
    four times the elements, up to 1024, then raised saying that the coarser one ended in
    compression too; another failure after a compressed solve saying so."""
    tried = []

    def fails(n, seconds, error=ConvergenceError, from_n=64):
        tried.append(n)
        raise (ResolutionError if n < from_n else error)(f"failed on {n}; error.last: kept", [float(n)])

    with pytest.raises(ConvergenceError) as first:
        solve_resolved(lambda n, seconds: fails(n, seconds), "auto", 60.0)
    assert str(first.value) == "failed on 64; error.last: kept (last 1 of 1: 6.400e+01)" and tried == [64]
    tried.clear()
    with pytest.raises(ResolutionError, match="on 256 the discrete line ended in compression") as last:
        solve_resolved(lambda n, seconds: fails(n, seconds, ResolutionError), "auto", 60.0)
    assert tried == [64, 256, 1024] and "n_elements='auto': on 1024 elements" in str(last.value)
    tried.clear()
    with pytest.raises(ConvergenceError, match="on 64 the discrete line ended in compression") as other:
        solve_resolved(lambda n, seconds: fails(n, seconds, from_n=256), "auto", 60.0)
    assert tried == [64, 256] and not isinstance(other.value, ResolutionError)


def test_auto_elements_go_on_where_a_mesh_ends_in_compression():
    """The fuzz's case ``solve_line_bvp:61:52`` (`tests.fuzz.multi`): three light segments rising
    almost vertically from the seabed, a buoy at the upper joint, H = 5.5e-4 N. On its default 64
    elements the discrete line ends in compression (a `skcable.errors.ResolutionError`: the
    elements do not resolve its bends); ``n_elements="auto"`` goes on to 256, and its H, V_B and
    H_A agree with the fuzz's oracle, an independent walk along the segments, to 1e-6 of the force
    scale."""
    from tests.fuzz.regimes import case

    args = (
        15.693738724184808,
        7.4056324685310875,
        [
            (1.698036108831134, 0.1003170124182903, 21157396.93831615),
            (16.089492906938233, 0.01999044146132842, 15312.883684955064),
            (5.307158181122778, 8.925886579466441, 2989071.26943129),
        ],
    )
    options = dict(
        seabed=0.0,
        friction=0.020744307061020477,
        point_loads=[(17.787529015769366, -0.531205939294393), (1.698036108831134, 0.06080096682661319)],
    )
    with pytest.raises(ResolutionError, match="elements do not resolve its bends"):
        solve_line_bvp(*args, **options)
    auto = solve_line_bvp(*args, **options, n_elements="auto")
    assert auto.n_elements == 256
    assert case("solve_line_bvp", 61, 52).check(auto, []) == []


def test_auto_elements_of_a_warm_start_are_those_from_scratch():
    """A warm start of ``n_elements="auto"`` chooses its elements afresh, from 64, as a solve from
    scratch does: the line in space of scene 3:160 (`HANGING_TO_CLUMP`) takes 256 at its ends; 1 m
    farther out, from scratch and from that line, it takes 64, and the two give the same end forces
    to round-off (the meshes are the ends', `skcable.mooring.line_bvp.space.driver`; measured
    equal)."""
    sc = HANGING_TO_CLUMP
    seabed = Plane(sc.seabed[0], (sc.seabed[1], 0.0))
    model = LineBVP3D(list(sc.segments), point_loads=sc.point_loads, seabed=seabed, n_elements="auto")
    anchor, fairlead = np.zeros(3), np.array([sc.span, 0.0, sc.dh])
    first = model.solve(anchor, fairlead)
    farther = fairlead + (1.0, 0.0, 0.0)
    warm, cold = model.solve(anchor, farther, start=first), model.solve(anchor, farther)
    assert (first.n_elements, warm.n_elements, cold.n_elements) == (256, 64, 64)
    scale = np.abs(space_forces(cold)).max()
    np.testing.assert_allclose(space_forces(warm), space_forces(cold), rtol=0, atol=1e-12 * scale)


def test_a_mesh_that_does_not_resolve_a_varying_weight_warns():
    """Scene 3:53 (`SHORT_WAVES`): a rope whose weight varies ±40 % over a wavelength of 8.5 m,
    lying on a slope from the anchor, then a wire and a rope. On 32 elements the mesh has two
    elements in that rope, and the solve's quadrature misplaces 4.4e-3 of the line's weight
    (against 16-point Gauss–Legendre per element, `skcable.mooring.line_bvp.check`): the end forces
    are 4.4e-3 off the line in space on 1024 elements, with no bend to see. Both lines warn
    (`skcable.errors.ResolutionWarning`); on 64 elements both are within 1e-5 of the reference
    (measured 1.3e-7) and quiet."""
    reference = space_forces(solvers(SHORT_WAVES._replace(n_elements=1024))[1]())
    scale = np.abs(reference).max()
    mapped = (plane_forces, space_forces)
    for solve, forces in zip(solvers(SHORT_WAVES._replace(n_elements=32)), mapped, strict=True):
        with pytest.warns(ResolutionWarning, match="do not resolve the weight varying along the line"):
            coarse = forces(solve())
        assert np.abs(coarse - reference).max() > 1e-3 * scale
    for solve, forces in zip(solvers(SHORT_WAVES), mapped, strict=True):
        np.testing.assert_allclose(forces(solve()), reference, rtol=0, atol=1e-5 * scale)


def test_a_clump_just_past_a_buoys_arch_is_graded_without_the_arch():
    """Scene 2:136: the buoy's arch on the chain (``|P|/w`` = 0.52 m) ends 0.29 m before a clump,
    and the line bends there to a radius ``H/w`` of 3 cm. On the meshes with nodes at the arch's
    ends the line in space ended in compression (the plane line solves them); it grades without
    them too, and agrees with its 1024-element solution within 1e-5 of the largest end force
    (measured 3.2e-6)."""

    def on(n):
        return space_forces(solvers(CLUMP_PAST_ARCH._replace(n_elements=n))[1]())

    reference = on(1024)
    np.testing.assert_allclose(on(64), reference, rtol=0, atol=1e-5 * np.abs(reference).max())


def test_a_failed_solve_keeps_the_line_on_its_finest_mesh():
    """Scene 1:121 on 256 elements (`STANDING`): the bend where the chain leaves the seabed has a
    radius of 4.7 cm, and the plane line's grading pass to elements of 4 mm there stagnates, so
    its solve fails. The failure keeps what converged (``error.last``): the line on the finest
    mesh reached, free of compression, whose end forces agree with the line in space's on 256
    elements (which keeps its last converged graded mesh) within 1e-6 of the largest (measured
    7e-10). Before, ``last`` was the failed Newton's iterate, without its mesh (the line in
    space's failures: the same, or its driver's private record of a solve). `solve_line_bvp` solves
    it by its fallback on the line in space's strategy (`skcable.mooring.line_bvp.fallback`): the
    line in space's to round-off, on its mesh."""
    plane, space = solvers(STANDING, own_strategy=True)
    with pytest.raises(ConvergenceError) as failed:
        plane()
    kept = failed.value.last
    elements = kept.problem.mesh.t.shape[1]
    assert isinstance(kept, LineBVPSolution) and elements >= STANDING.n_elements
    assert f"error.last: the line that converged on {elements} elements" in str(failed.value)
    assert not kept.problem.compressed(kept.dofs, 1e-10)
    want = space_forces(space())
    np.testing.assert_allclose(plane_forces(kept), want, rtol=0, atol=1e-6 * np.abs(want).max())
    by_fallback = plane_forces(solvers(STANDING)[0]())
    np.testing.assert_allclose(by_fallback, want, rtol=0, atol=1e-9 * np.abs(want).max())
    # the line in space keeps its solution too: scene 3:223 converged in compression only, and
    # the plane line fails it as well (the line in space's last resort, in its vertical plane)
    with pytest.raises(ConvergenceError) as failed:
        solvers(SPACE_IN_COMPRESSION)[1]()
    assert "the plane line's strategy failed too" in str(failed.value)
    kept = failed.value.last
    assert isinstance(kept, LineBVP3DSolution) and kept.problem.compressed(kept.dofs, 1e-10)


def test_the_plane_lines_default_fitting_passes_are_the_line_in_spaces():
    """Scene 1:223 (`SLOW_TOUCHDOWN`: a chain, a rope and a chain landing on a slope of -0.087
    below the anchor): from the flat line lifted onto the slope, each pass of fitting moved the
    touchdown node a tenth of the way it had left (0.30 m, 35 mm, 3.4 mm at 788e226), so two passes left it
    35 mm from where the line's balance puts it and H 2.4e-6 off the settled line's (eight
    passes): hence three passes by default, as the line in space. From the line touching down on
    the slope (`skcable.cable.seabed.slope_touchdown`, the start on a straight slope below both
    ends since), the first mesh lands the touchdown nearly where it is: two passes leave the node
    within 0.1 mm (measured 2.6e-6 m), and the defaults H within 1e-6 of the settled line's."""
    plane, _ = solvers(SLOW_TOUCHDOWN)
    segments = [(length, w, EA) for length, w, EA in SLOW_TOUCHDOWN.segments]
    height, slope = SLOW_TOUCHDOWN.seabed
    bed = dict(
        seabed=lambda x: height + slope * np.asarray(x),
        seabed_slope=lambda x: np.full(np.shape(x), slope),
    )

    def node_off(line):
        """How far (m) the nearest node lies from the line's touchdown."""
        return float(np.min(np.abs(line.problem.mesh.p[0] - line.s_touchdown)))

    def passes(fit):
        return solve_line_bvp(
            SLOW_TOUCHDOWN.span, SLOW_TOUCHDOWN.dh, segments, n_elements=64, fit_touchdown=fit, **bed
        )

    reference, two, default = passes(8), passes(2), plane()
    assert node_off(reference) < 3e-4 and node_off(default) < 5e-3 and node_off(two) < 1e-4
    assert abs(two.H - reference.H) <= 1e-6 * reference.H
    assert abs(default.H - reference.H) <= 1e-6 * reference.H


#: scene 2:35: chain, wire and chain (1023, 66 and 1057 N/m) on a straight slope of 0.058 rising
#: from 9.4 m below the anchor, a 34 kN buoy 2.3 m before the fairlead, 64 elements
BUOY_BY_FAIRLEAD = (
    269.6243145679015,
    30.02155706521642,
    [
        (106.64649617996385, 1023.4379607827417, 28599943.999211386),
        (78.57297475067752, 65.51703575068102, 307170790.9805231),
        (103.303426678956, 1057.0276378719975, 5021882864.82908),
    ],
    dict(
        seabed=-9.400984967836123,
        seabed_slope=0.05818703469860276,
        point_loads=[(267.3682651047835, -33988.28565714568)],
        friction=0.0,
        n_elements=64,
    ),
)
#: scene 2:99: a rope (23.8 N/m) 1870 m long over a straight slope of -0.053 from 34 m below the
#: anchor, a 4.06 kN buoy 771 m along it, the fairlead 84 m below the anchor, 64 elements
BUOY_OVER_A_SLOPE = (
    1795.6878663874159,
    -84.38883090602786,
    [(1869.7369800538029, 23.819711896346156, 626495519.9262357)],
    dict(
        seabed=-34.07559471873762,
        seabed_slope=-0.05315649526333741,
        point_loads=[(771.2496266917531, -4062.0090742128345)],
        friction=0.0,
        n_elements=64,
    ),
)


def balanced(line, segments, options):
    """The plane line's end forces balance its weight, its point loads and the frictionless
    slope's reaction, normal to the slope (to round-off of the weight)."""
    weight = sum(length * w for length, w, _ in segments) + sum(P for _, P in options["point_loads"])
    R = line.contact_force.sum(axis=0)  # the seabed's reaction on the line (N)
    assert line.V_A + line.V_B + R[1] == pytest.approx(weight, rel=1e-9)
    assert line.H_B - line.H_A + R[0] == pytest.approx(0.0, abs=1e-9 * weight)
    assert R[0] == pytest.approx(-options["seabed_slope"] * R[1], rel=1e-9, abs=1e-9 * weight)


def in_space(span, dh, segments, options):
    """The scene's line in space (`solve_line_bvp_3d`), its end forces as the plane line's."""
    space = solve_line_bvp_3d(
        (0.0, 0.0, 0.0),
        (span, 0.0, dh),
        segments,
        seabed=Plane(options["seabed"], (options["seabed_slope"], 0.0)),
        point_loads=options["point_loads"],
        n_elements=options["n_elements"],
    )
    return space_forces(space)


def test_the_plane_line_falls_back_on_the_line_in_spaces_strategy():
    """Scene 2:99 (`BUOY_OVER_A_SLOPE`): the plane line's own strategy finds no descent (one of
    the eight scenes of the survey, seeds 1–3, that only the line in space solved). `solve_line_bvp`
    then takes the line in space's strategy and solves the plane line on its mesh from it
    (`skcable.mooring.line_bvp.fallback.space_for_plane`): the line passes the plane line's
    checks (its equilibrium residual by scikit-fem's own assembly), balances the weight, the
    buoy and the frictionless slope's reaction, and its end forces are the line in space's to
    round-off (one discrete line on one mesh; measured 1.2e-14)."""
    span, dh, segments, options = BUOY_OVER_A_SLOPE
    with pytest.raises(ConvergenceError):  # its own strategy, without the fallback
        LineBVPSolver(scene(span, dh, segments, fit_touchdown=3, **options)).solve()
    line = solve_line_bvp(span, dh, segments, **options)
    balanced(line, segments, options)
    want = in_space(span, dh, segments, options)
    np.testing.assert_allclose(plane_forces(line), want, rtol=0, atol=1e-9 * np.abs(want).max())


def test_a_buoy_is_grown_in_steps_where_every_start_fails():
    """Scene 2:35 (`BUOY_BY_FAIRLEAD`): from every closed-form start the plane line's solves
    stagnated (the survey's plane line failed it; the line in space solved it). The line without
    its buoy solves, and the buoy grown on its mesh in steps (`LineBVPSolver.loads_by_steps`,
    `skcable.mooring.line_bvp.solver.LineSolver.continued`) takes the plane line's own strategy
    to it: it balances, and agrees with the line in space within 1e-6 of the largest end force
    (measured 1.9e-8)."""
    span, dh, segments, options = BUOY_BY_FAIRLEAD
    checked = scene(span, dh, segments, fit_touchdown=3, **options)
    line = LineBVPSolver(checked).solve()  # its own strategy, without the fallback
    balanced(line, segments, options)
    want = in_space(span, dh, segments, options)
    np.testing.assert_allclose(plane_forces(line), want, rtol=0, atol=1e-6 * np.abs(want).max())
    solver = LineBVPSolver(checked)
    with pytest.raises(ConvergenceError):  # the starts alone: the failure before
        solver.checked(solver.level(options["n_elements"], every_start=True))


#: scene 1:50: chain, wire and rope (806, 18.6 and 71.3 N/m), no seabed, 172.5 m between ends
#: 83.2 m apart and 33.2 m down, a 2.13 kN buoy 12.2 m into the wire (it lifts more than the
#: wire weighs); 256 elements
BUOY_IN_A_DEEP_SAG = (
    83.19382821085433,
    -33.17499054448351,
    [
        (32.16750443945661, 806.3558919343956, 39688703.474536054),
        (65.63886342564933, 18.575255040726148, 261021385.60133183),
        (74.70785479632985, 71.29454763944148, 106354130.64925216),
    ],
    [(44.37510675776214, -2133.9817342290225)],
)


def test_a_buoy_inside_a_segment_starts_from_the_segments_closed_form():
    """Scene 1:50 (`BUOY_IN_A_DEEP_SAG`): both line BVPs failed from the closed-form starts (the
    uniform line's and the smeared weights', far from a line that hangs in a deep U, H = 854 N
    against 26 kN of chain). The segment-wise closed form now splits a segment at a point load
    inside it (`skcable.mooring.line_bvp.start`): `skcable.mooring.Line` with the buoy at that
    joint, an independent closed form (Irvine's elastic catenary piece by piece), gives the
    end forces both solve to within 1e-6 of the largest (measured 7.9e-12 plane, 2.1e-7 space)."""
    from skcable import mooring

    span, dh, segments, loads = BUOY_IN_A_DEEP_SAG
    (s_buoy, P), first = loads[0], segments[0][0]
    (L1, w1, EA1), (L2, w2, EA2), (L3, w3, EA3) = segments
    closed = mooring.line_in_plane(
        mooring.Line(
            [
                mooring.Segment(L1, w1, EA1),
                mooring.Segment(s_buoy - first, w2, EA2),
                mooring.Segment(L1 + L2 - s_buoy, w2, EA2),
                mooring.Segment(L3, w3, EA3),
            ],
            attachments=[mooring.Buoy(2, -P)],
        ),
        span,
        dh,
    )
    assert closed.model == "free"
    want = np.array([closed.H_A, -closed.V_A, -closed.H_B, -closed.V_B])
    plane = solve_line_bvp(span, dh, segments, point_loads=loads, n_elements=256)
    space = solve_line_bvp_3d((0.0, 0.0, 0.0), (span, 0.0, dh), segments, point_loads=loads, n_elements=256)
    for got in (plane_forces(plane), space_forces(space)):
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-6 * np.abs(want).max())


def test_a_buoy_that_holds_a_long_line_taut_is_not_refused_for_the_line_without_it():
    """A chain 131 m long on a flat seabed, from an anchor on it to a fairlead 100 m away and 30 m
    up, is longer than its L-shape (130 m): without its 20 kN buoy 40 m along it, it heaps. With
    the buoy, whose arch takes up the slack, it has a taut equilibrium (the energy minimum of
    ``benchmarks/line_energy_minimum.py``: H = 3356 N). Growing the buoy from the line without it
    (`LineBVPSolver.loads_by_steps`) cannot start there; that line's heap is not this line's
    verdict, so the solve fails as a `ConvergenceError` (both strategies fail it), not an
    ``InputError("length")``. The same line 133 m long solves: H = 2722.44 N, as the energy minimum
    gives (2722.437 N on 4000 nodes)."""
    common = dict(seabed=0.0, point_loads=[(40.0, -20000.0)])
    with pytest.raises(ConvergenceError):
        solve_line_bvp(100.0, 30.0, [(131.0, 1000.0, 1e9)], **common)
    taut = solve_line_bvp(100.0, 30.0, [(133.0, 1000.0, 1e9)], **common)
    assert taut.H == pytest.approx(2722.437, rel=1e-5)


def test_the_slope_diagnosis_allows_for_the_buoys_arches():
    """Scene 3:100: a rope, a wire and a chain (91 ± 30, 86 and 960 N/m) over a slope of -0.089
    from 73 m below the anchor, a 10.8 kN buoy 791 m along the line. Both solvers fail it, and
    its uniform line of the mean weight is longer than the slope holds taut; but the line's
    energy minimum (``benchmarks/line_energy_minimum.py``) is taut, its least tension 67 N: the
    buoy's arch takes up the slack. The diagnosis says that a buoy may hold the line taut."""
    rope = varying(90.8556990300907, 0.3251537529423415, 881.3934582266562, 1.9909702715555997)
    segments = [
        (508.0263457925181, rope, 20954283.306145195),
        (251.8277347814075, 85.52611364241302, 61128943.9851113),
        (105.5344715703199, 959.5541437088216, 25528476.20420965),
    ]  # fmt: skip
    with pytest.raises(ConvergenceError, match="longer than the .* unless its buoys hold it taut"):
        solve_line_bvp(
            695.9627093144995, -7.055411220817746, segments, seabed=-73.3236024885062,
            seabed_slope=-0.08878620640747992, point_loads=[(790.6131570248047, -10829.226522068919)],
        )  # fmt: skip
