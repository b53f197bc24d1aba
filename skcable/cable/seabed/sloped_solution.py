r"""`SlopedSeabedCatenary`: the solution of a line on a sloped seabed, mapped along the line.

The grounded part lies straight along the slope from A over the unstretched length
``L_B``; at ``u`` from A its tension is :math:`T(u) = \max(T_t - k(L_B - u), 0)`, so the
point ``s <= L_B`` lies at the stretched distance
:math:`D(s) = s + \int_0^s T\,du/EA` along the slope. The suspended part, at
:math:`\sigma = s - L_B` from the touchdown with :math:`V = V_t + w\sigma`, lies at

.. math::
    x = x_t + \frac{H\sigma}{EA} + \frac{H}{w}\Big(\operatorname{asinh}\frac{V}{H}
        - \operatorname{asinh}\frac{V_t}{H}\Big), \qquad
    y = y_t + \frac{\sigma(V_t + w\sigma/2)}{EA} + \frac{T - T_t}{w}

(H.M. Irvine, "Cable Structures", MIT Press, 1981). Its fairlead stiffness follows from the
closure's Jacobian (`skcable.cable.closure.on_slope`) by the implicit function
theorem: :math:`\partial(H, L_B)/\partial(\mathrm{span}, dh) = J^{-1}` and
:math:`V_B = H\tan\alpha + w(L - L_B)`, so
:math:`K = \begin{pmatrix}1 & 0\\ \tan\alpha & -w\end{pmatrix} J^{-1}`.
"""

from __future__ import annotations

import numpy as np

from skcable._checks import real, require, whole
from skcable.cable.arc_samples import arc_samples, write_profile
from skcable.cable.closure import grounded, on_slope, positions, slope_frame, tensioned
from skcable.cable.seabed.heap import as_float as _out
from skcable.errors import ConvergenceError
from skcable.results import ProfileMixin

__all__ = ["SlopedSeabedCatenary"]


class SlopedSeabedCatenary(ProfileMixin):
    """Solution of `sloped_seabed_catenary` (one scene, scalar attributes).

    ``H`` (``= H_B``) is the horizontal tension of the suspended part (the fairlead's),
    ``V_B`` the vertical force at B, ``H_A, V_A`` the anchor's reaction
    (the grounded line pulls A along the slope, up it for α > 0: the upward
    reaction is ``V_A = -H_A tan α``; with the
    line lifted off A they are the free line's), ``T_A, T_B`` the end
    tensions, ``length_on_seabed`` the unstretched grounded length
    (0 when the line leaves A above the slope), ``x_touchdown, y_touchdown``
    where it leaves the seabed, ``history`` the closure residuals of the
    Newton (``hybr``) solve. ``free`` is the free `ElasticCatenary` where the line leaves A
    above the slope, else None.

    It satisfies the result protocol (`skcable.results`): ``xy(s)``, ``T_of_s(s)``,
    ``profile(n)``, ``stiffness()``, ``tensions()``, ``to_frame(n)``, ``to_vtk(path)``.
    """

    def __init__(self, span, dh, w, EA, length, slope, friction, H, L_B, history, free=None):
        self.span, self.dh, self.w, self.EA, self.length = span, dh, w, EA, length
        self.seabed_slope, self.friction = slope, friction
        self.H, self.length_on_seabed, self.history = H, L_B, list(history)
        self.free = free
        cos, sin = slope_frame(slope)
        self._cos, self._sin = cos, sin
        self._k = k = w * (sin + friction * cos)  # tension gradient along the grounded line
        T_td = H / cos
        self._slack = L_B - tensioned(T_td, L_B, k)  # untensioned grounded length at the anchor
        self.T_touchdown = T_td
        stretch, _, _, self.T_A = grounded(T_td, L_B, k, EA)
        self.x_touchdown, self.y_touchdown = (L_B + stretch) * cos, (L_B + stretch) * sin
        self.V_touchdown = H * slope
        self.V_B = self.V_touchdown + w * (length - L_B)
        self.H_A = self.T_A * cos
        self.V_A = -self.T_A * sin  # upward reaction: the grounded line pulls A up the slope
        self.T_B = float(np.hypot(H, self.V_B))
        if free is not None:  # the free line: its own forces
            self.V_B, self.T_B, self.x_touchdown, self.y_touchdown = free.V_B, free.T_B, 0.0, 0.0
            self.H_A, self.V_A, self.T_A = free.H, free.V_A, free.T_A

    @property
    def H_B(self):
        """Horizontal tension at B (N), ``H``."""
        return self.H

    def closure(self):
        """``(X - span, Z - dh)`` (m) of the grounded solution: what the solve drove to zero."""
        if self.length_on_seabed == 0.0:
            return 0.0, 0.0  # the free line: `elastic_catenary` checked its own residual
        scene = (self.w, self.EA, self.length, self.seabed_slope, self.friction)
        X, Z = on_slope(self.H, self.length_on_seabed, *scene)[:2]
        return X - self.span, Z - self.dh

    def residual(self):
        """Largest closure residual over the chord."""
        fx, fz = self.closure()
        return float(max(abs(fx), abs(fz)) / np.hypot(self.span, self.dh))

    # -- along the line ---------------------------------------------------------------
    def _arc(self, s):
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def _grounded_T(self, u):
        """Tension (N) at ``u`` from A on the grounded part."""
        return np.maximum(self.T_touchdown - self._k * (self.length_on_seabed - u), 0.0)

    def _grounded_D(self, u):
        """Stretched distance (m) along the slope of the grounded point ``u`` from A."""
        a = self._slack
        c = np.maximum(u - a, 0.0)
        T_a = self.T_touchdown - self._k * (self.length_on_seabed - a)  # the tension where it starts
        return u + (T_a * c + 0.5 * self._k * c * c) / self.EA

    def _suspended(self, s):
        """``x, y, T, V`` of the suspended point ``s`` (its arc length from the touchdown)."""
        H, w, EA, V_t = self.H, self.w, self.EA, self.V_touchdown
        sigma = np.maximum(s - self.length_on_seabed, 0.0)
        V = V_t + w * sigma
        x, y = positions(H, V_t, w, EA, sigma, np)  # the hanging piece from the touchdown
        return self.x_touchdown + x, self.y_touchdown + y, np.hypot(H, V), V

    def _maps(self, s):
        """``x, y, T, angle`` (m, N, rad) at unstretched arc length ``s`` (checked)."""
        if self.free is not None:
            free = self.free
            V = self.w * s - free.V_A  # the vertical component of the tension at s
            return free.x_of_s(s), free.y_of_s(s), np.hypot(free.H, V), np.arctan2(V, free.H)
        x, y, T, V = self._suspended(s)
        grounded = s < self.length_on_seabed
        D = self._grounded_D(np.minimum(s, self.length_on_seabed))
        x = np.where(grounded, D * self._cos, x)
        y = np.where(grounded, D * self._sin, y)
        T = np.where(grounded, self._grounded_T(np.minimum(s, self.length_on_seabed)), T)
        angle = np.where(grounded, np.arctan(self.seabed_slope), np.arctan2(V, self.H))
        return x, y, T, angle

    def xy(self, s):
        """Positions ``(..., 2)`` (m) of the material points at unstretched arc length ``s`` from A."""
        x, y = self._maps(self._arc(s))[:2]
        return np.stack(np.broadcast_arrays(x, y), axis=-1)

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` from A."""
        return _out(self._maps(self._arc(s))[2])

    def samples(self, n: int = 201) -> dict:
        """``n`` points evenly spaced in unstretched arc length, the input of `to_vtk`: ``xy``
        (n, 2) m, ``tension`` (N), ``angle`` (rad above the horizontal), ``load`` (n, 2) N/m."""
        s = np.linspace(0.0, self.length, whole("n", n, 2))
        x, y, T, angle = self._maps(s)
        return arc_samples(x, y, T, angle, self.w)

    def to_vtk(self, path, n: int = 201):
        """Write the profile as a VTK polyline (see `skcable.io.cable_mesh`); returns the path."""
        return write_profile(self, path, n)

    # -- stiffness ----------------------------------------------------------------------
    def stiffness(self):
        """Fairlead stiffness ``∂(H, V_B)/∂(span, dh)`` with A fixed (N/m), shape ``(2, 2)``.

        Grounded: ``[[1, 0], [tan α, -w]] J^{-1}`` with ``J = ∂(X, Z)/∂(H, L_B)`` (module
        docstring); the free line: its elastic catenary's stiffness (one-sided where the
        line just touches the slope)."""
        if self.free is not None:
            return np.asarray(self.free.stiffness(), dtype=float)
        scene = (self.w, self.EA, self.length, self.seabed_slope, self.friction)
        X_H, X_L, Z_H, Z_L = on_slope(self.H, self.length_on_seabed, *scene)[2:]
        det = X_H * Z_L - X_L * Z_H
        inverse = np.array([[Z_L, -X_L], [-Z_H, X_H]]) / det
        K = np.array([[1.0, 0.0], [self.seabed_slope, -self.w]]) @ inverse
        if not np.isfinite(K).all():
            raise ConvergenceError("SlopedSeabedCatenary.stiffness: the closure's Jacobian is singular here")
        return K

    def __repr__(self):
        shown = ("H", "H_A", "V_A", "V_B", "T_A", "T_B", "length", "length_on_seabed", "x_touchdown")
        numbers = ", ".join(f"{name}={float(getattr(self, name)):.9g}" for name in shown)
        return (
            f"SlopedSeabedCatenary(span={self.span:g}, dh={self.dh:g}, w={self.w:g}, "
            f"seabed_slope={self.seabed_slope:g}: {numbers})"
        )
