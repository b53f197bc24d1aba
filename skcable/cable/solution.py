"""Common interface of every suspended-cable solution (conventions: `skcable.cable`).

Every solver broadcasts over its arguments: a solution holds scalars for
scalar input, arrays for array input, and its methods broadcast ``x``
against that shape.

Every solution satisfies `skcable.results.CableResult`: end forces named by end (``H_A``,
``V_A``, ``H_B``, ``V_B``, ``T_A``, ``T_B``), ``xy(s)`` and ``T_of_s(s)`` at unstretched arc
length ``s`` from A, ``profile(n)``, ``stiffness()``, ``tensions()``, ``to_frame()``,
``to_vtk(path)``; ``y(x)``, ``T(x)`` and ``slope(x)`` take the abscissa ``x`` along the span.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from skcable._checks import real, require, whole
from skcable._show import Shown, counted, quantity
from skcable._xp import PicklesBackend, namespace
from skcable.cable._special import largest_abs
from skcable.cable.arc_samples import arc_samples
from skcable.errors import ConvergenceError, InputError
from skcable.results import ProfileMixin

__all__ = ["CableSolution", "checked", "matrix_2x2"]

#: Largest relative residual a solver may hand back without raising.
ACCEPT = 1e-9
#: Which attribute of a solution each constraint keyword fixes.
ATTRIBUTE_OF = {"length": "length", "sag": "sag", "H": "H", "low": "y_low", "T_max": "T_max"}
_SHOWN = ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low", "x_vertex", "y_vertex")
#: The forces among them (an overflow there is blamed on the load unless a force is the constraint).
_FORCES = frozenset(("H", "V_A", "V_B", "T_A", "T_B"))


def matrix_2x2(k11, k12, k21, k22):
    """Stack four broadcastable entries into an array of shape ``(*shape, 2, 2)``."""
    return np.stack(
        [np.stack(np.broadcast_arrays(k11, k12), -1), np.stack(np.broadcast_arrays(k21, k22), -1)], -2
    )


class CableSolution(PicklesBackend, Shown):
    """Base of the suspended-cable solutions (`skcable.results.CableResult`).

    Subclasses define ``H, V_A, V_B, T_A, T_B, length, sag, x_low, y_low``,
    the methods ``y(x)``, ``T(x)``, ``slope(x)`` (``x`` in m along the span),
    ``xy(s)``, ``T_of_s(s)`` (``s`` in m of unstretched arc length from A),
    ``stiffness()`` and ``_residuals()``. ``H_A`` and ``H_B`` are ``H`` unless a
    subclass says otherwise: under vertical loads the horizontal tension is
    the same all along the cable.
    ``x_low, y_low`` is the lowest point *of the cable*, in ``[0, span]``: a
    support when the profile rises or falls all along the span. The closed
    forms also define ``x_vertex, y_vertex``, the vertex (horizontal tangent)
    of the catenary or parabola the cable is a piece of, which may lie outside
    the span; the two coincide when the vertex lies between the supports.
    """

    # what each subclass defines, on the instance or as a property: a float for one scene, an
    # array of the broadcast shape for many (annotations only: no class attribute, `_shown`)
    span: Any
    dh: Any
    w: Any
    H: Any
    V_A: Any
    V_B: Any
    T_A: Any
    T_B: Any
    length: Any
    constraint: tuple[str, Any]  # the keyword the user fixed and its value

    if TYPE_CHECKING:  # every subclass defines them (the ``x`` functions of the class docstring)

        def y(self, x) -> Any: ...
        def slope(self, x) -> Any: ...
        def T(self, x) -> Any: ...

    # `ProfileMixin`'s methods, not its class as a base: subclasses that also list the mixin
    # (the finite-element solutions) keep a consistent method order
    profile = ProfileMixin.profile
    to_frame = ProfileMixin.to_frame
    tensions = ProfileMixin.tensions

    @cached_property
    def H_A(self):
        """Horizontal tension at A (N): ``H``, the same all along under vertical loads."""
        return self.H

    @cached_property
    def H_B(self):
        """Horizontal tension at B (N): ``H``, the same all along under vertical loads."""
        return self.H

    def _arc(self, s):
        """``s`` checked to lie in [0, length]."""
        s = real("s", s)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def _abscissa(self, x):
        """``x`` checked to lie in [0, span]."""
        x = real("x", x)
        require("x", (x >= 0) & (x <= self.span), "must lie in [0, span]", x)
        return x

    def xy(self, s):  # pragma: no cover - abstract
        """Positions ``(..., 2)`` (m) at unstretched arc length ``s`` (m) from A."""
        raise NotImplementedError

    def T_of_s(self, s):  # pragma: no cover - abstract
        """Tension (N) at unstretched arc length ``s`` (m) from A."""
        raise NotImplementedError

    def stiffness(self):  # pragma: no cover - abstract
        """Fairlead stiffness ``∂(H_B, V_B)/∂(span, dh)`` with A fixed (N/m), ``(*shape, 2, 2)``."""
        raise NotImplementedError

    def finite_beyond_residual(self) -> bool:
        """Whether the shown attributes the residual does not evaluate (the length and the
        vertex of the closed forms) are finite floats (a subclass may bound them instead)."""
        return all(_finite(getattr(self, name)) for name in _BEYOND_RESIDUAL)

    def residual(self) -> float:
        """Largest relative residual of equilibrium, closure and constraint.

        Each term is evaluated from the solution's own state: closure of the
        profile at B, vertical equilibrium of the whole cable, the direction
        of the end tensions, and the constraint the user gave (length, sag,
        H, lowest point or maximum tension). The largest over all terms and
        all broadcast elements is returned.
        """
        values = [largest_abs(r) for r in self._residuals()]
        return float("nan") if any(v != v for v in values) else max(values)

    def _residuals(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def _common_residuals(self, xp):
        """End tensions along the tangent, and the user's constraint met.

        ``T² = H² + V²`` as ``((1 - t)(1 + t) - v²)/2`` with ``t = H/T``, ``v = V/T``
        (``≈ 1 - hypot(H, V)/T``, without a hypot: 3 ulps of it at most)."""
        H_A = getattr(self, "H_A", None)
        H_A = self.H if H_A is None else H_A
        H_B = getattr(self, "H_B", None)  # differ from H only under horizontal loads
        H_B = H_A if H_B is None else H_B
        out = []
        for T, H, V in ((self.T_A, H_A, self.V_A), (self.T_B, H_B, self.V_B)):
            t, v = H / T, V / T
            out.append(0.5 * ((1.0 - t) * (1.0 + t) - v * v))
        name, value = self.constraint
        achieved = getattr(self, ATTRIBUTE_OF[name])
        # the lowest point against the chord, or against itself when deeper
        scale = xp.hypot(self.span, self.dh) + xp.abs(value) if name == "low" else value
        out.append((achieved - value) / scale)
        return out

    def __repr__(self):
        name = type(self).__name__
        if np.ndim(self.H) != 0:  # every scene's numbers, or their ranges (`skcable._show`)
            shown = ", ".join(
                quantity(k, getattr(self, k)) for k in _shown(self) if k in _FORCES | {"length", "sag"}
            )
            scenes = counted(np.shape(self.H), "scene")
            return f"{name}({scenes}, constraint {self.constraint[0]!r}: {shown})"
        # instance attributes (H, V_A, length of the elastic forms) as well as the class's
        shown = ", ".join(f"{k}={float(getattr(self, k)):.9g}" for k in _shown(self))
        return f"{name}(span={self.span:g}, dh={self.dh:g}, w={self.w:g}: {shown})"

    @cached_property
    def T_max(self):
        """Largest tension in the cable (at the higher support)."""
        return namespace(self.T_A, self.T_B).maximum(self.T_A, self.T_B)

    def samples(self, n: int = 201) -> dict:
        """One scene's profile at ``n`` equally spaced x (the input to `to_vtk`).

        Returns a dict: ``xy`` (n, 2) in m, ``tension`` (N), ``angle`` (rad
        above the horizontal) and ``load`` (n, 2): the distributed load in N
        per metre of unstretched cable, y up (concentrated loads not included).
        """
        x = np.linspace(0.0, float(self.span), whole("n", n, 2))
        slope = np.asarray(self.slope(x), dtype=float)
        weight = np.broadcast_to(self.weight_per_length(x, slope), x.shape)
        return arc_samples(x, self.y(x), self.T(x), np.arctan(slope), weight)

    def weight_per_length(self, x, slope):
        """Downward distributed load per unit unstretched cable length (N/m) at ``x``: ``w``, the
        weight of the forms under their own weight (the others say theirs)."""
        return self.w + 0.0 * slope

    def to_vtk(self, path, n: int = 201, *, point_data=None):
        """Write the profile as a VTK polyline (see `skcable.io.cable_mesh`, which also takes the
        user's ``point_data``); returns the path."""
        from skcable.io import cable_mesh, write

        return write(cable_mesh(self, n, point_data=point_data), path)

    def points(self, n: int = 101) -> np.ndarray:
        """Profile sampled at ``n`` equally spaced x: array ``(*shape, n, 2)``."""
        x = np.multiply.outer(np.linspace(0.0, 1.0, whole("n", n, 2)), self.span)  # (n, *shape)
        xy = np.stack([x, np.broadcast_to(self.y(x), x.shape)], axis=-1)
        return np.moveaxis(xy, 0, -2)


#: The shown attributes a closed form's residual does not evaluate (a finite
#: residual implies finite forces and, where it enters, length). The rest of
#: ``_SHOWN`` is bounded by these (0 <= sag <= length; the lowest point lies
#: between the supports and the vertex).
_BEYOND_RESIDUAL = ("length", "x_vertex", "y_vertex")
_CHECKED = ("H", "V_A", "V_B", "T_A", "T_B", *_BEYOND_RESIDUAL)


def _finite(value) -> bool:
    return bool(np.isfinite(value).all()) if isinstance(value, np.ndarray) else math.isfinite(value)


def representable(solution: CableSolution, argument: str, load: str = "w") -> None:
    """Raise `InputError` if a force, the length or the vertex of a
    closed-form ``solution`` is not a finite float (the other shown
    attributes are bounded by them).

    Overflowing forces are blamed on ``load`` unless the constraint is itself
    a force (``H``, ``T_max``); everything else on ``argument``.
    """
    force_constraint = solution.constraint[0] in ("H", "T_max")
    for name in _CHECKED:
        try:
            finite = _finite(getattr(solution, name))
        except (OverflowError, ZeroDivisionError):  # math on Python floats raises, NumPy gives inf
            finite = False
        if not finite:
            blame = load if name in _FORCES and not force_constraint else argument
            raise InputError(blame, f"puts {name} outside the range of a float (the data are too extreme)")


def checked_closed_form(solution: CableSolution, argument: str, history=(), load: str = "w") -> CableSolution:
    """`checked` for a closed form: a result outside the range of a float
    raises `InputError` naming ``argument`` (or ``load``), a residual
    above `ACCEPT` `ConvergenceError`."""
    try:
        residual = solution.residual()
        if residual <= ACCEPT and solution.finite_beyond_residual():
            return solution
    except (OverflowError, ZeroDivisionError):
        pass
    representable(solution, argument, load)  # raises if a result is not finite
    return checked(solution, history)


def _shown(solution) -> tuple[str, ...]:
    """The `_SHOWN` names a solution has: its class's, and its instance attributes (the
    elastic forms store ``H``, ``V_A`` and ``length`` on the instance)."""
    cls, own = type(solution), vars(solution)
    return tuple(name for name in _SHOWN if name in own or hasattr(cls, name))


def checked(solution, history=(), accept: float = ACCEPT):
    """Return ``solution`` if its residual is below ``accept`` (`ACCEPT`), else raise."""
    residual = solution.residual()
    if not residual <= accept:
        raise ConvergenceError(
            f"{type(solution).__name__}: residual {residual:.3e} above {accept:.0e} after the solver stopped",
            history,
        )
    return solution
