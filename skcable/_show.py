"""One-line ``repr`` of results: every key number as ``name=value unit``.

A number prints with 6 significant digits; an array of at most `LISTED` values as
the list of them, ``[a, b]``; a longer one as its range, ``lo..hi``. The name is the
result's attribute (or says what it is computed from), so what a prompt shows can be
read back and compared with the object.

Examples
--------
>>> quantity("H", 85819.21737, "N")
'H=85819.2 N'
>>> quantity("f", [0.45, 0.9], "Hz")
'f=[0.45, 0.9] Hz'
>>> quantity("sag", range(20), "m")
'sag=0..19 m'
>>> from types import SimpleNamespace
>>> attributes(SimpleNamespace(H=2.0, sag=0.5), {"H": "N", "sag": "m"})
'H=2 N, sag=0.5 m'
>>> counted((3, 2), "state")
'3×2 states'
"""

from __future__ import annotations

import numpy as np

__all__ = ["LISTED", "attributes", "counted", "quantity"]

#: Longest array printed value by value (a longer one prints as its range).
LISTED = 8


def quantity(name: str, value, unit: str = "", digits: int = 6) -> str:
    """``name=value unit``: a number, the list of a short array's values, or a long one's range.

    Parameters
    ----------
    name : str
        The attribute's name.
    value : float or array_like
        Its value (a boolean or integer prints as a number).
    unit : str
        The unit (SI), empty for a dimensionless number.
    digits : int
        Significant digits.

    Returns
    -------
    str
    """
    values = np.asarray(value, dtype=float)
    if values.ndim == 0:
        text = f"{float(values):.{digits}g}"
    elif values.size <= LISTED:
        text = "[" + ", ".join(f"{v:.{digits}g}" for v in values.ravel()) + "]"
    else:
        text = f"{values.min():.{digits}g}..{values.max():.{digits}g}"
    return f"{name}={text} {unit}" if unit else f"{name}={text}"


def attributes(result, units: dict) -> str:
    """`quantity` of each attribute of ``result`` named in ``units`` (name -> unit), joined by commas."""
    return ", ".join(quantity(name, getattr(result, name), unit) for name, unit in units.items())


def counted(shape, noun: str) -> str:
    """How many of ``noun`` an array shape holds, e.g. ``"3 spans"``, ``"3×2 states"``."""
    shape = tuple(shape)
    if not shape:
        return f"1 {noun}"
    size = "×".join(map(str, shape))
    return f"{size} {noun}" if shape == (1,) else f"{size} {noun}s"
