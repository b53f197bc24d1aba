"""Warnings of the study package, pointed at the user's line rather than at the package's."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path
from types import FrameType

__all__ = ["warn"]

_HERE = Path(__file__).resolve().parent


def warn(message: str, category: type[Warning]) -> None:
    """`warnings.warn` with the stack level of the first caller outside ``skcable/study``."""
    frame: FrameType | None = sys._getframe(1)
    level = 2  # warn's caller
    while frame is not None and Path(frame.f_code.co_filename).resolve().parent == _HERE:
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level)
