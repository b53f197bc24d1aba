"""skcable: structural cables and metallic strands on scikit-fem.

Subpackages
-----------
cable
    Suspended cables: closed forms (funicular polygon, parabola, catenary,
    elastic catenary), geometric stiffness, end conditions and cables on
    surfaces.
"""

from skcable import cable, strand
from skcable.errors import ConvergenceError, InputError

__all__ = ["cable", "strand", "ConvergenceError", "InputError"]
__version__ = "0.1.0"
