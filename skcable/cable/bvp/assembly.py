"""Deprecated: the cable BVPs' assembly is `skcable.fe.assembly.Assembly` (one assembly for
strands and cables). ``LineAssembly`` is served for one release with a `DeprecationWarning`."""

from skcable._lazy import attach

__all__: list[str] = []
__getattr__, __dir__ = attach(__name__, moved={"LineAssembly": "skcable.fe.assembly.Assembly"})
