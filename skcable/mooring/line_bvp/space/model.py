"""The public entry points of the 3-D line BVP: `solve_line_bvp_3d`, and `LineBVP3D`, a line model."""

from __future__ import annotations

from dataclasses import fields

from skcable.errors import InputError
from skcable.fe import NewtonOptions
from skcable.mooring.line_bvp.check import warn_unresolved
from skcable.mooring.line_bvp.fallback import plane_for_space
from skcable.mooring.line_bvp.resolution import solve_resolved
from skcable.mooring.line_bvp.space.driver import LineBVP3DSolver
from skcable.mooring.line_bvp.space.inputs import checked_options, scene
from skcable.mooring.line_bvp.space.solution import LineBVP3DSolution

__all__ = ["LineBVP3D", "solve_line_bvp_3d"]

#: the Newton options `LineBVP3D` takes as keywords (`skcable.fe.NewtonOptions`'s fields)
NEWTON_FIELDS = frozenset(f.name for f in fields(NewtonOptions))

_DEFAULTS = dict(
    attachments=(),
    point_loads=(),
    seabed=None,
    friction=0.0,
    current=None,
    rho_water=1025.0,
    terms=(),
    n_elements=64,
    fit_touchdown=3,
    mesh="graded",
    rtol=None,
    max_iter=None,
    time_limit=60.0,
    options=None,
)


def solve_line_bvp_3d(
    anchor,
    fairlead,
    segments,
    *,
    attachments=(),
    point_loads=(),
    seabed=None,
    friction: float = 0.0,
    current=None,
    rho_water: float = 1025.0,
    terms=(),
    n_elements: int | str = 64,
    fit_touchdown: int = 3,
    mesh: str = "graded",
    rtol: float | None = None,
    max_iter: int | None = None,
    time_limit: float = 60.0,
    options=None,
    **newton_options,
) -> LineBVP3DSolution:
    """A line in space from ``anchor`` to ``fairlead`` by finite elements, in a current, on a
    seabed of any shape (see `skcable.mooring.line_bvp.space`).

    Parameters
    ----------
    anchor, fairlead : array_like (3,)
        The ends (m), z up (the water's surface at z = 0 for the current's depths).
    segments : list of LineSegment or tuples
        From the anchor: ``LineSegment(length, w, EA, diameter, cd_normal, cd_tangential)``
        (`skcable.mooring.line_bvp.inputs.LineSegment`, the plane line's; ``w`` a number or a
        callable of the arc length, ``EA`` a stiffness or a strain law).
    attachments : sequence
        Point loads at the inner joints: ``(joint, P)`` (``P`` downward, N; negative: a buoy) or
        `skcable.mooring.ClumpWeight` / `skcable.mooring.Buoy`.
    point_loads : sequence of (s, P)
        Point loads anywhere inside the line, as for `skcable.mooring.solve_line_bvp`: at the
        arc length ``0 < s < L`` (m) from the anchor, ``P`` downward (N).
    seabed : float, Bathymetry or (height, gradient), optional
        The seabed (`skcable.mooring.bathymetry.bathymetry_of`): a flat height (m), a `Plane`, a
        `DepthFunction`, a `Grid`.
    friction : float
        Coulomb coefficient μ on the seabed, fully mobilised along the line (needs a seabed).
    current : (Ux, Uy), callable or Current, optional
        The current (`skcable.bvp.current.current_of`), m/s; it drags the segments that have
        a diameter and drag coefficients.
    rho_water : float
        Density of the water (kg/m³) for the drag.
    terms : sequence of CableTerm
        More distributed loads (`skcable.bvp.terms`: `Buoyancy` for a line given its dry
        weight, the analyst's own).
    n_elements : int or "auto"
        Elements over the line, shared among segments by length (at least one each);
        ``"auto"``: the elements the line needs, 64 then four times as many while the mesh does
        not resolve the line, up to 1024 (`skcable.mooring.line_bvp.resolution`; the solution's
        ``n_elements`` says how many). A mesh that does not resolve the line warns
        (`skcable.errors.ResolutionWarning`).
    fit_touchdown : int
        Passes putting a node at the touchdown and the landing (0: nodal contact only, on the
        uniform mesh).
    mesh : {"graded", "uniform"}
        On a seabed, with ``fit_touchdown``: ``"graded"``, the
        ``n_elements`` graded by the closed-form start's turning, then by the line's, pass by
        pass (as the plane line's: the bend where the line lands on the seabed resolved, 1e-9
        to 1e-7 of the end forces at 64 elements); ``"uniform"``, equal elements per segment,
        graded only where the line ends in compression on them (faster by about a third, its
        end forces up to 2 % off where a line lands on the seabed from an anchor above it:
        ``python benchmarks/bench_bvp.py --space-mesh``). Otherwise uniform.
    rtol : float
        Newton's tolerance on the scaled residual (forces over the total load, stretches over
        the length; default 1e-10, ``tol`` of `skcable.fe.NewtonOptions`).
    max_iter : int
        Newton iterations at most per solve (default 50).
    time_limit : float
        Seconds at most for the whole strategy (default 60): past them a `ConvergenceError`
        whose ``history`` holds the last merit of every solve.
    options : NewtonOptions, optional
        The Newton options of every solve, as for `skcable.mooring.solve_line_bvp` (the line
        BVP's defaults ``tol=1e-10, max_iter=50, line_search="residual",
        stagnation_window=8``).
    **newton_options
        Any field of `skcable.fe.NewtonOptions`, over ``options``, as for
        `skcable.mooring.solve_line_bvp`: ``atol``, ``line_search`` (``"energy"`` refused),
        ``callback(iteration, residual_norm, step_norm)`` (after every step of every solve,
        numbered from 1 in each; the last solve's merits are the solution's ``history``),
        ``max_halvings``, ``stagnation_window``, ``tol``. An unknown name is an `InputError`
        naming it.

    Returns
    -------
    LineBVP3DSolution

    Raises
    ------
    InputError
        Bad data, named.
    ConvergenceError
        No solve converged (``history`` holds the merit per iteration); the line in compression
        (a `skcable.errors.ResolutionError` where no other reason is found: more elements may
        solve it);
        its equilibrium residual above its bound. Its ``last`` keeps what converged: the
        `LineBVP3DSolution` on the finest mesh reached (not checked), None where no solve
        converged; with ``n_elements="auto"``, where a refined solve fails, the coarser line
        (checked, not resolved). Before it, a line that hangs in the vertical plane of its ends is solved by
        the plane line's strategy within what is left of ``time_limit``, then in space from it
        (`skcable.mooring.line_bvp.fallback.plane_for_space`); a failure of both says so.

    Examples
    --------
    >>> from skcable.mooring.line_bvp.space import LineSegment, solve_line_bvp_3d
    >>> line = solve_line_bvp_3d(
    ...     (0.0, 0.0, -200.0), (400.0, 0.0, -20.0), [LineSegment(500.0, 600.0, 4e8, 0.1, 1.2, 0.0)],
    ...     current=(0.0, 0.8),
    ... )
    >>> bool(line.force_on_fairlead[1] > 0)  # the cross current pulls the fairlead along +y
    True
    """
    options = dict(
        attachments=attachments, point_loads=point_loads, seabed=seabed, friction=friction,
        current=current, rho_water=rho_water, terms=terms, n_elements=n_elements,
        fit_touchdown=fit_touchdown, mesh=mesh, rtol=rtol, max_iter=max_iter, time_limit=time_limit,
        options=options, newton_options=newton_options,
    )  # fmt: skip
    solution = _solved(anchor, fairlead, checked_options(segments, options))
    warn_unresolved(solution)
    return solution


def _solved(anchor, fairlead, checked: dict, start: LineBVP3DSolution | None = None) -> LineBVP3DSolution:
    """The line between ``anchor`` and ``fairlead`` (m) of the `checked_options` ``checked``, on
    its ``n_elements`` or the ones it needs (`skcable.mooring.line_bvp.resolution`), from
    ``start`` where given."""

    def on(n_elements: int, time_limit: float) -> LineBVP3DSolution:
        at = scene(anchor, fairlead, {**checked, "n_elements": n_elements, "time_limit": time_limit})
        return LineBVP3DSolver(at, plane_for_space).solve(start)

    return solve_resolved(on, checked["n_elements"], checked["time_limit"])


class LineBVP3D:
    """A line in space solved by `solve_line_bvp_3d`, as a line model: everything but its ends,
    checked once; ``solve(anchor, fairlead, start=None)`` gives a `LineBVP3DSolution`.

    Parameters
    ----------
    segments : list of LineSegment or tuples
        As for `solve_line_bvp_3d`.
    **options
        ``attachments``, ``point_loads``, ``seabed``, ``friction``, ``current``, ``rho_water``,
        ``terms``, ``n_elements``, ``fit_touchdown``, ``mesh``, ``rtol``, ``max_iter``,
        ``time_limit``, ``options`` and the fields of `skcable.fe.NewtonOptions`: as for
        `solve_line_bvp_3d`.
    """

    def __init__(self, segments, **options):
        newton = {k: options.pop(k) for k in list(options) if k in NEWTON_FIELDS - set(_DEFAULTS)}
        unknown = set(options) - set(_DEFAULTS)
        if unknown:
            raise InputError(
                sorted(unknown)[0],
                f"is not an option of LineBVP3D (options are {sorted({*_DEFAULTS, *NEWTON_FIELDS})})",
            )
        self.options = {**_DEFAULTS, **options, **newton}
        self.checked = checked_options(segments, {**_DEFAULTS, **options, "newton_options": newton})
        self.segments = self.checked["segments"]

    @property
    def length(self) -> float:
        """Unstretched length (m)."""
        return float(sum(seg.length for seg in self.segments))

    def solve(self, anchor, fairlead, start: LineBVP3DSolution | None = None) -> LineBVP3DSolution:
        """The line between ``anchor`` and ``fairlead`` (m); ``start``: a solution of this model at
        other ends (a moored body's previous position), which the solve starts from.

        Raises
        ------
        InputError
            Bad ends; ``start`` that is no solution of this model.
        ConvergenceError
            As `solve_line_bvp_3d`.
        """
        if start is not None and not (isinstance(start, LineBVP3DSolution) and start.model is self):
            raise InputError("start", f"must be a solution of this LineBVP3D, got {type(start).__name__}")
        solution = _solved(anchor, fairlead, self.checked, start)
        warn_unresolved(solution)
        solution.model = self
        return solution

    def __repr__(self):
        o, n = self.options, self.checked["n_elements"]
        return (
            f"LineBVP3D({len(self.segments)} segments, length={self.length:g} m, seabed={o['seabed']!r}, "
            f"friction={o['friction']:g}, current={o['current']!r}, n_elements={n!r}, "
            f"mesh={o['mesh']!r})"
        )
