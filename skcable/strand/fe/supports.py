"""The strand's end conditions and its axial load as data: which dofs each end fixes, at what
value, and what loads the axial dof at x = L.

A strand of the model lies on x ∈ [0, L]; each end fixes some of its six nodal dofs

    ``u`` (axial, m), ``v``, ``w`` (transverse, m), ``phi`` (twist, rad),
    ``v'``, ``w'`` (slopes of v and w, rad)

to given values (scikit-fem's ``condense`` with ``x=``: prescribed values, not only zeros).
Named conditions:

- ``"clamped"``: u, v, w, v′, w′ and φ fixed at 0;
- ``"pinned"``: u, v, w and φ fixed at 0, the slopes free (no bending moment);
- ``"sliding"``: v′, w′ and φ fixed at 0, the displacements free (no shear, no axial force);
- ``"free"``: nothing fixed;
- a dict ``{dof: value}`` over the names above: exactly those dofs, at those values (a
  prescribed end rotation is ``{"u": 0.0, "v": 0.0, "v'": 0.01, ...}``).

The axial load at x = L (`AXIAL_LOADS`, the model's ``axial=``) owns the axial dof there:

- ``"strain"`` (default): an imposed end displacement, ``u(L) = u(0) + ε L`` for the strain ε
  of the step (the thesis's "fixed – fixed sliding", pulled: Pino Vidal 2021, §4.1). The left
  end must hold u; at the right end a named condition holds every other dof it names (u is the
  load's), and ``"free"`` or ``"sliding"``, which would leave u free, are refused; a dict lists
  the dofs besides u;
- ``"force"``: an axial force P at x = L (load control); u(L) is free and loaded, the left end
  must hold u; at the right end the named conditions hold the dofs they name besides u;
- ``"none"``: no axial load; u at both ends is a support like the others (named conditions hold
  it as named, a dict exactly as given): a clamped–free strand is free at its tip.

The axial reaction of a held u appears with the other reactions (``StepResult.reactions``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from skcable._checks import one_of, real
from skcable.errors import InputError

__all__ = ["AXIAL_LOADS", "DOFS", "END_CONDITIONS", "StrandSupports"]

#: the nodal dofs an end condition may fix
DOFS = ("u", "v", "w", "phi", "v'", "w'")
#: the named end conditions: the dofs each fixes at zero
END_CONDITIONS = {
    "clamped": ("u", "v", "w", "v'", "w'", "phi"),
    "pinned": ("u", "v", "w", "phi"),
    "sliding": ("v'", "w'", "phi"),
    "free": (),
}
#: what loads the axial dof at x = L: an imposed strain, an axial force, or nothing
AXIAL_LOADS = ("strain", "force", "none")
#: the largest prescribed end slope (rad): the moderate-rotation strain u' + ½v'² errs by about
#: v'²/4 of the stretch of the bent axis against the exact one, 1.6 % at 0.25 rad
MAX_SLOPE = 0.25
#: (field, scikit-fem nodal dof name) of each dof
_FIELD_DOF = {
    "u": ("u", "u"),
    "v": ("v", "u"),
    "w": ("w", "u"),
    "phi": ("phi", "u"),
    "v'": ("v", "u_x"),
    "w'": ("w", "u_x"),
}


def _end(name: str, given) -> dict[str, float]:
    if isinstance(given, str):
        if given not in END_CONDITIONS:
            raise InputError(
                "supports", f"{name} end: must be one of {tuple(END_CONDITIONS)} or a dict, got {given!r}"
            )
        return dict.fromkeys(END_CONDITIONS[given], 0.0)
    if not isinstance(given, Mapping):
        raise InputError("supports", f"{name} end: must be a name or a dict {{dof: value}}, got {given!r}")
    if not given:
        raise InputError(
            "supports", f"{name} end: the dict names no dof (use 'free' for an end that fixes none)"
        )
    out = {}
    for dof, value in given.items():
        if dof not in DOFS:
            raise InputError("supports", f"{name} end: unknown dof {dof!r}; the dofs are {DOFS}")
        value = real("supports", value)
        if np.ndim(value) != 0:
            raise InputError(
                "supports", f"{name} end: the value of {dof!r} must be one number, got {value!r}"
            )
        if dof in ("v'", "w'") and abs(float(value)) > MAX_SLOPE:
            raise InputError(
                "supports",
                f"{name} end: a slope {dof} = {float(value)!r} rad is beyond the moderate rotations the "
                f"model's kinematics hold (ε_a = u' + ½(v'² + w'²), |slope| <= {MAX_SLOPE:g} rad)",
            )
        out[dof] = float(value)
    return out


@dataclass(frozen=True)
class StrandSupports:
    """The dofs fixed at each end, their values, and the axial load (module docstring).

    Attributes
    ----------
    left, right : dict of str to float
        ``{dof: value}`` at x = 0 and at x = L. Under an axial load (``"strain"``, ``"force"``)
        the right end's u is the load's and is not listed.
    axial : str
        The axial load at x = L, one of `AXIAL_LOADS`.
    """

    left: dict
    right: dict
    axial: str = "strain"

    @classmethod
    def of(cls, supports=None, twist: str = "clamped", axial: str = "strain") -> StrandSupports:
        """From the model's ``supports=(left, right)``, its ``twist`` shortcut and its ``axial`` load."""
        one_of("twist", twist, ("clamped", "free"))
        one_of("axial", axial, AXIAL_LOADS)
        if supports is None:
            supports = ("clamped", "clamped")
        if isinstance(supports, (str, Mapping)) or len(supports) != 2:
            raise InputError("supports", f"must be a pair (left, right) of end conditions, got {supports!r}")
        left, right = _end("left", supports[0]), _end("right", supports[1])
        if axial != "none":
            _load_owns_u(supports[1], right, axial)
            if "u" not in left:
                raise InputError(
                    "supports",
                    f"left end: axial={axial!r} pulls the strand against x = 0, which must hold u "
                    "(a named 'clamped' or 'pinned' end, or 'u' in its dict)",
                )
        if twist == "free":
            if right.get("phi", 0.0) != 0.0:
                raise InputError("twist", "'free' contradicts the twist prescribed at x = L by supports")
            right.pop("phi", None)
        return cls(left, right, axial)

    def describe(self) -> tuple:
        """The pair in the form ``supports=`` takes (names where they match)."""

        def name(end, loaded, refused=()):
            for key, dofs in END_CONDITIONS.items():
                named = [d for d in dofs if not (loaded and d == "u")]
                if end == dict.fromkeys(named, 0.0) and key not in refused:
                    return key
            return dict(end)

        strain = ("free", "sliding") if self.axial == "strain" else ()
        return name(self.left, False), name(self.right, self.axial != "none", strain)

    @staticmethod
    def value(end: str, dof: str, value, argument: str = "supports") -> float:
        """``value`` of ``dof`` at ``end`` checked as a support's (a finite number; a slope within
        `MAX_SLOPE`), or `InputError` naming ``argument``."""
        try:
            return _end(end, {dof: value})[dof]
        except InputError as exc:
            if argument == "supports":
                raise
            raise InputError(argument, str(exc).removeprefix("supports: ")) from None

    @staticmethod
    def index(end: str, dof: str, bases: Mapping, offsets: Mapping, seen: dict | None = None) -> int:
        """The global index of ``dof`` (a name of `DOFS`) at ``end`` ("left" or "right");
        ``seen``: a cache of the bases' end dofs shared between calls (`_nodal`)."""
        return int(offsets[_FIELD_DOF[dof][0]] + _nodal(bases, end, dof, {} if seen is None else seen)[0])

    def indices(self, bases: Mapping, offsets: Mapping, seen: dict | None = None) -> dict:
        """``{"left": {dof: index}, "right": {...}}``: `index` of every supported dof (for the
        reactions), each basis's end dofs looked up once."""
        seen = {} if seen is None else seen
        return {
            end: {dof: int(offsets[_FIELD_DOF[dof][0]] + _nodal(bases, end, dof, seen)[0]) for dof in given}
            for end, given in (("left", self.left), ("right", self.right))
        }

    def dofs(
        self, bases: Mapping, offsets: Mapping, seen: dict | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """``(fixed, values)``: global dof indices and their prescribed values, the axial load's
        dof excluded; ``bases`` has the fields' scikit-fem bases (a mesh with
        boundaries ``left`` and ``right``) and ``offsets`` where each field starts."""
        index, value = [], []
        seen = {} if seen is None else seen
        for end, values in (("left", self.left), ("right", self.right)):
            for dof, v in values.items():
                nodal = _nodal(bases, end, dof, seen)
                index.append(offsets[_FIELD_DOF[dof][0]] + nodal)
                value.append(np.full(len(nodal), v))
        fixed = np.concatenate(index).astype(int) if index else np.zeros(0, dtype=int)
        prescribed = np.concatenate(value) if value else np.zeros(0)
        order = np.argsort(fixed, kind="stable")
        return fixed[order], prescribed[order]


def _load_owns_u(given, right: dict, axial: str) -> None:
    """Under an axial load the right end's u is the load's: drop it from a named condition, refuse
    it in a dict, and refuse a named condition that would leave it free under an imposed strain."""
    if isinstance(given, str):
        if axial == "strain" and given in ("free", "sliding"):
            raise InputError(
                "supports",
                f"right end {given!r} leaves u(L) free, which axial='strain' imposes (u(L) = u(0) + "
                "ε L): choose axial='force' (an axial force at x = L) or axial='none' (no axial "
                "load), or a right end that holds u ('clamped', 'pinned', or a dict of the dofs "
                "it holds besides u)",
            )
        right.pop("u", None)
    elif "u" in right:
        raise InputError(
            "supports", f"right end: u(L) is the axial load's dof under axial={axial!r}; do not fix it"
        )


def _nodal(bases: Mapping, end: str, dof: str, seen: dict) -> np.ndarray:
    """The nodal dofs of ``dof`` at ``end`` (InputError when its field's basis has none), each
    basis's ``get_dofs(end)`` asked once per ``seen`` (scikit-fem searches the facets each time;
    fields on one basis share it)."""
    field, name = _FIELD_DOF[dof]
    key = (id(bases[field]), end)
    if key not in seen:
        seen[key] = bases[field].get_dofs(end).nodal
    nodal = seen[key]
    if name not in nodal:
        raise InputError("supports", f"{end} end: the basis of {field!r} has no dof {dof!r}")
    return nodal[name]
