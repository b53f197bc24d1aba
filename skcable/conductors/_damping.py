r"""Self-damping of a vibrating conductor: from its own bending law, Foti & Martinelli's closed
form, and the published power laws.

A conductor under tension T (N) with mass m (kg/m) vibrating at frequency f (Hz) in a loop of a
taut string has the wavelength :math:`\lambda = \sqrt{T/m}/f` and, at the antinode amplitude y
(m, zero to peak), the curvature :math:`\kappa(x) = (4\pi^2 y/\lambda^2)\sin(2\pi x/\lambda)`.
Each point loses per cycle the loop energy :math:`W(\kappa_a)` (J/m) of its bending law at its
curvature amplitude, so the power dissipated per unit length is

$$
P = f\,\frac{2}{\lambda}\int_0^{\lambda/2} W(\kappa(x))\,dx
  = f\,\frac{2}{\pi}\int_0^{\pi/2} W(\kappa_0\sin u)\,du,
\qquad \kappa_0 = \frac{4\pi^2 y}{\lambda^2} = \frac{4\pi^2 y f^2 m}{T}
$$

(`self_damping`; a `skcable.strand.StageLaw` gives the integral in closed form,
`StageLaw.sine_averaged_energy`; any other law with ``energy_per_cycle(kappa_a, axis)``, by
64-point Gauss–Legendre quadrature). Since P depends on y, f, T and m only through
:math:`f\,\bar W(\kappa_0)`, a loop energy :math:`W \propto \kappa_a^p` gives
:math:`P \propto y^p f^{2p+1} m^p / T^p`; for a stick/slip law p varies with the amplitude and
`damping_exponents` gives the local exponents :math:`l = p`, :math:`m = 2p + 1`, :math:`n = p`,
:math:`p = d\ln\bar W/d\ln\kappa_0`.

**Foti & Martinelli's closed form** (F. Foti, L. Martinelli, "An enhanced unified model for the
self-damping of stranded cables under aeolian vibrations", J. Wind Eng. Ind. Aerodyn. 182, 2018,
eqs. 23–30): with the limit curvature :math:`\kappa_0` and the stick stiffness
:math:`EI_{\max}` of the linearised law (`StageLaw.kappa_0`, `StageLaw.EI_max`),

$$
P = G_1(k_n)\,\frac{128\pi^5 m^3 EI_{\max}}{\kappa_0}\frac{y^3 f^7}{T^3}
  + G_2(k_n)\,4\pi^3 m^2 EI_{\max}\frac{y^2 f^5}{T^2},
$$

:math:`G_1 = 1/3 - (3/8)\cos 2\pi k_n + (1/24)\cos 6\pi k_n`,
:math:`G_2 = \pi - 4\pi k_n + \sin 4\pi k_n`, :math:`2\pi k_n = \arcsin\min(1,
\kappa_0\lambda^2/4\pi^2 y)`: the string-loop integral of the loop energy
:math:`W = EI_{\max}\kappa_a^3/(2\kappa_0)` (micro-slip, :math:`\kappa_a \le \kappa_0`) and
:math:`EI_{\max}\kappa_a^2/2` (gross slip) beyond. It is evaluated here in that integrated form,
without cancellation: with :math:`r = \min(1, \kappa_0/\kappa_{y})`, :math:`\kappa_y = 4\pi^2 y /
\lambda^2`, :math:`s = \sqrt{1 - r^2}`, :math:`\psi = \arccos r`,

$$
P = \frac{f\,EI_{\max}}{\pi}\left[\frac{\kappa_y^3}{\kappa_0}\frac{(1 - s)^2(2 + s)}{3}
    + \frac{\kappa_y^2}{2}(\psi + r s)\right].
$$

**Power laws** :math:`P = k\,y^l f^m / T^n` fitted to laboratory measurements (SI units here: y
in m, f in Hz, T in N, P in W/m; k depends on the conductor and on these units): exponents of
`DAMPING_EXPONENTS`, as compiled in RTE's pallas-dohl (rte-france/pallas-dohl,
``src/dohl/damping_power_data.yaml``).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import broadcast, positive
from skcable.errors import InputError

__all__ = ["DAMPING_EXPONENTS", "damping_exponents", "foti_damping", "power_law_damping", "self_damping"]

#: Exponents (l, m, n) of the published power laws P = k y^l f^m / T^n, by study.
DAMPING_EXPONENTS = {
    "noiseux-1991": (2.44, 5.63, 2.76),  # Noiseux (1991)
    "kraus-hagedorn-1991": (2.47, 5.38, 2.80),  # Kraus & Hagedorn (1991)
    "seppa-1971": (2.5, 5.75, 2.8),  # Seppa (1971)
    "moecks-schmidt-1989": (2.45, 5.38, 2.4),  # Möcks & Schmidt (1989)
    "politecnico-milano-2000": (2.43, 5.5, 2.0),  # Mechanical Laboratory, Politecnico di Milano (2000)
}

#: Gauss–Legendre nodes and weights on [0, π/2] for laws without a closed form.
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(64)
_U, _W = np.pi / 4 * (_NODES + 1.0), np.pi / 4 * _WEIGHTS


def _positive(**values):
    out = {name: positive(name, value) for name, value in values.items()}
    broadcast(**out)
    return out


def _curvature_amplitude(y, f, tension, mass):
    """κ_0 = 4π² y f² m / T (1/m): the curvature at the antinode of the string loop."""
    kappa = 4.0 * np.pi**2 * y * f * f * mass / tension
    if not np.all(np.isfinite(kappa)):
        raise InputError("y", "gives an antinode curvature 4π² y f² m / T beyond floating point")
    return kappa


def _scalar_or_array(value):
    value = np.asarray(value, dtype=float)
    return float(value) if value.ndim == 0 else value


def _averaged(law, kappa_0, axis):
    """(2/π) ∫_0^{π/2} W(κ_0 sin u) du of ``law`` (J/m)."""
    exact = getattr(law, "sine_averaged_energy", None)
    if callable(exact):
        return np.asarray(exact(kappa_0, axis), dtype=float)
    energy = getattr(law, "energy_per_cycle", None)
    if not callable(energy):
        raise InputError("law", f"must have energy_per_cycle(kappa_a, axis) (a bending law), got {law!r:.80}")
    values = np.asarray(energy(np.multiply.outer(kappa_0, np.sin(_U)), axis), dtype=float)
    if values.shape != np.shape(kappa_0) + _U.shape or not np.all(np.isfinite(values)) or np.any(values < 0):
        raise InputError("law", "energy_per_cycle must return finite energies >= 0 of the shape of kappa_a")
    return 2.0 / np.pi * values @ _W


def self_damping(law, y, f, tension, mass, *, axis: int = 0):
    r"""Power (W/m) a conductor dissipates vibrating in a loop of a taut string, from the loop
    energy of its bending law (module text: :math:`P = f\,(2/\pi)\int_0^{\pi/2}
    W(\kappa_0\sin u)\,du`, :math:`\kappa_0 = 4\pi^2 y f^2 m/T`).

    Parameters
    ----------
    law : StageLaw or object with ``energy_per_cycle(kappa_a, axis)``
        The conductor's bending law, e.g. ``strand.LayerSlipLaw(section, mu=0.7, tension=T)``
        (at the same tension as ``tension``).
    y : float or array_like
        Antinode amplitude, zero to peak (m), > 0.
    f : float or array_like
        Frequency (Hz), > 0.
    tension : float or array_like
        Conductor tension (N), > 0.
    mass : float or array_like
        Mass per unit length (kg/m), > 0.
    axis : {0, 1}
        The principal axis of the law the conductor bends about.

    Returns
    -------
    float or ndarray
        The power per unit length (W/m), broadcast over the arguments; 0 where the curvature
        stays below every knee (a stick/slip law dissipates nothing there).
    """
    values = _positive(y=y, f=f, tension=tension, mass=mass)
    kappa_0 = _curvature_amplitude(values["y"], values["f"], values["tension"], values["mass"])
    return _scalar_or_array(values["f"] * _averaged(law, kappa_0, axis))


def damping_exponents(law, y, f, tension, mass, *, axis: int = 0):
    r"""The local exponents (l, m, n) of the model's self-damping, :math:`P \propto y^l f^m / T^n`
    at (y, f, T): :math:`l = n = p`, :math:`m = 2p + 1`, with :math:`p = d\ln\bar W/d\ln\kappa_0`
    of the law's sine-averaged loop energy (module text). Arguments as `self_damping`; the law
    must give ``sine_averaged_energy(kappa_0, axis, derivative=True)`` (a `StageLaw` does).

    Returns
    -------
    tuple of float or ndarray
        ``(l, m, n)``, broadcast over the arguments.

    Raises
    ------
    InputError
        ``y`` where the curvature stays below every knee (no dissipation, no exponent); ``law``
        without the closed form.
    """
    values = _positive(y=y, f=f, tension=tension, mass=mass)
    kappa_0 = _curvature_amplitude(values["y"], values["f"], values["tension"], values["mass"])
    exact = getattr(law, "sine_averaged_energy", None)
    if not callable(exact):
        raise InputError(
            "law", f"must give sine_averaged_energy(kappa_0, axis, derivative=True), got {law!r:.80}"
        )
    energy, slope = (np.asarray(v, dtype=float) for v in exact(kappa_0, axis, derivative=True))
    if not np.all(energy > 0):
        raise InputError(
            "y", "leaves the curvature below every knee of the law: it dissipates nothing, no exponent"
        )
    p = _scalar_or_array(np.broadcast_to(kappa_0 * slope / energy, np.shape(energy)))
    return p, 2.0 * p + 1.0, p


def foti_damping(y, f, tension, mass, EI_max, kappa_0):
    r"""Foti & Martinelli (2018)'s self-damping power (W/m), in closed form (module text).

    Parameters
    ----------
    y, f, tension, mass : float or array_like
        As in `self_damping`.
    EI_max : float or array_like
        Stick bending stiffness of the linearised law (N·m²), > 0 (`StageLaw.EI_max`).
    kappa_0 : float or array_like
        Its limit curvature (1/m), > 0 (`StageLaw.kappa_0`).

    Returns
    -------
    float or ndarray
        The power per unit length (W/m), broadcast over the arguments.
    """
    v = _positive(y=y, f=f, tension=tension, mass=mass, EI_max=EI_max, kappa_0=kappa_0)
    k_y = _curvature_amplitude(v["y"], v["f"], v["tension"], v["mass"])
    r = np.minimum(1.0, v["kappa_0"] / k_y)
    s = np.sqrt((1.0 - r) * (1.0 + r))
    micro = k_y**3 / v["kappa_0"] * (r * r / (1.0 + s)) ** 2 * (2.0 + s) / 3.0  # (1 - s)² = (r²/(1 + s))²
    gross = k_y**2 / 2.0 * (np.arctan2(s, r) + r * s)
    power = v["f"] * v["EI_max"] / np.pi * (micro + gross)
    if not np.all(np.isfinite(power)):
        raise InputError("y", "gives a damping power beyond floating point")
    return _scalar_or_array(power)


def power_law_damping(y, f, tension, k, exponents="noiseux-1991"):
    r"""A published self-damping power law :math:`P = k\,y^l f^m / T^n` (W/m; SI units).

    Parameters
    ----------
    y, f, tension : float or array_like
        Antinode amplitude zero to peak (m), frequency (Hz), tension (N), each > 0.
    k : float
        The law's constant for the conductor, in these units (> 0): fitted to a measurement or
        to another model at one point, ``k = P T^n / (y^l f^m)``.
    exponents : str or (l, m, n)
        A key of `DAMPING_EXPONENTS` or the three exponents.
    """
    if isinstance(exponents, str):
        if exponents not in DAMPING_EXPONENTS:
            raise InputError(
                "exponents", f"must be one of {sorted(DAMPING_EXPONENTS)} or (l, m, n), got {exponents!r}"
            )
        l, m, n = DAMPING_EXPONENTS[exponents]
    else:
        try:
            l, m, n = (float(e) for e in exponents)
        except (TypeError, ValueError):
            raise InputError(
                "exponents", f"must be a name or three numbers (l, m, n), got {exponents!r}"
            ) from None
        if not all(np.isfinite([l, m, n])):
            raise InputError("exponents", f"must be finite, got {exponents!r}")
    v = _positive(y=y, f=f, tension=tension, k=k)
    power = v["k"] * v["y"] ** l * v["f"] ** m / v["tension"] ** n
    if not np.all(np.isfinite(power)):
        raise InputError("k", "gives a damping power beyond floating point")
    return _scalar_or_array(power)
