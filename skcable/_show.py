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

import html as _html
import re

import numpy as np

__all__ = ["LISTED", "Shown", "attributes", "counted", "html_table", "quantity"]

#: Longest array printed value by value (a longer one prints as its range).
LISTED = 8


def quantity(name: str, value, unit: str = "", digits: int = 6) -> str:
    """``name=value unit``: a number (a boolean or integer prints as a number) with ``digits``
    significant digits, the list of a short array's values, or a long one's range; no unit for a
    dimensionless number.
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


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+|inf|nan)(?:e[-+]?\d+)?"
_VALUE = rf"\[{_NUMBER}(?:, {_NUMBER})*\]|\({_NUMBER}(?:, {_NUMBER})*\)|{_NUMBER}\.\.{_NUMBER}|{_NUMBER}"
#: One ``name=value unit`` of a repr (`quantity`'s form).
_ITEM = re.compile(rf"(\w+)=({_VALUE})(?: ([^\s,;:()=]+))?")


def html_table(text: str) -> str:
    """A result's one-line ``repr`` as an HTML table (Jupyter's rich display): its head (the
    class and what it holds, the text before the first quantity) as the caption, then one row
    per ``name=value unit`` (`quantity`'s form), in the order printed."""
    items = list(_ITEM.finditer(text))
    head = text[: items[0].start()].rstrip(" :(") if items else text
    tail = text[items[-1].end() :].strip(" ,;)") if items else ""
    head = f"{head}: {tail}" if tail else head
    rows = "".join(
        f"<tr><th style='text-align:left'>{_html.escape(m[1])}</th><td>{_html.escape(m[2])}</td>"
        f"<td>{_html.escape(m[3] or '')}</td></tr>"
        for m in items
    )
    header = "<tr><th>quantity</th><th>value</th><th>unit</th></tr>"
    return f"<table><caption>{_html.escape(head)}</caption>{header}{rows}</table>"


class Shown:
    """Mixin: a result that displays in Jupyter as the table of its ``repr`` (`html_table`)."""

    __slots__ = ()

    def _repr_html_(self) -> str:
        return html_table(repr(self))
