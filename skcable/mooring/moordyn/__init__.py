r"""MoorDyn input files: read one into a `skcable.mooring.MooringSystem`, write a system as one.

What MoorDyn reads is read here (M. Hall et al., MoorDyn-C v2 and MoorDyn-F): v1 and v2 files,
sections found as MoorDyn-C finds them, every attachment kind (anchors, coupled and FAST.Farm
turbine points, free points, bodies, rods and their ends), line types whose EA is a number, a
strain–tension file or a viscoelastic or Syrope rope. One concern per module:

- `text`: the file's lines, sections, rows and numbers, and the refusals naming file and line;
- `options`: the OPTIONS the statics use (depth, gravity, water density) and those they leave
  aside, and MoorDyn's water depth;
- `linetypes`: LINE TYPES and ROD TYPES, each EA column as an axial law;
- `reader`: `read_moordyn`, the rows' meaning; `build`: the system of the rows;
- `model`: `MoorDynModel`, the system with what the statics leave aside;
- `writer`: `write_moordyn`, a system (at its equilibrium, if given one) as a MoorDyn v2 file.
"""

from __future__ import annotations

from skcable.mooring.moordyn.model import MoorDynModel
from skcable.mooring.moordyn.reader import read_moordyn
from skcable.mooring.moordyn.writer import moordyn_text, write_moordyn

__all__ = ["MoorDynModel", "moordyn_text", "read_moordyn", "write_moordyn"]
