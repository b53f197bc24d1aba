"""Multi-segment mooring lines with clump weights and buoys, in closed form.

One concern per module:

- `parts`: `Segment`, `ClumpWeight`, `Buoy`;
- `arrays`: `LineArrays`, the line's read-only per-segment and per-joint numbers;
- `state`: the closed form at given fairlead forces, its closure and Jacobian
  (`ClosureState`), composed of segments of the one closure (`skcable.cable.closure`);
- `batch`: many scenes of one single-segment line at once, Newton on arrays;
- `heap`: the heap state (``H = 0``, the slack on the seabed);
- `line`: `Line` and its solve (warm start, uniform-line start, bracketing, Newton);
- `solution`: `LineSolution`, the equilibrium mapped along the line, its checks,
  stiffness and tension table.

Data flow: ``parts`` → ``line`` (its ``arrays``) → ``state`` / ``heap`` → ``solution``.
"""

from skcable.mooring.segments.arrays import LineArrays
from skcable.mooring.segments.line import Line
from skcable.mooring.segments.parts import Buoy, ClumpWeight, Segment
from skcable.mooring.segments.solution import LineSolution
from skcable.mooring.segments.state import ClosureState

__all__ = ["Buoy", "ClosureState", "ClumpWeight", "Line", "LineArrays", "LineSolution", "Segment"]
