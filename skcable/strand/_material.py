r"""Wire constitutive law: bilinear with a C¹ cubic blend (Pino Vidal (2021), eq. 3.21, annex B).

$$
\sigma(\varepsilon) = \begin{cases}
  E_e\,\varepsilon & |\varepsilon| \le \varepsilon'_y \\
  a t^3 + b t^2 + c t + d,\quad t = \varepsilon - \varepsilon'_y
    & \varepsilon'_y < |\varepsilon| < \varepsilon''_y \\
  E_e\,\varepsilon_y + E_p(\varepsilon - \varepsilon_y) & |\varepsilon| \ge \varepsilon''_y
\end{cases}
$$

odd in ε. The cubic's coefficients follow from the C¹ conditions B.1–B.4
(slope ``E_e`` and value ``E_e ε'_y`` at ε'_y; slope ``E_p`` and the
hardening line's value at ε''_y); they are computed, not typed in. The
third branch is the line through (ε_y, E_e ε_y) of slope E_p, as B.4
states; eq. 3.21 writes it through ε'_y, a misprint (B.4 is the form that
gives Table 3.4's rupture stress, 1443 MPa for steel).

Reference: S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico",
Universidad de Chile, 2021 (the thesis; its tables and equations are cited by
number).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable.errors import InputError
from skcable.strand._arguments import float_array, name_text, real_number

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
    density : float or None
        Mass density (kg/m³), > 0; None (the default) when unknown: the section
        and the FE model do not need it, a conductor's weight does
        (`skcable.conductors.Conductor.from_strand` raises InputError naming it).
    alpha : float or None
        Coefficient of linear thermal expansion (1/K), finite (composite cores of
        high-temperature conductors have it near 0, some slightly below); None (the
        default) when unknown (a conductor's thermal strain needs it, as ``density``).
    """

    E_e: float
    E_p: float
    eps_y: float
    eps_y1: float
    eps_y2: float
    eps_rupture: float
    poisson: float = 0.3
    name: str = ""
    density: float | None = None
    alpha: float | None = None
    _cubic: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        E_e = real_number("E_e", self.E_e, lower=0.0, strict=True)
        E_p = real_number("E_p", self.E_p)
        if not 0 <= E_p < E_e:
            raise InputError("E_p", f"must satisfy 0 <= E_p < E_e = {E_e!r}, got {E_p!r}")
        e1, ey, e2 = (
            real_number(n, getattr(self, n), lower=0.0, strict=True) for n in ("eps_y1", "eps_y", "eps_y2")
        )
        if not e1 < ey < e2:
            raise InputError("eps_y", f"need eps_y1 < eps_y < eps_y2, got {e1!r}, {ey!r}, {e2!r}")
        rupture = real_number("eps_rupture", self.eps_rupture)
        if not rupture > e2:
            raise InputError("eps_rupture", f"must exceed eps_y2 = {e2!r}, got {rupture!r}")
        poisson = real_number("poisson", self.poisson)
        if not 0 <= poisson < 0.5:
            raise InputError("poisson", f"must lie in [0, 0.5), got {poisson!r}")
        name_text(self.name)
        values = dict(E_e=E_e, E_p=E_p, eps_y=ey, eps_y1=e1, eps_y2=e2, eps_rupture=rupture, poisson=poisson)
        if self.density is not None:
            values["density"] = real_number("density", self.density, lower=0.0, strict=True)
        if self.alpha is not None:
            values["alpha"] = real_number("alpha", self.alpha)  # carbon-fibre cores: about 0, or below
        for key, value in values.items():  # plain floats (np.float32 etc. are not kept)
            object.__setattr__(self, key, value)
        # B.1 slope E_e and B.3 value at eps_y1 give c and d; B.2 and B.4 a and b
        delta = e2 - e1
        lhs = np.array([[3 * delta**2, 2 * delta], [delta**3, delta**2]])
        rhs = np.array([E_p - E_e, E_e * ey + E_p * (e2 - ey) - E_e * e1 - E_e * delta])
        a, b = np.linalg.solve(lhs, rhs)
        object.__setattr__(self, "_cubic", (float(a), float(b), E_e, E_e * e1))

    def __repr__(self):
        return (
            f"Material({self.name or 'custom'!r}: E_e={self.E_e:.4g} Pa, E_p={self.E_p:.4g} Pa, "
            f"eps_y={self.eps_y:g} (blend {self.eps_y1:g} to {self.eps_y2:g}), "
            f"eps_rupture={self.eps_rupture:g}, poisson={self.poisson:g}"
            + (f", density={self.density:g} kg/m³" if self.density is not None else "")
            + (f", alpha={self.alpha:g} 1/K" if self.alpha is not None else "")
            + ")"
        )

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

    def stress(self, strain):
        """Stress (Pa) at ``strain``: element-wise over an array of any shape, odd in the strain.

        Strings, booleans and other non-numbers raise InputError. Non-finite strains are
        not refused: they give non-finite stresses (the finite-element model relies on this
        to report a diverged Newton iterate as a ConvergenceError, not as bad input).
        """
        out, _ = self.stress_and_tangent(float_array("strain", strain, finite=False, empty=True))
        return out[()] if out.ndim == 0 else out

    def tangent(self, strain):
        """Tangent modulus dσ/dε (Pa) at ``strain``: element-wise, even in the strain
        (inputs as for `stress`)."""
        _, out = self.stress_and_tangent(float_array("strain", strain, finite=False, empty=True))
        return out[()] if out.ndim == 0 else out

    def stress_and_tangent(self, strain: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """`stress` and `tangent` of a float array in one pass, without input checks (the
        finite-element models' hot path)."""
        stress, tangent, _ = self._evaluate(strain, law=True, energy=False)
        return stress, tangent

    def energy(self, strain: np.ndarray) -> np.ndarray:
        r"""Strain energy density :math:`W(\varepsilon) = \int_0^\varepsilon \sigma\,d\varepsilon` (J/m³)
        of a float array, without input checks (even in the strain):
        ½E_eε² on the linear branch, the integral of the cubic blend (t = |ε| − ε'_y)
        :math:`W(\varepsilon'_y) + d t + c t^2/2 + b t^3/3 + a t^4/4`, then the hardening line's
        :math:`W(\varepsilon''_y) + E_e\varepsilon_y(|\varepsilon| - \varepsilon''_y)
        + \tfrac12 E_p[(|\varepsilon| - \varepsilon_y)^2 - (\varepsilon''_y - \varepsilon_y)^2]`."""
        return self._evaluate(strain, law=False, energy=True)[2]

    def stress_tangent_energy(self, strain: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """`stress_and_tangent` and `energy` of a float array in one pass (the finite-element
        models' hot path), without input checks; the same numbers, bit for bit."""
        stress, tangent, energy = self._evaluate(strain, law=True, energy=True)
        return stress, tangent, energy

    def _evaluate(self, strain, law: bool, energy: bool):
        """``(stress, tangent, energy)`` (None for what is not asked), each branch of the law
        evaluated only where some point lies on it: a point takes its own branch's value, so the
        numbers are those of evaluating every branch everywhere and selecting (``np.where``)."""
        eps = np.abs(strain)
        e1, e2, ey, E_e, E_p = self.eps_y1, self.eps_y2, self.eps_y, self.E_e, self.E_p
        elastic = plastic = None  # the masks, where more than one branch is on
        if eps.max(initial=-np.inf) <= e1:  # every point elastic (NaN fails every comparison)
            on = (True, False, False)
        elif eps.min(initial=np.inf) >= e2:  # every point on the hardening line
            on = (False, True, False)
        else:
            elastic, plastic = eps <= e1, eps >= e2
            n_elastic, n_plastic = int(np.count_nonzero(elastic)), int(np.count_nonzero(plastic))
            on = (n_elastic > 0, n_plastic > 0, n_elastic + n_plastic < eps.size)  # NaN: in the blend
        t = eps - e1 if on[2] else None
        over = eps - ey if on[1] else None  # beyond the bilinear yield, on the hardening line
        a, b, c, d = self._cubic
        stress = tangent = density = None
        if law:  # in place on temporaries: the operations of E_e ε_y + E_p (ε − ε_y), Horner's cubic
            line = blend = slope = None
            if over is not None:
                line = np.multiply(E_p, over)
                line += E_e * ey
            if t is not None:  # on[2]
                blend = np.multiply(a, t)  # ((a t + b) t + c) t + d
                blend += b
                blend *= t
                blend += c
                blend *= t
                blend += d
                slope = np.multiply(3 * a, t)  # (3 a t + 2 b) t + c
                slope += 2 * b
                slope *= t
                slope += c
            stress = _select(eps, elastic, plastic, on, E_e * eps if on[0] else None, line, blend)
            np.copysign(stress, strain, out=stress)
            tangent = _select(eps, elastic, plastic, on, E_e, E_p, slope)
        if energy:

            def cubic(t):
                return (((a / 4 * t + b / 3) * t + c / 2) * t + d) * t

            W1 = 0.5 * E_e * e1**2
            W2 = W1 + cubic(e2 - e1)
            line = (
                W2 + E_e * ey * (eps - e2) + 0.5 * E_p * (over**2 - (e2 - ey) ** 2)
                if over is not None
                else None
            )
            blend = W1 + cubic(t) if on[2] else None
            density = _select(eps, elastic, plastic, on, 0.5 * E_e * eps**2 if on[0] else None, line, blend)
        return stress, tangent, density

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
        """Secant modulus σ/ε (Pa), ``E_e`` at zero strain: element-wise, even in the strain
        (inputs as for `stress`)."""
        strain = float_array("strain", strain, finite=False, empty=True)
        safe = np.where(strain == 0.0, 1.0, strain)
        out = np.where(strain == 0.0, self.E_e, self.stress(safe) / safe)
        return out[()] if out.ndim == 0 else out


def _select(eps, elastic, plastic, on, on_elastic, on_line, on_blend):
    """``np.where(elastic, on_elastic, np.where(plastic, on_line, on_blend))`` with the branches
    no point lies on (``on``: elastic, line, blend) left out, and a constant branch spread over
    ``eps``'s shape when it is the only one."""
    values = [v for v, present in zip((on_elastic, on_line, on_blend), on, strict=True) if present]
    if len(values) == 1:
        return values[0] if isinstance(values[0], np.ndarray) else np.full(eps.shape, values[0])
    # two or three branches: the last one's array (a temporary of `_evaluate`, overwritten) with
    # the others copied over it where they hold (the masks are disjoint: the same selection)
    last = on_blend if on[2] else on_line
    out = last if isinstance(last, np.ndarray) else np.full(eps.shape, last)
    if on[1] and on[2]:
        np.copyto(out, on_line, where=plastic)
    if on[0]:
        np.copyto(out, on_elastic, where=elastic)
    return out


#: Pino Vidal (2021), Table B.1 (MPa in the table, Pa here); density and thermal expansion: `material`.
_PRESETS = {
    "steel": dict(
        E_e=196603.774e6,
        E_p=5228.162e6,
        eps_y=0.0053,
        eps_y1=0.005,
        eps_y2=0.006,
        eps_rupture=0.082,
        density=7780.0,
        alpha=11.5e-6,
    ),
    # Table B.1 prints eps_y = 0.0049; its a and b follow from 0.0049 (Table 3.3 reads 0.00449)
    "aluminium": dict(
        E_e=64509.8e6,
        E_p=207e6,
        eps_y=0.0049,
        eps_y1=0.003,
        eps_y2=0.0095,
        eps_rupture=0.0745,
        density=2703.0,
        alpha=23e-6,
    ),
}


def material(name: str) -> Material:
    """Wire material of Pino Vidal (2021), Table B.1: ``"steel"`` (galvanised) or ``"aluminium"``.

    The constitutive law is the thesis's; ``density`` (kg/m³) and ``alpha`` (1/K) are those of
    IEC 61089:1991, "Round wire concentric lay overhead electrical stranded conductors",
    Annex B (also EN 50182:2001, "Conductors for overhead lines"): zinc-coated steel wire
    7780 kg/m³ and 11.5e-6 /K, hard-drawn aluminium 1350 wire 2703 kg/m³ and 23e-6 /K.
    """
    if not isinstance(name, str) or name not in _PRESETS:
        raise InputError("name", f"unknown material {name!r}; known: {', '.join(_PRESETS)}")
    return Material(**_PRESETS[name], name=name)


class WireMaterials:
    """The material of every wire of a strand, grouped by material (one entry per wire, core first).

    A strand of one material has one group; ACSR (a steel core under aluminium layers) has two.
    Material laws are evaluated by one vectorised call per group (a single-material strand: on the
    whole array).

    Parameters
    ----------
    materials : tuple of Material
        The distinct materials, in order of first appearance (core outward).
    index : ndarray of int (n_wires,)
        Position in ``materials`` of every wire's material.
    """

    def __init__(self, materials: tuple, index: np.ndarray):
        self.materials = tuple(materials)
        self.index = np.asarray(index, dtype=int)
        self._masks = [self.index == k for k in range(len(self.materials))]

    @property
    def uniform(self) -> bool:
        """True when every wire has the same material."""
        return len(self.materials) == 1

    def take(self, attribute: str) -> np.ndarray:
        """A material attribute (``"E_e"``, ``"G"``, ``"eps_rupture"``, ``"density"`` ...) per wire."""
        values = np.array([float(getattr(m, attribute)) for m in self.materials])
        return values[self.index]

    def subset(self, selection) -> WireMaterials:
        """The map of the wires ``selection`` (a boolean mask or indices over the wires)."""
        return WireMaterials(self.materials, self.index[selection])

    def _per_group(self, method: str, strain: np.ndarray, axis: int, outputs: int):
        if self.uniform:
            out = getattr(self.materials[0], method)(strain)
            return out if outputs > 1 else (out,)
        moved = np.moveaxis(strain, axis, 0)
        results = [np.empty(moved.shape) for _ in range(outputs)]
        for material, mask in zip(self.materials, self._masks, strict=True):
            if not mask.any():
                continue
            values = getattr(material, method)(moved[mask])
            values = values if outputs > 1 else (values,)
            for result, value in zip(results, values, strict=True):
                result[mask] = value
        return tuple(np.moveaxis(r, 0, axis) for r in results)

    def stress_and_tangent(self, strain: np.ndarray, axis: int = 0) -> tuple[np.ndarray, np.ndarray]:
        """`Material.stress_and_tangent` of every wire's own material; the wires run along ``axis``."""
        return self._per_group("stress_and_tangent", strain, axis, 2)

    def stress(self, strain: np.ndarray, axis: int = 0) -> np.ndarray:
        """`Material.stress` (Pa) of every wire's own material; the wires run along ``axis``."""
        return self.stress_and_tangent(np.asarray(strain, dtype=float), axis)[0]

    def secant(self, strain: np.ndarray, axis: int = 0) -> np.ndarray:
        """`Material.secant` (Pa) of every wire's own material; the wires run along ``axis``."""
        return self._per_group("secant", np.asarray(strain, dtype=float), axis, 1)[0]

    def energy(self, strain: np.ndarray, axis: int = 0) -> np.ndarray:
        """`Material.energy` (J/m³) of every wire's own material; the wires run along ``axis``."""
        return self._per_group("energy", strain, axis, 1)[0]

    def stress_tangent_energy(
        self, strain: np.ndarray, axis: int = 0
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """`Material.stress_tangent_energy` of every wire's own material (one pass per material);
        the wires run along ``axis``."""
        return self._per_group("stress_tangent_energy", strain, axis, 3)
