r"""One elastic line on a flat or sloped seabed, in closed form.

Anchor A at (0, 0) on (or above) the seabed, fairlead B at (span, dh) above it, weight
``w`` per unstretched length, axial stiffness ``EA``, unstretched length ``L``, Coulomb
friction ``C_B`` on the grounded part (J.M. Jonkman, "Dynamics modeling and loads analysis
of an offshore floating wind turbine", NREL, 2007; H.M. Irvine, "Cable Structures", MIT
Press, 1981). One concern per module:

- the closure equations of the grounded line and their closed-form parts (the part
  hanging from an anchor above the seabed, the vertical hanging length) are those of every
  elastic segment, `skcable.cable.closure` (`on_seabed`, `grounded_closure`);
- the regimes: `free` (the line hangs clear of the seabed), `grounded` (it rests on the
  seabed and rises to B: the Newton solve of the closure) and `heap` (longer than its
  L-shape, ``H = 0``);
- `solve`: `elastic_catenary`, which picks each element's regime and solves it;
- `solution`: `SeabedCatenary`, the solution in every regime (maps, checks, stiffness);
- the sloped seabed (its closure and Jacobian `skcable.cable.closure.on_slope`): `sloped`
  (`sloped_seabed_catenary`; below both ends and without friction, `taut_length_on_slope`, the
  longest line the slope holds taut) and `sloped_solution` (`SlopedSeabedCatenary`);
  `touchdown` (`slope_touchdown`, `touchdown_on_slope`, `SlopeTouchdownLine`): below both ends
  and without friction, the line that touches down between them.

Data flow: ``solve`` → (``free`` | ``heap`` | ``grounded`` → `skcable.cable.closure`) → ``solution``;
``sloped`` starts from ``solve`` in the slope's frame → `skcable.cable.closure` →
``sloped_solution``.
"""

from skcable.cable.closure import anchor_part, grounded_closure, hanging_length
from skcable.cable.seabed.sloped import refuse_slack_on_slope, sloped_seabed_catenary, taut_length_on_slope
from skcable.cable.seabed.sloped_solution import SlopedSeabedCatenary
from skcable.cable.seabed.solution import SeabedCatenary
from skcable.cable.seabed.solve import elastic_catenary
from skcable.cable.seabed.touchdown import (
    SlopeTouchdown,
    SlopeTouchdownLine,
    slope_touchdown,
    touchdown_on_slope,
)

__all__ = [
    "SeabedCatenary",
    "SlopeTouchdown",
    "SlopeTouchdownLine",
    "SlopedSeabedCatenary",
    "anchor_part",
    "elastic_catenary",
    "grounded_closure",
    "hanging_length",
    "refuse_slack_on_slope",
    "slope_touchdown",
    "sloped_seabed_catenary",
    "taut_length_on_slope",
    "touchdown_on_slope",
]
