r"""Bathymetry: the seabed as a surface ``z = b(x, y)`` (m, z up), with its gradient and normal.

A seabed gives, vectorised over points ``(x, y)`` of any shape ``P``:

- ``height(x, y)``: ``b`` (m), shape ``P``;
- ``gradient(x, y)``: ``∇b = (∂b/∂x, ∂b/∂y)``, shape ``(2, *P)``;
- ``hessian(x, y)``: ``∇∇b``, shape ``(2, 2, *P)`` (1/m; the contact rows' Jacobian needs it);
- ``normal(x, y)``: the unit upward normal ``(−b_x, −b_y, 1)/sqrt(1 + |∇b|²)``, ``(3, *P)``.

Three kinds:

- `Plane`: ``b = height + slope·((x, y) − origin)``, flat when the slope is zero;
- `DepthFunction`: the user's ``b(x, y)`` with its gradient (required: a seabed's slope is a
  force on the line, not a detail), and its Hessian if given, else central differences of the
  gradient with a step of ``1e-6`` times the point's size (1 m at least; the Hessian enters
  the Jacobian only, never the solution);
- `Grid`: depths on a rectangular grid, bilinear between its nodes as MoorPy's
  ``setBathymetry`` (scipy's ``RegularGridInterpolator`` for the height; the bilinear cell's
  own derivatives, ``b_x = ((1 − t_y)(z₁₀ − z₀₀) + t_y(z₁₁ − z₀₁))/Δx`` and its twist
  ``b_xy = (z₁₁ − z₁₀ − z₀₁ + z₀₀)/(Δx Δy)``, which scipy's interpolators do not give); a
  point off the grid is refused, never extrapolated. On a cell's edge the gradient is the
  cell's above it (the slope jumps there: a grid seabed is only piecewise smooth).

`bathymetry_of` turns what a user gives (None, a number, a pair of callables, a `Bathymetry`)
into one; `Bathymetry.along` gives the profile ``b(σ)`` under a horizontal line, for the plane
closed forms and the 2-D line BVP.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import real
from skcable.errors import InputError

__all__ = ["Bathymetry", "DepthFunction", "Grid", "OffGrid", "Plane", "Profile", "bathymetry_of"]


class OffGrid(InputError):
    """A point where a `Grid` has no height (an `skcable.InputError` naming ``seabed``): a solver
    may reject a trial iterate for it and step back."""


def _pair(name: str, value) -> np.ndarray:
    v = real(name, value)
    if np.shape(v) != (2,):
        raise InputError(name, f"must be a pair of numbers (x, y), got {value!r}")
    return np.array(v, dtype=float)


class Bathymetry:
    """Base of the seabeds (module docstring). ``flat`` is the height (m) of a horizontal
    seabed, None otherwise."""

    flat: float | None = None

    def height(self, x, y) -> np.ndarray:
        """``b(x, y)`` (m)."""
        raise NotImplementedError

    def gradient(self, x, y) -> np.ndarray:
        """``∇b`` (2, *P)."""
        raise NotImplementedError

    def hessian(self, x, y) -> np.ndarray:
        """``∇∇b`` (2, 2, *P) (1/m)."""
        raise NotImplementedError

    def normal(self, x, y) -> np.ndarray:
        """The unit upward normal (3, *P)."""
        g = self.gradient(x, y)
        n = np.array([-g[0], -g[1], np.ones_like(g[0])])
        return n / np.sqrt(1.0 + g[0] * g[0] + g[1] * g[1])

    def along(self, origin, direction) -> Profile:
        """The profile under the horizontal line ``origin + σ e`` (``e`` the unit ``direction``)."""
        o, e = _pair("origin", origin), _pair("direction", direction)
        size = float(np.hypot(*e))
        if not size > 0:
            raise InputError("direction", "must be a non-zero horizontal vector")
        return Profile(self, o, e / size)


@dataclass(frozen=True)
class Profile:
    """The seabed ``b(σ)`` under the horizontal line ``origin + σ e`` (m), with its slope and
    curvature along σ."""

    seabed: Bathymetry
    origin: np.ndarray
    e: np.ndarray

    def _at(self, sigma):
        sigma = np.asarray(sigma, dtype=float)
        return self.origin[0] + sigma * self.e[0], self.origin[1] + sigma * self.e[1]

    def __call__(self, sigma) -> np.ndarray:
        return self.seabed.height(*self._at(sigma))

    def slope(self, sigma) -> np.ndarray:
        """``db/dσ = ∇b·e``."""
        g = self.seabed.gradient(*self._at(sigma))
        return g[0] * self.e[0] + g[1] * self.e[1]

    def curvature(self, sigma) -> np.ndarray:
        """``d²b/dσ² = eᵀ ∇∇b e``."""
        h = self.seabed.hessian(*self._at(sigma))
        e = self.e
        return h[0, 0] * e[0] * e[0] + 2.0 * h[0, 1] * e[0] * e[1] + h[1, 1] * e[1] * e[1]


class Plane(Bathymetry):
    """The plane ``b = height + slope·((x, y) − origin)`` (m): ``slope`` the gradient
    ``(∂b/∂x, ∂b/∂y)``, zero for a flat seabed at ``height``."""

    def __init__(self, height: float = 0.0, slope=(0.0, 0.0), origin=(0.0, 0.0)):
        self.level = float(real("height", height))
        self.slope = _pair("slope", slope)
        self.origin = _pair("origin", origin)
        self.flat = self.level if not np.any(self.slope) else None

    def height(self, x, y):
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return self.level + self.slope[0] * (x - self.origin[0]) + self.slope[1] * (y - self.origin[1])

    def gradient(self, x, y):
        shape = np.broadcast_shapes(np.shape(x), np.shape(y))
        return np.broadcast_to(self.slope.reshape(2, *([1] * len(shape))), (2, *shape)).copy()

    def hessian(self, x, y):
        return np.zeros((2, 2, *np.broadcast_shapes(np.shape(x), np.shape(y))))

    def __repr__(self):
        return f"Plane(height={self.level:g} m, slope=({self.slope[0]:g}, {self.slope[1]:g}))"


def _values(name: str, out, shape, rows: int | None = None) -> np.ndarray:
    """A callable's values as a finite float array of ``shape`` (with ``rows`` leading rows)."""
    try:
        if rows is None:
            values = np.broadcast_to(np.asarray(out, dtype=float), shape)
        else:
            values = np.array([np.broadcast_to(np.asarray(part, dtype=float), shape) for part in out])
    except (TypeError, ValueError) as exc:
        raise InputError(
            name, f"must return values broadcastable to the points' shape {shape}: {exc}"
        ) from exc
    if rows is not None and len(values) != rows:
        raise InputError(name, f"must return {rows} components, got {len(values)}")
    if not np.all(np.isfinite(values)):
        raise InputError(name, "returned non-finite values")
    return values


class DepthFunction(Bathymetry):
    """A seabed given as callables: ``height(x, y) -> b`` (m), ``gradient(x, y) -> (b_x, b_y)``
    and optionally ``hessian(x, y) -> ((b_xx, b_xy), (b_xy, b_yy))`` (1/m), arrays in, arrays
    out (module docstring).
    """

    STEP = 1e-6

    def __init__(self, height, gradient, hessian=None):
        for name, fn in (("seabed", height), ("gradient", gradient)):
            if not callable(fn):
                raise InputError(name, f"must be a callable of (x, y), got {fn!r}")
        if hessian is not None and not callable(hessian):
            raise InputError("hessian", f"must be a callable of (x, y), got {hessian!r}")
        self.function, self.slope_function, self.hessian_function = height, gradient, hessian

    def height(self, x, y):
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return _values("seabed", self.function(x, y), np.broadcast_shapes(x.shape, y.shape))

    def gradient(self, x, y):
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return _values("gradient", self.slope_function(x, y), np.broadcast_shapes(x.shape, y.shape), 2)

    def hessian(self, x, y):
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        shape = np.broadcast_shapes(x.shape, y.shape)
        if self.hessian_function is not None:
            rows = [_values("hessian", row, shape, 2) for row in self.hessian_function(x, y)]
            if len(rows) != 2:
                raise InputError("hessian", f"must return a 2 x 2 matrix of components, got {len(rows)} rows")
            return np.array(rows)
        h = self.STEP * np.maximum(1.0, np.maximum(np.abs(x), np.abs(y)))
        dx = (self.gradient(x + h, y) - self.gradient(x - h, y)) / (2 * h)
        dy = (self.gradient(x, y + h) - self.gradient(x, y - h)) / (2 * h)
        cross = 0.5 * (dx[1] + dy[0])
        return np.array([[dx[0], cross], [cross, dy[1]]])

    def __repr__(self):
        return f"DepthFunction({getattr(self.function, '__name__', 'callable')})"


class Grid(Bathymetry):
    """Seabed heights ``z[i, j]`` (m) at ``(x[i], y[j])`` on a rectangular grid, bilinear in each
    cell (module docstring); ``x`` and ``y`` strictly increasing, ``z`` finite.

    Parameters
    ----------
    x, y : array_like
        The grid's axes (m), at least two values each, strictly increasing.
    z : array_like (len(x), len(y))
        Heights of the seabed (m, up; negative below the surface).
    """

    def __init__(self, x, y, z):
        from scipy.interpolate import RegularGridInterpolator

        axes = []
        for name, axis in (("x", x), ("y", y)):
            a = real(name, axis)
            if np.ndim(a) != 1 or np.size(a) < 2:
                raise InputError(name, f"must be an axis of at least two values, got {axis!r}")
            if not np.all(np.diff(a) > 0):
                k = int(np.argmin(np.diff(a) > 0))
                raise InputError(name, f"must be sorted strictly increasing, got {a[k]:g} then {a[k + 1]:g}")
            axes.append(np.array(a, dtype=float))
        values = np.asarray(z, dtype=float)
        if values.shape != (axes[0].size, axes[1].size):
            raise InputError(
                "z", f"must have shape (len(x), len(y)) = {(axes[0].size, axes[1].size)}, got {values.shape}"
            )
        if not np.all(np.isfinite(values)):
            i, j = np.argwhere(~np.isfinite(values))[0]
            raise InputError("z", f"must be finite (NaN or inf at x = {axes[0][i]:g}, y = {axes[1][j]:g})")
        self.x, self.y, self.z = axes[0], axes[1], values
        self.surface = RegularGridInterpolator((self.x, self.y), values, method="linear")

    def _inside(self, x, y):
        x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
        out = ~((x >= self.x[0]) & (x <= self.x[-1]) & (y >= self.y[0]) & (y <= self.y[-1]))
        if np.any(out):
            k = np.argwhere(out)[0]
            raise OffGrid(
                "seabed",
                f"the point ({x[tuple(k)]:g}, {y[tuple(k)]:g}) lies off the grid "
                f"[{self.x[0]:g}, {self.x[-1]:g}] x [{self.y[0]:g}, {self.y[-1]:g}] m",
            )
        return x, y

    def height(self, x, y):
        x, y = self._inside(x, y)
        return self.surface(np.stack([x, y], axis=-1).reshape(-1, 2)).reshape(x.shape)

    def _cell(self, x, y):
        """The cell of each point: its fractions ``(t_x, t_y)``, sizes and corner heights."""
        x, y = self._inside(x, y)
        i = np.clip(np.searchsorted(self.x, x, side="right") - 1, 0, self.x.size - 2)
        j = np.clip(np.searchsorted(self.y, y, side="right") - 1, 0, self.y.size - 2)
        hx, hy = self.x[i + 1] - self.x[i], self.y[j + 1] - self.y[j]
        z = self.z
        corners = z[i, j], z[i + 1, j], z[i, j + 1], z[i + 1, j + 1]
        return (x - self.x[i]) / hx, (y - self.y[j]) / hy, hx, hy, corners

    def gradient(self, x, y):
        tx, ty, hx, hy, (z00, z10, z01, z11) = self._cell(x, y)
        bx = ((1.0 - ty) * (z10 - z00) + ty * (z11 - z01)) / hx
        by = ((1.0 - tx) * (z01 - z00) + tx * (z11 - z10)) / hy
        return np.array([bx, by])

    def hessian(self, x, y):
        _, _, hx, hy, (z00, z10, z01, z11) = self._cell(x, y)
        cross = (z11 - z10 - z01 + z00) / (hx * hy)
        zero = np.zeros_like(cross)
        return np.array([[zero, cross], [cross, zero]])

    def __repr__(self):
        return (
            f"Grid({self.x.size} x {self.y.size} over [{self.x[0]:g}, {self.x[-1]:g}] x "
            f"[{self.y[0]:g}, {self.y[-1]:g}] m)"
        )


def bathymetry_of(value) -> Bathymetry | None:
    """The seabed a user means: None (none), a number (a flat seabed at that height, m), a
    `Bathymetry`, or a pair of callables ``(height, gradient)`` (`DepthFunction`); a callable
    alone is refused (its gradient is needed)."""
    if value is None or isinstance(value, Bathymetry):
        return value
    if callable(value):
        raise InputError(
            "seabed",
            "a callable height needs its gradient: (height, gradient) or DepthFunction(height, gradient)",
        )
    if isinstance(value, (tuple, list)) and len(value) in (2, 3) and all(callable(v) for v in value):
        return DepthFunction(*value)
    if np.ndim(value) != 0:
        raise InputError("seabed", f"must be a height, a Bathymetry or (height, gradient), got {value!r}")
    return Plane(real("seabed", value))
