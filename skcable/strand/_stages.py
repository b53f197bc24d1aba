r"""A piecewise-linear stick/slip bending law of several stages, monotonic and cyclic.

Per principal axis, the bending moment is carried by the wires' own bending, stiffness
:math:`EI_{\min}`, and by stages k = 1..n, each an elastic element of stiffness :math:`B_k` that
slips at the moment :math:`M_k` (a Coulomb element: Iwan's parallel model, W.D. Iwan, "A
distributed-element model for hysteresis and its steady-state dynamic response", J. Appl. Mech.
33, 1966). With the slip curvature :math:`\kappa_{p,k}` of stage k as its history,

$$
M = EI_{\min}\,\kappa + \sum_k m_k, \qquad m_k = B_k(\kappa - \kappa_{p,k}), \qquad |m_k| \le M_k .
$$

**Backbone.** From the straight, unslipped state, :math:`M_b(\kappa) = EI_{\min}\kappa + \sum_k
\min(B_k|\kappa|, M_k)\,\mathrm{sign}\,\kappa`: piecewise linear from
:math:`EI_{\max} = EI_{\min} + \sum_k B_k` to :math:`EI_{\min}`, one knee per stage at
:math:`\kappa_k = M_k/B_k` (a stage without stiffness carries nothing: :math:`\kappa_k = 0`).

**Any curvature path.** Each stage is updated by its exact return mapping (trial
:math:`m_k = B_k(\kappa - \kappa_{p,k})`; where :math:`|m_k| > M_k`, :math:`\kappa_{p,k}` moves
so that :math:`|m_k| = M_k`), exact for a curvature linear in between two calls. A parallel set
of Coulomb elements obeys Masing's rules: from a reversal at :math:`(\kappa_r, M_r)` the branch is
:math:`M = M_r + 2 M_b((\kappa - \kappa_r)/2)` (G. Masing, "Eigenspannungen und Verfestigung beim
Messing", Proc. 2nd Int. Congress of Applied Mechanics, Zürich, 1926). Under cycles
:math:`\pm\kappa_a` the loop closes after the first loading and the energy lost per cycle and
unit length is

$$
W(\kappa_a) = 8\int_0^{\kappa_a} M_b\,d\kappa - 4\kappa_a M_b(\kappa_a)
           = 4\sum_k M_k\,(\kappa_a - \kappa_k)^+ ,
$$

for one stage (a bilinear law, :math:`EI_1 = EI_{\min} + B`, :math:`EI_2 = EI_{\min}`,
:math:`\kappa_s = M/B`) :math:`W = 4(EI_1 - EI_2)\kappa_s(\kappa_a - \kappa_s)^+`.

**Over a sine.** A vibration loop whose curvature amplitude varies as
:math:`\kappa_0\sin u` dissipates on average per cycle

$$
\bar W(\kappa_0) = \frac{2}{\pi}\int_0^{\pi/2} W(\kappa_0\sin u)\,du
 = \frac{8}{\pi}\sum_k M_k\left[\sqrt{\kappa_0^2-\kappa_k^2}
   - \kappa_k\arccos\frac{\kappa_k}{\kappa_0}\right]^+ ,
\qquad
\frac{d\bar W}{d\kappa_0} = \frac{8}{\pi}\sum_{\kappa_k<\kappa_0}
  M_k\frac{\sqrt{\kappa_0^2-\kappa_k^2}}{\kappa_0}.
$$

**In a finite element.** `StageLaw.update` is the law at many points at once, from the last
converged state; a solver keeps the new state once the step has converged. Axes as in `Section`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from skcable._checks import one_of, whole
from skcable.errors import InputError
from skcable.strand._arguments import float_array, name_text, principal_axis
from skcable.strand._section import axis_pair

__all__ = ["StageLaw", "StageResponse", "CurvaturePath"]


class StageResponse(NamedTuple):
    """What `StageLaw.update` returns at every point: the moments (N·m), the tangent
    stiffnesses dM/dκ (N·m², exact: the law is piecewise linear), the new slip curvatures (1/m)
    and the friction work of the step :math:`\\sum_k M_k|\\Delta\\kappa_{p,k}|` (J/m), shapes
    ``(2, *points)``, ``(2, *points)``, ``(2, n_stages, *points)``, ``(2, *points)``."""

    moment: np.ndarray
    tangent: np.ndarray
    slip: np.ndarray
    work: np.ndarray


class CurvaturePath(NamedTuple):
    """A curvature path through a `StageLaw` (`StageLaw.path`): the curvatures (1/m), the
    moments (N·m) and the friction work done from the start (J/m), one entry per point."""

    kappa: np.ndarray
    moment: np.ndarray
    work: np.ndarray


def _per_axis(name: str, value, shape: tuple) -> np.ndarray:
    array = float_array(name, value)
    try:
        return np.array(np.broadcast_to(array, shape), dtype=float)
    except ValueError:
        raise InputError(
            name, f"must broadcast to {shape} (principal axes × stages), got {array.shape}"
        ) from None


def _x_minus_arctan(x: np.ndarray) -> np.ndarray:
    """``x - arctan(x)`` for x >= 0 without cancellation: its series below x = 0.1."""
    small = x < 0.1
    s = np.where(small, x, 0.0)
    s2 = s * s
    # x³/3 - x⁵/5 + ... to x^17 (the next term is below 1e-20 x³ there)
    series = s * s2 * (1 / 3 + s2 * (-1 / 5 + s2 * (1 / 7 + s2 * (-1 / 9 + s2 * (
        1 / 11 + s2 * (-1 / 13 + s2 * (1 / 15 - s2 / 17)))))))  # fmt: skip
    big = np.where(small, 1.0, x)
    return np.where(small, series, big - np.arctan(big))


class StageLaw:
    r"""A stick/slip bending law of several stages per principal axis (the module's text).

    Parameters
    ----------
    EI_min : float or array_like (2,)
        Stiffness of the wires' own bending (N·m²), > 0, per principal axis.
    stiffness : array_like (n,) or (2, n)
        Stiffness B_k of each stage (N·m²), >= 0; a row per principal axis, or one for both.
    slip_moment : array_like (n,) or (2, n)
        Moment M_k at which each stage slips (N·m), >= 0 (0 where its stiffness is 0).
    name : str
        Label.

    Attributes
    ----------
    stiffness, slip_moment, kappa_slip : ndarray (2, n)
        B_k (N·m²), M_k (N·m) and the knees κ_k = M_k/B_k (1/m) of each stage.

    Examples
    --------
    A bilinear law, EI 1000 N·m² to 0.01 1/m and 50 N·m² beyond:

    >>> law = StageLaw(50.0, [950.0], [9.5])
    >>> round(float(law.energy_per_cycle(0.03)), 12)  # 4 (EI1 - EI2) κs (κa - κs)
    0.76
    """

    def __init__(self, EI_min, stiffness, slip_moment, *, name: str = ""):
        stiffness = float_array("stiffness", stiffness)
        n = stiffness.shape[-1] if stiffness.ndim else 1
        self.stiffness = _per_axis("stiffness", stiffness, (2, n))
        self.slip_moment = _per_axis("slip_moment", slip_moment, (2, n))
        self.EI_min = _per_axis("EI_min", EI_min, (2,))
        if not np.all(self.EI_min > 0):
            raise InputError("EI_min", f"must be > 0, got {self.EI_min.tolist()}")
        for key in ("stiffness", "slip_moment"):
            if not np.all(getattr(self, key) >= 0):
                raise InputError(key, f"must be >= 0, got {getattr(self, key).tolist()}")
        if np.any((self.stiffness == 0) & (self.slip_moment > 0)):
            raise InputError("slip_moment", "must be 0 for a stage without stiffness (it carries nothing)")
        self.name = name_text(name)
        carries = self.stiffness > 0
        self.kappa_slip = np.where(carries, self.slip_moment / np.where(carries, self.stiffness, 1.0), 0.0)
        if not np.all(np.isfinite(self.kappa_slip)):
            raise InputError("stiffness", "gives a knee curvature M_k/B_k beyond floating point")

    # --- the backbone ---------------------------------------------------------------------
    @property
    def n_stages(self) -> int:
        """Number of stages (some may carry nothing about an axis)."""
        return self.stiffness.shape[1]

    @property
    def EI_max(self) -> np.ndarray:
        """``EI_min + sum B_k`` per principal axis (N·m²)."""
        return self.EI_min + self.stiffness.sum(axis=1)

    @property
    def kappa_0(self) -> np.ndarray:
        """``sum M_k / sum B_k`` per principal axis (1/m): where the stick line meets the
        full-slip line ``sum M_k + EI_min κ``, the knee of the bilinear law with the same
        asymptotes (Foti & Martinelli 2018's limit curvature); 0 about an axis without stages."""
        total = self.stiffness.sum(axis=1)
        return np.where(total > 0, self.slip_moment.sum(axis=1) / np.where(total > 0, total, 1.0), 0.0)

    @property
    def M_0(self) -> np.ndarray:
        """``EI_max κ_0`` per principal axis (N·m)."""
        return self.EI_max * self.kappa_0

    def knees(self, axis: int = 0) -> np.ndarray:
        """The distinct knee curvatures κ_k (1/m) of the stages that carry a moment about
        ``axis``, ascending."""
        axis = principal_axis(axis)
        carries = self.slip_moment[axis] > 0
        return np.unique(self.kappa_slip[axis][carries])

    def moment(self, kappa, axis: int = 0):
        """Backbone moment M_b (N·m) at curvature ``kappa`` (1/m, any shape) about ``axis``:
        the law loaded from the straight, unslipped state."""
        axis = principal_axis(axis)
        kappa = float_array("kappa", kappa)
        stages = np.clip(
            kappa[..., None] * self.stiffness[axis], -self.slip_moment[axis], self.slip_moment[axis]
        ).sum(axis=-1)
        out = self.EI_min[axis] * kappa + stages
        return out[()] if out.ndim == 0 else out

    def bending_stiffness(self, kappa, axis: int = 0, kind: str = "secant"):
        """``M_b/κ`` (``kind="secant"``) or ``dM_b/dκ`` (``"tangent"``) of the backbone at
        ``kappa`` (N·m²) about ``axis``; at a knee, the stick side (a stage that slips at 0
        never sticks)."""
        axis = principal_axis(axis)
        one_of("kind", kind, ("secant", "tangent"))
        kappa = float_array("kappa", kappa)
        size = np.abs(kappa)
        stick = (size[..., None] <= self.kappa_slip[axis]) & (self.slip_moment[axis] > 0)
        tangent = self.EI_min[axis] + np.sum(np.where(stick, self.stiffness[axis], 0.0), axis=-1)
        if kind == "tangent":
            out = tangent
        else:
            safe = np.where(size == 0.0, 1.0, size)
            out = np.where(size == 0.0, tangent, np.abs(self.moment(safe, axis)) / safe)
        return out[()] if out.ndim == 0 else out

    # --- history ----------------------------------------------------------------------------
    def initial_slip(self, shape=()) -> np.ndarray:
        """Slip curvatures of the straight, unslipped state: zeros ``(2, n_stages, *shape)``."""
        return np.zeros((2, self.n_stages, *tuple(shape)))

    def update(self, kappa, slip) -> StageResponse:
        """The return mapping of every stage (module text) from the slip curvatures ``slip``
        ``(2, n_stages, *points)`` to the curvatures ``kappa`` ``(2, *points)`` (1/m): a
        `StageResponse` (``slip`` is not modified)."""
        kappa = float_array("kappa", kappa)
        slip = float_array("slip", slip)
        if kappa.ndim < 1 or kappa.shape[0] != 2 or slip.shape != (2, self.n_stages, *kappa.shape[1:]):
            raise InputError(
                "slip",
                f"must have shape (2, n_stages={self.n_stages}, *points) for kappa of shape (2, *points); "
                f"got slip {slip.shape}, kappa {kappa.shape}",
            )
        extra = (slice(None), slice(None)) + (None,) * (kappa.ndim - 1)
        B, limit = self.stiffness[extra], self.slip_moment[extra]
        trial = B * (kappa[:, None] - slip)
        slipping = np.abs(trial) > limit
        inverse = np.where(B > 0, 1.0 / np.where(B > 0, B, 1.0), 0.0)
        new = np.where(slipping, kappa[:, None] - np.sign(trial) * limit * inverse, slip)
        m = np.where(slipping, np.sign(trial) * limit, trial)
        EI_min = self.EI_min.reshape((2,) + (1,) * (kappa.ndim - 1))
        return StageResponse(
            moment=EI_min * kappa + m.sum(axis=1),
            tangent=EI_min + np.sum(np.where(slipping, 0.0, B), axis=1),
            slip=new,
            work=np.sum(limit * np.abs(new - slip), axis=1),
        )

    def path(self, kappa, axis: int = 0) -> CurvaturePath:
        """The law along a curvature path about ``axis`` from the straight, unslipped state:
        ``kappa`` (1/m, a 1-D sequence, the curvature linear between its points; the first
        point is reached from 0 in a straight line). Returns a `CurvaturePath`: the moments at
        the points (exact) and the cumulative friction work (J/m)."""
        axis = principal_axis(axis)
        kappa = float_array("kappa", kappa)
        if kappa.ndim != 1:
            raise InputError("kappa", f"must be a 1-D sequence of curvatures, got shape {kappa.shape}")
        slip = self.initial_slip()
        both = np.zeros(2)
        moment, work = np.empty(kappa.size), np.empty(kappa.size)
        done = 0.0
        for i, value in enumerate(kappa.tolist()):
            both[axis] = value
            response = self.update(both, slip)
            slip = response.slip
            done += float(response.work[axis])
            moment[i], work[i] = response.moment[axis], done
        return CurvaturePath(kappa.copy(), moment, work)

    def _amplitude(self, kappa_a):
        kappa_a = float_array("kappa_a", kappa_a)
        if not np.all(kappa_a >= 0):
            raise InputError("kappa_a", f"must be >= 0 (a curvature amplitude), got {kappa_a.min()!r}")
        return kappa_a

    def loop(self, kappa_a: float, axis: int = 0, n: int = 0):
        """One steady cycle between ``+kappa_a`` and ``-kappa_a`` (1/m) about ``axis``, traced
        by the history (`update`) after the first loading from the straight state.

        Returns ``(kappa, M)``: from ``+kappa_a`` down to ``-kappa_a`` and back (the first and
        last points equal), with every vertex of the loop (Masing's knees at
        ``±(kappa_a - 2 κ_k)``) and ``n`` more evenly spaced points per branch (>= 0): the
        moment is linear between the points."""
        amplitude = self._amplitude(kappa_a)
        if amplitude.ndim:
            raise InputError("kappa_a", f"must be a single number for a loop, got shape {amplitude.shape}")
        a = float(amplitude)
        whole("n", n, 0)
        knees = self.knees(axis)
        turns = a - 2.0 * knees[2.0 * knees < 2.0 * a]
        down = np.unique(np.concatenate([[a, -a], turns, np.linspace(a, -a, n + 2)]))[::-1]
        branch = np.concatenate([down, -down[1:]])
        moment = self.path(np.concatenate([[a], branch]), axis).moment[1:]
        return branch, moment

    def energy_per_cycle(self, kappa_a, axis: int = 0):
        """Energy lost per cycle ``±kappa_a`` and unit length (J/m), ``4 sum M_k (κ_a - κ_k)^+``
        (Masing's loop of the backbone, module text); ``kappa_a`` (1/m, >= 0) any shape."""
        axis = principal_axis(axis)
        kappa_a = self._amplitude(kappa_a)
        excess = np.maximum(kappa_a[..., None] - self.kappa_slip[axis], 0.0)
        out = 4.0 * np.sum(self.slip_moment[axis] * excess, axis=-1)
        return out[()] if out.ndim == 0 else out

    def sine_averaged_energy(self, kappa_0, axis: int = 0, derivative: bool = False):
        r"""``(2/π) ∫_0^{π/2} W(κ_0 sin u) du`` (J/m) in closed form (module text), the mean
        energy per cycle of a loop whose curvature amplitude varies as a sine of peak
        ``kappa_0`` (1/m, >= 0, any shape); with ``derivative``, also its derivative in
        ``kappa_0`` (J)."""
        axis = principal_axis(axis)
        k0 = self._amplitude(kappa_0)[..., None]
        knee, M = self.kappa_slip[axis], self.slip_moment[axis]
        above = k0 > knee
        top = np.where(above, k0, 1.0)
        root = np.sqrt(np.maximum(top - knee, 0.0) * (top + knee))  # sqrt(κ0² - κk²)
        # sqrt(κ0² - κk²) - κk arccos(κk/κ0) = κk (x - arctan x), x = root/κk; root itself at κk = 0
        safe = np.where(knee > 0, knee, 1.0)
        term = np.where(knee > 0, knee * _x_minus_arctan(root / safe), root)
        value = 8.0 / np.pi * np.sum(np.where(above, M * term, 0.0), axis=-1)
        value = value[()] if value.ndim == 0 else value
        if not derivative:
            return value
        slope = 8.0 / np.pi * np.sum(np.where(above, M * root / top, 0.0), axis=-1)
        return value, (slope[()] if slope.ndim == 0 else slope)

    def __repr__(self):
        return (
            f"{type(self).__name__}({self.name or 'law'!r}: {self.n_stages} stages, "
            f"EI_max={axis_pair(self.EI_max, 'N·m²')}, EI_min={axis_pair(self.EI_min, 'N·m²')}, "
            f"kappa_0={axis_pair(self.kappa_0, '1/m')})"
        )
