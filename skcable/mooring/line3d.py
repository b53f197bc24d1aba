r"""A line between two points in space hangs in its vertical plane.

Anchor :math:`\mathbf a` and fairlead :math:`\mathbf b` (3-vectors, z up, m). The
line lies in the vertical plane through them: horizontal distance
:math:`r = |\mathbf b_{xy} - \mathbf a_{xy}| > 0`, unit horizontal direction
:math:`\mathbf e = (\mathbf b_{xy} - \mathbf a_{xy})/r`, height :math:`dh = b_z - a_z`.
Its 2-D model, solved for ``(span, dh) = (r, dh)``, gives the fairlead forces
``H, V_B`` and the anchor forces ``H_A, V_A``; the force the line exerts on the
fairlead and on the anchor are

.. math:: \mathbf F_b = (-H\,\mathbf e,\; -V_B), \qquad \mathbf F_a = (H_A\,\mathbf e,\; -V_A)

(``V_A`` is the upward reaction at A: the line pulls the anchor down by it). The
difference :math:`(H - H_A)\,\mathbf e` is the friction the seabed carries, and
:math:`\mathbf F_a + \mathbf F_b = (0, 0, -W) + \mathbf R`: the forces the line
exerts on its ends balance its weight ``W`` less what the seabed carries, ``R``.

The 3x3 fairlead stiffness in global axes, :math:`K = -\partial\mathbf F_b/\partial\mathbf b`
with the anchor fixed, follows from the 2x2 stiffness
:math:`k = \partial(H, V_B)/\partial(r, dh)` and :math:`\partial\mathbf e/\partial\mathbf b_{xy}
= (I - \mathbf e\mathbf e^T)/r`:

.. math::
    K = \begin{pmatrix} k_{HH}\,\mathbf e\mathbf e^T + \frac{H}{r}(I_2 - \mathbf e\mathbf e^T)
        & k_{HV}\,\mathbf e \\ k_{VH}\,\mathbf e^T & k_{VV} \end{pmatrix},

the radial block from the line's own stiffness and the transverse (pendulum) term
:math:`H/r`: the standard result of quasi-static mooring analysis (J.M. Jonkman,
"Dynamics modeling and loads analysis of an offshore floating wind turbine", NREL,
2007; MoorPy, M. Hall's quasi-static mooring code at NREL, builds the same matrix).
It has the sign of the 2-D stiffness: the growth of the reaction the fairlead
must supply as it moves (MoorPy's convention), positive semi-definite for a line
in tension.

A *line model* is any object with ``solve(span, dh)`` returning a 2-D solution
with ``H, V_A, V_B, H_A, length, length_on_seabed, x_touchdown``, ``x_of_s(s)``,
``y_of_s(s)``, ``T_of_s(s)`` (unstretched arc length ``s`` from A), ``stiffness()``
and ``tensions()`` (a pandas DataFrame, one row per segment). A model may also take
a warm start, ``solve(span, dh, start=previous_solution)`` (as `skcable.mooring.Line`
does): the 3-D layer then passes the line's previous solution (`takes_start` tells).
"""

from __future__ import annotations

import inspect
import math
from functools import cached_property, lru_cache

import numpy as np

from skcable._checks import point, whole
from skcable._show import Shown
from skcable.errors import InputError

__all__ = [
    "Line3D",
    "line_3d",
    "line_model",
    "point",
    "solve_in_plane_of_ends",
    "solve_in_space",
    "takes_start",
]


def line_model(name: str, model):
    """``model`` if it is a line model (it has a callable ``solve``), else `InputError` naming ``name``."""
    if not callable(getattr(model, "solve", None)):
        raise InputError(
            name,
            "must be a line model with a solve(span, dh) method (a mooring.Line, say), got "
            f"{type(model).__name__}",
        )
    return model


def _finite(name: str, value) -> float:
    value = float(value)
    if not math.isfinite(value):
        raise InputError(name, f"the line model returned a non-finite value {value!r}")
    return value


class Line3D(Shown):
    """A line solved between an anchor and a fairlead in space (see module docstring).

    Attributes
    ----------
    anchor, fairlead : ndarray, shape (3,)
        The end points (m), z up.
    span, dh : float
        Horizontal distance ``r`` (m, > 0) and height of the fairlead above the anchor (m).
    direction : ndarray, shape (3,)
        Unit horizontal vector ``e`` from the anchor towards the fairlead.
    solution : object
        The 2-D solution of the line model in the line's plane (A at (0, 0)).
    H, V_B, H_A, V_A : float
        Fairlead and anchor forces of the 2-D solution (N).
    force_on_fairlead, force_on_anchor : ndarray, shape (3,)
        ``F_b = (-H e, -V_B)`` and ``F_a = (H_A e, -V_A)`` (N), global axes.
    tension_at_fairlead, tension_at_anchor : float
        ``|F_b|`` and ``|F_a|`` (N).
    """

    def __init__(self, model, anchor, fairlead, solution):
        self.model, self.anchor, self.fairlead, self.solution = model, anchor, fairlead, solution
        dx, dy, dz = (fairlead - anchor).tolist()
        self.span = r = math.hypot(dx, dy)
        self.dh = dz
        ex, ey = dx / r, dy / r
        self.direction = np.array([ex, ey, 0.0])
        self.H = H = _finite("model", solution.H)
        self.V_B = V_B = _finite("model", solution.V_B)
        self.H_A = H_A = _finite("model", solution.H_A)
        self.V_A = V_A = _finite("model", solution.V_A)
        self.force_on_fairlead = np.array([-H * ex, -H * ey, -V_B])
        self.force_on_anchor = np.array([H_A * ex, H_A * ey, -V_A])
        self.tension_at_fairlead = math.hypot(H * ex, H * ey, V_B)
        self.tension_at_anchor = math.hypot(H_A * ex, H_A * ey, V_A)

    @property
    def end_forces(self) -> np.ndarray:
        """The line's forces on its ends, anchor then fairlead (N), shape (2, 3)."""
        return np.array([self.force_on_anchor, self.force_on_fairlead])

    @cached_property
    def _k2(self) -> np.ndarray:
        k2 = np.asarray(self.solution.stiffness(), dtype=float)
        if k2.shape != (2, 2) or not all(map(math.isfinite, k2.flat)):
            raise InputError("model", f"the line model's stiffness() must be a finite 2x2 matrix, got {k2!r}")
        return k2

    def stiffness(self) -> np.ndarray:
        """Fairlead stiffness ``K = -∂F_b/∂b`` (N/m), shape (3, 3), global axes, anchor fixed.

        Radial and vertical terms from the 2-D ``stiffness()`` ``∂(H, V_B)/∂(span, dh)``,
        transverse term ``H/r`` (see the module docstring for the matrix).
        """
        (k_hh, k_hv), (k_vh, k_vv) = self._k2.tolist()
        ex, ey = float(self.direction[0]), float(self.direction[1])
        exx, exy, eyy = ex * ex, ex * ey, ey * ey
        c = self.H / self.span
        return np.array(
            [
                [k_hh * exx + c * (1.0 - exx), k_hh * exy + c * (0.0 - exy), k_hv * ex],
                [k_hh * exy + c * (0.0 - exy), k_hh * eyy + c * (1.0 - eyy), k_hv * ey],
                [k_vh * ex, k_vh * ey, k_vv],
            ]
        )

    def to_global(self, x, y) -> np.ndarray:
        """Points ``(x, y)`` of the line's plane (A at the origin, y up) in global axes, shape (n, 3)."""
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return self.anchor + np.multiply.outer(x, self.direction) + np.multiply.outer(y, [0.0, 0.0, 1.0])

    def profile(self, n: int = 101) -> np.ndarray:
        """The line at ``n`` material points equally spaced in unstretched arc length: positions
        ``(n, 3)`` in global axes (m), from the model's ``x_of_s, y_of_s``."""
        return self.profile_with_tension(n)[0]

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from the anchor (the model's ``T_of_s``)."""
        return self.solution.T_of_s(s)

    def profile_with_tension(self, n: int = 101) -> tuple[np.ndarray, np.ndarray]:
        """``(points, tension)``: `profile` ``(n, 3)`` (m) and the tension there ``(n,)`` (N), from the
        model's ``x_of_s, y_of_s, T_of_s`` (what ``profile`` returned before 0.2)."""
        n = whole("n", n, 2)
        s = np.linspace(0.0, float(self.solution.length), n)
        points = self.to_global(self.solution.x_of_s(s), self.solution.y_of_s(s))
        tension = np.asarray(self.solution.T_of_s(s), dtype=float)
        if not (np.isfinite(points).all() and np.isfinite(tension).all()):
            raise InputError("model", "the line model returned a non-finite profile")
        return points, np.broadcast_to(tension, (int(n),)).copy()

    def tensions(self):
        """The model's tension table (pandas DataFrame, one row per segment)."""
        return self.solution.tensions()

    def __repr__(self):
        return (
            f"Line3D(anchor={self.anchor.tolist()}, fairlead={self.fairlead.tolist()}, "
            f"H={self.H:.6g}, V_B={self.V_B:.6g})"
        )


@lru_cache(maxsize=256)
def _solve_takes_start(solve) -> bool:
    try:
        parameters = inspect.signature(solve).parameters.values()
    except (TypeError, ValueError):  # a callable without an introspectable signature
        return False
    return any(
        (p.name == "start" and p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)) or p.kind is p.VAR_KEYWORD
        for p in parameters
    )


def takes_start(model) -> bool:
    """Whether ``model.solve`` accepts a warm start ``start=`` (a keyword or ``**kwargs``).

    Inspected once per ``solve`` function (cached): third-party line models with
    ``solve(span, dh)`` only are called without it.
    """
    solve = model.solve
    solve = getattr(solve, "__func__", solve)
    try:
        return _solve_takes_start(solve)
    except TypeError:  # an unhashable callable: inspected each time
        return _solve_takes_start.__wrapped__(solve)


def line_3d(model, anchor, fairlead, start=None) -> Line3D:
    """Solve a line model between an anchor and a fairlead in space.

    Parameters
    ----------
    model : Line or object
        A `skcable.mooring.Line`: solved by the model it needs, chosen per line and reported
        (`skcable.mooring.choice`: the closed form, the closed form with its axial laws'
        elongation integrals, or the 3-D line BVP in a current or on a shaped seabed). Or any
        line model: ``model.solve(span, dh)`` returns the 2-D solution (see the module
        docstring for the attributes it must have).
    anchor, fairlead : array_like, shape (3,)
        End points (m), z up. The fairlead must not lie on the anchor's vertical.
    start : LineInSea, Line3D or 2-D solution, optional
        A previous solution of the same model (typically at a nearby fairlead),
        passed on as ``model.solve(span, dh, start=...)``: a warm start for Newton's
        method (see `skcable.mooring.Line.solve`); the model must accept it
        (`takes_start`).

    Returns
    -------
    LineInSea or Line3D
        For a `skcable.mooring.Line` a `skcable.mooring.LineInSea`: the end forces, ``profile(n)``
        ``(n, 3)`` over the unstretched arc length, ``T_of_s(s)``, the 3x3 fairlead
        ``stiffness()``, ``model`` (which model ran, why, its estimated error) and
        ``equilibrium_residual`` (and, from the closed forms, the `Line3D` attributes). For
        another line model a `Line3D`: forces on both ends in global axes and the 3x3 fairlead
        ``stiffness()``.

    Raises
    ------
    InputError
        A ``model`` without a ``solve`` method; a point that is not 3 finite numbers, or
        a fairlead directly above or below the anchor (``r = 0``: the line's plane, the horizontal direction
        and the transverse stiffness ``H/r`` are undefined); a ``start`` given to a
        model whose ``solve`` takes none; errors of the model.
    ConvergenceError
        The model's solver did not converge.
    """
    line_model("model", model)
    a = point("anchor", anchor)
    b = point("fairlead", fairlead)
    r = math.hypot(float(b[0] - a[0]), float(b[1] - a[1]))
    if not r > 1e-9 * max(1.0, float(np.abs(b - a).max())):
        raise InputError(
            "fairlead",
            f"lies on the vertical of the anchor (horizontal distance {r:.3g} m): the line's vertical "
            "plane is undefined; give a fairlead offset horizontally from the anchor",
        )
    from skcable.mooring.segments import Line

    if isinstance(model, Line):  # the model it needs, reported (`skcable.mooring.choice`)
        from skcable.mooring.choice import solve_line_in_sea

        return solve_line_in_sea(model, a, b, r, start, solve_in_plane_of_ends)  # type: ignore[return-value]
    if start is not None and not takes_start(model):
        raise InputError("start", f"the line model {type(model).__name__}.solve takes no start= argument")
    return solve_in_space(model, a, b, r, start)


def solve_in_space(model, anchor, fairlead, span, start=None) -> Line3D:
    """`line_3d` on checked arguments: float 3-vectors ``anchor`` and ``fairlead`` at the
    horizontal distance ``span > 0``, and a ``start`` the model takes (or None).

    For callers that checked them once (`skcable.mooring.MooringSystem` in its Newton loop). A
    `skcable.mooring.Line` in a current, over a shaped seabed or with a nonlinear axial law is solved
    by the model it needs (`skcable.mooring.choice`: a `LineInSea`, with the force on the
    fairlead and the 3 × 3 ``stiffness()`` of a `Line3D`).
    """
    if getattr(model, "in_space", None) is not None or getattr(model, "nonlinear", False):
        from skcable.mooring.choice import solve_line_in_sea

        return solve_line_in_sea(model, anchor, fairlead, span, start, solve_in_plane_of_ends)  # type: ignore[return-value]
    return solve_in_plane_of_ends(model, anchor, fairlead, span, start)


def solve_in_plane_of_ends(model, anchor, fairlead, span, start=None) -> Line3D:
    """`solve_in_space` by the line model's own ``solve(span, dh)`` in the vertical plane of the
    ends, whatever the model."""
    dh = float(fairlead[2] - anchor[2])
    if start is None:
        solution = model.solve(span, dh)
    else:
        solution = model.solve(span, dh, start=start.solution if isinstance(start, Line3D) else start)
    return Line3D(model, anchor, fairlead, solution)
