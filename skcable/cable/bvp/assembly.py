"""The cable BVPs' assembly is `skcable.fe.Assembly` (one assembly for strands and cables).

``LineAssembly`` is its old name, kept for the line BVP's modules until they import
`skcable.fe.Assembly` themselves.
"""

from skcable.fe.assembly import Assembly as LineAssembly

__all__ = ["LineAssembly"]
