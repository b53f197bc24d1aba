r"""A MoorDyn file written back as it was read, its free parts where an equilibrium puts them.

`write_moordyn` of a `MoorDynModel` read from a file writes that file's lines again, every
section, option, column and comment as it was, and only the rows of what the statics moved
rewritten (their tokens joined by two blanks, a comment kept after them):

- a **free point**: its ``X Y Z``;
- a **free** (or ``CoupledPinned``) **body**: its ``X0 Y0 Z0 r0 p0 y0``, the angles (degrees)
  of its rotation matrix :math:`R = R_z(\psi) R_y(\theta) R_x(\phi)`:
  :math:`\theta = -\arcsin R_{31}`, :math:`\phi = \operatorname{atan2}(R_{32}, R_{33})`,
  :math:`\psi = \operatorname{atan2}(R_{21}, R_{11})` (its axes as the file gives them);
- a **rod that turns** (free or pinned) and a free rod of zero length (a connector): its ends
  ``Xa Ya Za Xb Yb Zb``, in the axes the file gives them in (global, or its body's for a rod
  pinned to one).

MoorDyn then starts from rest at the equilibrium, and the file read back gives the same system
at its equilibrium: the statics take no Newton step, or one at the round-off of the positions.
"""

from __future__ import annotations

import math

from skcable.errors import InputError
from skcable.mooring.body import rotation_matrix
from skcable.mooring.moordyn.text import tokens

__all__ = ["float_text", "rewritten_text"]


def float_text(value: float) -> str:
    """The shortest text that reads back as the same float."""
    return repr(float(value))


def _angles(R) -> tuple[float, float, float]:
    """``(roll, pitch, yaw)`` (rad) of ``R = Rz(yaw) Ry(pitch) Rx(roll)``."""
    pitch = -math.asin(max(-1.0, min(1.0, float(R[2, 0]))))
    return math.atan2(float(R[2, 1]), float(R[2, 2])), pitch, math.atan2(float(R[1, 0]), float(R[0, 0]))


def _row(raw: str, tokens, replace: dict) -> str:
    """The row ``raw`` with its tokens ``replace``d (``{index: text}``), its comment kept."""
    words = list(tokens)
    for k, text in replace.items():
        words[k] = text
    comment = ""
    for mark in ("#", "!"):
        at = raw.find(mark)
        if at >= 0 and (not comment or at < raw.find(comment[0])):
            comment = raw[at:]
    return "  ".join(words) + (f"  {comment}" if comment else "")


def _body_pose(record, state) -> list[str]:
    """The BODIES columns ``X0 .. y0`` of a body at its equilibrium ``state``."""
    roll, pitch, yaw = _angles(state.rotation @ record.frame)
    return [*map(float_text, state.offset), *(float_text(math.degrees(a)) for a in (roll, pitch, yaw))]


def _rod_ends(model, rod, eq) -> list[str] | None:
    """The RODS columns ``Xa .. Zb`` of a rod that turns, at the equilibrium, in the axes the file
    gives them in; None for a rod the statics do not move."""
    if rod.points and rod.points[0] is rod.points[1] and rod.points[0].kind == "free":  # a connector
        where = eq.points[rod.points[0].index].position
        return [*map(float_text, where), *map(float_text, where)]
    if getattr(rod, "body", None) is None:
        return None
    a, b = (eq.points[p.index].position for p in rod.points)
    if rod.kind == "bodypinned":  # in its body's axes at its equilibrium pose
        host = model.bodies[rod.owner]
        state = eq.bodies[model.system.bodies.index(host.body)] if host.body is not None else None
        if state is not None:
            R, x = state.rotation @ host.frame, state.offset
        else:
            R, x = rotation_matrix(*host.pose[3:]), host.pose[:3]
        a, b = R.T @ (a - x), R.T @ (b - x)
        b = b - (a - rod.a)  # its pin where the file has it on its body (the tie's gap taken out)
        a = rod.a
    else:  # a turbine's rod: relative to its turbine
        a, b = a - rod.offset, b - rod.offset
    return [*map(float_text, a), *map(float_text, b)]


def rewritten_text(model, eq) -> str:
    """The text of the file ``model`` was read from, its free points, bodies and turning rods where
    the equilibrium ``eq`` (of ``model.system``; None: where the file puts them) has them."""
    lines = list(model.text)
    if eq is None:
        return "\n".join(lines) + "\n"
    if eq.system is not model.system:
        raise InputError("equilibrium", "is the equilibrium of another system than the model's")
    changes: dict = {}
    for number, record in model.records.get("points", {}).items():
        p = model.points[number]
        if p.kind == "free":
            changes[record.line] = {
                k: float_text(v) for k, v in zip((2, 3, 4), eq.points[p.index].position, strict=True)
            }
    for record in model.bodies.values():
        if record.body is not None:
            state = eq.bodies[model.system.bodies.index(record.body)]
            changes[record.line] = dict(zip(range(2, 8), _body_pose(record, state), strict=True))
    for rod in model.rods.values():
        ends = _rod_ends(model, rod, eq)
        if ends is not None:
            changes[rod.line] = dict(zip(range(3, 9), ends, strict=True))
    for line, replace in changes.items():
        raw = lines[line - 1]
        lines[line - 1] = _row(raw, tokens(raw), replace)
    return "\n".join(lines) + "\n"
