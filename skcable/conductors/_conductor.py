r"""Overhead line conductors: the data of a sag–tension calculation, from a strand or a catalogue.

A `Conductor` holds the axial stiffness ``EA`` (N), the weight per unit length ``w``
(N/m, per unstressed length), the coefficient of thermal expansion ``alpha`` (1/K),
the outer diameter (m) and, optionally, the rated tensile strength ``rts`` (N). It
delegates sag–tension work to `change_of_state` and `sag_tension_table`, adding the
loads of radial ice and of wind pressure on the (iced) diameter.

From a strand (`Conductor.from_strand`, any `skcable.strand.Strand`, several
materials or one, damaged or not), with every wire i of area A_i, lay angle α_i,
modulus E_i, density ρ_i and thermal expansion coefficient α_T,i of its own material:

.. math::
    EA = \sum_{\text{intact}} E_i A_i\cos^3\alpha_i, \qquad
    w = g \sum_{\text{all}} \rho_i A_i / \cos\alpha_i, \qquad
    \alpha = \frac{\sum_{\text{intact}} E_i A_i\cos^3\alpha_i\,\alpha_{T,i}}
                  {\sum_{\text{intact}} E_i A_i\cos^3\alpha_i}.

``EA`` is the section's axial stiffness (`skcable.strand.Section.EA`; K.O. Papailiou,
"On the bending stiffness of transmission line conductors", IEEE Trans. Power Delivery
12(4), 1997): the net section of the intact wires, a broken wire taken as carrying no
tension over the whole span. It is the library's axial stiffness of a damaged strand
that belongs to the conductor alone: the finite-element equivalent stiffness ``K_Leq`` of
a capacity curve adds the bending of the eccentric net section, which depends on the
specimen's length and end clamps, not on a span. ``w`` counts every wire, broken or not
(a broken wire stays in the span: its mass does too), each wire's length per unit
strand length being ``1/cos α_i``. ``alpha`` is the composite coefficient of a
conductor of several materials, the stiffness-weighted mean (F. Kiessling, P. Nefzger,
J.F. Nolasco, U. Kaintzyk, "Overhead Power Lines", Springer, 2003, §13; IEC/TR 61597:1995,
"Overhead electrical conductors – Calculation methods for stranded bare conductors"),
weighted here with the same lay factors as ``EA``. ``rupture_force`` is the axial force
at which the first intact wire reaches its material's rupture strain in straight tension,
``Σ A_i cos α_i σ_i(cos²α_i ε*)`` at ``ε* = min ε_rupture,i / cos²α_i`` — a figure of the
wire laws, not a rated strength: ``rts`` (used by ``T_max_per_rts``) is only ever the value
you give, from the conductor's standard or catalogue.

Ice and wind: a radial ice thickness b on a conductor of diameter d weighs
:math:`w_\text{ice} = \rho_\text{ice}\,g\,\pi\,b\,(d + b)` per unit length (the
annulus between diameters d and d + 2b; ASCE, "Guidelines for Electrical Transmission
Line Structural Loading", Manual of Practice 74, 2010), and a wind pressure p (Pa,
drag and gust factors included, as in IEC 60826:2017, "Design criteria of overhead
transmission lines") loads it with :math:`p\,(d + 2b)` per unit length, transverse.
The default ice density, 917 kg/m³, is that of pure ice at 0 °C (glaze, the densest
accretion; ASCE 7 takes at least 900 kg/m³): give your standard's value as
``ice_density``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from skcable._checks import broadcast, nonnegative, positive_scalar, real, scalar
from skcable._show import Shown
from skcable.cable._elastic import elastic_catenary_unchecked as elastic_catenary
from skcable.conductors._inputs import normal
from skcable.conductors._state import change_of_state, sag_tension_table
from skcable.errors import InputError

__all__ = ["Conductor", "STANDARD_GRAVITY", "ICE_DENSITY"]

#: Standard acceleration of gravity (m/s², 3rd CGPM, 1901).
STANDARD_GRAVITY = 9.80665
#: Density of pure ice at 0 °C (kg/m³), the default for glaze ice.
ICE_DENSITY = 917.0


@dataclass(frozen=True)
class Conductor(Shown):
    """An overhead line conductor for sag–tension calculations. SI units.

    Parameters
    ----------
    EA : float
        Axial stiffness (N), > 0.
    w : float
        Weight per unit (unstressed) length of the bare conductor (N/m), > 0.
    alpha : float
        Coefficient of linear thermal expansion (1/K), finite.
    diameter : float
        Outer diameter (m), > 0: the ice and wind loads act on it.
    rts : float or None
        Rated tensile strength (N), > 0, from the conductor's standard or catalogue; None
        when unknown.
    name : str
        Label.
    rupture_force : float or None
        Axial force (N) at which the first wire breaks in straight tension, from the wire
        laws (`Conductor.from_strand` sets it); not a rated strength.

    Notes
    -----
    Build one from catalogue values with this constructor, or from a strand (its
    section, materials and broken wires) with `Conductor.from_strand`. ``strand`` is
    the strand it was built from (None from catalogue values).
    """

    EA: float
    w: float
    alpha: float
    diameter: float
    rts: float | None = None
    name: str = ""
    strand: object = None
    rupture_force: float | None = None

    def __post_init__(self):
        values = dict(
            EA=positive_scalar("EA", self.EA),
            w=positive_scalar("w", self.w),
            alpha=scalar("alpha", self.alpha),
            diameter=positive_scalar("diameter", self.diameter),
            rts=None if self.rts is None else positive_scalar("rts", self.rts),
            rupture_force=None
            if self.rupture_force is None
            else positive_scalar("rupture_force", self.rupture_force),
        )
        if not isinstance(self.name, str):
            raise InputError("name", f"must be a str, got {self.name!r}")
        for key, value in values.items():
            object.__setattr__(self, key, value)

    def __repr__(self):
        rts = f", rts={self.rts:.6g} N" if self.rts is not None else ""
        return (
            f"Conductor({self.name or 'conductor'!r}: EA={self.EA:.6g} N, w={self.w:.6g} N/m, "
            f"alpha={self.alpha:.4g} 1/K, diameter={self.diameter:.4g} m{rts})"
        )

    # --- from a strand ----------------------------------------------------------------
    @classmethod
    def from_strand(
        cls,
        strand,
        *,
        damage=None,
        EA=None,
        rts=None,
        g: float = STANDARD_GRAVITY,
        name: str | None = None,
    ):
        """The conductor of a strand (see the module text for the formulas and their sources).

        Parameters
        ----------
        strand : skcable.strand.Strand
            Any strand, of one material or a material per layer (``strand.preset("acsr-drake")``),
            intact or with broken wires. Every material needs ``density`` and ``alpha``.
        damage : None, int or list of (layer, index)
            Wires to break first: an int n breaks n adjacent outer wires
            (``strand.damaged(n)``), a list of pairs those wires (``strand.damaged(wires=...)``);
            None (default) takes the strand as it is.
        EA : float, optional
            Axial stiffness (N) to use instead of the section's, e.g. the secant
            ``K_Leq`` of a finite-element capacity curve of the damaged strand
            (``StrandModel(strand, length).capacity_curve().K_Leq``) for a span where the
            broken wires' eccentric bending matters; the weight and ``alpha`` still come
            from the strand.
        rts : float, optional
            Rated tensile strength (N) from the conductor's standard or catalogue (of the
            intact conductor, or reduced for the broken wires as your standard says); None
            (default) leaves it unknown. It is never derived from the wire laws.
        g : float
            Acceleration of gravity (m/s²), > 0; standard gravity by default.
        name : str, optional
            Label; by default the strand's name.

        Returns
        -------
        Conductor
            ``EA``, ``w``, ``alpha`` and ``rupture_force`` as the module text says, ``rts`` as
            given; ``strand`` the (damaged) strand.

        Raises
        ------
        InputError
            ``strand`` is not a strand, or one of its materials has no ``density`` or
            ``alpha``; ``damage`` not a valid pattern (named as in `Strand.damaged`).
        """
        from skcable.strand._choice import axial_force, first_wire_strain

        if not all(
            callable(getattr(strand, k, None)) for k in ("section", "wires", "wire_materials", "damaged")
        ):
            raise InputError(
                "strand", f"must be a skcable.strand.Strand (e.g. strand.preset(...)), got {strand!r}"
            )
        g = positive_scalar("g", g)
        if damage is not None:
            if isinstance(damage, (int, np.integer)) and not isinstance(damage, (bool, np.bool_)):
                strand = strand.damaged(int(damage))
            elif isinstance(damage, (list, tuple, set, frozenset)):
                strand = strand.damaged(wires=damage)
            else:
                raise InputError(
                    "damage",
                    f"must be None, an int (outer wires) or a list of (layer, index), got {damage!r}",
                )
        for k, material in enumerate(strand.layer_materials):
            where = "the core" if k == 0 else f"layer {k}"
            for attribute, unit in (("density", "kg/m³"), ("alpha", "1/K")):
                if getattr(material, attribute) is None:
                    raise InputError(
                        "strand",
                        f"the material {material.name or 'custom'!r} of {where} has no {attribute} ({unit}): "
                        f"give Material(..., {attribute}=...) to make a conductor of it",
                    )
        section = strand.section()
        wires = strand.wires()
        materials = strand.wire_materials()
        cos = np.cos(wires.lay_angle)
        weight = g * float(np.sum(materials.take("density") * wires.area / cos))
        stiffness = np.where(wires.intact, materials.take("E_e") * wires.area * cos**3, 0.0)
        alpha = float(stiffness @ materials.take("alpha") / np.sum(stiffness))
        first = first_wire_strain(strand, "eps_rupture")
        rupture_force = float(axial_force(strand, first))
        label = strand.name if name is None else name
        return cls(
            EA=section.EA if EA is None else positive_scalar("EA", EA),
            w=weight,
            alpha=alpha,
            diameter=strand.diameter,
            rts=None if rts is None else positive_scalar("rts", rts),
            name=label,
            strand=strand,
            rupture_force=rupture_force,
        )

    @classmethod
    def from_catalogue(cls, name: str, *, g: float = STANDARD_GRAVITY):
        """The conductor of a catalogue size (ASTM B232 ACSR, B231 AAC, B399 AAAC; see
        `skcable.conductors.catalogue`): the published mass (``w = mass · g``), outer
        diameter and rated strength (``rts``), with ``EA`` and ``alpha`` of its strand
        (``strand.preset(name)``, built from the stranding; `Conductor.from_strand`).

        Raises
        ------
        InputError
            ``name`` not in the catalogue (``'name'``, with the nearest names suggested).
        """
        from skcable.strand import preset
        from skcable.strand._catalogue import entry

        item = entry(name)
        g = positive_scalar("g", g)
        base = cls.from_strand(preset(item.name), g=g)
        return cls(
            EA=base.EA, w=item.mass * g, alpha=base.alpha, diameter=item.diameter, rts=item.rts,
            name=item.name, strand=base.strand, rupture_force=base.rupture_force,
        )  # fmt: skip

    # --- loads ------------------------------------------------------------------------
    def ice_load(self, thickness, *, density: float = ICE_DENSITY, g: float = STANDARD_GRAVITY):
        """Weight per unit length (N/m) of radial ice ``thickness`` b (m, >= 0, any shape):
        ``density · g · π b (d + b)``, ``density`` in kg/m³ (> 0)."""
        return self._ice_load(thickness, density, g, names=("thickness", "density"))

    def wind_load(self, pressure, *, ice=0.0):
        """Transverse load per unit length (N/m) of wind ``pressure`` (Pa, >= 0) on the diameter
        iced with radial thickness ``ice`` (m, >= 0): ``pressure · (d + 2 ice)``; broadcast."""
        return self._wind_load(pressure, ice, names=("pressure", "ice"))

    def _ice_load(self, thickness, density, g, *, names=("ice", "ice_density")):
        b = nonnegative(names[0], thickness)
        density = positive_scalar(names[1], density)
        g = positive_scalar("g", g)
        return density * g * np.pi * b * (self.diameter + b)

    def _wind_load(self, pressure, ice, *, names=("wind_pressure", "ice")):
        p = nonnegative(names[0], pressure)
        b = nonnegative(names[1], ice)
        return p * (self.diameter + 2.0 * b)

    def _reference(self, span, dh, H0, sag0, length, model):
        """(H0, sag0) for `change_of_state`: a given unstressed ``length`` at t0 becomes the H0
        of the bare conductor of that length (the elastic catenary)."""
        if length is None:
            return H0, sag0
        if H0 is not None or sag0 is not None:
            raise InputError("length", "give exactly one of H0, sag0, length for the reference state")
        if model == "parabola":  # "auto" takes the exact H0 of that length, and each state within rtol
            raise InputError("length", f"a reference length needs model='catenary' or 'auto', got {model!r}")
        length, span, dh = normal("length", length), normal("span", span), real("dh", dh)
        broadcast(span=span, dh=dh, length=length)
        H0 = elastic_catenary(span, dh, self.w, self.EA, length=length).H
        return (float(H0) if np.ndim(H0) == 0 else H0), None

    # --- sag and tension ----------------------------------------------------------------
    def change_of_state(
        self,
        span,
        dh=0.0,
        *,
        t0,
        H0=None,
        sag0=None,
        length=None,
        t,
        ice=0.0,
        wind_pressure=0.0,
        ice_density: float = ICE_DENSITY,
        g: float = STANDARD_GRAVITY,
        model: str = "catenary",
        rtol: float | None = None,
    ):
        """Sag and tension in other states (`skcable.conductors.change_of_state` with this conductor's data).

        Parameters
        ----------
        span, dh : float or array_like
            Horizontal distance between the supports (m, > 0) and height of B above A (m);
            arrays for a line of spans (every result then has the spans' shape followed by
            the states').
        t0 : float
            Reference temperature (°C or K, as ``t``): the bare conductor, no wind.
        H0, sag0, length : float or array_like
            Exactly one (one number, or one per span): the reference state's horizontal
            tension (N), sag (m), or the unstressed length at ``t0`` (m, ``model="catenary"``
            or ``"auto"``) — e.g. the ``L0`` of the intact conductor, for the same conductor after wires
            broke.
        t, ice, wind_pressure : float or array_like
            The states: temperature, radial ice thickness (m, >= 0), wind pressure (Pa, >= 0)
            on the iced diameter; broadcast together.
        ice_density, g : float
            Ice density (kg/m³) and gravity (m/s²), > 0.
        model, rtol
            As in `skcable.conductors.change_of_state` (the result's ``reason`` says which model
            and why).

        Returns
        -------
        ChangeOfState
            ``H, H_plane, sag, T_max, length, blowout, L0`` over the states; with ``rts``
            known, ``T_max_pct_rts`` (``T_max`` in % of the rated strength).
        """
        H0, sag0 = self._reference(span, dh, H0, sag0, length, model)
        w = self.w + self._ice_load(ice, ice_density, g)
        wind = self._wind_load(wind_pressure, ice)
        result = change_of_state(
            span, dh, EA=self.EA, alpha=self.alpha, w0=self.w, t0=t0, H0=H0, sag0=sag0,
            w=w, t=real("t", t), wind=wind, model=model, rtol=rtol,
        )  # fmt: skip
        if self.rts is not None:
            result.T_max_pct_rts = 100.0 * np.asarray(result.T_max) / self.rts
        return result

    def sag_tension_table(
        self,
        span,
        dh=0.0,
        *,
        t0,
        H0=None,
        sag0=None,
        length=None,
        temperatures,
        load_cases=None,
        ice_density: float = ICE_DENSITY,
        g: float = STANDARD_GRAVITY,
        model: str = "catenary",
        rtol: float | None = None,
    ):
        """Sag–tension table (pandas DataFrame) of this conductor over load case × temperature.

        ``load_cases`` maps a case name to ``(ice, wind_pressure)``: radial ice thickness (m)
        and wind pressure (Pa) on the iced diameter; default ``{"bare": (0.0, 0.0)}``. The
        reference state and the other arguments are those of `Conductor.change_of_state`.
        The columns are those of `skcable.conductors.sag_tension_table` (``w`` and ``wind`` the
        loads per length these give) and, when ``rts`` is known, ``T_max_per_rts`` and
        ``T_max_pct_rts`` (the same in % RTS).
        """
        cases = {"bare": (0.0, 0.0)} if load_cases is None else load_cases
        if not isinstance(cases, dict) or not cases:
            raise InputError("load_cases", "must be a non-empty dict name -> (ice, wind_pressure)")
        loads = {}
        for case, value in cases.items():
            if not isinstance(value, (tuple, list)) or len(value) != 2:
                raise InputError(
                    "load_cases", f"case {case!r} must be a pair (ice, wind_pressure), got {value!r}"
                )
            ice, pressure = scalar("load_cases", value[0]), scalar("load_cases", value[1])
            nonnegative("load_cases", np.array([ice, pressure]))  # ice thickness and pressure >= 0
            w = float(self.w + self._ice_load(ice, ice_density, g))
            loads[case] = (w, float(self._wind_load(pressure, ice)))
        H0, sag0 = self._reference(span, dh, H0, sag0, length, model)
        table = sag_tension_table(
            span, dh, EA=self.EA, alpha=self.alpha, w0=self.w, t0=t0, H0=H0, sag0=sag0,
            temperatures=temperatures, load_cases=loads, model=model, rtol=rtol,
        )  # fmt: skip
        if self.rts is not None:
            table["T_max_per_rts"] = table["T_max"] / self.rts
            table["T_max_pct_rts"] = 100.0 * table["T_max"] / self.rts
        return table
