"""Every domain's numbers pinned from the code before the one-library restructuring.

``python tests/pinned_library.py`` recorded them (its commit is in the JSON file) on ordinary
scenes; the library must reproduce each array to 1e-12 of its largest entry (bit-for-bit where
no operation order changed).

Re-pinned (issue 34; each with its commit and reason in the file's ``repinned`` list): the
strand group's ``strand_free_twist_axis_slip`` and ``analyse`` (the stick-slip model of
`strand.analyse`), whose ``slip="axis"`` is now Cardou's law as a section law with the friction
moment M_rf in slip (the previous model lost it: its section moment in slip was EI_slip κ). The
axial force of the free-twist step moves from 19862.2 to 19995.1 N, ``analyse``'s K_Leq from
8320.0 to 8330.8 kN; ``tests/strand/test_slip_law.py`` checks the new law against
`BendingLaw.moment` at every point and against a shooting solution.
"""

import json
from pathlib import Path

import numpy as np
import pytest

from tests.pinned_library import CASES

#: eigenvalues come from iterative or threaded eigensolvers whose results move by 1e-12 to 1e-10
#: with the BLAS thread count: pinned to 1e-9 (the frequencies' own accuracy is checked elsewhere);
#: ``analyse`` runs capacity curves at the default Newton tolerance (1e-9 of each equation's
#: force scale), whose K_Leq is accurate to about 1e-9: pinned to 1e-8; the pushed mooring's
#: equilibrium is solved to its default tolerance (1e-10 of the force scale) on a soft surge
#: stiffness, so its position is accurate to about 1e-10 m: the pinned one lies 1.9e-12 (of its
#: largest entry) from the equilibrium solved to round-off (tol=1e-13), the watchdog's first step
#: (`skcable.fe.newton`) ends 1.9e-11 from it, and its K_lines moves with it: pinned to 1e-9
TOLERANCE = {
    ("mooring", "mooring_pushed"): 1e-9,
    ("conductor", "natural_frequencies"): 1e-9,
    ("strand", "strand_frequencies"): 1e-9,
    ("strand", "analyse"): 1e-8,
}
#: a result that is zero up to round-off is compared at the round-off of the force it is part of:
#: with friction taking the whole pull, the anchor's H_A is round-off of the fairlead's H; a
#: number is the scale itself: the model choice's error estimate is a relative difference of two
#: solves' H, T_max and length (``|a/b - 1|``), so its round-off is that of the ratio (a few
#: 1e-16 whatever its size: 4.4e-16 between numpy 2.2 and 2.4), not a fraction of its own 2.5e-10
SCALE_OF: dict[tuple[str, str, str], str | float] = {
    ("bvp", "line_bvp_friction", "H_A"): "H",
    ("bvp", "choice", "error_estimate"): 1.0,
}
PINNED = json.loads((Path(__file__).parent / "data" / "pinned_library.json").read_text())


@pytest.mark.parametrize("group", sorted(CASES))
def test_library_numbers_are_unchanged(group):
    expected = PINNED["groups"][group]
    computed = CASES[group]()
    assert sorted(computed) == sorted(expected)
    for case, values in expected.items():
        assert sorted(computed[case]) == sorted(values), case
        for key, pinned in values.items():
            want = np.array(pinned["values"], dtype=float).reshape(pinned["shape"])
            got = np.asarray(computed[case][key], dtype=float)
            assert got.shape == want.shape, (case, key)
            of = SCALE_OF.get((group, case, key), key)
            of = of if isinstance(of, float) else values[of]["values"]
            scale = float(np.max(np.abs(of), initial=0.0)) or 1.0
            np.testing.assert_allclose(
                got, want, rtol=0, atol=TOLERANCE.get((group, case), 1e-12) * scale, err_msg=f"{case}.{key}"
            )
