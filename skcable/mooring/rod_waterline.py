r"""The buoyancy of a rod cut by the still water line: the submerged area of its cross-sections.

A rod (`skcable.mooring.rod`) is a slender cylinder of radius :math:`r` whose axis runs from its
end A at height :math:`z_a` to its end B at :math:`z_b`, at an inclination :math:`\beta` from the
horizontal. Each cross-section is a disc normal to the axis; the still water line :math:`z = 0`
cuts it along a chord. The disc's vertical half-extent is :math:`h = r\cos\beta` and the part of
it below the water line is a circular segment, a fraction

.. math:: f(u) = \frac{\arccos u - u\sqrt{1 - u^2}}{\pi}, \qquad u = \frac{z}{h}
    \text{ clipped to } [-1, 1],

of its area (:math:`z` the height of the section's centre on the axis). With
:math:`t \in [0, 1]` along the axis from A, :math:`z(t) = z_a + t\,(z_b - z_a)`, the buoyancy
:math:`q\int_0^1 f\,dt` (:math:`q = \rho g \tfrac{\pi}{4} d^2 L`) acts at :math:`t_c =
\int_0^1 t f\,dt / \int_0^1 f\,dt` of the axis, shared on the ends by the lever rule:

.. math:: F_a = q\int_0^1 (1 - t)\,f\,dt, \qquad F_b = q\int_0^1 t\,f\,dt.

Slices normal to the axis give the cylinder's volume below the plane exactly, at every
inclination: a vertical rod (:math:`h = 0`) has the submerged length of its axis (a step in
:math:`f`), a horizontal one the circular segment of its section all along, and the volume is
continuous in between. The segment's centroid lies off the axis within its section (by at most
:math:`4r/3\pi`): its moment is not held, the loads act on the axis, as on MoorDyn's nodes (a
floating rod's pitch stiffness :math:`\rho g I_{WP}` leaves out :math:`W (z_G - z_B)`, 6 % of it for
a rod of :math:`L/d = 4` floating half out, MoorDyn's ``AddedMass.txt``); its end caps take no
pressure of their own.

MoorDyn v2 (M. Hall and the MoorDyn contributors, FloatingArrayDesign/MoorDyn, the rod's node
loads) takes at each node the blend
:math:`\mathrm{VOF} = \mathrm{VOF}_0\cos^2\phi + (A/A_0)\sin^2\phi` of the axis model's
submerged fraction :math:`\mathrm{VOF}_0` of the node's segment and the circular segment
:math:`A/A_0` of the node's section, :math:`\phi` the inclination from the vertical. The two agree
for a vertical and a horizontal rod; for a tilted rod crossing the water line the blend is not a
volume (it weighs the two models by the angle) and differs from this one, which is.

The integrals are taken to round-off: the axis is split where :math:`u = -1, 0, 1`; the pieces
outside :math:`|u| < 1` are wholly wet or dry (closed forms), and on each piece inside, with
:math:`|u| = \cos\theta` (:math:`\theta \in [0, \pi/2]`; the lower half by
:math:`f(-u) = 1 - f(u)`), :math:`f = (\theta - \sin\theta\cos\theta)/\pi` and
:math:`f' = -\tfrac{2}{\pi}\sin\theta` are entire in :math:`\theta`, integrated by
Gauss--Legendre in :math:`\theta` (`NODES` nodes). The position along the axis comes from
:math:`\cos\theta - \cos\theta_1 = -2\sin\tfrac{\theta + \theta_1}{2}\sin\tfrac{\theta -
\theta_1}{2}`: no difference cancels, a near-horizontal rod (:math:`u_a \approx u_b`) included.
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np

__all__ = ["NODES", "WaterlineShares", "slice_integrals", "submerged_fraction", "waterline_shares"]

#: Gauss--Legendre nodes per piece of the axis within the water line's band (`slice_integrals`).
NODES = 12


@cache
def _gauss() -> tuple[np.ndarray, np.ndarray]:
    s, w = np.polynomial.legendre.leggauss(NODES)
    return 0.5 * (s + 1.0), 0.5 * w


def submerged_fraction(u):
    r"""``f(u) = (arccos u - u sqrt(1 - u²))/π``: the fraction of a disc below a chord at ``u``
    radii above its centre (``u`` clipped to [-1, 1]; module docstring)."""
    u = np.clip(np.asarray(u, dtype=float), -1.0, 1.0)
    return (np.arccos(u) - u * np.sqrt(1.0 - u * u)) / math.pi


def _band_pieces(za: float, zb: float, h: float) -> tuple[list, list]:
    """The pieces of ``t`` in [0, 1] wholly wet, ``[(t1, t2)]``, and within the band ``|z| < h``,
    ``[(t1, t2, z1, z2)]``, each band piece on one side of ``z = 0``."""
    dz = zb - za
    cuts = {0.0: za, 1.0: zb}
    if dz != 0.0:
        for c in (-h, 0.0, h):
            t = (c - za) / dz
            if 0.0 < t < 1.0:
                cuts[t] = c
    ts = sorted(cuts)
    wet, band = [], []
    for t1, t2 in zip(ts[:-1], ts[1:], strict=True):
        z1, z2 = cuts[t1], cuts[t2]
        zm = 0.5 * (z1 + z2)
        if zm <= -h:
            wet.append((t1, t2))
        elif zm < h:
            band.append((t1, t2, z1, z2))
    return wet, band


def slice_integrals(za: float, zb: float, h: float) -> np.ndarray:
    r"""The integrals along the axis of a rod with its ends at heights ``za``, ``zb`` (m) and
    sections of vertical half-extent ``h`` = r cos β > 0 (m) (module docstring):
    ``[I0, I1, J0, J1, J2, K0, K1]`` with

    .. math:: I_k = \int_0^1 t^k f\,dt, \quad J_k = \int_0^1 t^k \frac{f'(u)}{h}\,dt, \quad
        K_k = \int_0^1 t^k u\,\frac{f'(u)}{h}\,dt,

    so that :math:`\partial I_0/\partial z_a = J_0 - J_1`, :math:`\partial I_0/\partial z_b = J_1`,
    :math:`\partial I_1/\partial z_a = J_1 - J_2`, :math:`\partial I_1/\partial z_b = J_2`,
    :math:`\partial I_k/\partial h = -K_k` (1/m for the J and K)."""
    out = np.zeros(7)
    wet, band = _band_pieces(za, zb, h)
    for t1, t2 in wet:
        out[0] += t2 - t1
        out[1] += 0.5 * (t2 * t2 - t1 * t1)
    if not band:
        return out
    s, w = _gauss()
    t1, t2, z1, z2 = (np.array(c)[:, None] for c in zip(*band, strict=True))
    lower = (z1 + z2) < 0.0  # the lower half: |u| = -u, f = 1 - f(|u|)
    sign = np.where(lower, -1.0, 1.0)
    th1 = np.arccos(np.clip(sign * z1 / h, 0.0, 1.0))
    th2 = np.arccos(np.clip(sign * z2 / h, 0.0, 1.0))
    dth = th2 - th1
    mean = 0.5 * (th1 + th2)
    th = th1 + s * dth
    flat = mean == 0.0  # a piece of zero extent in θ at |u| = 1: f constant along it
    ratio = np.sinc(s * dth / (2.0 * math.pi)) / np.sinc(dth / (2.0 * math.pi))
    sin_mean = np.where(flat, 1.0, np.sin(mean))
    R = np.where(flat, s, s * ratio * np.sin(0.5 * (th + th1)) / sin_mean)
    dR = np.where(flat, 1.0, np.sin(th) / sin_mean / np.sinc(dth / (2.0 * math.pi)))
    t = t1 + (t2 - t1) * R
    dt = (t2 - t1) * dR * w
    c = np.cos(th)
    f_abs = (th - np.sin(th) * c) / math.pi
    f = np.where(lower, 1.0 - f_abs, f_abs)
    fp = -2.0 / math.pi * np.sin(th) * dt / h  # f'(u) dt / h (f' is even)
    u = sign * c
    out[0] += np.sum(f * dt)
    out[1] += np.sum(t * f * dt)
    out[2] += np.sum(fp)
    out[3] += np.sum(t * fp)
    out[4] += np.sum(t * t * fp)
    out[5] += np.sum(u * fp)
    out[6] += np.sum(t * u * fp)
    return out


class WaterlineShares:
    """The buoyancy (N, up) on the ends of a rod and its gradients (`waterline_shares`).

    Attributes
    ----------
    fa, fb : float
        The buoyancy's shares on A and on B (N).
    grad : ndarray, shape (2, 2, 3)
        ``grad[i, j] = ∂f_i/∂p_j`` (N/m): the gradient of the share on end ``i`` (0: A, 1: B)
        with the position of end ``j``.
    """

    __slots__ = ("fa", "fb", "grad")

    def __init__(self, fa, fb, grad):
        self.fa, self.fb, self.grad = fa, fb, grad


def _axis_model(q: float, za: float, zb: float) -> tuple[float, float, float, float, float, float]:
    """``(f_a, f_b, dfa/dza, dfa/dzb, dfb/dza, dfb/dzb)`` of the submerged length of the axis: the
    vertical rod's (``h = 0``), the step ``f = [z < 0]``."""
    dz = za - zb
    t = za / dz  # where the axis crosses z = 0, from a
    dt_a, dt_b = -zb / dz**2, za / dz**2
    if za < 0.0:  # [0, t] submerged: f_b = q t²/2, f_a = q (t - t²/2)
        fb, dfb = 0.5 * q * t * t, q * t
        fa, dfa = q * (t - 0.5 * t * t), q * (1.0 - t)
    else:  # [t, 1] submerged: f_b = q (1 - t²)/2, f_a = q (1 - t)²/2
        fb, dfb = 0.5 * q * (1.0 - t * t), -q * t
        fa, dfa = 0.5 * q * (1.0 - t) ** 2, -q * (1.0 - t)
    return fa, fb, dfa * dt_a, dfa * dt_b, dfb * dt_a, dfb * dt_b


def waterline_shares(q: float, radius: float, a, b) -> WaterlineShares:
    r"""The buoyancy on the ends ``a``, ``b`` (float 3-vectors, m) of a rod of radius ``radius``
    (m) whose whole buoyancy is ``q`` = ρ g π r² L (N), and its gradients (module docstring).

    ``h = r ℓ_h/ℓ`` (``ℓ_h`` the horizontal span of the ends, ``ℓ`` their distance); its gradient
    with ``d = b - a`` is :math:`r\,[(d_x, d_y, 0)/(\ell_h\ell) - \ell_h\,\mathbf d/\ell^3]`, taken
    as zero at ``ℓ_h = 0`` (there :math:`\partial I_k/\partial h = 0`: the band lies within the rod,
    where :math:`u f'(u)` is odd, or is empty). A rod wholly below ``z = -h`` or above ``z = h``
    has all of its buoyancy (half on each end) or none, and no gradient."""
    za, zb = float(a[2]), float(b[2])
    dx, dy, dz = float(b[0] - a[0]), float(b[1] - a[1]), float(b[2] - a[2])
    span = math.hypot(dx, dy)
    length = math.sqrt(span * span + dz * dz)
    h = radius * span / length
    grad = np.zeros((2, 2, 3))
    if max(za, zb) <= -h:
        return WaterlineShares(0.5 * q, 0.5 * q, grad)
    if min(za, zb) >= h:
        return WaterlineShares(0.0, 0.0, grad)
    if h == 0.0:  # vertical, crossing z = 0: the submerged length of the axis
        fa, fb, *d = _axis_model(q, za, zb)
        grad[:, :, 2] = np.reshape(d, (2, 2))
        return WaterlineShares(fa, fb, grad)
    I0, I1, J0, J1, J2, K0, K1 = slice_integrals(za, zb, h)
    grad[0, 0, 2] = q * (J0 - 2.0 * J1 + J2)
    grad[0, 1, 2] = grad[1, 0, 2] = q * (J1 - J2)
    grad[1, 1, 2] = q * J2
    gh = radius * (np.array([dx, dy, 0.0]) / (span * length) - span * np.array([dx, dy, dz]) / length**3)
    dfa_dh, dfb_dh = q * (K1 - K0), -q * K1
    grad[0, 1] += dfa_dh * gh
    grad[0, 0] -= dfa_dh * gh
    grad[1, 1] += dfb_dh * gh
    grad[1, 0] -= dfb_dh * gh
    return WaterlineShares(q * (I0 - I1), q * I1, grad)
