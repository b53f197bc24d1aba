"""Seeded scene generators: the random data of the fuzzed calls (numpy's PCG64).

Magnitudes are drawn log-uniformly over many decades and in random unit systems (lengths
from centimetres to kilometres, forces from millinewtons to meganewtons), with the
regime-setting ratios (slack, strain, slope, friction) drawn where the regimes change.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["log_uniform", "line_data", "rng_for", "slack_length", "pick"]


def rng_for(regime: str, seed: int, index: int) -> np.random.Generator:
    """The generator of case ``index`` of ``regime`` under ``seed`` (independent of the others)."""
    key = [int(b) for b in regime.encode()]
    return np.random.default_rng([seed, index, *key])


def log_uniform(rng, lo: float, hi: float) -> float:
    """``10**U(log10 lo, log10 hi)``."""
    return float(10.0 ** rng.uniform(math.log10(lo), math.log10(hi)))


def pick(rng, options):
    return options[int(rng.integers(len(options)))]


def slack_length(rng, chord: float) -> float:
    """An unstretched length around the chord: shorter (a stretched bar), barely longer
    (taut), or slack."""
    kind = rng.uniform()
    if kind < 0.25:
        return chord * (1.0 - log_uniform(rng, 1e-7, 3e-2))
    if kind < 0.6:
        return chord * (1.0 + log_uniform(rng, 1e-9, 1e-1))
    return chord * (1.0 + log_uniform(rng, 1e-1, 4.0))


def line_data(rng, *, steep: float = 1.45):
    """``(span, dh, w, EA, L)`` of one elastic line in a random unit system."""
    span = log_uniform(rng, 1e-1, 1e4)
    dh = 0.0 if rng.uniform() < 0.1 else span * math.tan(rng.uniform(-steep, steep))
    w = log_uniform(rng, 1e-2, 1e4)
    chord = math.hypot(span, dh)
    L = slack_length(rng, chord)
    EA = w * L * log_uniform(rng, 1e1, 1e13)
    return span, dh, w, EA, L
