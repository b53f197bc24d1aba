"""Mooring and anchor lines: seabed contact, multi-segment lines, line systems.

Conventions as in :mod:`skcable.cable`: anchor A at (0, 0), fairlead B at
(span, dh), y up, weights per unstretched length act downward.
"""

from skcable.cable.lines.seabed import SeabedCatenary, elastic_catenary
from skcable.cable.lines.segments import Buoy, ClumpWeight, Line, LineSolution, Segment

__all__ = ["SeabedCatenary", "elastic_catenary", "Buoy", "ClumpWeight", "Line", "LineSolution", "Segment"]
