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
a generalized symmetric eigenproblem solved by `scipy.linalg.eigh`; with
:math:`N = 0` its first root is :math:`\beta_1\ell = 4.7300407\ldots` of
:math:`\cos\beta\ell\cosh\beta\ell = 1` (Rao 2007, §11.5).

The strand's stiffness is that of its stick/slip bending law
(`Section.EI_stick`, `Section.EI_slip`; Pino Vidal 2021, §3.1; Cardou 2013):
`strand_bending_frequencies` gives the frequencies of both, for the intact or
a damaged strand, so that the drop when the wires slip (small amplitudes
vibrate at the stick stiffness, large ones tend to the slip stiffness) and
when wires break can be read off. Those are the two bounds of a bilinear law:
the frequency of a slipping strand at a given amplitude lies between them.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import eigh
from skfem import Basis, BilinearForm, ElementLineHermite, MeshLine
from skfem.helpers import dd, ddot

from skcable._checks import nonnegative, positive, scalar, whole
from skcable.errors import ConvergenceError, InputError

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
    r"""Closed-form frequencies (Hz) of a pinned–pinned beam under tension.

    :math:`f_n = \frac{1}{2\pi}(n\pi/\ell)^2\sqrt{EI/m}\sqrt{1 + N\ell^2/(n^2\pi^2EI)}`
    (S.S. Rao, "Vibration of Continuous Systems", Wiley, 2007, §11.6).

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
    return k**2 * np.sqrt(EI / m) * np.sqrt(1.0 + N / (k**2 * EI)) / (2.0 * np.pi)


class BeamFrequencies:
    """Result of `beam_frequencies`.

    Attributes
    ----------
    f : (n_modes,) array
        Natural frequencies (Hz), ascending.
    x : (n_nodes,) array
        Node abscissae (m), ends included.
    modes : (n_modes, n_nodes) array
        Transverse displacement of each mode at the nodes, mass-normalised
        (``φᵀMφ = 1`` with the consistent mass).
    EI, N, length, mass_per_length, ends : as given.
    pinned_closed_form : (n_modes,) array
        `pinned_beam_frequencies` for the same data (the exact value for
        ``ends="pinned"``, a lower bound for clamped ends).
    """

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        return f"BeamFrequencies(ends={self.ends!r}, f={np.round(self.f, 6).tolist()})"


@BilinearForm
def _bending(u, v, p):
    return ddot(dd(u), dd(v))


@BilinearForm
def _geometric(u, v, p):
    return u.grad[0] * v.grad[0]


@BilinearForm
def _mass(u, v, p):
    return u * v


def beam_frequencies(EI, N, length, mass_per_length, *, ends="clamped", n_modes=6, n_elements=None):
    r"""Bending frequencies of a tensioned beam, clamped or pinned at both ends.

    Finite elements on scikit-fem (cubic Hermite, consistent mass) of
    :math:`EI\,w'''' - N w'' + m\ddot w = 0`; see the module docstring.

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
        A non-physical argument, named.
    ConvergenceError
        An eigenvalue came out not finite or not positive.
    """
    EI, length, m = _scalar("EI", EI), _scalar("length", length), _scalar("mass_per_length", mass_per_length)
    N = _scalar("N", N, nonnegative)
    if not isinstance(ends, str) or ends not in _ENDS:
        raise InputError("ends", f"must be one of {_ENDS}, got {ends!r}")
    n_modes = whole("n_modes", n_modes, 1, 40)
    if n_elements is None:
        n_elements = max(96, 16 * n_modes)
    if isinstance(n_elements, (bool, np.bool_)) or not isinstance(n_elements, (int, np.integer)):
        raise InputError("n_elements", f"must be a whole number, got {n_elements!r}")
    if not 2 * n_modes <= n_elements <= 4000:
        raise InputError("n_elements", f"must lie in [2 n_modes = {2 * n_modes}, 4000], got {n_elements}")

    mesh = MeshLine(np.linspace(0.0, length, int(n_elements) + 1))
    basis = Basis(mesh, ElementLineHermite())
    K = (EI * _bending.assemble(basis) + N * _geometric.assemble(basis)).toarray()
    M = m * _mass.assemble(basis).toarray()
    boundary = basis.get_dofs()  # the two end nodes
    fixed = boundary.nodal["u"] if ends == "pinned" else boundary.all()
    free = basis.complement_dofs(fixed)
    omega2, phi = eigh(K[np.ix_(free, free)], M[np.ix_(free, free)], subset_by_index=[0, n_modes - 1])
    if not (np.all(np.isfinite(omega2)) and np.all(omega2 > 0)):
        raise ConvergenceError("beam_frequencies: eigenvalues not finite and > 0", list(omega2))
    full = np.zeros((n_modes, basis.N))
    full[:, free] = phi.T
    displacement = basis.nodal_dofs[0]  # the 'u' DOF of every node, in node order
    return BeamFrequencies(
        f=np.sqrt(omega2) / (2.0 * np.pi),
        x=mesh.p[0].copy(),
        modes=full[:, displacement],
        EI=EI,
        N=N,
        length=length,
        mass_per_length=m,
        ends=ends,
        pinned_closed_form=pinned_beam_frequencies(EI, N, length, m, n_modes=n_modes),
    )


class StrandFrequencies:
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

    def __init__(self, **values):
        self.__dict__.update(values)

    def __repr__(self):
        return (
            f"StrandFrequencies(f_stick={np.round(self.f_stick, 4).tolist()}, "
            f"f_slip={np.round(self.f_slip, 4).tolist()})"
        )


def strand_bending_frequencies(
    section, N, length, mass_per_length, *, axis=0, ends="clamped", n_modes=6, n_elements=None
):
    r"""Bending frequencies of a tensioned strand with its stick and slip stiffness.

    The strand between two supports (clamps by default) under the tension
    ``N`` vibrates as the tensioned beam of `beam_frequencies` with the
    bending stiffness ``section.EI_stick[axis]`` (wires bonded: small
    amplitudes) and ``section.EI_slip[axis]`` (wires slipping freely: the
    limit of large amplitudes) of Cardou's stick/slip law (Pino Vidal 2021,
    §3.1, eqs. 3.11–3.12). A damaged strand (``strand.damaged(n).section()``)
    has its own, smaller stiffnesses and two distinct principal axes.

    Parameters
    ----------
    section : Section
        ``strand.section()`` of an intact or damaged strand.
    N : float
        Axial tension (N), >= 0.
    length : float
        Distance between the supports (m), > 0.
    mass_per_length : float
        Mass per length of the strand (kg/m), > 0 (e.g. density × area).
    axis : {0, 1}
        Principal axis of bending (0: axis 1, 1: axis 2).
    ends, n_modes, n_elements
        As `beam_frequencies`.

    Returns
    -------
    StrandFrequencies
    """
    from skcable.strand._section import Section

    if not isinstance(section, Section):
        raise InputError("section", f"must be a Section (strand.section()), got {section!r:.80}")
    if isinstance(axis, (bool, np.bool_)) or not isinstance(axis, (int, np.integer)) or axis not in (0, 1):
        raise InputError("axis", f"must be 0 (principal axis 1) or 1 (principal axis 2), got {axis!r}")
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
        axis=int(axis),
    )
