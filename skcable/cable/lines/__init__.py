"""Mooring and anchor lines: seabed contact, multi-segment lines, line systems.

Conventions as in :mod:`skcable.cable`: anchor A at (0, 0), fairlead B at
(span, dh), y up, weights per unstretched length act downward.
"""

from skcable.cable.lines.seabed import (
    SeabedCatenary,
    SlopedSeabedCatenary,
    elastic_catenary,
    sloped_seabed_catenary,
)

__all__ = ["SeabedCatenary", "SlopedSeabedCatenary", "elastic_catenary", "sloped_seabed_catenary"]

# lines in 3-D and moored bodies
from skcable.cable.lines.body import PointBody, RigidBody, rotation_matrix  # noqa: E402
from skcable.cable.lines.line3d import Line3D, line_3d  # noqa: E402
from skcable.cable.lines.system import MooringEquilibrium, MooringSystem  # noqa: E402

__all__ += [
    "Line3D",
    "MooringEquilibrium",
    "MooringSystem",
    "PointBody",
    "RigidBody",
    "line_3d",
    "rotation_matrix",
]
