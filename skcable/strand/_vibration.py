r"""Bending frequencies of a tensioned strand between two supports.

A straight strand of length :math:`\ell` under the axial tension :math:`N`,
bending stiffness :math:`EI` and mass per length :math:`m` vibrates
transversely as the Euler–Bernoulli beam with a geometric stiffness
(small vibrations about the straight state; rotary inertia and shear
neglected):

.. math:: EI\,w'''' - N\,w'' + m\,\ddot w = 0 .

Pinned (simply supported) ends have the closed form (e.g. S.S. Rao,
"Vibration of Continuous Systems", Wiley, 2007, §11.6)

.. math:: \omega_n = \left(\frac{n\pi}{\ell}\right)^2\sqrt{\frac{EI}{m}}
          \sqrt{1 + \frac{N\ell^2}{n^2\pi^2 EI}},

which tends to the taut string :math:`\omega_n = (n\pi/\ell)\sqrt{N/m}` as
:math:`EI \to 0` and to the beam as :math:`N \to 0`. Clamped ends are solved
by finite elements on scikit-fem: cubic Hermite elements
(``skfem.ElementLineHermite``) with the weak form
:math:`\int EI\,w''v'' + N\,w'v' = \omega^2\int m\,w v` (consistent mass),
a generalized symmetric eigenproblem; with
:math:`N = 0` its first root is :math:`\beta_1\ell = 4.7300407\ldots` of
:math:`\cos\beta\ell\cosh\beta\ell = 1` (Rao 2007, §11.5). It is solved on the unit
interval :math:`\xi = x/\ell` with the tension ratio :math:`\kappa = N\ell^2/EI`:
:math:`\omega^2 = (EI/m\ell^4)\,\mu`, :math:`\mu` an eigenvalue of
:math:`\int w''v''\,d\xi + \kappa\int w'v'\,d\xi` over :math:`\int wv\,d\xi`, where
:math:`\kappa \le 1`, and :math:`\omega^2 = (N/m\ell^2)\,\mu` with
:math:`\int w'v'\,d\xi + \kappa^{-1}\int w''v''\,d\xi` where :math:`\kappa > 1`, so that
any magnitudes whose frequencies a float holds give them; by shift-invert Lanczos on the
band, checked by residual, mass orthonormality and a Sturm count (`skcable._eigen`).

`strand_bending_frequencies` gives the frequencies at the stick and at the slip stiffness of the
strand's bending law (`Section.EI_stick`, `Section.EI_slip`; Pino Vidal 2021, §3.1; Cardou
2013), intact or damaged: the two bounds between which a slipping strand's frequency lies.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np
from skfem import Basis, BilinearForm, ElementLineHermite, MeshLine
from skfem.helpers import dd, ddot

from skcable._checks import TINY, nonnegative, one_of, positive, scalar, whole
from skcable._eigen import BandPattern, farthest_from_one, first_lobe_positive, lowest_modes
from skcable._show import Shown, attributes, counted
from skcable.errors import InputError

__all__ = [
    "BeamFrequencies",
    "StrandFrequencies",
    "beam_frequencies",
    "pinned_beam_frequencies",
    "strand_bending_frequencies",
]

_ENDS = ("clamped", "pinned")


def _scalar(name, value, check=positive):
    return check(name, scalar(name, value))


def pinned_beam_frequencies(EI, N, length, mass_per_length, *, n_modes=6):
    r"""Closed-form frequencies (Hz) of a pinned–pinned beam under tension, ``ω_n / 2π`` of the
    module docstring (Rao 2007, §11.6).

    Parameters
    ----------
    EI : float
        Bending stiffness (N m²), > 0.
    N : float
        Axial tension (N), >= 0.
    length : float
        Distance between the supports (m), > 0.
    mass_per_length : float
        Mass per length (kg/m), > 0.
    n_modes : int
        Number of modes, 1 to 40.

    Returns
    -------
    ndarray (n_modes,)
        Frequencies (Hz), ascending.
    """
    EI, length, m = _scalar("EI", EI), _scalar("length", length), _scalar("mass_per_length", mass_per_length)
    N = _scalar("N", N, nonnegative)
    n = np.arange(1, whole("n_modes", n_modes, 1, 40) + 1)
    k = n * np.pi / length
    f = np.array([_pinned_mode(kn, EI, N, m) for kn in k.tolist()])
    if not (np.all(np.isfinite(f)) and np.all(f >= TINY)):
        blame = {"EI": EI, "length": length, "mass_per_length": m} | ({"N": N} if N > 0 else {})
        raise InputError(farthest_from_one(**blame), "gives frequencies outside the range of a float")
    return f


def _pinned_mode(k, EI, N, m):
    """(k/2π) sqrt((k² EI + N)/m) in Python floats (inf on overflow, no warning), its larger
    term factored out: k² sqrt(EI/m) sqrt(1 + r) or k sqrt(N/m) sqrt(1 + 1/r), r = N/(k² EI)."""
    kk = k * k
    ratio = N / EI / kk if kk > 0.0 else math.inf  # the string's share
    if ratio <= 1.0:
        return kk * (math.sqrt(EI) / math.sqrt(m)) * math.sqrt(1.0 + ratio) / (2.0 * math.pi)
    return k * (math.sqrt(N) / math.sqrt(m)) * math.sqrt(1.0 + 1.0 / ratio) / (2.0 * math.pi)


class BeamFrequencies(Shown):
    """Result of `beam_frequencies`.

    Attributes
    ----------
    f : (n_modes,) array
        Natural frequencies (Hz), ascending.
    x : (n_nodes,) array
        Node abscissae (m), ends included.
    modes : (n_modes, n_nodes) array
        Transverse displacement of each mode at the nodes, mass-normalised
        (``φᵀMφ = 1`` with the consistent mass), each signed so that its first
        lobe from ``x = 0`` is positive.
    EI, N, length, mass_per_length, ends : as given.
    pinned_closed_form : (n_modes,) array
        `pinned_beam_frequencies` for the same data (the exact value for
        ``ends="pinned"``, a lower bound for clamped ends).
    """

    f: np.ndarray
    x: np.ndarray
    modes: np.ndarray
    EI: float
    N: float
    length: float
    mass_per_length: float
    ends: str
    pinned_closed_form: np.ndarray

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        shown = attributes(
            self, {"f": "Hz", "EI": "N·m²", "N": "N", "length": "m", "mass_per_length": "kg/m"}
        )
        return f"BeamFrequencies({self.ends}, {counted([len(self.f)], 'mode')}: {shown})"


@BilinearForm
def _bending(u, v, p):
    return ddot(dd(u), dd(v))


@BilinearForm
def _geometric(u, v, p):
    return u.grad[0] * v.grad[0]


@BilinearForm
def _mass(u, v, p):
    return u * v


class _UnitBeam(NamedTuple):
    """Hermite elements on [0, 1] with the ends' DOFs fixed: the bands of the bending,
    geometric and mass matrices on the free DOFs, where each node's displacement is in
    them (-1 where fixed), and the nodes' ξ."""

    bending: np.ndarray
    geometric: np.ndarray
    mass: np.ndarray
    displacement: np.ndarray
    xi: np.ndarray


def _band(form, basis, free):
    """The upper band of ``form`` assembled on ``basis``, on the DOFs ``free``."""
    coo = form.coo_data(basis)
    rows, cols = coo.indices
    return BandPattern(rows, cols, free, basis.N).band(coo.data)


@functools.lru_cache(maxsize=16)
def _unit_beam(n_elements: int, ends: str) -> _UnitBeam:
    mesh = MeshLine(np.linspace(0.0, 1.0, n_elements + 1))
    basis = Basis(mesh, ElementLineHermite())
    boundary = basis.get_dofs()  # the two end nodes
    fixed = boundary.nodal["u"] if ends == "pinned" else boundary.all()
    free = basis.complement_dofs(fixed)  # node by node: banded
    position = np.full(basis.N, -1)
    position[free] = np.arange(free.size)
    bending, geometric, mass = (_band(form, basis, free) for form in (_bending, _geometric, _mass))
    beam = _UnitBeam(bending, geometric, mass, position[basis.nodal_dofs[0]], mesh.p[0].copy())
    for array in beam:
        array.flags.writeable = False
    return beam


def beam_frequencies(EI, N, length, mass_per_length, *, ends="clamped", n_modes=6, n_elements=None):
    r"""Bending frequencies of a tensioned beam, clamped or pinned at both ends: finite elements
    on scikit-fem (cubic Hermite, consistent mass; the module docstring).

    Parameters
    ----------
    EI, N, length, mass_per_length : float
        As `pinned_beam_frequencies`.
    ends : {"clamped", "pinned"}
        Both ends clamped (no displacement, no rotation) or pinned (no
        displacement).
    n_modes : int
        Number of modes, 1 to 40.
    n_elements : int, optional
        Elements along the beam (default ``max(96, 16 n_modes)``; >= 2 n_modes).

    Returns
    -------
    BeamFrequencies

    Raises
    ------
    InputError
        A non-physical argument, named; or magnitudes whose frequencies or mode
        shapes a float cannot hold (the argument farthest from 1 is named).
    ConvergenceError
        The eigenpairs failed their checks (`skcable._eigen`).
    """
    EI, length, m = _scalar("EI", EI), _scalar("length", length), _scalar("mass_per_length", mass_per_length)
    N = _scalar("N", N, nonnegative)
    one_of("ends", ends, _ENDS)
    n_modes = whole("n_modes", n_modes, 1, 40)
    if n_elements is None:
        n_elements = max(96, 16 * n_modes)
    if isinstance(n_elements, (bool, np.bool_)) or not isinstance(n_elements, (int, np.integer)):
        raise InputError("n_elements", f"must be a whole number, got {n_elements!r}")
    if not 2 * n_modes <= n_elements <= 4000:
        raise InputError("n_elements", f"must lie in [2 n_modes = {2 * n_modes}, 4000], got {n_elements}")

    beam = _unit_beam(int(n_elements), ends)
    f, phi = _solve(beam, EI, N, length, m, n_modes)
    mode_scale = 1.0 / (math.sqrt(m) * math.sqrt(length))  # the mass is m l times the unit one
    if not (np.isfinite(mode_scale) and mode_scale >= TINY):
        blame = farthest_from_one(length=length, mass_per_length=m)
        raise InputError(blame, "gives mode shapes outside the range of a float")
    modes = np.where(beam.displacement >= 0, phi.T[:, beam.displacement], 0.0) * mode_scale
    return BeamFrequencies(
        f=f,
        x=length * beam.xi,
        modes=first_lobe_positive(modes),
        EI=EI,
        N=N,
        length=length,
        mass_per_length=m,
        ends=ends,
        pinned_closed_form=pinned_beam_frequencies(EI, N, length, m, n_modes=n_modes),
    )


def _solve(beam, EI, N, length, m, n_modes):
    """Frequencies (Hz) and unit-mass-normalised eigenvectors of the dimensionless beam."""
    kappa = N / EI * length * length  # N l²/EI
    if kappa <= 1.0:  # the bending term leads: omega² = EI/(m l⁴) mu
        stiffness = beam.bending + kappa * beam.geometric
        scale, blame = math.sqrt(EI) / math.sqrt(m) / length / length, {"EI": EI}
    else:  # the tension leads: omega² = N/(m l²) mu
        stiffness = beam.geometric + beam.bending / kappa
        scale, blame = math.sqrt(N) / math.sqrt(m) / length, {"N": N}
    mu, phi = lowest_modes(stiffness, beam.mass, n_modes, what="beam_frequencies")
    f = np.sqrt(mu) * scale / (2.0 * np.pi)
    if not (np.all(np.isfinite(f)) and np.all(f >= TINY)):
        blame |= {"length": length, "mass_per_length": m}
        raise InputError(farthest_from_one(**blame), "gives frequencies outside the range of a float")
    return f, phi


class StrandFrequencies(Shown):
    """Result of `strand_bending_frequencies`.

    Attributes
    ----------
    f_stick, f_slip : (n_modes,) arrays
        Bending frequencies (Hz) with the stick and the full-slip bending
        stiffness about the chosen principal axis.
    EI_stick, EI_slip : float
        Those stiffnesses (N m²).
    drop : (n_modes,) array
        ``1 - f_slip / f_stick``: the relative drop of each frequency when the
        wires slip.
    stick, slip : BeamFrequencies
        The two full results (mode shapes included).
    axis : int
        Principal axis (0: axis 1, the stiffer; 1: axis 2).
    """

    f_stick: np.ndarray
    f_slip: np.ndarray
    EI_stick: float
    EI_slip: float
    drop: np.ndarray
    stick: BeamFrequencies
    slip: BeamFrequencies
    axis: int

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        shown = attributes(
            self, {"f_stick": "Hz", "f_slip": "Hz", "drop": "", "EI_stick": "N·m²", "EI_slip": "N·m²"}
        )
        modes = counted([len(self.f_stick)], "mode")
        return f"StrandFrequencies(principal axis {self.axis + 1}, {modes}: {shown})"


def strand_bending_frequencies(
    section, N, length, mass_per_length, *, axis=0, ends="clamped", n_modes=6, n_elements=None
):
    r"""Bending frequencies of a tensioned strand with its stick and slip stiffness.

    The tensioned beam of `beam_frequencies` with the bending stiffness ``section.EI_stick[axis]``
    (wires bonded: small amplitudes) and ``section.EI_slip[axis]`` (wires slipping freely: the
    limit of large amplitudes) of Cardou's law (Pino Vidal 2021, §3.1, eqs. 3.11–3.12).

    Parameters
    ----------
    section : Section
        ``strand.section()`` of an intact or damaged strand.
    N, length, mass_per_length : float
        As `pinned_beam_frequencies` (the strand's mass per length, e.g. density × area).
    axis : {0, 1}
        Principal axis of bending (0: axis 1, 1: axis 2).
    ends, n_modes, n_elements
        As `beam_frequencies`.

    Returns
    -------
    StrandFrequencies
    """
    from skcable.strand._arguments import principal_axis
    from skcable.strand._section import checked_section

    checked_section(section)
    axis = principal_axis(axis)
    EI_stick, EI_slip = float(section.EI_stick[axis]), float(section.EI_slip[axis])
    kw = dict(ends=ends, n_modes=n_modes, n_elements=n_elements)
    stick = beam_frequencies(EI_stick, N, length, mass_per_length, **kw)
    slip = beam_frequencies(EI_slip, N, length, mass_per_length, **kw)
    return StrandFrequencies(
        f_stick=stick.f,
        f_slip=slip.f,
        EI_stick=EI_stick,
        EI_slip=EI_slip,
        drop=1.0 - slip.f / stick.f,
        stick=stick,
        slip=slip,
        axis=axis,
    )
