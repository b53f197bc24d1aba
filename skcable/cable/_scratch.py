"""Scratch rows for the vectorised paths (the catenary's passes, the conductors' line path),
reused from call to call.

On arrays of 1e4 floats a new NumPy array costs more than the arithmetic on it: each 80 kB
temporary is served by the C allocator from memory it returned to the system at the last
free, and every one of its 20 pages is then faulted in anew (about 1.5 µs a page here, 30 µs
an array, against 1.5 µs for an addition over it). The vectorised paths therefore work in place in
the rows of one block taken from a small per-thread pool and given back at the end: blocks
up to `KEEP` floats stay allocated between calls, so that their pages stay mapped.
"""

from __future__ import annotations

import threading

import numpy as np

__all__ = ["scratch", "KEEP"]

#: Floats kept per thread between calls (8 MiB); larger blocks are freed after use.
KEEP = 1 << 20
_POOL = threading.local()


class scratch:  # noqa: N801 - used like a function: ``with scratch(rows, size) as block:``
    """A ``(rows, size)`` float block of uninitialised scratch memory for the duration of the
    ``with`` block (taken from this thread's pool when one there is large enough: the
    smallest such; given back at the end, the pool keeping its largest blocks up to `KEEP`
    floats). A class rather than a generator: it opens every vectorised pass."""

    __slots__ = ("block", "pool", "rows", "size")

    def __init__(self, rows: int, size: int):
        self.rows, self.size = rows, size

    def __enter__(self) -> np.ndarray:
        pool = getattr(_POOL, "blocks", None)
        if pool is None:
            pool = _POOL.blocks = []
        need = self.rows * self.size
        best = None  # the pool is sorted largest first: the last block that fits is the smallest
        for i, block in enumerate(pool):
            if block.size < need:
                break
            best = i
        self.pool = pool
        self.block = pool.pop(best) if best is not None else np.empty(need)
        return self.block[:need].reshape(self.rows, self.size)

    def __exit__(self, kind, exc, traceback):
        block, pool = self.block, self.pool
        if block.size <= KEEP:
            pool.append(block)
            pool.sort(key=len, reverse=True)
            while sum(b.size for b in pool) > KEEP:
                pool.pop()  # the smallest go first
        return False
