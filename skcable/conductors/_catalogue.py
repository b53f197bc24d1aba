"""The conductor catalogue as a table (its data and strands: `skcable.strand`'s catalogue)."""

from __future__ import annotations

__all__ = ["catalogue"]


def catalogue(kind: str | None = None):
    """The catalogue's sizes (pandas DataFrame indexed by name): ``kind`` (ACSR, AAC, AAAC),
    ``size`` (kcmil or AWG), ``stranding``, ``diameter_mm``, ``mass_kg_km``, ``rts_kN`` and the
    ``source`` (standard, table, code word); ``kind`` selects one kind."""
    import pandas as pd

    from skcable._checks import one_of
    from skcable.strand._catalogue import ENTRIES

    if kind is not None:
        one_of("kind", kind, sorted({e.kind for e in ENTRIES.values()}), " or None")
    rows = [
        dict(
            name=e.name,
            kind=e.kind,
            size=e.size,
            stranding=e.stranding,
            diameter_mm=e.diameter * 1e3,
            mass_kg_km=e.mass * 1e3,
            rts_kN=e.rts / 1e3,
            source=e.source,
        )  # fmt: skip
        for e in ENTRIES.values()
        if kind is None or e.kind == kind
    ]
    return pd.DataFrame(rows).set_index("name")
