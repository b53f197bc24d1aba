r"""A `skcable.mooring.Line` in the sea solved between an anchor and a fairlead: `LineInSea`.

The model a line in the sea takes, and why, is chosen by `skcable.mooring.choice`
(`skcable.mooring.choice.solve_line_in_sea`): the closed form in the vertical plane of the ends
(`skcable.mooring.line3d.Line3D` over `skcable.mooring.Line`'s closed form: H.M. Irvine, "Cable
Structures", MIT Press, 1981; J.M. Jonkman, "Dynamics modeling and loads analysis of an offshore
floating wind turbine", NREL, 2007), on a plane slope, with nonlinear axial laws, or the 3-D line
BVP (`skcable.mooring.line_bvp.space`, `bvp_model`). Its `ModelChoice` carries its estimated
relative error: for a closed form the closure's relative residual (round-off); for the BVP the
difference of the end forces on ``n`` and ``n/2`` elements over the largest end force (the P2
line converges at ``h³``: the difference bounds the coarser solution's error, the finer one's
is smaller). Its tension field (P1, discontinuous) converges at ``h²`` only: ``field_error``
is the largest difference of the two lines' tension fields over the largest end tension (for
an error ``c h²`` the difference is ``3 c h²``, three times the finer field's), and it bounds
the field's disagreement with the end forces at the ends (the supports' reactions, accurate to
``error``): on a 600 m chain in a current, 1.3e-5 where the end forces' ``error`` is 1.6e-8.

A flat seabed given as a `skcable.mooring.bathymetry.Bathymetry` (global heights) is placed
relative to the anchor for the closed forms; a ``seabed`` float of the `Line` is relative to the
anchor as in `skcable.mooring.Line`.

`LineInSea` gives the end forces, ``profile(n)`` ``(n, 3)`` over the unstretched arc length,
``T_of_s(s)``, the fairlead ``stiffness()`` (3 × 3), ``model`` and ``equilibrium_residual``:
for the BVP the largest ``|d(T t)/ds + q|`` at its quadrature points
(`skcable.mooring.line_bvp.space.solution`); for a closed form, which meets the equilibrium equations
exactly along the line, the balance of the forces on the whole line,
``|F_a + F_b + W e_z − R| / L`` (N/m; ``R`` the seabed's force), to round-off; on a slope, where
``R`` is the closure's own, the closure's relative residual times the weight per length.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from skcable import _plausible
from skcable._checks import whole
from skcable._show import Shown
from skcable.errors import InputError
from skcable.mooring.slope import SlopeSolution

__all__ = [
    "BVP_ELEMENTS",
    "LineInSea",
    "LineInSeaBetween",
    "ModelChoice",
    "bvp_model",
    "placed_line",
    "relative_seabed",
]

#: elements of the 3-D line BVP of a line in the sea (the error estimate solves on half as many)
BVP_ELEMENTS = 96


@dataclass(frozen=True)
class ModelChoice:
    """Which model solved a line, why, and its estimated relative errors: of the end forces, and of
    the fields (the tension profile), both over the largest end tension.

    Attributes
    ----------
    name : str
        ``"closed form"``, ``"closed form (slope)"``, ``"closed form (axial laws)"`` or
        ``"3-D line BVP"``.
    reason : str
        Why (`skcable.mooring.choice`).
    error : float
        Estimated relative error of the end forces (-).
    field_error : float
        Estimated relative error of the tension field ``T_of_s`` (and so of its agreement with the
        end forces at the ends), at least ``error`` (-): a closed form's fields are its closure's,
        the BVP's P1 tension field converges at ``h²`` only (module docstring).
    """

    name: str
    reason: str
    error: float
    field_error: float = 0.0

    def __post_init__(self):
        object.__setattr__(self, "field_error", max(float(self.field_error), float(self.error)))

    def __str__(self):
        return (
            f"{self.name}: {self.reason} (estimated error {self.error:.1e} in the end forces, "
            f"{self.field_error:.1e} in the tension field)"
        )


class LineInSea:
    """A `skcable.mooring.Line` solved between ``anchor`` and ``fairlead`` (module docstring).

    Attributes
    ----------
    line : Line
    anchor, fairlead : ndarray (3,)
        The ends (m), z up.
    result : Line3D or LineBVP3DSolution
        What the model gave in space.
    solution : LineSolution, LawLineSolution or LineBVP3DSolution
        The closed form's 2-D solution in the plane of the ends (``Line3D.solution``), or the
        BVP's.
    model : ModelChoice
        Which model ran, why, and its estimated error (the BVP's estimate, a second solve on
        half the elements, is computed when first asked for).
    force_on_anchor, force_on_fairlead : ndarray (3,)
        The line's forces on its ends (N), global axes.
    tension_at_anchor, tension_at_fairlead : float
        Their magnitudes (N).
    """

    def __init__(self, line, anchor, fairlead, result, name, reason, error=None, end_loads=(0.0, 0.0)):
        self.line, self.anchor, self.fairlead = line, anchor, fairlead
        self.result, self.name, self.reason, self._error = result, name, reason, error
        self.end_loads = end_loads
        self.solution = getattr(result, "solution", result)
        solution = result
        self.force_on_anchor = np.array(solution.force_on_anchor, dtype=float)
        self.force_on_fairlead = np.array(solution.force_on_fairlead, dtype=float)
        self.force_on_anchor[2] -= end_loads[0]  # attachments at the ends pull their supports down
        self.force_on_fairlead[2] -= end_loads[1]
        self.tension_at_anchor = float(np.linalg.norm(self.force_on_anchor))
        self.tension_at_fairlead = float(np.linalg.norm(self.force_on_fairlead))
        if not (np.isfinite(self.force_on_anchor).all() and np.isfinite(self.force_on_fairlead).all()):
            raise InputError("line", "the line's solution has non-finite end forces")

    def __getattr__(self, name):
        # the closed form's other attributes (`Line3D`: ``H``, ``V_B``, ``direction``, ...), as
        # ``line_3d`` gave them before it returned a LineInSea for a Line
        if name.startswith("_") or name in ("result", "solution", "name", "line"):
            raise AttributeError(name)
        if self.name != "3-D line BVP" and hasattr(self.result, name):
            return getattr(self.result, name)
        raise AttributeError(f"{type(self).__name__} of the {self.name} has no attribute {name!r}")

    @cached_property
    def model(self) -> ModelChoice:
        """Which model ran, why, and its estimated error (`ModelChoice`)."""
        error, field = (self._error, 0.0) if self._error is not None else _bvp_error(self)
        return ModelChoice(self.name, self.reason, max(float(error), 1e-15), float(field))

    @property
    def bvp(self) -> bool:
        """Whether the 3-D line BVP solved the line."""
        return self.name == "3-D line BVP"

    @property
    def end_forces(self) -> np.ndarray:
        """The line's forces on its ends, anchor then fairlead (N), (2, 3)."""
        return np.array([self.force_on_anchor, self.force_on_fairlead])

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), tension (n,))`` (m, N) at ``n`` points evenly spaced in unstretched arc
        length from the anchor."""
        return self.result.profile_with_tension(whole("n", n, 2))

    def profile(self, n: int = 101) -> np.ndarray:
        """Positions ``(n, 3)`` (m) evenly spaced in unstretched arc length from the anchor."""
        return self.profile_with_tension(n)[0]

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m) from the anchor."""
        return self.result.T_of_s(s)

    def stiffness(self) -> np.ndarray:
        """The fairlead stiffness ``−∂F_b/∂b`` (N/m), 3 × 3, global axes, the anchor fixed (the
        static one)."""
        return np.asarray(self.result.stiffness(), dtype=float)

    def tensions(self):
        """The solution's tension table (pandas DataFrame, one row per segment)."""
        return self.result.tensions()

    @property
    def equilibrium_residual(self) -> float:
        """N/m (module docstring)."""
        if self.bvp:
            return float(self.result.equilibrium_residual)
        sol = self.solution
        if isinstance(sol, SlopeSolution):
            return sol.residual() * self.line.weight / self.line.length
        seabed = float(getattr(sol, "seabed_reaction", 0.0))
        friction = (sol.H - sol.H_A) * self.result.direction
        total = self.end_forces.sum(axis=0) + np.array([*friction[:2], self.line.weight - seabed])
        return float(np.linalg.norm(total)) / self.line.length

    def __repr__(self):
        Fb = self.force_on_fairlead
        return (
            f"LineInSea(model={self.name!r}, force_on_fairlead=[{Fb[0]:.6g}, {Fb[1]:.6g}, "
            f"{Fb[2]:.6g}] N, tension_at_fairlead={self.tension_at_fairlead:.6g} N)"
        )


def relative_seabed(line, anchor):
    """The line's seabed relative to the anchor (m) for the closed forms, or None; the flat
    `Bathymetry` placed at the anchor (``0`` where the anchor lies on it)."""
    if line.bathymetry is None:
        return line.seabed
    rel = float(line.bathymetry.flat) - float(anchor[2])
    if rel > 1e-9 * max(1.0, abs(float(anchor[2]))):
        raise InputError("seabed", f"must be at or below the anchor, got {rel:g} m above it")
    return 0.0 if abs(rel) <= 1e-9 * max(1.0, abs(float(anchor[2]))) else rel


def bvp_model(line, n_elements: int = BVP_ELEMENTS, anchor_z: float = 0.0):
    """The `skcable.mooring.line_bvp.space.LineBVP3D` of ``line`` on ``n_elements`` (its seabed placed at
    the anchor's height ``anchor_z`` where it is a float), and its end attachments ``(P_0, P_n)``
    (N); cached on the line (a warm start needs the same model).

    Its mesh is uniform (``mesh="uniform"``): the line's anchor lies on the seabed, where that mesh
    resolves the touchdown (2.8e-8 of the end forces for a 500 m chain on 96 elements, 8.5e-10
    graded), its error estimate (the line on half the elements) says what it costs, and a
    system's warm starts stay on it (graded meshes took a 12-line system on grounded chains 3.0
    times as long to its equilibrium: ``python benchmarks/bench_line3d.py``, scene 9)."""
    from skcable.mooring.line_bvp.space import LineBVP3D, LineSegment

    cache = line.__dict__.setdefault("_bvp_models", {})
    key = (int(n_elements), None if line.seabed is None else float(anchor_z))
    if key in cache:
        return cache[key]
    segments = [
        LineSegment(s.length, s.w, s.law, s.diameter, s.cd_normal, s.cd_tangential) for s in line.segments
    ]
    n = len(segments)
    inner = [(a.joint, a.force) for a in line.attachments if 0 < a.joint < n]
    seabed = line.bathymetry
    if seabed is None and line.seabed is not None:
        seabed = anchor_z + line.seabed
    model = LineBVP3D(
        segments, attachments=inner, seabed=seabed, friction=line.friction, current=line.current,
        rho_water=line.rho_water, n_elements=n_elements, mesh="uniform",
    )  # fmt: skip
    cache[key] = model, (float(line.joint_forces[0]), float(line.joint_forces[n]))
    return cache[key]


def _bvp_error(solved: LineInSea) -> tuple[float, float]:
    """The BVP's error estimates (module docstring): the line on half the elements, against it;
    ``(end forces, tension field)`` over the largest end tension, the field's the largest
    difference of the two tension fields at ``4 n + 1`` points evenly spaced in arc length (the
    ends included)."""
    coarse_model, _ = bvp_model(solved.line, BVP_ELEMENTS // 2, float(solved.anchor[2]))
    fine = solved.result
    with _plausible.quiet():  # an estimate's solve, not an answer
        coarse = coarse_model.solve(solved.anchor, solved.fairlead)
    diff = np.vstack(
        [fine.force_on_anchor - coarse.force_on_anchor, fine.force_on_fairlead - coarse.force_on_fairlead]
    )
    scale = max(fine.T_A, fine.T_B)
    s = np.linspace(0.0, fine.length, 4 * BVP_ELEMENTS + 1)
    field = np.abs(np.asarray(fine.T_of_s(s)) - np.asarray(coarse.T_of_s(s)))
    return float(np.abs(diff).max()) / scale, float(field.max()) / scale


def placed_line(line, depth, reverse: bool):
    r"""The `skcable.mooring.Line` a `skcable.mooring.MooringSystem` solves for ``line``, a line in the sea
    (a current, a `skcable.mooring.bathymetry.Bathymetry` or a nonlinear axial law), from its fixed
    end: its segments (and attachments) in reverse order where that end is its end b
    (``reverse``), over its own `Bathymetry` where it has one, else over the system's flat
    seabed ``z = -depth`` (a flat `skcable.mooring.bathymetry.Plane`, in global heights as the
    system's; none without a ``depth``); its current, friction and water density kept."""
    from skcable.mooring.bathymetry import Plane
    from skcable.mooring.segments import Line

    segments, attachments = list(line.segments), list(line.attachments)
    if reverse:
        n = len(segments)
        segments = segments[::-1]
        attachments = [type(a)(n - a.joint, abs(a.force)) for a in attachments]
    seabed = line.bathymetry if line.bathymetry is not None else None if depth is None else Plane(-depth)
    friction = line.friction if seabed is not None else 0.0
    return Line(
        segments,
        attachments,
        seabed=seabed,
        friction=friction,
        current=line.current,
        rho_water=line.rho_water,
    )


def _reversed_table(table):
    """A segment table from the other end: rows in reverse order, renumbered, each ``*_lower``
    column swapped with its ``*_upper``."""
    table = table.iloc[::-1].reset_index(drop=True)
    swap = {}
    for name in table.columns:
        if name.endswith("_lower") and name[:-6] + "_upper" in table.columns:
            swap[name], swap[name[:-6] + "_upper"] = name[:-6] + "_upper", name
    table = table.rename(columns=swap)[list(table.columns)]
    if "segment" in table.columns:
        table["segment"] = np.arange(len(table))
    return table


class LineInSeaBetween(Shown):
    """A line in the sea of a `skcable.mooring.MooringSystem`, solved from its fixed end (a
    `LineInSea`, anchor at the fixed point), seen from its ends a and b in the order of the
    system's line.

    Attributes
    ----------
    line : Line
        The line as added to the system (segments from a to b).
    sea : LineInSea
        The solution from the fixed end: ``sea.anchor`` the fixed point, ``sea.fairlead`` the
        moving one.
    reversed : bool
        Whether the fixed end is b (``sea`` then runs from b to a).
    a, b : ndarray (3,)
        The ends (m).
    end_forces : ndarray (2, 3)
        The line's forces on a and on b (N), global axes.
    model, reason : str
        The model that ran (`ModelChoice.name`) and why.
    force_on_fairlead, tension_at_fairlead, fairlead, H
        Of the moving end (N, m): its force, its tension, where it is and the horizontal force
        there (what the system's assembly and its Newton method read).
    """

    def __init__(self, line, sea: LineInSea, reverse: bool):
        self.line, self.sea, self.reversed = line, sea, bool(reverse)
        self.a, self.b = (sea.fairlead, sea.anchor) if reverse else (sea.anchor, sea.fairlead)
        self.end_forces = sea.end_forces[::-1].copy() if reverse else sea.end_forces
        self.model, self.reason = sea.name, sea.reason
        self.fairlead, self.force_on_fairlead = sea.fairlead, sea.force_on_fairlead
        self.tension_at_fairlead = sea.tension_at_fairlead
        self.H = float(np.hypot(*sea.force_on_fairlead[:2]))

    @property
    def model_choice(self) -> ModelChoice:
        """Which model ran, why, and its estimated error (`LineInSea.model`)."""
        return self.sea.model

    @property
    def solution(self):
        """The solution from the fixed end (`LineInSea.solution`)."""
        return self.sea.solution

    @property
    def equilibrium_residual(self) -> float:
        """N/m (`LineInSea.equilibrium_residual`)."""
        return self.sea.equilibrium_residual

    @cached_property
    def length_on_seabed(self) -> float:
        """The unstretched length resting on the seabed (m): the closed form's, or the BVP's
        contact nodes' span summed over its segments."""
        if not self.sea.bvp:
            return float(getattr(self.sea.solution, "length_on_seabed", 0.0))
        return float(np.asarray(self.sea.tensions()["grounded_length"], dtype=float).sum())

    @cached_property
    def x_touchdown(self) -> float:
        """The horizontal distance (m) from the fixed end to the touchdown, 0 without one."""
        if not self.length_on_seabed > 0:
            return 0.0
        if not self.sea.bvp:
            return float(self.sea.solution.x_touchdown)
        where = self.sea.result.xyz(self.sea.result.s_touchdown)
        return float(np.hypot(*(where - self.sea.anchor)[:2]))

    def stiffness(self) -> np.ndarray:
        """The moving end's stiffness ``−∂F/∂p`` (N/m), 3 × 3, global axes, the fixed end fixed."""
        return self.sea.stiffness()

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m) from a."""
        if not self.reversed:
            return self.sea.T_of_s(s)
        return self.sea.T_of_s(float(self.line.length) - np.asarray(s, dtype=float))

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points (n, 3), tension (n,))`` (m, N) evenly spaced in unstretched arc length from a."""
        points, tension = self.sea.profile_with_tension(n)
        return (points[::-1].copy(), tension[::-1].copy()) if self.reversed else (points, tension)

    def profile(self, n: int = 101) -> np.ndarray:
        """Positions ``(n, 3)`` (m) from a to b."""
        return self.profile_with_tension(n)[0]

    def tensions(self):
        """One row per segment from a to b (`LineInSea.tensions`, turned round where b is fixed)."""
        table = self.sea.tensions()
        return _reversed_table(table) if self.reversed else table

    def __repr__(self):
        Ta, Tb = np.linalg.norm(self.end_forces, axis=1)
        return f"LineInSeaBetween(model={self.model!r}, tension_a={Ta:.6g}, tension_b={Tb:.6g})"
