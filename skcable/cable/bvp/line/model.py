"""The public entry points of the line BVP: `solve_line_bvp`."""

from __future__ import annotations

from skcable.cable.bvp.line.driver import LineBVPSolver
from skcable.cable.bvp.line.inputs import scene
from skcable.cable.bvp.line.solution import LineBVPSolution

__all__ = ["solve_line_bvp"]


def solve_line_bvp(
    span,
    dh,
    segments,
    *,
    seabed=None,
    seabed_slope=None,
    friction: float = 0.0,
    point_loads=(),
    n_elements: int = 64,
    fit_touchdown: int = 2,
    rtol: float = 1e-10,
    max_iter: int = 50,
) -> LineBVPSolution:
    """A mooring line from anchor A = (0, 0) to fairlead B = (span, dh), by finite elements,
    optionally resting on a seabed of any shape (see `skcable.cable.bvp.line`).

    Parameters
    ----------
    span, dh : float
        Fairlead position relative to the anchor (m), ``span > 0``.
    segments : list of BVPSegment or (length, w, EA) tuples
        From A to B: unstretched length (m), weight per unstretched length
        (N/m, or a callable of the arc length s from A) and axial stiffness
        (N, None for inextensible). Joints are mesh nodes.
    seabed : float or callable, optional
        Seabed height ``b`` relative to A (m): a number (flat) or a callable
        ``b(x)`` (array in, array out). A must lie on or above it, B above it.
    seabed_slope : callable, optional
        ``b'(x)``; central differences of ``b`` (step 1e-5 span) otherwise.
    friction : float
        Coulomb coefficient μ of the grounded line, fully mobilised towards
        the anchor (Jonkman's model); needs a seabed.
    point_loads : sequence of (s, P)
        Downward force ``P`` (N; negative for a buoy) at arc length ``s``
        from A (a mesh node is put there).
    n_elements : int
        Elements over the whole line, shared among segments by length (at
        least one each).
    fit_touchdown : int
        Passes of touchdown fitting (and, when > 0, meshes graded by the
        line's curvature: `skcable.cable.bvp.line.mesh`): after a solve that touches the seabed,
        a mesh node is put at the touchdown (and the landing, for an anchor
        above the seabed) the vertical balance gives
        (`LineBVPSolution.s_touchdown`, ``s_landing``: the nearest inner node moves there
        when it is closer than a quarter of an element, else a node is
        inserted) and the line is solved again from the previous solution,
        until the touchdown moves less than 1e-9 of the length. Nodal contact
        otherwise misplaces the touchdown by up to half an element, an error
        in H of order (that distance)² that jumps with the mesh; 0 turns it off.
    rtol : float
        Newton stops when every scaled residual (forces over the total load,
        the stretch over the length, the complementarity rows over the total
        load) is below ``rtol``.
    max_iter : int
        Newton iterations at most.

    Returns
    -------
    LineBVPSolution

    Raises
    ------
    InputError
        Bad data, named; friction too weak to hold a slack stretch on a
        sloping seabed.
    ConvergenceError
        Newton stalled (``history`` holds the merit per iteration); the end
        of a slack stretch not found; the discrete line in compression (its
        bends not resolved by the mesh).

    Notes
    -----
    The continuation (levels, gradings, friction, touchdown fitting, the slack stretch and the
    retries) is `skcable.cable.bvp.line.driver.LineBVPSolver`'s.
    """
    checked = scene(
        span,
        dh,
        segments,
        seabed=seabed,
        seabed_slope=seabed_slope,
        friction=friction,
        point_loads=point_loads,
        n_elements=n_elements,
        fit_touchdown=fit_touchdown,
        rtol=rtol,
        max_iter=max_iter,
    )
    return LineBVPSolver(checked).solve()
