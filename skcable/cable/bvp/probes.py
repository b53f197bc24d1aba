"""Evaluation of a field at arbitrary points: now `skcable.fe.probes`, re-exported here."""

from skcable.fe.probes import element_minimum, element_values, gradient_probes, minimum_near

__all__ = ["element_minimum", "element_values", "gradient_probes", "minimum_near"]
