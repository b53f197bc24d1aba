r"""`elastic_catenary` with a seabed: the regime of each element, then its solve.

Per element of the (broadcast) input: a line whose anchor lies on the seabed and that
leaves it upwards hangs free (`skcable.cable.seabed.free.lifted`); one whose anchor
lies above the seabed hangs free unless the free line dips below it. A line in contact
lies in a heap when it is longer than its L-shape (`skcable.cable.seabed.heap`),
else it is grounded and its closure is solved
(`skcable.cable.seabed.grounded`). One scene runs on Python floats
(`_seabed_catenary_scalar`), arrays with NumPy masks; both give the same numbers.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from skcable import _plausible
from skcable._checks import broadcast, float_range, nonnegative, positive, real, require
from skcable.cable._answers import check_catenary
from skcable.cable._elastic import elastic_catenary as free_elastic_catenary
from skcable.cable._extreme import outsized
from skcable.cable.closure import anchor_part, hanging_length
from skcable.cable.seabed.free import free_part, lifted
from skcable.cable.seabed.grounded import solve_grounded
from skcable.cable.seabed.solution import SeabedCatenary
from skcable.cable.solution import checked_closed_form
from skcable.errors import InputError

__all__ = ["elastic_catenary"]

_INDETERMINATE = (
    "must be 0 where the line touches down between A and B (anchor above the seabed): "
    "the static friction there depends on the history of the motion"
)


@_plausible.answer(check_catenary)
def elastic_catenary(span, dh, w, EA, *, length, seabed=None, friction=0.0):
    """Elastic (Irvine) catenary from A = (0, 0) to B = (span, dh), optionally on a seabed.

    Parameters
    ----------
    span, dh : float or array_like
        Horizontal distance A→B (> 0) and height of B above A (m).
    w : float or array_like
        Weight per unit *unstretched* length (N/m), > 0.
    EA : float or array_like
        Axial stiffness (N), > 0.
    length : float or array_like
        Unstretched length (m), > 0; it may be shorter than the chord (the
        cable then stretches to reach B).
    seabed : float or array_like, optional
        Height of a flat seabed relative to A (m), ``<= 0``. With ``seabed=0``
        (the anchor on the seabed) the part of the line that would hang below
        A rests on it (J.M. Jonkman, "Dynamics modeling and loads analysis of
        an offshore floating wind turbine", NREL, 2007). Below A (``seabed < 0``)
        a line that reaches it hangs from A down to the seabed, rests on it and
        rises to B (frictionless only). B must lie above the seabed.
    friction : float or array_like, optional
        Coulomb friction coefficient of the grounded part, ``>= 0``; only with
        a ``seabed``, and 0 where the line touches down between A and B.

    Returns
    -------
    ElasticCatenary
        Without a seabed (H.M. Irvine, "Cable Structures", MIT Press, 1981):
        ``H, V_A, V_B, T_A, T_B, length`` (unstretched), ``stretched_length``,
        ``sag``, the lowest point ``x_low, y_low``, the vertex ``x_vertex,
        y_vertex``, ``y(x), T(x), slope(x), residual()``, ``stiffness()``.
    SeabedCatenary
        With a ``seabed``: the same forces, maps and ``stiffness()``, plus the seabed's
        (`SeabedCatenary`), in a heap state too (``heap`` True, ``H = 0``: a line longer
        than its L-shape, ``span <= L - l_A - l_B``, `hanging_length`; MoorPy's slack
        profiles 4 and 5).

    Raises
    ------
    InputError
        A non-physical argument, named: a seabed above A, B on or below it,
        friction without a seabed or where it is indeterminate.
    ConvergenceError
        Newton stalled; the error carries the residual history.
    """
    if seabed is None:
        if friction is not None and (
            friction != 0.0 if type(friction) is float else np.any(np.asarray(friction) != 0.0)
        ):
            raise InputError("friction", "applies to a line on the seabed: give seabed= as well")
        return free_elastic_catenary(span, dh, w, EA, length=length)
    span = positive("span", span)
    dh = real("dh", dh)
    w = positive("w", w)
    EA = positive("EA", EA)
    L0 = positive("length", length)
    seabed = real("seabed", seabed)
    friction = nonnegative("friction", friction)
    broadcast(span=span, dh=dh, w=w, EA=EA, length=L0, seabed=seabed, friction=friction)
    _plausible.stiffness(EA, w, L0)
    _plausible.friction(friction)
    require("seabed", np.asarray(seabed) <= 0, "must be at or below the anchor (A at height 0)", seabed)
    require("dh", np.asarray(dh) > seabed, "must put B above the seabed", dh)
    # a refusal or a float failure inside names the outsized argument, if one is
    with outsized(span=span, dh=dh, w=w, EA=EA, length=L0, seabed=seabed, friction=friction):
        if all(isinstance(v, float) for v in (span, dh, w, EA, L0, seabed, friction)):
            return _seabed_catenary_scalar(span, dh, w, EA, L0, seabed, friction)
        return _seabed_catenary_array(span, dh, w, EA, L0, seabed, friction)


def _free_elements(span, dh, w, EA, L0, seabed, shape):
    """The elements that hang free and those whose free line dips to the seabed.

    Returns ``contact, H, V_t, guess, depth, dips`` (arrays of ``shape``): ``H, V_t`` the
    free line's where it hangs, ``guess`` the start of the grounded solve (the lift-off
    or free ``H``), ``depth`` the anchor's height above the seabed where the line dips."""
    on_bed = np.broadcast_to(np.asarray(seabed) == 0, shape)
    is_lifted, H_lift = lifted(span, dh, w, EA, L0)
    contact = np.asarray(on_bed & ~np.broadcast_to(is_lifted, shape))
    H, V_t = np.zeros(shape), np.zeros(shape)
    guess = np.array(np.broadcast_to(np.where(H_lift > 0, np.minimum(H_lift, w * L0), w * L0), shape))
    depth = np.zeros(shape)
    dips = np.zeros(shape, dtype=bool)
    if not contact.all():
        hanging = np.asarray(~contact)
        args = [np.broadcast_to(v, shape)[hanging] for v in (span, dh, w, EA, L0)]
        if shape == ():
            args = [float(v[0]) for v in args]
        # anchor above the seabed and the free line below it: a touchdown between A and B
        span_h, dh_h, w_h, EA_h, L_h = args
        bed = np.broadcast_to(seabed, shape)[hanging]
        H[hanging], V_t[hanging], dips[hanging] = free_part(span_h, dh_h, w_h, EA_h, L_h, bed)
        if dips.any():
            contact = contact | dips
            depth[dips] = -np.broadcast_to(seabed, shape)[dips]
            guess[dips] = H[dips]
    return contact, H, V_t, guess, depth, dips


def _heap_elements(span, dh, w, EA, L0, friction, contact, depth, dips, shape):
    """The elements in contact whose slack lies in a heap (H = 0), with their anchor-side
    vertical force ``V_1 = w l_A`` and grounded length ``L - l_A - l_B``.

    H -> 0: A and B hold the vertical parts l = V_0/w (`hanging_length`), the rest lies at
    X_0 = L - l_A - l_B; a shorter span leaves the slack in a heap."""
    l_A, l_B = hanging_length(depth, w, EA), hanging_length(dh + depth, w, EA)
    heap = contact & np.broadcast_to(span <= L0 - l_A - l_B, shape)
    if dips.any():  # a taut line between two touchdowns: friction indeterminate
        determinate = ~(dips & ~heap) | (np.broadcast_to(friction, shape) == 0)
        require("friction", determinate, _INDETERMINATE, friction)
    V_1, L_B = np.zeros(shape), np.zeros(shape)
    if heap.any():  # the heap state: H = 0, vertical parts at A and B, the slack between
        l_A, l_B = np.broadcast_to(l_A, shape), np.broadcast_to(l_B, shape)
        V_1[heap] = (np.broadcast_to(w, shape) * l_A)[heap]
        L_B[heap] = (np.broadcast_to(L0, shape) - l_A - l_B)[heap]
    return heap, V_1, L_B


def _seabed_catenary_array(span, dh, w, EA, L0, seabed, friction):
    """`elastic_catenary` with a seabed on checked, broadcastable arrays."""
    shape = np.broadcast_shapes(*(np.shape(v) for v in (span, dh, w, EA, L0, seabed, friction)))
    H: Any  # arrays of the scenes, floats for one
    V_t: Any
    heap: Any
    V_1: Any
    L_B: Any
    y_t: Any
    contact, H, V_t, guess, depth, dips = _free_elements(span, dh, w, EA, L0, seabed, shape)
    heap = np.zeros(shape, dtype=bool)
    V_1, L_B = np.zeros(shape), np.zeros(shape)
    if contact.any():
        heap, V_1, L_B = _heap_elements(span, dh, w, EA, L0, friction, contact, depth, dips, shape)
        H[heap], V_t[heap] = 0.0, 0.0
    history: list = []
    taut = contact & ~heap
    if taut.any():
        args = [np.broadcast_to(v, shape)[taut] for v in (span, dh, w, EA, L0, friction * w, guess, depth)]
        if shape == ():  # one scene: the same Newton on Python floats
            args = [float(v[0]) for v in args]
        Hc, Vc, history = solve_grounded(*args)
        V1 = anchor_part(Hc, args[2], args[3], args[7])[0]
        H[taut], V_t[taut], V_1[taut] = Hc, 0.0, V1
        L_B[taut] = np.maximum(args[4] - V1 / args[2] - Vc / args[2], 0.0)
    y_t = np.where(contact, np.broadcast_to(seabed, shape), 0.0)
    if shape == ():
        H, V_t, L_B, V_1, y_t = (float(v) for v in (H, V_t, L_B, V_1, y_t))
        heap = bool(heap)
    with float_range("length", "a result"):
        solution = SeabedCatenary(span, dh, w, EA, L0, friction, seabed, H, V_t, L_B, V_1, y_t, heap)
        return checked_closed_form(solution, "length", history)


def _seabed_catenary_scalar(span, dh, w, EA, L0, seabed, friction):
    """`elastic_catenary` with a seabed for one scene (checked Python floats): the same
    steps as the array path without its masks and broadcasts."""
    is_lifted, H_lift = lifted(span, dh, w, EA, L0)
    contact = seabed == 0 and not is_lifted
    guess = min(H_lift, w * L0) if H_lift > 0 else w * L0
    H, V_t, L_B, V_1, depth, history = 0.0, 0.0, 0.0, 0.0, 0.0, []
    dips = heap = False
    if not contact:
        H, V_t, dips = free_part(span, dh, w, EA, L0, seabed)
        if dips:  # anchor above the seabed, the free line below it: a touchdown
            contact, depth, guess = True, -seabed, H
    if contact:
        # H -> 0: A and B hold the vertical parts l = V_0/w (`hanging_length`), the rest
        # lies at X_0 = L - l_A - l_B; a shorter span leaves the slack in a heap (H = 0)
        l_A, l_B = hanging_length(depth, w, EA), hanging_length(dh + depth, w, EA)
        heap = span <= L0 - l_A - l_B
        if dips and not heap:  # a taut line between two touchdowns: friction indeterminate
            require("friction", friction == 0, _INDETERMINATE, friction)
    if heap:  # the heap state: H = 0, vertical parts at A and B, the slack between
        H, V_t, V_1, L_B = 0.0, 0.0, w * l_A, L0 - l_A - l_B
    elif contact:
        H, Vc, history = solve_grounded(span, dh, w, EA, L0, friction * w, guess, depth)
        V_1 = anchor_part(H, w, EA, depth)[0]
        V_t, L_B = 0.0, max(L0 - V_1 / w - Vc / w, 0.0)
    y_t = seabed if contact else 0.0
    with float_range("length", "a result"):
        solution = SeabedCatenary(span, dh, w, EA, L0, friction, seabed, H, V_t, L_B, V_1, y_t, heap)
        return checked_closed_form(solution, "length", history)
