"""Deprecated: the evaluation of a field at arbitrary points is `skcable.fe.probes`, served here
for one release with a `DeprecationWarning`."""

from skcable._lazy import attach

__all__: list[str] = []
__getattr__, __dir__ = attach(
    __name__,
    moved={
        name: f"skcable.fe.probes.{name}"
        for name in ("element_minimum", "element_values", "gradient_probes", "minimum_near")
    },
)
