"""`LineArrays`: the read-only per-segment and per-joint numbers of a `Line`.

The closed form of a multi-segment line (`skcable.mooring.segments.state`), its heap
state and its solution read a line through this view only. Arrays are read-only NumPy
arrays; the ``*_list`` fields hold the same numbers as Python floats, for the scalar
parts of the closed form (``math`` on floats is 5–20 times faster than NumPy on one number).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["LineArrays", "line_arrays"]


@dataclass(frozen=True, slots=True)
class LineArrays:
    """Per-segment (``n``) and per-joint (``n + 1``) numbers of a line, SI units.

    Attributes
    ----------
    n : int
        Number of segments.
    L, w, EA : ndarray, shape (n,)
        Unstretched length (m), weight in water per unstretched length (N/m) and axial
        stiffness (N) of each segment, from the anchor.
    wL : ndarray, shape (n,)
        Weight of each segment (N).
    L_list, w_list, EA_list, wL_list : tuple of float
        The same, as Python floats.
    P : ndarray, shape (n + 1,)
        Downward point force at each joint (N; buoys negative), joint 0 the anchor.
    P_list : tuple of float
        The same, as Python floats.
    P_end : tuple of float
        ``(P_0, P_n)``: the point forces at the anchor and at the fairlead (N).
    load_above : ndarray, shape (n,)
        Load between the top of segment ``i`` and the fairlead, the fairlead's joint left
        out (N): ``V_top,i = V - load_above[i]`` for the vertical force ``V`` below B.
    s_joint : ndarray, shape (n + 1,)
        Unstretched arc length of each joint from the anchor (m).
    total_length : float
        Unstretched length of the line (m).
    total_weight : float
        Weight in water of the segments and the attachments (N).
    segment_weight : float
        Weight in water of the segments alone (N; buoyant segments count negative).
    abs_segment_weight : float
        Sum of the magnitudes of the segments' weights in water (N): a force scale.
    abs_joint_forces : float
        Sum of the magnitudes of the point forces (N): a force scale of the checks.
    """

    n: int
    L: np.ndarray
    w: np.ndarray
    EA: np.ndarray
    wL: np.ndarray
    L_list: tuple
    w_list: tuple
    EA_list: tuple
    wL_list: tuple
    P: np.ndarray
    P_list: tuple
    P_end: tuple
    load_above: np.ndarray
    s_joint: np.ndarray
    total_length: float
    total_weight: float
    segment_weight: float
    abs_segment_weight: float
    abs_joint_forces: float


def _frozen(array) -> np.ndarray:
    array.flags.writeable = False
    return array


def line_arrays(segments, P) -> LineArrays:
    """`LineArrays` of ``segments`` (each with ``length, w`` and ``nominal_EA`` or ``EA``) and joint
    forces ``P`` (n + 1)."""
    n = len(segments)
    L = np.array([s.length for s in segments])
    w = np.array([s.w for s in segments])
    EA = np.array([getattr(s, "nominal_EA", s.EA) for s in segments])
    wL = w * L
    P = np.array(P, dtype=float)
    c = P[1:n] + w[1:] * L[1:]
    return LineArrays(
        n=n,
        L=_frozen(L),
        w=_frozen(w),
        EA=_frozen(EA),
        wL=_frozen(wL),
        L_list=tuple(float(s.length) for s in segments),
        w_list=tuple(float(s.w) for s in segments),
        EA_list=tuple(EA.tolist()),
        wL_list=tuple(wL.tolist()),
        P=_frozen(P),
        P_list=tuple(P.tolist()),
        P_end=(float(P[0]), float(P[n])),
        load_above=_frozen(np.append(np.cumsum(c[::-1])[::-1], 0.0)),
        s_joint=_frozen(np.concatenate([[0.0], np.cumsum(L)])),
        total_length=float(L.sum()),
        total_weight=float(w @ L + P.sum()),
        segment_weight=float(w @ L),
        abs_segment_weight=float(np.abs(w) @ L),
        abs_joint_forces=float(np.abs(P).sum()),
    )
