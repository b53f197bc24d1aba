r"""Meshes of the unstretched arc length: uniform, graded by the line's turning, fitted, nested.

- `line_nodes`: the nodes of one solve: uniform per segment (joints and point loads are nodes),
  or given (a graded mesh), with nodes put at fitted points (the touchdown, the landing, the end
  of a slack stretch);
- `start_nodes`: the first solve's grading, from the closed-form start's angle;
- `graded_nodes`: each later solve's grading, from the last solution's turning, with nodes at
  the ends of the arch each buoy resting on the seabed lifts (`arch_ends`), and
  `grading_passes`, the passes of grading (either line's);
- `nested_sizes`: the element counts of nested solves, from `COARSE` elements up, and
  `solve_nested`, the nested solves themselves (each level from the coarser one, else from
  scratch).

The gradings equidistribute a monitor function (W. Huang, R.D. Russell, "Adaptive Moving Mesh
Methods", Springer, 2011, ch. 2): ``1 + L |dθ/ds|`` (θ the line's angle to the horizontal), or
``1 + L max(|dθ/ds|, |d ln cos θ/ds|)`` on a line whose ``cos θ`` varies more than tenfold, with
neighbouring elements within a factor ``1 + GROWTH`` (`smoothed`).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from skcable._checks import positive, require
from skcable.errors import ConvergenceError

__all__ = [
    "COARSE",
    "GRADE_PASSES",
    "GROWTH",
    "REFINEMENT",
    "TAIL_RATIO",
    "arch_ends",
    "composite_gauss",
    "equidistributed",
    "fixed_nodes",
    "grading_passes",
    "graded_nodes",
    "joints_of",
    "line_nodes",
    "nested_sizes",
    "smoothed",
    "solve_nested",
    "start_nodes",
    "with_fitted",
]

#: a buoy's arch (`_half_arches`): Gauss–Legendre points of each piece of its weight and moment,
#: pieces on each side, and Newton steps at most (a weight varying ±80 % over the arch takes about 8)
ARCH_POINTS, ARCH_QUADRATURE, ARCH_NEWTON = 8, 4, 30
#: elements of the first solve of a fine mesh whose start touches the seabed
COARSE = 32
#: how much finer an element may get at one grading
REFINEMENT = 4.0
#: gradings of the mesh at most
GRADE_PASSES = 10
#: growth of the element size per length away from small elements (neighbours differ by 1.5 at most)
GROWTH = 0.5
#: the monitor's tail term only on lines whose cos θ (= H/T on a catenary) varies more than tenfold
TAIL_RATIO = float(np.log(10.0))


def fixed_nodes(joints, point_loads) -> np.ndarray:
    """The nodes every mesh keeps: the joints (ends included) and the point loads (m)."""
    return np.unique(np.concatenate([joints, [s_p for s_p, _ in point_loads]]))


def joints_of(lengths) -> np.ndarray:
    """The joints of segments of unstretched ``lengths`` (m), from 0 to the length."""
    return np.concatenate([[0.0], np.cumsum(lengths)])


def line_nodes(lengths, point_loads, n_elements, fitted=(), nodes_at=None) -> np.ndarray:
    """The nodes (unstretched arc length, m) of a solve on ``n_elements`` over segments of
    ``lengths`` (m): uniform per segment (its share of ``n_elements`` by length, at least one),
    or ``nodes_at`` (a graded mesh), joints and point loads always nodes; then a node at each
    ``fitted`` point (`with_fitted`)."""
    joints = joints_of(lengths)
    L = float(joints[-1])
    n = positive("n_elements", n_elements)
    require("n_elements", n == int(n), "must be a whole number", n)
    per = np.maximum(1, np.round(int(n) * lengths / L)).astype(int)
    pieces = [np.linspace(a, b, k + 1) for a, b, k in zip(joints[:-1], joints[1:], per, strict=True)]
    nodes = np.unique(np.concatenate([*pieces, [s for s, _ in point_loads]]))
    if nodes_at is not None:  # a graded mesh: joints and point loads stay nodes
        nodes = np.unique(np.concatenate([nodes_at, joints, [s for s, _ in point_loads]]))
    return with_fitted(nodes, fitted, joints, point_loads)


def with_fitted(nodes, fitted, joints, point_loads) -> np.ndarray:
    """``nodes`` with a node at each ``fitted`` point: the nearest inner node moved there when it
    is closer than a quarter of an element and is neither a joint, a point load nor fitted
    already, else a node inserted (unless one lies within 1e-9 of the length)."""
    L = float(joints[-1])
    loads = [s for s, _ in point_loads]
    placed: list[float] = []
    for s_fit in fitted:
        k = int(np.argmin(np.abs(nodes - s_fit)))
        spacing = np.min(np.diff(nodes[max(k - 1, 0) : k + 2]))  # of the elements at that node
        movable = 0 < k < len(nodes) - 1 and not np.any(np.isclose(nodes[k], joints))
        movable = movable and not any(np.isclose(nodes[k], s) for s in [*placed, *loads])
        placed.append(s_fit)
        if movable and abs(nodes[k] - s_fit) < 0.25 * spacing:
            nodes[k] = s_fit
        elif np.min(np.abs(nodes - s_fit)) > 1e-9 * L:
            nodes = np.sort(np.append(nodes, s_fit))
    return nodes


def arch_ends(line, z) -> np.ndarray:
    """The ends of the arch that each buoy (a point load ``P < 0``) lifts off the seabed, where
    the discrete ``line`` at its dofs ``z`` rests on the seabed on both sides of that arch
    (m, unstretched arc length; empty without a seabed or such a buoy).

    A line lying on the seabed leaves it only where the buoy's lift carries its weight: the arch
    is the length whose weight is ``|P|``, ``s ± |P|/(2 w)`` about the buoy at ``s`` under a
    uniform weight (vertical balance of the lifted length; the line leaves the seabed tangent to
    it, so no reaction is concentrated there), its sides' weights of equal moments about the buoy
    under a weight varying along it (`_half_arches`). Nodal contact resolves it only with nodes
    at its ends: an element longer than the arch holds the buoy down (H 8 % low on a light line
    with a small buoy on 64 elements; H half the energy minimum's for the plane line under a
    weight varying ±35 %, the survey's scene 3:19). "Rests" means the nearest node beyond each end
    (a node at the end excluded), away from the buoy, lies on the seabed within ``1e-8 L``: where
    the buoy floats free, or the line lands within its arch, the mesh is left alone. So it is
    where the arch lies inside one segment of positive weight, with no joint or other point load
    in it (a clump inside it, or another weight, moves its ends)."""
    buoys = [(s, -P) for s, P in line.point_loads if P < 0]
    if line.seabed is None or not buoys:
        return np.empty(0)
    s_b, lift = np.array(buoys, dtype=float).T
    low, high, found = _half_arches(line, s_b, lift)
    nodes = np.sort(line.mesh.p[0])
    apart = 1e-9 * line.L  # a node at an end (a mesh graded by a line with its arch) is not beyond it
    before = nodes[np.maximum(np.searchsorted(nodes, low - apart, side="right") - 1, 0)]
    after = nodes[np.minimum(np.searchsorted(nodes, high + apart), nodes.size - 1)]
    gap = line.heights(line.state_at(z, np.concatenate([before, after])).position)
    rests = np.all(gap.reshape(2, -1) <= 1e-8 * line.L, axis=0)
    others = np.concatenate([line.joints, [s for s, _ in line.point_loads]])
    alone = [
        0 < a and b < line.L and not np.any((others > a) & (others < b) & (others != s))
        for a, s, b in zip(low, s_b, high, strict=True)
    ]
    keep = found & rests & np.array(alone, dtype=bool)
    return np.concatenate([low[keep], high[keep]])


def composite_gauss(a, b, pieces: int, points: int) -> tuple[np.ndarray, np.ndarray]:
    """``(s, h)``: composite Gauss–Legendre on each interval from ``a`` to ``b`` (arrays (n,), m),
    ``pieces`` equal pieces of ``points`` points each: the abscissae ``s`` (n, pieces, points) and
    the weights ``h`` (m, the same shape, negative where ``b < a``), so that ``∫_a^b f ds`` is
    ``(f(s) h).sum(axis=(1, 2))``."""
    x, weights = np.polynomial.legendre.leggauss(points)
    edges = a[:, None] + (b - a)[:, None] * np.linspace(0.0, 1.0, pieces + 1)
    half = 0.5 * np.diff(edges, axis=1)  # (n, pieces), signed
    s = (edges[:, :-1] + half)[:, :, None] + half[:, :, None] * x
    return s, half[:, :, None] * weights


def _arch_integrals(line, s_b, end):
    """``(W, M)``: the weight (N) between each buoy at ``s_b`` and ``end`` (m, either side) and its
    moment about the buoy (N·m), both positive, by composite Gauss–Legendre (`ARCH_QUADRATURE`
    pieces of `ARCH_POINTS` points each, `composite_gauss`)."""
    s, h = composite_gauss(s_b, end, ARCH_QUADRATURE, ARCH_POINTS)
    dW = np.abs(h) * line.weight_at(s.ravel()).reshape(s.shape)
    return dW.sum(axis=(1, 2)), (dW * np.abs(s - s_b[:, None, None])).sum(axis=(1, 2))


def _half_arches(line, s_b, lift):
    """``(low, high, found)``: the ends (m) of the arch each buoy at ``s_b`` lifts (N, ``lift``),
    where the lifted line weighs the lift and its two sides reach the buoy's height alike: for a
    shallow arch, ``H y'' = w`` from a tangent lift-off, equal moments of the two sides' weights
    about the buoy (equal halves under a uniform weight). Newton on the two, from the uniform
    weight's ends, at most `ARCH_NEWTON` steps, each end kept on the line; ``found`` where both
    hold to 1e-9 of the lift (and of its moment) at the ends returned, under a positive weight
    (else no arch: `arch_ends` leaves the mesh alone)."""
    w_b = line.weight_at(s_b)
    half = 0.5 * lift / np.where(w_b > 0, w_b, np.inf)  # none where the line floats there
    low, high = s_b - half, s_b + half
    for step in range(ARCH_NEWTON + 1):
        low, high = np.clip(low, 0.0, line.L), np.clip(high, 0.0, line.L)
        (W_a, M_a), (W_b, M_b) = _arch_integrals(line, s_b, low), _arch_integrals(line, s_b, high)
        weight, moment = W_a + W_b - lift, M_a - M_b
        w_a, w_z = line.weight_at(low), line.weight_at(high)
        heavy = (w_a > 0) & (w_z > 0)
        found = heavy & (low < s_b) & (s_b < high)
        found &= (np.abs(weight) <= 1e-9 * lift) & (np.abs(moment) <= 1e-9 * lift * (high - low))
        if step == ARCH_NEWTON or np.all(found | ~heavy):
            break
        move = heavy & ~found & (low < high)  # the 2 x 2 Newton step: its determinant w_a w_z (high - low)
        span = np.where(move, high - low, 1.0)
        low, high = (
            low + np.where(move, ((high - s_b) * weight + moment) / (np.where(move, w_a, 1.0) * span), 0.0),
            high + np.where(move, (moment - (s_b - low) * weight) / (np.where(move, w_z, 1.0) * span), 0.0),
        )
    return low, high, found


def graded_nodes(line, z, n_elements, fixed, refinement=REFINEMENT, arches=True):
    """Mesh nodes (unstretched arc length, m) equidistributing
    ``1 + L max(|dθ/ds|, |d ln cos θ/ds|)`` over the discrete ``line`` (in the plane or in
    space) at its dofs ``z``, no element smaller than ``1/refinement`` of ``line``'s element
    there; and whether that bound held anywhere (another pass would refine further).

    θ(s) is the line's angle to the horizontal (from its tangent `DiscreteLine.state_at`), and
    ``|dθ/ds|`` its turning: in space the turning of its unit tangent ``|dt/ds|`` (the drag of
    a current bends it out of its vertical plane) and ``cos θ = |t_h|``. So
    the density is one per length plus the turning of the line per length: a slack line's
    elements gather where it bends, near its touchdown or its lowest point, instead of lying on
    the seabed where it is straight. Where the line is steeper than 45° the second term,
    ``|d ln cos θ/ds| = |tan θ| |dθ/ds|``, takes over: past the bend of a nearly L-shaped line
    (radius ``r = H/w``) the catenary's ``x = r asinh(σ/r)`` grows like ``r ln σ`` (σ the
    arc length past the touchdown) while ``|dθ/ds| = r/σ²`` falls fast; ``cos θ = r/σ`` there,
    so the second term is ``1/σ``, a geometric grading that interpolates the logarithm (the
    horizontal closure that sets H) instead of leaving its P2 error at ``r`` times a constant
    (H converged like h, 3e-4 of H at 80 elements, before it). The term is used only on a line
    whose ``cos θ`` varies more than tenfold (``ln`` of the ratio above ``TAIL_RATIO``): taut
    and ordinary lines keep the turning monitor. The bound keeps each solve's
    start (the previous solution interpolated) within a node or two of its contact set. Each
    stretch between the ``fixed`` nodes (joints and point loads, and the `arch_ends` of buoys
    resting on the seabed, where ``arches``: a solved line's, not a start's) gets its share (at
    least one element) of the ``n_elements``.
    """
    L = float(fixed[-1])
    ends = arch_ends(line, z) if arches else np.empty(0)
    ends = ends[np.abs(ends[:, None] - fixed[None, :]).min(axis=1, initial=np.inf) > 1e-6 * L]
    fixed = np.unique(np.concatenate([fixed, ends]))
    old = np.sort(line.mesh.p[0])
    h_old = np.diff(old)
    cells = 16  # per element of the line: its turning is measured inside each element, so
    # that the kink of a point load or a joint (a node of every mesh) draws no elements
    fraction = (np.arange(cells) + 0.5) / cells
    inside = old[:-1, None] + fraction[None, :] * h_old[:, None]  # (ne, cells)
    a = line.state_at(z, inside.ravel()).a
    if line.dim == 2:
        theta = np.unwrap(np.arctan2(a[1], a[0]).reshape(inside.shape), axis=1)
        turning = np.abs(np.gradient(theta, axis=1)) / (h_old[:, None] / cells)
        cosine = np.log(np.maximum(np.abs(np.cos(theta)), 1e-12))
    else:
        t = (a / np.linalg.norm(a, axis=0)).reshape(line.dim, *inside.shape)
        turning = np.linalg.norm(np.gradient(t, axis=2), axis=0) / (h_old[:, None] / cells)
        cosine = np.log(np.maximum(np.linalg.norm(t[:-1], axis=0), 1e-12))
    stretching = np.abs(np.gradient(cosine, axis=1)) / (h_old[:, None] / cells)
    ds = np.repeat(h_old / cells, cells)
    if np.sum(stretching.ravel() * ds) <= TAIL_RATIO:  # cos θ = H/T varies less than tenfold
        stretching = 0.0
    rho = (1.0 + L * np.maximum(turning, stretching)).ravel()
    h_old = np.repeat(h_old, cells)
    s = np.concatenate([[0.0], np.cumsum(ds)])
    s[-1] = L

    def density(scale):  # elements per length: the monitor over scale, at most refinement / h_old
        return np.minimum(rho / scale, refinement / h_old)

    total = np.sum(rho * ds)
    if np.sum(refinement / h_old * ds) <= n_elements:
        scale = 0.0
    else:
        scale = brentq(lambda c: np.sum(density(c) * ds) - n_elements, 1e-12 * total / n_elements, total)
    rate = density(scale) if scale > 0 else refinement / h_old
    capped = bool(np.any(rho / max(scale, 1e-300) > refinement / h_old * (1 + 1e-9)))
    rate = smoothed(s, rate, n_elements)
    mass = np.concatenate([[0.0], np.cumsum(rate * ds)])
    return equidistributed(fixed, s, mass, n_elements), capped


def grading_passes(solution, n_elements, fixed, resolve, compressed, keep=False, arches=True):
    """Passes of grading by the last solution's turning (`graded_nodes`), either line's:
    ``resolve(nodes, solution)`` solves the line on the graded ``nodes`` from ``solution``; again
    while the elements of the bends could shrink no more than `REFINEMENT` times at one pass (a
    start farther refined would put the touchdown more than a node or two off: nodal contact
    moves a few nodes per Newton iteration) or while ``compressed(solution)`` (its bends not
    resolved); `GRADE_PASSES` at most. ``(solution, nodes)``: the last solution and its graded
    nodes (those of the last pass, without fitted points; where the first pass failed, the
    nodes of ``solution``'s own mesh).

    A pass that fails raises its `skcable.ConvergenceError` (the caller's fallbacks, nested
    meshes for the plane line, may grade better); with ``keep``, it ends the passes with the last
    solution instead, where that is not in compression (a converged line, on a mesh graded less
    than it could be). ``arches``: with nodes at the `arch_ends` of buoys (`graded_nodes`)."""
    nodes = None
    for _ in range(GRADE_PASSES):
        graded, capped = graded_nodes(solution.problem, solution.dofs, n_elements, fixed, arches=arches)
        try:
            solution = resolve(graded, solution)
        except ConvergenceError:
            if not keep or compressed(solution):
                raise
            break
        nodes = graded
        if not (capped or compressed(solution)):
            break
    return solution, (np.sort(solution.problem.mesh.p[0]) if nodes is None else nodes)


def smoothed(s, rate, n_elements, growth=None):
    """Elements per length ``rate`` on the intervals of ``s``, raised where the element size
    ``h = 1/rate`` would grow faster than ``growth`` per length away from small elements (a mesh
    whose neighbouring elements differ by a factor ``1 + growth`` at most), and scaled back to
    ``n_elements`` in all: ``h_i = min_j (h_j + growth |m_i - m_j|)``, m the midpoints, two running
    minima."""
    growth = GROWTH if growth is None else growth
    m = 0.5 * (s[1:] + s[:-1])
    ds = np.diff(s)
    for _ in range(3):
        h = 1.0 / rate
        forward = growth * m + np.minimum.accumulate(h - growth * m)
        backward = -growth * m + np.minimum.accumulate((h + growth * m)[::-1])[::-1]
        rate = 1.0 / np.minimum(forward, backward)
        rate *= n_elements / np.sum(rate * ds)
    return rate


def equidistributed(fixed, s, mass, n_elements):
    """Nodes at equal steps of ``mass(s)`` (increasing, sampled at ``s``), each stretch between
    the ``fixed`` nodes (sorted, from 0 to the length) getting its share (at least one element)
    of ``n_elements``."""
    L = float(fixed[-1])
    at_fixed = np.interp(fixed, s, mass)
    share = np.diff(at_fixed) / at_fixed[-1]
    counts = np.maximum(1, np.round(n_elements * share)).astype(int)
    stretches = [  # the nodes inside each stretch; its ends are the fixed nodes themselves
        np.interp(np.linspace(a, b, k + 1)[1:-1], mass, s)
        for a, b, k in zip(at_fixed[:-1], at_fixed[1:], counts, strict=True)
    ]
    inner = np.unique(np.concatenate(stretches))
    near = np.abs(inner[:, None] - fixed[None, :]).min(axis=1, initial=np.inf) <= 1e-9 * L
    inner = inner[~near & np.concatenate([[True], np.diff(inner) > 1e-9 * L])]  # no slivers
    return np.unique(np.concatenate([inner, fixed]))


def start_nodes(form, fixed, n_elements):
    """Mesh nodes for the first solve: ``1 + L |dθ/ds|`` equidistributed over the start's shape
    ``form = (H, w, s_v, grounded)`` (`skcable.mooring.line_bvp.start.start_form`), whose angle is
    known in closed form, ``tan θ = w (s - s_v) / H`` (zero on the grounded part): the elements
    gather at its touchdown or lowest point down to the bend's radius ``H/w``, which a uniform
    mesh of a nearly L-shaped line cannot see."""
    H, w, s_v, grounded = form
    L = float(fixed[-1])

    def angle(s):
        v = w * (s - s_v)
        return np.arctan((np.maximum(v, 0.0) if grounded else v) / H)

    turns = np.linspace(angle(0.0), angle(L), 32 * n_elements + 1)
    s = np.unique(
        np.concatenate(
            [np.linspace(0.0, L, 16 * n_elements + 1), np.clip(s_v + H / w * np.tan(turns), 0.0, L)]
        )
    )
    m = 0.5 * (s[1:] + s[:-1])
    v = w * (m - s_v)
    turning = np.where(grounded & (v < 0), 0.0, (abs(w) / H) / (1.0 + (v / H) ** 2))  # |dθ/ds|
    monitor = 1.0 + L * turning
    rate = smoothed(s, n_elements * monitor / np.sum(monitor * np.diff(s)), n_elements)
    mass = np.concatenate([[0.0], np.cumsum(rate * np.diff(s))])
    return equidistributed(fixed, s, mass, n_elements)


def nested_sizes(n_elements):
    """The element counts of nested solves up to ``n_elements``: halved down to `COARSE` or
    above, coarsest first."""
    sizes = [n_elements]
    while sizes[-1] // 2 >= COARSE:
        sizes.append(sizes[-1] // 2)
    return sizes[::-1]


def solve_nested(n_elements, level):
    """The line on ``n_elements`` by nested solves (`nested_sizes`): ``level(size, coarser)``
    solves one mesh from the coarser mesh's solution, or from scratch (``coarser`` None). A level
    that fails from the coarser solution is solved from scratch; a coarse level that fails even
    so is skipped (the next one starts from scratch); the finest level's failure is final (its
    `skcable.ConvergenceError` raised)."""
    solution = None
    for size in nested_sizes(n_elements):
        finest = size == n_elements
        try:
            solution = level(size, solution)
        except ConvergenceError:
            if solution is None and not finest:
                continue
            if solution is None:
                raise
            try:
                solution = level(size, None)
            except ConvergenceError:
                if finest:
                    raise
                solution = None
    return solution
