"""The strand's end conditions as data: which dofs each end fixes, and at what value.

A strand of the model lies on x ∈ [0, L]; each end fixes some of its six nodal dofs

    ``u`` (axial, m), ``v``, ``w`` (transverse, m), ``phi`` (twist, rad),
    ``v'``, ``w'`` (slopes of v and w, rad)

to given values (scikit-fem's ``condense`` with ``x=``: prescribed values, not only zeros).
Named conditions:

- ``"clamped"``: v, w, v′, w′ and φ fixed at 0 (the thesis's "fixed – fixed sliding", with
  the axial pull at x = L; Pino Vidal 2021, §4.1);
- ``"pinned"``: v, w and φ fixed at 0, the slopes free (no bending moment);
- ``"sliding"``: v′, w′ and φ fixed at 0, the displacements free (no shear);
- ``"free"``: nothing fixed;
- a dict ``{dof: value}`` over the names above: exactly those dofs, at those values (a
  prescribed end rotation is ``{"v": 0.0, "v'": 0.01, ...}``).

The axial dof is the load of a capacity curve: ``u(L) = ε L`` always, for the imposed strain
ε of the step, and ``u(0) = 0`` unless the left end's dict gives another value. ``u`` in the
right end's dict is refused (it is the imposed strain's dof).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from skcable._checks import real
from skcable.errors import InputError

__all__ = ["DOFS", "END_CONDITIONS", "StrandSupports"]

#: the nodal dofs an end condition may fix
DOFS = ("u", "v", "w", "phi", "v'", "w'")
#: the named end conditions: the dofs each fixes at zero
END_CONDITIONS = {
    "clamped": ("v", "w", "v'", "w'", "phi"),
    "pinned": ("v", "w", "phi"),
    "sliding": ("v'", "w'", "phi"),
    "free": (),
}
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
        out[dof] = float(value)
    return out


@dataclass(frozen=True)
class StrandSupports:
    """The dofs fixed at each end and their values (module docstring).

    Attributes
    ----------
    left, right : dict of str to float
        ``{dof: value}`` at x = 0 and at x = L; ``u`` at the left is included (0 unless
        given), ``u`` at the right is the imposed strain's and is not listed.
    """

    left: dict
    right: dict

    @classmethod
    def of(cls, supports=None, twist: str = "clamped") -> StrandSupports:
        """From the model's ``supports=(left, right)`` and its ``twist`` shortcut."""
        if twist not in ("clamped", "free"):
            raise InputError("twist", f"must be 'clamped' or 'free', got {twist!r}")
        if supports is None:
            supports = ("clamped", "clamped")
        if isinstance(supports, (str, Mapping)) or len(supports) != 2:
            raise InputError("supports", f"must be a pair (left, right) of end conditions, got {supports!r}")
        left, right = _end("left", supports[0]), _end("right", supports[1])
        if "u" in right:
            raise InputError("supports", "right end: u(L) is the imposed strain's dof (ε L); do not fix it")
        left.setdefault("u", 0.0)
        if twist == "free":
            if right.get("phi", 0.0) != 0.0:
                raise InputError("twist", "'free' contradicts the twist prescribed at x = L by supports")
            right.pop("phi", None)
        return cls(left, right)

    def describe(self) -> tuple:
        """The pair in the form ``supports=`` takes (names where they match)."""

        def name(end, axial):
            fixed = {k: v for k, v in end.items() if not (axial and k == "u" and v == 0.0)}
            for key, dofs in END_CONDITIONS.items():
                if fixed == dict.fromkeys(dofs, 0.0):
                    return key
            return dict(end)

        return name(self.left, True), name(self.right, False)

    @staticmethod
    def index(end: str, dof: str, bases: Mapping, offsets: Mapping) -> int:
        """The global index of ``dof`` (a name of `DOFS`) at ``end`` ("left" or "right")."""
        field, nodal = _FIELD_DOF[dof]
        return int(offsets[field] + bases[field].get_dofs(end).nodal[nodal][0])

    def indices(self, bases: Mapping, offsets: Mapping) -> dict:
        """``{"left": {dof: index}, "right": {...}}``: `index` of every supported dof (for the
        reactions), each field's end dofs looked up once."""
        seen: dict = {}
        return {
            end: {dof: int(offsets[_FIELD_DOF[dof][0]] + _nodal(bases, end, dof, seen)[0]) for dof in given}
            for end, given in (("left", self.left), ("right", self.right))
        }

    def dofs(self, bases: Mapping, offsets: Mapping) -> tuple[np.ndarray, np.ndarray]:
        """``(fixed, values)``: global dof indices and their prescribed values, the imposed
        strain's dof excluded; ``bases`` has the fields' scikit-fem bases (a mesh with
        boundaries ``left`` and ``right``) and ``offsets`` where each field starts."""
        index, value = [], []
        seen: dict = {}
        for end, values in (("left", self.left), ("right", self.right)):
            for dof, v in values.items():
                nodal = _nodal(bases, end, dof, seen)
                index.append(offsets[_FIELD_DOF[dof][0]] + nodal)
                value.append(np.full(len(nodal), v))
        fixed = np.concatenate(index).astype(int)
        prescribed = np.concatenate(value)
        order = np.argsort(fixed, kind="stable")
        return fixed[order], prescribed[order]


def _nodal(bases: Mapping, end: str, dof: str, seen: dict) -> np.ndarray:
    """The nodal dofs of ``dof`` at ``end`` (InputError when its field's basis has none), each
    field's ``get_dofs(end)`` asked once per ``seen`` (scikit-fem searches the facets each time)."""
    field, name = _FIELD_DOF[dof]
    if (field, end) not in seen:
        seen[field, end] = bases[field].get_dofs(end).nodal
    nodal = seen[field, end]
    if name not in nodal:
        raise InputError("supports", f"{end} end: the basis of {field!r} has no dof {dof!r}")
    return nodal[name]
