r"""Current profiles: the water's horizontal velocity :math:`\mathbf U(z)` at each height.

A current is a horizontal vector field of the height ``z`` alone (m, up; the water surface at
``z = surface``, 0 by default): ``velocity(z)`` gives :math:`(U_x, U_y)` (m/s), shape
``(2, *z.shape)``, and ``gradient(z)`` its derivative :math:`d\mathbf U/dz` (1/s), which a
cable term's tangent needs (`skcable.bvp.terms.CurrentDrag`). Three kinds:

- `UniformCurrent`: one vector at every height;
- `ProfileCurrent`: a callable ``z -> (Ux, Uy)`` (a sheared current), with its derivative if
  the user has it, else central differences of step ``1e-6`` m (the derivative only enters
  the tangent: the solution is the callable's own);
- `TabulatedCurrent`: a table of velocities at depths below the surface, interpolated
  linearly in depth and held at its end values beyond the table (as MoorDyn's and MoorPy's
  current profiles: M. Hall, "MoorDyn user's guide", 2017; MoorPy's ``System.current``).

`current_of` turns what a user gives (None, a vector, a callable, a `Current`) into one.
Every velocity returned is finite, or the call raises `skcable.InputError` naming the
argument.
"""

from __future__ import annotations

import numpy as np

from skcable._checks import real
from skcable.errors import InputError

__all__ = ["Current", "ProfileCurrent", "TabulatedCurrent", "UniformCurrent", "current_of"]


class Current:
    """Base of the current profiles: ``velocity(z)`` and ``gradient(z)``, both ``(2, *z.shape)``
    (m/s and 1/s), ``z`` the height (m, up)."""

    def velocity(self, z) -> np.ndarray:
        """The horizontal velocity ``(Ux, Uy)`` (m/s) at heights ``z`` (m): ``(2, *z.shape)``."""
        raise NotImplementedError

    def gradient(self, z) -> np.ndarray:
        """``dU/dz`` (1/s) at heights ``z`` (m): ``(2, *z.shape)``."""
        raise NotImplementedError


def _vector(name: str, value) -> np.ndarray:
    v = real(name, value)
    if np.shape(v) != (2,):
        raise InputError(name, f"must be a horizontal vector (Ux, Uy) in m/s, got {value!r}")
    return np.array(v, dtype=float)


class UniformCurrent(Current):
    """The same horizontal velocity ``(Ux, Uy)`` (m/s) at every height."""

    def __init__(self, velocity):
        self.U = _vector("current", velocity)

    def velocity(self, z):
        z = np.asarray(z, dtype=float)
        return np.broadcast_to(self.U.reshape(2, *([1] * z.ndim)), (2, *z.shape)).copy()

    def gradient(self, z):
        return np.zeros((2, *np.shape(z)))

    def __repr__(self):
        return f"UniformCurrent(({self.U[0]:g}, {self.U[1]:g}) m/s)"


def _components(name: str, out, shape) -> np.ndarray:
    """A callable's ``(Ux, Uy)`` as a finite float array ``(2, *shape)``."""
    try:
        parts = [np.broadcast_to(np.asarray(part, dtype=float), shape) for part in out]
    except (TypeError, ValueError) as exc:
        raise InputError(
            name, f"must return (Ux, Uy), each broadcastable to z's shape {shape}: {exc}"
        ) from exc
    if len(parts) != 2:
        raise InputError(name, f"must return two components (Ux, Uy), got {len(parts)}")
    values = np.array(parts)
    if not np.all(np.isfinite(values)):
        raise InputError(name, "returned non-finite values")
    return values


class ProfileCurrent(Current):
    """A current given as a callable of the height: ``function(z) -> (Ux, Uy)`` (m/s), each
    component broadcastable to ``z``'s shape; ``derivative(z) -> (dUx/dz, dUy/dz)`` (1/s) if
    given, else central differences of ``function`` with a step of ``1e-6`` m."""

    STEP = 1e-6

    def __init__(self, function, derivative=None):
        if not callable(function):
            raise InputError("current", f"must be callable z -> (Ux, Uy), got {function!r}")
        if derivative is not None and not callable(derivative):
            raise InputError("derivative", f"must be callable z -> (dUx/dz, dUy/dz), got {derivative!r}")
        self.function, self.derivative = function, derivative

    def velocity(self, z):
        z = np.asarray(z, dtype=float)
        return _components("current", self.function(z), z.shape)

    def gradient(self, z):
        z = np.asarray(z, dtype=float)
        if self.derivative is not None:
            return _components("derivative", self.derivative(z), z.shape)
        h = self.STEP
        return (self.velocity(z + h) - self.velocity(z - h)) / (2.0 * h)

    def __repr__(self):
        given = "given" if self.derivative is not None else "central differences"
        return f"ProfileCurrent({getattr(self.function, '__name__', 'callable')}, derivative {given})"


class TabulatedCurrent(Current):
    """A current tabulated over depth below the surface: ``velocities[k] = (Ux, Uy)`` (m/s) at
    ``depths[k]`` (m, strictly increasing), linear in depth between rows and held at the first
    (last) row above (below) the table; the depth of a point at height ``z`` is
    ``surface - z``. The derivative is the table's slope, piecewise constant (the current's
    kinks make a line's Newton semismooth there)."""

    def __init__(self, depths, velocities, *, surface: float = 0.0):
        d = real("depths", depths)
        if np.ndim(d) != 1 or np.size(d) < 2:
            raise InputError("depths", f"must be a 1-D table of at least two depths, got {depths!r}")
        if not np.all(np.diff(d) > 0):
            k = int(np.argmin(np.diff(d) > 0))
            raise InputError("depths", f"must be sorted strictly increasing, got {d[k]:g} then {d[k + 1]:g}")
        U = real("velocities", velocities)
        if np.shape(U) != (np.size(d), 2):
            raise InputError(
                "velocities",
                f"must be one (Ux, Uy) row per depth, shape ({np.size(d)}, 2), got {np.shape(U)}",
            )
        self.depths, self.U = np.array(d, dtype=float), np.array(U, dtype=float)
        self.surface = float(real("surface", surface))
        self.slopes = np.diff(self.U, axis=0) / np.diff(self.depths)[:, None]  # dU/d(depth) per interval

    def velocity(self, z):
        depth = self.surface - np.asarray(z, dtype=float)
        return np.array([np.interp(depth, self.depths, self.U[:, k]) for k in range(2)])

    def gradient(self, z):
        depth = self.surface - np.asarray(z, dtype=float)
        inside = (depth > self.depths[0]) & (depth < self.depths[-1])
        k = np.clip(np.searchsorted(self.depths, depth) - 1, 0, self.depths.size - 2)
        # dU/dz = -dU/d(depth) inside the table, 0 where it is held
        return np.array([np.where(inside, -self.slopes[k, j], 0.0) for j in range(2)])

    def __repr__(self):
        return (
            f"TabulatedCurrent({self.depths.size} depths from {self.depths[0]:g} to {self.depths[-1]:g} m, "
            f"surface={self.surface:g})"
        )


def current_of(value) -> Current | None:
    """The `Current` a user means: None (no current), a `Current`, a horizontal vector
    ``(Ux, Uy)`` (m/s, `UniformCurrent`) or a callable ``z -> (Ux, Uy)`` (`ProfileCurrent`)."""
    if value is None or isinstance(value, Current):
        return value
    if callable(value):
        return ProfileCurrent(value)
    return UniformCurrent(value)
