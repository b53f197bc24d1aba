"""Line failure: the damaged system's equilibrium beside the intact one, and how the tensions move.

A failure case leaves lines out of a `skcable.mooring.MooringSystem` (``equilibrium(without=...)``)
and solves the damaged system from the intact equilibrium's position (a transient is not
modelled: the statics of the system after the failure, as in the damaged-condition checks of
mooring design codes). `FailureCase.redistribution` lists, line by line, the largest end tension
intact and damaged, and `FailureCase.offsets` each body's move.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from skcable.errors import InputError
from skcable.mooring.network import largest_end_tension

__all__ = ["FailureCase", "failure_case", "failure_cases"]


def _largest_tensions(eq) -> dict:
    """``{line index: the largest of its end tensions (N)}`` of an equilibrium."""
    return {k: largest_end_tension(line) for k, line in zip(eq.line_indices, eq.lines, strict=True)}


class FailureCase:
    """An intact equilibrium and the damaged one without the ``failed`` lines.

    Attributes
    ----------
    intact, damaged : MooringEquilibrium
    failed : list of MooringLine
        The lines left out.
    """

    def __init__(self, intact, damaged, failed):
        self.intact, self.damaged, self.failed = intact, damaged, list(failed)

    def redistribution(self):
        """One row per line: ``line``, ``failed``, ``T_intact``, ``T_damaged`` (the largest end
        tension, N; 0 for a failed line), ``change`` (N) and ``ratio`` (damaged over intact; 0 for a
        failed line), a `pandas.DataFrame`."""
        import pandas as pd

        before, after = _largest_tensions(self.intact), _largest_tensions(self.damaged)
        lost = {h.index for h in self.failed}
        rows = sorted(before)
        T_i = np.array([before[k] for k in rows])
        T_d = np.array([0.0 if k in lost else after[k] for k in rows])
        ratio = np.divide(T_d, T_i, out=np.zeros_like(T_d), where=T_i > 0)
        return pd.DataFrame(
            {
                "line": rows,
                "failed": [k in lost for k in rows],
                "T_intact": T_i,
                "T_damaged": T_d,
                "change": T_d - T_i,
                "ratio": ratio,
            }
        )

    def offsets(self):
        """One row per body: ``body``, its reference point intact ``x, y, z`` and damaged
        ``x_damaged, y_damaged, z_damaged`` (m), the move ``distance`` (m) and the damaged ``heel``
        (rad), a `pandas.DataFrame`."""
        import pandas as pd

        rows = []
        for a, b in zip(self.intact.bodies, self.damaged.bodies, strict=True):
            row = {"body": a.index, "x": a.offset[0], "y": a.offset[1], "z": a.offset[2]}
            row.update(x_damaged=b.offset[0], y_damaged=b.offset[1], z_damaged=b.offset[2])
            row.update(distance=float(np.linalg.norm(b.offset - a.offset)), heel=b.heel)
            rows.append(row)
        return pd.DataFrame(rows)

    def __repr__(self):
        names = ", ".join(str(h.index) for h in self.failed)
        return f"FailureCase(without lines [{names}]: {self.damaged!r})"


def failure_case(system, failed, *, intact=None, **options) -> FailureCase:
    """The equilibrium of ``system`` without the ``failed`` lines beside the intact one.

    Parameters
    ----------
    system : MooringSystem
    failed : sequence of MooringLine
        The lines that fail (handles of ``add_line``).
    intact : MooringEquilibrium, optional
        The intact equilibrium under the same loads (solved here if not given).
    **options
        The loads and settings of `MooringSystem.equilibrium` (``force``, ``moment``, ``tol``,
        ``max_iter``), the same for both.

    Raises
    ------
    InputError
        ``failed`` empty or not lines of the system; a point or body left with no line.
    """
    if isinstance(failed, (str, bytes)) or not isinstance(failed, Iterable):
        raise InputError("failed", "must be a list of the system's lines (from add_line)")
    failed = list(failed)
    if not failed:
        raise InputError("failed", "give at least one line that fails")
    if "without" in options or "start" in options:
        raise InputError("options", "without= and start= are set by the failure case")
    if intact is None:
        intact = system.equilibrium(**options)
    elif intact.system is not system or intact.without:
        raise InputError("intact", "must be an intact equilibrium of this system")
    damaged = system.equilibrium(**options, start=intact.position, without=failed)
    return FailureCase(intact, damaged, [system.mooring_lines[k] for k in sorted(damaged.without)])


def failure_cases(system, **options) -> list[FailureCase]:
    """Each line failing alone: one `FailureCase` per line, from one intact equilibrium (the
    loads and settings of `MooringSystem.equilibrium` in ``options``). A line whose failure leaves
    a point or body unheld raises `InputError` naming it."""
    intact = system.equilibrium(**options)
    return [failure_case(system, [h], intact=intact, **options) for h in system.mooring_lines]
