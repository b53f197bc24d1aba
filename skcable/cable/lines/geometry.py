r"""A line between two ends over a flat seabed: which end is lower, which model, and why.

A `skcable.cable.Line` runs from its end A to its end B, whichever is higher, in the vertical
plane through them: B at ``(span, dh)`` from A, the seabed the plane ``y = seabed`` (relative
to A, at or below both ends; or none). Its closed forms put the anchor at the lower end, so
the line is solved from its lower end (`Line.variant` with ``reverse`` when B is lower), and
the model is chosen by where the ends are (the same choice as `skcable.cable.solve`, which
reports ``model`` and ``reason``):

- no seabed, or the lower end above it and the free line clear of it: the line hangs free
  (``"free"``; H.M. Irvine, "Cable Structures", MIT Press, 1981, segment by segment);
- the lower end on the seabed: it rests on it from there up to a touchdown, with Coulomb
  friction (``"grounded"``; J.M. Jonkman, "Dynamics modeling and loads analysis of an
  offshore floating wind turbine", NREL, 2007), or lies in a heap (``H = 0``);
- the lower end above the seabed and the free line below it: one uniform segment hangs from
  the lower end down to the seabed, lies on it and rises to the upper end, in closed form
  (``"touchdown between the ends"``, `skcable.cable.elastic_catenary` with ``seabed < 0``;
  frictionless only: between two touchdowns static friction depends on the history of the
  motion);
- both ends on the seabed: the line lies on it, straight and taut or slack
  (``"on the seabed"``, `skcable.cable.lines.lying`);
- anything else (several segments or attachments touching down between the ends, a buoy or a
  buoyant segment on the grounded part, a second touchdown): the line BVP
  (``"bvp"``, `skcable.cable.solve_line_bvp` through `skcable.cable.lines.bvp_model`).

**Forces and their derivatives.** The result gives the end forces by the user's ends, and
the Jacobian of ``(H_A, V_A, H_B, V_B)`` in ``(span, y_A, y_B)``, the heights of the ends with
the seabed fixed. Where nothing touches the line depends on ``y_B - y_A`` only and
``H_A = H_B``, ``V_A + V_B = W`` (its weight); on the grounded side
``H_A = \max(H - C_B (W - V_B - P_A), 0)`` (the friction of the grounded weight, fully
mobilised; ``P_A`` the attachment at the anchor); an end resting on the seabed has no
derivative in its height (it cannot move into the seabed): its column is that of the end and
the seabed moved together (a rigid shift, as in MoorPy's end stiffnesses). For the touchdown
between the ends the closure's dependence on the lower end's height ``d`` above the seabed is
differentiated in closed form (`touchdown_jacobian`).
"""

from __future__ import annotations

import numpy as np

from skcable.cable.lines.bvp_model import solve_bvp_line
from skcable.cable.lines.lying import lying_line
from skcable.cable.lines.plane import MODELS, PlaneLine, on_seabed_tolerance
from skcable.cable.lines.seabed import anchor_part, elastic_catenary, grounded_closure
from skcable.cable.lines.segments import Line
from skcable.errors import InputError

__all__ = ["MODELS", "PlaneLine", "is_line", "on_seabed_tolerance", "solve_in_plane"]


# -- the Jacobians of the closed forms (oriented: A the lower end) -----------------------------------
def free_jacobian(k) -> np.ndarray:
    """Nothing touches: ``H_A = H_B``, ``V_A = W - V_B``, a function of ``y_B - y_A``."""
    (k_hh, k_hv), (k_vh, k_vv) = np.asarray(k, dtype=float).tolist()
    return np.array(
        [[k_hh, -k_hv, k_hv], [-k_vh, k_vv, -k_vv], [k_hh, -k_hv, k_hv], [k_vh, -k_vv, k_vv]], dtype=float
    )


def grounded_jacobian(k, friction, H_A) -> np.ndarray:
    """Grounded at A: ``V_A`` constant, ``H_A = max(H - C_B (W - V_B - P_A), 0)``; A and the seabed
    move together (the height columns opposite)."""
    (k_hh, k_hv), (k_vh, k_vv) = np.asarray(k, dtype=float).tolist()
    J = np.array([[0.0] * 3, [0.0] * 3, [k_hh, -k_hv, k_hv], [k_vh, -k_vv, k_vv]])
    if H_A > 0:
        J[0] = J[2] + friction * J[3]
    return J


def touchdown_jacobian(solution) -> np.ndarray:
    r"""The touchdown between the ends of one uniform segment (`elastic_catenary`, ``seabed < 0``).

    Its closure (`skcable.cable.lines.seabed.closure.grounded_closure`) at the lower end's
    height ``d`` above the seabed adds the part hanging from A, whose height
    :math:`u^2/(2EA) + u(1 + H/EA) = w d` (:math:`u = T_1 - H`) gives, at constant ``H``,
    :math:`\partial u/\partial d = w/(1 + T_1/EA)`, :math:`\partial V_1/\partial d = T_1 u_d/V_1`
    and, the grounded length shortened by :math:`V_1/w`,
    :math:`\partial f_x/\partial d = (H - T_1)/(V_1 (1 + T_1/EA))`, :math:`\partial f_z/\partial d = -1`
    (at constant ``dh``). Then ``∂(H, V_B)/∂d = -J⁻¹ ∂f/∂d``, ``V_A = V_1(H, d)``, ``H_A = H``;
    in the heights, ``∂/∂y_B = ∂/∂dh`` and ``∂/∂y_A = ∂/∂d - ∂/∂dh``.
    """
    s = solution
    H, V_B, w, EA, depth = float(s.H), float(s.V_B), float(s.w), float(s.EA), -float(s.seabed)
    k = np.asarray(s.stiffness(), dtype=float)
    if bool(s.heap):  # vertical parts at A and B: V = w l, dV/dheight = w / (1 + w l/EA)
        l_A = float(s.length_to_seabed)
        return np.array([[0.0] * 3, [0.0, w / (1.0 + w * l_A / EA), 0.0], [0.0] * 3, [0.0, 0.0, k[1, 1]]])
    V1, T1, _, _, dV1_dH = anchor_part(H, w, EA, depth)
    j = grounded_closure(s.span, s.dh, w, EA, s.length, 0.0, H, V_B, depth)[2:]
    fx_d, fz_d = (H - T1) / (V1 * (1.0 + T1 / EA)), -1.0
    det = j[0] * j[3] - j[1] * j[2]
    dH_d = -(j[3] * fx_d - j[1] * fz_d) / det
    dV_d = -(-j[2] * fx_d + j[0] * fz_d) / det
    dV1_d = T1 * w / (V1 * (1.0 + T1 / EA))
    row_H = [k[0, 0], dH_d - k[0, 1], k[0, 1]]
    row_V = [k[1, 0], dV_d - k[1, 1], k[1, 1]]
    row_VA = [dV1_dH * r for r in row_H]
    row_VA[1] += dV1_d
    return np.array([row_H, row_VA, row_H, row_V])


# -- the choice of the model ---------------------------------------------------------------------------
def _check_ends(span, dh, seabed):
    """``(gap_A, gap_B, tol)``: the ends' heights above the seabed (m) and the on-seabed tolerance."""
    tol = on_seabed_tolerance(span, dh, seabed)
    gaps = (-seabed, dh - seabed)
    for name, gap in zip(("A", "B"), gaps, strict=True):
        if gap < -tol:
            raise InputError(
                "seabed",
                f"end {name} lies {-gap:.6g} m below the seabed: both ends must be on or above it",
            )
    return max(gaps[0], 0.0), max(gaps[1], 0.0), tol


def _warm(previous, key):
    """The previous solution as a warm start where it is of the same variant."""
    if previous is not None and previous.key == key and key[0] in ("free", "grounded"):
        return previous.solution
    return None


def _line_solve(model_line, span, dh, start):
    return model_line.solve(span, dh) if start is None else model_line.solve(span, dh, start=start)


def solve_in_plane(line, span, dh, *, seabed=None, start=None, bvp=None) -> PlaneLine:
    """Solve ``line`` (a `skcable.cable.Line`) between its ends A = (0, 0) and B = (span, dh).

    Parameters
    ----------
    line : Line
        Its segments run from A to B; its own ``seabed`` is not used (``seabed`` below is),
        its ``friction`` is.
    span, dh : float
        B relative to A (m), ``span > 0`` (checked by the caller).
    seabed : float, optional
        The flat seabed's height relative to A (m), at or below both ends; None: no seabed.
    start : PlaneLine, optional
        A previous solution of this line: a warm start where the same model applies.
    bvp : callable, optional
        ``bvp(line, span, dh, seabed, reason)`` → `PlaneLine` for the scenes no closed form
        takes (`skcable.cable.lines.bvp_model.solve_bvp_line` by default).

    Returns
    -------
    PlaneLine
        With ``model`` and ``reason`` (module docstring).
    """
    if seabed is None:
        return _free(line, span, dh, None, start, "no seabed: the line hangs free")
    gap_A, gap_B, tol = _check_ends(span, dh, seabed)
    reverse = dh < 0
    low, high = (gap_B, gap_A) if reverse else (gap_A, gap_B)
    if low <= tol and high <= tol:
        variant = line.variant(reverse=reverse)
        try:
            solution = lying_line(variant, span)
        except InputError as err:
            return _bvp(bvp, line, span, dh, seabed, f"both ends on the seabed and {err.reason}")
        return PlaneLine(
            span,
            dh,
            seabed,
            solution,
            reverse,
            "on the seabed",
            "both ends on the seabed: the line lies on it",
            ("on the seabed",),
            solution.jacobian,
            variant,
        )
    if low <= tol:
        return _grounded(line, span, dh, seabed, reverse, start, bvp)
    free = _free(line, span, dh, seabed, start, "the lower end above the seabed and the line clear of it")
    floor = -low  # the seabed below the lower end, in the solution's axes
    if free.solution.lowest_height() >= floor - tol:
        return free
    return _touchdown(line, span, dh, seabed, reverse, low, bvp)


def _free(line, span, dh, seabed, start, reason) -> PlaneLine:
    reverse = dh < 0
    key = ("free", reverse)
    variant = line.variant(reverse=reverse)
    solution = _line_solve(variant, span, abs(dh), _warm(start, key))
    return PlaneLine(
        span,
        dh,
        seabed,
        solution,
        reverse,
        "free",
        reason,
        key,
        lambda: free_jacobian(solution.stiffness()),
        variant,
    )


def _grounded(line, span, dh, seabed, reverse, start, bvp) -> PlaneLine:
    key = ("grounded", reverse)
    variant = line.variant(reverse=reverse, contact=True)
    try:
        solution = _line_solve(variant, span, abs(dh), _warm(start, key))
    except InputError as err:
        if err.argument not in ("attachments", "segments"):
            raise
        return _bvp(bvp, line, span, dh, seabed, f"the lower end on the seabed and {err.reason}")
    if not solution.state.contact:
        reason = "the lower end on the seabed and the line leaving it upwards: it hangs free"
        return PlaneLine(
            span,
            dh,
            seabed,
            solution,
            reverse,
            "free",
            reason,
            key,
            lambda: free_jacobian(solution.stiffness()),
            variant,
        )
    reason = "the lower end on the seabed: the line rests on it up to a touchdown (Jonkman's closed form)"
    if solution.heap:
        reason = "the lower end on the seabed and the line longer than its L-shape: its slack lies in a heap"
    friction, H_A = variant.friction, solution.H_A
    return PlaneLine(
        span,
        dh,
        seabed,
        solution,
        reverse,
        "grounded",
        reason,
        key,
        lambda: grounded_jacobian(solution.stiffness(), friction, H_A),
        variant,
    )


def _touchdown(line, span, dh, seabed, reverse, depth, bvp) -> PlaneLine:
    """The lower end ``depth`` above the seabed, the free line below it: a touchdown between the ends."""
    variant = line.variant(reverse=reverse)
    uniform = len(variant.segments) == 1 and not variant.attachments and variant.segments[0].w > 0
    if not uniform:
        reason = "the line touches down between its ends and is not one uniform segment (no closed form)"
        return _bvp(bvp, line, span, dh, seabed, reason)
    if line.friction > 0:
        raise InputError(
            "friction",
            f"the line touches down between its ends (both {depth:.6g} m and more above the seabed): static "
            "friction there depends on the history of the motion; give the line friction=0",
        )
    seg = variant.segments[0]
    solution = elastic_catenary(span, abs(dh), seg.w, seg.EA, length=seg.length, seabed=-depth)
    reason = "the lower end above the seabed and the line reaching it: it hangs down, rests on it and rises"
    return PlaneLine(
        span,
        dh,
        seabed,
        solution,
        reverse,
        "touchdown between the ends",
        reason,
        ("touchdown",),
        lambda: touchdown_jacobian(solution),
        variant,
    )


def _bvp(bvp, line, span, dh, seabed, reason) -> PlaneLine:
    return (solve_bvp_line if bvp is None else bvp)(line, span, dh, seabed, reason)


def is_line(model) -> bool:
    """Whether ``model`` is a `skcable.cable.Line` (solved here) rather than another line model."""
    return isinstance(model, Line)
