"""Every fuzzed regime by name: a seeded generator of `Case` objects (`tests.fuzz.harness`)."""

from __future__ import annotations

from tests.fuzz import commands, conductors, edges, lines, moored, multi, networks, spectra
from tests.fuzz.harness import Case
from tests.fuzz.scenes import rng_for

__all__ = ["REGIMES", "case"]

REGIMES = {
    **lines.REGIMES,
    **multi.REGIMES,
    **moored.REGIMES,
    **networks.REGIMES,
    **conductors.REGIMES,
    **spectra.REGIMES,
    **commands.REGIMES,
    **edges.REGIMES,
}


def case(regime: str, seed: int, index: int) -> Case:
    """Case ``index`` of ``regime`` under ``seed`` (the same on every run and machine)."""
    out = REGIMES[regime](rng_for(regime, seed, index))
    out.where = (regime, seed, index)
    return out
