r"""The result protocol of every two-dimensional cable solution.

A cable, line or mooring line runs from A = (0, 0) to B = (span, dh), y up. Every solution of
one scene — closed forms (catenary, parabola, elastic and thermal catenaries, lines on a flat or
sloped seabed), multi-segment lines and the finite-element solutions (graph, arc, line BVP) —
answers the same questions in the same words:

- **end forces named by end**, in N: ``H_A``, ``H_B`` the horizontal component of the tension
  at A and at B (positive: the cable pulls A towards B and B towards A), ``V_A``, ``V_B`` the
  upward support reactions, ``T_A``, ``T_B`` the tensions there. ``H`` is kept only where the
  horizontal tension is the same at both ends, or (lines on a seabed, whose friction takes
  some of it) where it is the suspended part's, which is B's; each class says which;
- ``length``: the unstretched length (m);
- ``xy(s)``: positions ``(..., 2)`` (m) at unstretched arc length ``s`` (m) from A;
  ``profile(n)``: ``(n, 2)`` positions at ``n`` points evenly spaced in ``s`` from 0 to
  ``length``; ``T_of_s(s)``: the tension (N) at ``s``;
- ``stiffness()``: the 2 × 2 fairlead stiffness ``∂(H_B, V_B)/∂(span, dh)`` with A fixed
  (N/m), rows (H_B, V_B), columns (span, dh);
- ``tensions()``: a `pandas.DataFrame` with one row per segment (one row for a uniform cable);
- ``to_frame(n)``: a `pandas.DataFrame` of ``n`` profile samples (``s, x, y, T``, SI);
- ``to_vtk(path)``: the profile as a VTK polyline for ParaView; returns the path written;
- a ``repr`` that prints the key numbers.

`CableResult` states it as a `typing.Protocol` (``isinstance`` checks the names);
`ProfileMixin` derives ``profile``, ``to_frame`` and the one-row ``tensions`` from ``xy`` and
``T_of_s``. ``tests/test_result_protocol.py`` runs one set of checks over every result type.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np

from skcable._checks import whole
from skcable._show import Shown

if TYPE_CHECKING:  # pragma: no cover
    import pandas as pd

__all__ = ["CableResult", "ProfileMixin"]


@runtime_checkable
class CableResult(Protocol):
    """What every solution of one two-dimensional cable scene answers (module docstring)."""

    span: float
    dh: float

    @property
    def H_A(self) -> float: ...
    @property
    def V_A(self) -> float: ...
    @property
    def H_B(self) -> float: ...
    @property
    def V_B(self) -> float: ...
    @property
    def T_A(self) -> float: ...
    @property
    def T_B(self) -> float: ...
    @property
    def length(self) -> float: ...

    def xy(self, s) -> np.ndarray: ...
    def T_of_s(self, s) -> np.ndarray: ...
    def profile(self, n: int = 201) -> np.ndarray: ...
    def stiffness(self) -> np.ndarray: ...
    def tensions(self) -> pd.DataFrame: ...
    def to_frame(self, n: int = 201) -> pd.DataFrame: ...
    def to_vtk(self, path, n: int = 201) -> Path: ...


class ProfileMixin(Shown):
    """``profile``, ``to_frame`` and a one-row ``tensions`` of a `CableResult`, from its ``xy`` and
    ``T_of_s`` (the class it is mixed into)."""

    def profile(self: CableResult, n: int = 201) -> np.ndarray:
        """Positions ``(n, 2)`` (m) at ``n`` points evenly spaced in unstretched arc length."""
        return np.asarray(self.xy(np.linspace(0.0, float(self.length), whole("n", n, 2))), dtype=float)

    def to_frame(self: CableResult, n: int = 201) -> pd.DataFrame:
        """``n`` profile samples evenly spaced in unstretched arc length: columns ``s`` (m),
        ``x``, ``y`` (m) and ``T`` (N)."""
        import pandas as pd

        s = np.linspace(0.0, float(self.length), whole("n", n, 2))
        xy = np.asarray(self.xy(s), dtype=float)
        return pd.DataFrame(
            {"s": s, "x": xy[:, 0], "y": xy[:, 1], "T": np.asarray(self.T_of_s(s), dtype=float)}
        )

    def frame_with_outputs(self: CableResult, n: int, outputs: dict) -> pd.DataFrame:
        """`to_frame` at ``n`` points, then ``outputs`` sampled at the same points (name -> (n,) or
        (n, 2)), a vector as ``<name>_x`` and ``<name>_y`` columns."""
        frame = ProfileMixin.to_frame(self, n)
        for name, values in outputs.items():
            values = np.asarray(values, dtype=float)
            if values.ndim == 2:
                frame[f"{name}_x"], frame[f"{name}_y"] = values[:, 0], values[:, 1]
            else:
                frame[name] = values
        return frame

    def tensions(self: CableResult) -> pd.DataFrame:
        """One row (a uniform cable): ``segment, length, T_lower, T_upper, H_lower, H_upper`` (SI),
        the tensions and horizontal tensions at its ends towards A and B."""
        import pandas as pd

        return pd.DataFrame(
            {
                "segment": [0],
                "length": [float(self.length)],
                "T_lower": [float(self.T_A)],
                "T_upper": [float(self.T_B)],
                "H_lower": [float(self.H_A)],
                "H_upper": [float(self.H_B)],
            }
        )
