r"""Wire constitutive law: bilinear with a C¹ cubic blend (seed 003 eq. 3.21, annex B).

.. math::
    \sigma(\varepsilon) = \begin{cases}
      E_e\,\varepsilon & |\varepsilon| \le \varepsilon'_y \\
      a t^3 + b t^2 + c t + d,\quad t = \varepsilon - \varepsilon'_y
        & \varepsilon'_y < |\varepsilon| < \varepsilon''_y \\
      E_e\,\varepsilon_y + E_p(\varepsilon - \varepsilon_y) & |\varepsilon| \ge \varepsilon''_y
    \end{cases}

odd in ε. The cubic's coefficients follow from the C¹ conditions B.1–B.4
(slope ``E_e`` and value ``E_e ε'_y`` at ε'_y; slope ``E_p`` and the
hardening line's value at ε''_y); they are computed, not typed in. The
third branch is the line through (ε_y, E_e ε_y) of slope E_p, as B.4
states; eq. 3.21 writes it through ε'_y, a misprint (B.4 is the form that
gives Table 3.4's rupture stress, 1443 MPa for steel).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable._checks import positive, real
from skcable.errors import InputError

__all__ = ["Material", "material"]


@dataclass(frozen=True)
class Material:
    """Bilinear wire material with a cubic C¹ blend around yield. SI units.

    Parameters
    ----------
    E_e, E_p : float
        Elastic and hardening moduli (Pa), ``E_e > E_p >= 0``.
    eps_y : float
        Yield strain of the bilinear law.
    eps_y1, eps_y2 : float
        Start and end of the blend, ``0 < eps_y1 < eps_y < eps_y2``.
    eps_rupture : float
        Strain at which a wire breaks (``> eps_y2``).
    poisson : float
        Poisson's ratio (for the shear modulus of the wires), default 0.3.
    name : str
        Label.
    """

    E_e: float
    E_p: float
    eps_y: float
    eps_y1: float
    eps_y2: float
    eps_rupture: float
    poisson: float = 0.3
    name: str = ""
    _cubic: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        E_e, E_p = positive("E_e", self.E_e), float(real("E_p", self.E_p))
        if not 0 <= E_p < E_e:
            raise InputError("E_p", f"must satisfy 0 <= E_p < E_e, got {E_p!r}")
        e1, ey, e2 = (positive(n, getattr(self, n)) for n in ("eps_y1", "eps_y", "eps_y2"))
        if not e1 < ey < e2:
            raise InputError("eps_y", f"need eps_y1 < eps_y < eps_y2, got {e1!r}, {ey!r}, {e2!r}")
        if not positive("eps_rupture", self.eps_rupture) > e2:
            raise InputError("eps_rupture", f"must exceed eps_y2 = {e2!r}")
        if not 0 <= self.poisson < 0.5:
            raise InputError("poisson", f"must lie in [0, 0.5), got {self.poisson!r}")
        # B.1 slope E_e and B.3 value at eps_y1 give c and d; B.2 and B.4 a and b
        delta = e2 - e1
        lhs = np.array([[3 * delta**2, 2 * delta], [delta**3, delta**2]])
        rhs = np.array([E_p - E_e, E_e * ey + E_p * (e2 - ey) - E_e * e1 - E_e * delta])
        a, b = np.linalg.solve(lhs, rhs)
        object.__setattr__(self, "_cubic", (float(a), float(b), E_e, E_e * e1))

    @property
    def a(self) -> float:
        """Cubic coefficient (Pa per strain³)."""
        return self._cubic[0]

    @property
    def b(self) -> float:
        """Quadratic coefficient (Pa per strain²)."""
        return self._cubic[1]

    @property
    def c(self) -> float:
        """Linear coefficient, equal to ``E_e`` (Pa)."""
        return self._cubic[2]

    @property
    def d(self) -> float:
        """Constant term, ``E_e · eps_y1`` (Pa)."""
        return self._cubic[3]

    @property
    def G(self) -> float:
        """Elastic shear modulus ``E_e / (2 (1 + poisson))`` (Pa)."""
        return self.E_e / (2.0 * (1.0 + self.poisson))

    @property
    def stress_rupture(self) -> float:
        """Stress at ``eps_rupture`` (Pa)."""
        return float(self.stress(self.eps_rupture))

    def _branches(self, strain):
        eps = np.abs(np.asarray(strain, dtype=float))
        t = eps - self.eps_y1
        a, b, c, d = self._cubic
        elastic = eps <= self.eps_y1
        plastic = eps >= self.eps_y2
        return eps, t, elastic, plastic, (a, b, c, d)

    def stress(self, strain):
        """Stress (Pa) at ``strain``; vectorised, odd in the strain."""
        eps, t, elastic, plastic, (a, b, c, d) = self._branches(strain)
        blend = ((a * t + b) * t + c) * t + d
        line = self.E_e * self.eps_y + self.E_p * (eps - self.eps_y)
        out = np.where(elastic, self.E_e * eps, np.where(plastic, line, blend))
        out = np.copysign(out, strain)
        return out[()] if out.ndim == 0 else out

    def tangent(self, strain):
        """Tangent modulus dσ/dε (Pa) at ``strain``; vectorised, even."""
        eps, t, elastic, plastic, (a, b, c, _) = self._branches(strain)
        out = np.where(elastic, self.E_e, np.where(plastic, self.E_p, (3 * a * t + 2 * b) * t + c))
        return out[()] if out.ndim == 0 else out

    @property
    def softening_range(self) -> tuple[float, float] | None:
        """Strains ``(lo, hi)`` inside the blend where the tangent is negative, or None.

        The C¹ cubic (B.1–B.4) is fixed by its end values and slopes; when the line
        beyond ε″_y lies low enough it overshoots and the law softens before it rejoins
        the line (aluminium of Table B.1: its printed a, b, c give dσ/dε < 0 late in the blend).
        A softening wire law can take the strand's tangent to singular (a structural
        limit point): capacity curves that stop there say so.
        """
        a, b, c, _ = self._cubic
        roots = np.roots([3 * a, 2 * b, c])
        roots = np.sort(roots[np.isreal(roots)].real)
        if roots.size < 2 or roots[0] >= self.eps_y2 - self.eps_y1 or roots[1] <= 0:
            return None
        lo, hi = max(roots[0], 0.0), min(roots[1], self.eps_y2 - self.eps_y1)
        if float(self.tangent(self.eps_y1 + 0.5 * (lo + hi))) >= 0:
            return None
        return float(self.eps_y1 + lo), float(self.eps_y1 + hi)

    def secant(self, strain):
        """Secant modulus σ/ε (Pa); ``E_e`` at zero strain."""
        strain = np.asarray(strain, dtype=float)
        safe = np.where(strain == 0.0, 1.0, strain)
        out = np.where(strain == 0.0, self.E_e, self.stress(safe) / safe)
        return out[()] if out.ndim == 0 else out


#: Table B.1 of seed 003 (MPa in the table, Pa here).
_PRESETS = {
    "steel": dict(
        E_e=196603.774e6, E_p=5228.162e6, eps_y=0.0053, eps_y1=0.005, eps_y2=0.006, eps_rupture=0.082
    ),
    # Table B.1 prints eps_y = 0.0049; its a and b follow from 0.0049 (Table 3.3 reads 0.00449)
    "aluminium": dict(
        E_e=64509.8e6, E_p=207e6, eps_y=0.0049, eps_y1=0.003, eps_y2=0.0095, eps_rupture=0.0745
    ),
}


def material(name: str) -> Material:
    """Wire material of seed 003 Table B.1: ``"steel"`` (galvanised) or ``"aluminium"``."""
    try:
        return Material(**_PRESETS[name], name=name)
    except KeyError:
        raise InputError("name", f"unknown material {name!r}; known: {', '.join(_PRESETS)}") from None
