"""The closed-form start of a line BVP: the elastic catenary of the line's mean weight and stiffness.

`closed_form_start` gives the first iterate (positions and tensions on a problem's dofs),
`start_form` the shape that grades the first mesh (`skcable.cable.bvp.line.mesh.start_nodes`):
the free elastic catenary (H. M. Irvine, "Cable Structures", MIT Press, 1981, ch. 2)
or, where it dips below the seabed, Jonkman's grounded one on a flat seabed at the anchor's
level (J.M. Jonkman, NREL, 2007), its positions lifted onto the seabed.
"""

from __future__ import annotations

import numpy as np

from skcable.cable._elastic import elastic_catenary as free_catenary
from skcable.cable.lines.seabed import elastic_catenary
from skcable.errors import ConvergenceError, InputError

__all__ = ["closed_form_start", "start_form"]


def _closed_form(problem):
    """``(x, y, T, form)``: the start on the problem's dofs, and ``form = (H, w, s_v, grounded)``,
    the catenary's horizontal force, weight and vertical force ``w (s - s_v)`` (zero where
    grounded)."""
    span, dh, L = problem.span, problem.dh, problem.L
    w = problem.weight / L
    if not w > 0:
        raise InputError("segments", f"the line's mean weight must be > 0 (downward), got {w:g} N/m")
    c = problem.compliance / L
    EA = 1.0 / c if c > 0 else 1e6 * w * L
    s_dof, s_t = problem.basis.doflocs[0], problem.tbasis.doflocs[0]
    free = free_catenary(span, dh, w, EA, length=L)
    u_a = -free.V_A / free.H

    def free_x(s):
        return free.H * s / EA + free.H / w * (np.arcsinh(u_a + w * s / free.H) - np.arcsinh(u_a))

    def free_y(s):
        t0, t1 = np.hypot(1.0, u_a), np.hypot(1.0, u_a + w * s / free.H)
        return (free.H / w) * (t1 - t0) + (-free.V_A * s + 0.5 * w * s * s) / EA

    x, y = free_x(s_dof), free_y(s_dof)
    T = np.hypot(free.H, -free.V_A + w * s_t)
    form = (float(free.H), w, float(free.V_A) / w, False)
    bed = problem.seabed
    if bed is not None and np.any(y < bed(x)):
        level = min(float(bed(np.array([0.0]))[0]), 0.0)
        level = min(level, dh - 1e-3 * abs(span))
        try:
            grounded = elastic_catenary(span, dh, w, EA, length=L, seabed=level)
            if np.any(grounded.heap):  # H = 0: the arc form has no tension to solve for
                raise InputError(
                    "length",
                    "leaves slack line lying in a heap on the seabed (H = 0): elastic_catenary(seabed=...) "
                    "and cable.Line return that state",
                )
            x, y, T = grounded.x_of_s(s_dof), grounded.y_of_s(s_dof), grounded.T_of_s(s_t)
            form = (float(grounded.H), w, L - float(grounded.V_B) / w, True)
        except (InputError, ConvergenceError):
            if bed.flat is not None:  # on a flat seabed the closed form's refusal (slack in a heap) holds
                raise
        y = np.maximum(y, bed(x))  # a curved seabed: the free line lifted onto it, if nothing better
    return x, y, T, form


def start_form(problem):
    """``(H, w, s_v, grounded)`` of the start's catenary: its vertical force is ``w (s - s_v)``,
    zero where it is grounded."""
    return _closed_form(problem)[3]


def closed_form_start(problem):
    """The first iterate on ``problem``'s dofs: ``[x, y, T]``, the ends at A and B exactly."""
    x, y, T, _ = _closed_form(problem)
    x[problem.end_a], y[problem.end_a] = 0.0, 0.0
    x[problem.end_b], y[problem.end_b] = problem.span, problem.dh
    return np.concatenate([x, y, T])
