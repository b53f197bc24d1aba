r"""The closed form of a hanging line whose segments have nonlinear axial laws ``ε(T)``.

A line of segments in series (`skcable.mooring.segments.parts.Segment`, some with a strain
law of `skcable.mooring.axial` other than ``ε = T/EA``) hangs from A = (0, 0) to B = (span, dh)
clear of the seabed. With the horizontal force ``H`` and the vertical force ``V`` just below
the fairlead's joint, statics gives the vertical force at the bottom of each segment,
``V_{bot,i} = V - load_above_i - w_i L_i``, and each segment spans the rigid catenary's run and
rise plus the exact elastic integrals of its law along it,

.. math:: \Delta x_i = \frac{H}{w_i}\big(\operatorname{asinh}\tfrac{V_{top}}{H}
          - \operatorname{asinh}\tfrac{V_{bot}}{H}\big) + \int_0^{L_i}\varepsilon(T)\frac{H}{T}\,ds,
          \qquad
          \Delta z_i = \frac{T_{top} - T_{bot}}{w_i} + \int_0^{L_i}\varepsilon(T)\frac{V}{T}\,ds

(H.M. Irvine, "Cable Structures", MIT Press, 1981, ch. 2, with ``ε = T/EA`` replaced by the law;
`skcable.mooring.axial.catenary_ends`, Gauss–Legendre quadrature in ``u = asinh(V/H)``). The
closure ``ΣΔx_i = span``, ``ΣΔz_i = dh`` is solved by Newton's method with its analytic
Jacobian (`skcable._newton2.solve2`) from the uniform line of the same length, weight and
secant compliance, to a relative residual of 1e-13 of the chord; the result is a
`LawLineSolution`. A line that would rest on the seabed (``V_bot,0 < 0`` over a seabed through
the anchor) or dip below a lower one is refused with `GroundedLaw` (an `skcable.InputError`
naming ``EA``): `skcable.mooring.line_3d` solves it by the 3-D line BVP instead.
"""

from __future__ import annotations

import math

import numpy as np

from skcable._newton2 import solve2
from skcable._show import Shown
from skcable.errors import ConvergenceError, InputError
from skcable.mooring.axial import catenary_ends, elongation
from skcable.mooring.segments.solution import CLOSURE_TOLERANCE

__all__ = ["GroundedLaw", "LawLineSolution", "law_closure", "solve_law_line"]


class GroundedLaw(InputError):
    """A line with a nonlinear axial law that would touch the seabed: no closed form here (an
    `skcable.InputError` naming ``EA``)."""


def law_closure(line, H: float, V: float):
    """``(X, Z, J, V_bot)``: the run and rise (m) of ``line`` at fairlead forces ``(H, V)`` (N),
    their Jacobian ``∂(X, Z)/∂(H, V)`` (2, 2) and the vertical force at the bottom of each
    segment (N) (module docstring)."""
    arrays = line.arrays
    V_bot = V - arrays.load_above - arrays.wL
    X = Z = 0.0
    J = np.zeros((2, 2))
    for seg, V0 in zip(line.segments, V_bot.tolist(), strict=True):
        x, z, jac = catenary_ends(seg.law, H, V0, seg.w, seg.length)
        X, Z, J = X + x, Z + z, J + jac
    return X, Z, J, V_bot


def _closure(H, V, line, span, dh, sizes):
    if not H > 0:
        raise ValueError("H <= 0: no hanging line")
    X, Z, J, _ = law_closure(line, H, V)
    return X - span, Z - dh, J[0, 0], J[0, 1], J[1, 0], J[1, 1], sizes[0], sizes[1], None


def solve_law_line(line, span: float, dh: float, start=None) -> LawLineSolution:
    """The hanging line with nonlinear axial laws from A = (0, 0) to B = (span, dh) (module
    docstring) from ``start``, a pair ``(H, V)`` (N, ``V`` below the fairlead's joint; None: no
    start, a `ConvergenceError`).

    Raises
    ------
    GroundedLaw
        The line would rest on the seabed or dip below it.
    ConvergenceError
        Newton's method did not meet the closure (with its history).
    """
    chord = math.hypot(span, dh)
    if start is None:
        raise ConvergenceError("Line.solve: no start for the line with nonlinear axial laws", [])
    sizes = (line.length + span, line.length + abs(dh))
    result = solve2(
        _closure, float(start[0]), float(start[1]), (line, span, dh, sizes), max_iter=60, strict=False
    )
    f1, f2 = result.last[:2]
    norm = max(abs(f1), abs(f2)) / chord
    if not norm < CLOSURE_TOLERANCE:
        raise ConvergenceError(
            f"Line.solve: the closure of the line with nonlinear axial laws is not met ({norm:.3g})",
            result.history,
        )
    solution = LawLineSolution(line, span, dh, float(result.x), float(result.y), list(result.history))
    solution.check_seabed()
    return solution


class LawLineSolution(Shown):
    """A hanging line with nonlinear axial laws (module docstring); the attributes of
    `skcable.mooring.LineSolution` that a line model needs (`skcable.mooring.line_3d`).

    Attributes
    ----------
    line : Line
    span, dh : float
        B relative to A (m).
    H, H_A : float
        Horizontal force (N), the same at both ends.
    V : float
        Vertical force just below the fairlead's joint (N).
    V_A, V_B : float
        Upward reactions at A and B (N), the ends' attachments included.
    T_A, T_B : float
        End tensions (N).
    V_bot : ndarray
        Vertical force at the bottom of each segment (N).
    length, length_on_seabed, x_touchdown : float
        Unstretched length (m); 0 and 0 (it hangs free).
    history : list of float
        Newton's residual per iteration.
    """

    def __init__(self, line, span, dh, H, V, history):
        self.line, self.span, self.dh, self.H, self.H_A, self.V = line, span, dh, H, H, V
        self.history = history
        arrays = line.arrays
        _, _, self.jacobian, self.V_bot = law_closure(line, H, V)
        self.V_B = V + arrays.P_end[1]
        self.V_A = -float(self.V_bot[0]) + arrays.P_end[0]
        self.T_A, self.T_B = math.hypot(H, self.V_bot[0]), math.hypot(H, V)
        self.length, self.length_on_seabed, self.x_touchdown = line.length, 0.0, 0.0
        self.heap = False
        ends = [catenary_ends(seg.law, H, V0, seg.w, seg.length)[:2] for seg, V0 in self._pieces()]
        self.joints = np.vstack([[0.0, 0.0], np.cumsum(ends, axis=0)])
        values = (H, self.V_A, self.V_B, self.T_A, self.T_B, *self.joints.ravel())
        if not all(map(math.isfinite, values)):
            raise ConvergenceError("Line.solve: non-finite closed form", history)

    def _pieces(self):
        return zip(self.line.segments, self.V_bot.tolist(), strict=True)

    def check_seabed(self) -> None:
        """Raise `GroundedLaw` where the line would rest on or dip below its seabed."""
        line = self.line
        if line.seabed is None:
            return
        low = self.lowest_height()
        if (line.contact and self.V_bot[0] < 0) or (not line.contact and low < line.seabed):
            raise GroundedLaw(
                "EA",
                "a line with a nonlinear axial law that rests on the seabed has no closed form here: "
                "solve it in space with mooring.line_3d (the 3-D line BVP)",
            )

    def lowest_height(self) -> float:
        """The lowest height of the line relative to A (m): at a joint or a vertex ``V = 0``."""
        low = float(self.joints[:, 1].min())
        for i, (seg, V0) in enumerate(self._pieces()):
            s = -V0 / seg.w
            if 0.0 < s < seg.length:
                low = min(low, float(self.joints[i, 1] + catenary_ends(seg.law, self.H, V0, seg.w, s)[1]))
        return low

    def _locate(self, s):
        s = np.atleast_1d(np.asarray(s, dtype=float))
        if not (np.all(np.isfinite(s)) and np.all((s >= 0) & (s <= self.length))):
            raise InputError("s", f"must lie in [0, {self.length:g}] m")
        k = np.clip(np.searchsorted(self.line.arrays.s_joint, s, side="right") - 1, 0, self.line.arrays.n - 1)
        return s, k, s - self.line.arrays.s_joint[k]

    def xy(self, s) -> np.ndarray:
        """Position ``(x, y)`` (m) relative to A at unstretched arc lengths ``s`` (m), (n, 2)."""
        s, k, sigma = self._locate(s)
        segs, out = self.line.segments, np.empty((s.size, 2))
        for j, (i, d) in enumerate(zip(k.tolist(), sigma.tolist(), strict=True)):
            step = (
                catenary_ends(segs[i].law, self.H, float(self.V_bot[i]), segs[i].w, d)[:2]
                if d > 0
                else (0, 0)
            )
            out[j] = self.joints[i] + step
        return out

    def x_of_s(self, s):
        """Horizontal position (m) at unstretched arc length ``s`` (m)."""
        return self.xy(s)[:, 0].reshape(np.shape(s))

    def y_of_s(self, s):
        """Height (m) relative to A at unstretched arc length ``s`` (m)."""
        return self.xy(s)[:, 1].reshape(np.shape(s))

    def T_of_s(self, s):
        """Tension (N) at unstretched arc length ``s`` (m)."""
        s_, k, sigma = self._locate(s)
        T = np.hypot(self.H, self.V_bot[k] + self.line.arrays.w[k] * sigma)
        return T.reshape(np.shape(s))

    def stiffness(self) -> np.ndarray:
        """``∂(H, V_B)/∂(span, dh)`` (N/m), 2 × 2: the inverse of the closure's Jacobian (the
        quasi-static compliance of the laws)."""
        return np.linalg.inv(self.jacobian)

    def tensions(self):
        """One row per segment (pandas DataFrame): ``segment, length, w, T_lower, T_upper``
        (N) and ``stretch`` (m, ``∫ ε ds`` of the law)."""
        import pandas as pd

        rows = []
        for i, (seg, V0) in enumerate(self._pieces()):
            stretch = elongation(seg.law, self.H, V0, seg.w, seg.length).stretch
            T_lo, T_up = math.hypot(self.H, V0), math.hypot(self.H, V0 + seg.w * seg.length)
            rows.append(
                dict(segment=i, length=seg.length, w=seg.w, T_lower=T_lo, T_upper=T_up, stretch=stretch)
            )
        return pd.DataFrame(rows)

    def __repr__(self):
        return (
            f"LawLineSolution(H={self.H:.9g}, V_A={self.V_A:.9g}, V_B={self.V_B:.9g}, "
            f"T_A={self.T_A:.9g}, T_B={self.T_B:.9g}, length={self.length:.9g})"
        )
