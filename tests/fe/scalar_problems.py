"""Scalar equations posed for `skcable.fe.newton` (the tests of its watchdog and fallbacks)."""

import numpy as np


def scalar_problem(residual, derivative):
    """``assemble``, ``norm`` and ``increment`` of a scalar equation ``residual(x) = 0``."""

    def assemble(x):
        return float(residual(x[0])), float(derivative(x[0]))

    def norm(state):
        return abs(state[0])

    def increment(state):
        return np.array([-state[0] / state[1]])

    return assemble, norm, increment
