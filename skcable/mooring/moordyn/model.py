"""`MoorDynModel`: a MoorDyn file read into a system, with what the statics leave aside."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from skcable import _plausible
from skcable.mooring.equilibrium import MooringEquilibrium, warn_implausible
from skcable.mooring.system import MooringSystem

__all__ = ["MoorDynModel"]


@dataclass
class MoorDynModel:
    """A MoorDyn input file read into a `skcable.mooring.MooringSystem` (`read_moordyn`).

    Attributes
    ----------
    system : MooringSystem
        The bodies, points, lines and rods the statics solve; the file's lines are its first lines,
        in the file's order, its rods after them.
    line_types : dict
        ``{name: LineType}`` (`skcable.mooring.moordyn.linetypes.LineType`).
    line_type_of : list of str
        Each line's type name.
    segments : list of int
        Each line's ``NumSegs``.
    held : list
        The points held where given (``Coupled``/``Vessel`` points, the points of coupled, fixed
        and turbine bodies) and the poses of the bodies held.
    options : dict
        ``{name: value text}`` of the OPTIONS section (`skcable.mooring.moordyn.options`).
    outputs : list of str
        The OUTPUTS channels.
    header : str
        The free text at the top.
    ignored : dict
        ``{what: why}``: each option, section and column the statics leave aside, and why.
    points, bodies, rods : dict
        By the file's ID: the system's point of each point; ``(body or None, pose, kind)`` of each
        body (None where it is held); ``RodRecord`` of each rod (`skcable.mooring.moordyn.reader`).
    lines : list
        The system's line handle of each of the file's lines, in order.
    path : str
        The file read.
    text : list of str
        Its lines (`write_moordyn` writes them back, the free parts where an equilibrium puts them).
    records : dict
        The rows of its POINTS and LINES (`skcable.mooring.moordyn.reader`).
    """

    system: MooringSystem
    line_types: dict = field(default_factory=dict)
    line_type_of: list = field(default_factory=list)
    segments: list = field(default_factory=list)
    held: list = field(default_factory=list)
    options: dict = field(default_factory=dict)
    outputs: list = field(default_factory=list)
    header: str = ""
    ignored: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    bodies: dict = field(default_factory=dict)
    rods: dict = field(default_factory=dict)
    lines: list = field(default_factory=list)
    rod_types: dict = field(default_factory=dict)
    ties: list = field(default_factory=list)
    path: str = ""
    text: list = field(default_factory=list)
    records: dict = field(default_factory=dict)

    @_plausible.answer(warn_implausible)
    def equilibrium(self, **options):
        """The static equilibrium of the file's system (`MooringSystem.equilibrium`, its
        ``options``; a neutral direction held where the file starts it, as MoorDyn leaves it, and
        named in the result's ``neutral``). A system with nothing free (every point fixed or held)
        is its lines solved where the file puts them: a `skcable.mooring.MooringEquilibrium` with
        no dofs. Either way the answer is checked (`skcable.mooring.MooringEquilibrium.implausible`,
        each finding warned)."""
        system = self.system
        if system.n_dof:
            options.setdefault("neutral", "hold")
            options.setdefault("max_iter", 200)  # a free end of a line (a massless point) converges linearly
            return system.equilibrium(**options)
        q = np.zeros(0)
        lines = system.solve_lines(q) if system.mooring_lines else []
        empty = np.zeros(0)
        return MooringEquilibrium(system, q, empty, empty, np.zeros((0, 0)), lines, [0.0], empty)
