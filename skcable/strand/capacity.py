"""Step results and capacity curves of a strand under imposed axial strain: the equivalent
stiffness ``K_Leq`` (Pino Vidal 2021, eq. 4.30), the toughness and the damage index ``D_r``
(eq. 4.31) of `CapacityCurve`."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, NamedTuple, Protocol

import numpy as np

from skcable import _plausible
from skcable._checks import one_of, positive, whole
from skcable._show import Shown, counted, quantity
from skcable.errors import ConvergenceError, InputError
from skcable.fe.continuation import StepControl


class PulledModel(Protocol):
    """What a capacity curve asks of its model (`skcable.strand.fe.StrandModel` has it; named
    here, not imported, so that the curve does not import the model that imports it)."""

    EA: float
    layout: Any
    strand: Any
    options: Any

    def initial_state(self) -> Any: ...

    def solve(self, *args, **kwargs) -> Any: ...

    def twin(self) -> PulledModel: ...


__all__ = ["CapacityCurve", "Restick", "StepResult", "StrandLayout", "capacity_curve", "restick"]


class Restick(NamedTuple):
    """Where a strand re-sticks (`restick`, `CapacityCurve.restick`): the strains and slip
    fractions before and after the steps over which its slip fraction falls."""

    strain_before: float
    strain_after: float
    fraction_before: float
    fraction_after: float


def restick(strain, slip_fraction, drop: float = 0.5, step: float = 0.1) -> Restick | None:
    """Where a strand re-sticks: the run of load steps over which the fraction of the length
    in slip falls by more than ``step`` per step, around its steepest fall, if it falls by more
    than ``drop`` over that run (None otherwise: the strand never re-sticks).

    Slip starts at the first step, where the critical curvature κ_m (which grows with the axial
    strain: the wires' tension presses them together) is still below the curvature the broken
    wires impose; the strand re-sticks where κ_m passes it (Pino Vidal 2021, ch. 3).
    ``strain`` and ``slip_fraction`` are a curve's steps (`CapacityCurve.restick` passes its own).
    """
    fraction = np.asarray(slip_fraction, dtype=float)
    fall = -np.diff(fraction)
    if not fall.size or not fall.max() > step:
        return None
    first = last = int(np.argmax(fall))
    while first > 0 and fall[first - 1] > step:
        first -= 1
    while last + 1 < fall.size and fall[last + 1] > step:
        last += 1
    if not fraction[first] - fraction[last + 1] > drop:
        return None
    return Restick(
        float(strain[first]), float(strain[last + 1]), float(fraction[first]), float(fraction[last + 1])
    )


@dataclass(frozen=True, eq=False)
class StrandLayout:
    """What every step of one model shares: mesh, quadrature and wire geometry (for writers).

    Attributes
    ----------
    nodes, elements : ndarray (n_nodes,), (2, n_elements)
        Node abscissae (m) and the node indices of each element.
    x, dx : ndarray (n_elements, n_quad)
        Quadrature points (m) and weights (m).
    wire_psi, wire_rate, wire_radius, wire_layer, wire_broken, wire_size : ndarray (n_wires,)
        Angular position at x = 0 (rad), lay rate dψ/dx (rad/m, 0 for the core), helix radius
        (m), layer (0 core), whether the wire is broken, and its own radius (m).
    slip, element : str
        Name of the slip law; the element of u and φ ("P2" or "P3").
    eps_rupture, eps_y1 : float
        The rupture strain and the end of the linear branch (the smallest among the materials).
    wire_eps_rupture, wire_eps_y1 : ndarray (n_wires,) or None
        The same per wire, from its own material (None: the scalars for every wire).
    """

    nodes: np.ndarray
    elements: np.ndarray
    x: np.ndarray
    dx: np.ndarray
    wire_psi: np.ndarray
    wire_rate: np.ndarray
    wire_radius: np.ndarray
    wire_layer: np.ndarray
    wire_broken: np.ndarray
    wire_size: np.ndarray
    slip: str
    eps_rupture: float
    eps_y1: float
    wire_eps_rupture: np.ndarray | None = None
    wire_eps_y1: np.ndarray | None = None
    element: str = "P2"

    def _per_wire(self, attribute: str):
        """The limit strain ``attribute`` ("eps_rupture" or "eps_y1") per wire when the wires
        differ in it, else None (one scalar limit for every wire, ``getattr(self, attribute)``);
        decided once per attribute (a curve asks at every step; the layout is frozen)."""
        decided = self.__dict__.setdefault("_limits", {})
        if attribute not in decided:
            values = getattr(self, "wire_" + attribute)
            same = values is None or np.all(values == getattr(self, attribute))
            decided[attribute] = None if same else values
        return decided[attribute]

    def peak(self, wire_strain: np.ndarray, attribute: str) -> tuple[float, float]:
        """``(peak, limit)``: the largest wire strain and the limit ``attribute``, or, when the
        wires' materials differ in it, the largest ratio of a wire's strain to its own limit
        and 1 (a wire reaches its limit when ``peak >= limit``)."""
        own = self._per_wire(attribute)
        if not wire_strain.size:
            return 0.0, (getattr(self, attribute) if own is None else 1.0)
        if own is None:
            return float(wire_strain.max()), getattr(self, attribute)
        return float((wire_strain / own[:, None, None]).max()), 1.0

    def critical_wires(self, wire_strain: np.ndarray, attribute: str = "eps_rupture") -> np.ndarray:
        """Indices of the wires nearest their own limit ``attribute`` at these wire strains
        (the wires that break first at rupture), ties within 1e-9 relative included."""
        own = self._per_wire(attribute)
        limit = getattr(self, "wire_" + attribute) if own is not None else None
        limit = np.full(wire_strain.shape[0], getattr(self, attribute)) if limit is None else limit
        ratio = np.max(wire_strain.reshape(wire_strain.shape[0], -1), axis=1) / limit
        return np.flatnonzero(ratio >= np.max(ratio) * (1 - 1e-9))


@dataclass(eq=False)
class StepResult(Shown):
    """State of the strand at one load step: everything writers and plots need.

    Attributes
    ----------
    strain, force : float
        The strand's axial strain ``(u(L) − u(0))/L`` and the axial force at x = L (N): the
        imposed strain's reaction, the applied force, or the reaction of a support holding u(L)
        (0 where u(L) is free).
    x : ndarray (n_elements, n_quad)
        Quadrature points (m).
    curvature : ndarray (2, n_elements, n_quad)
        Curvature about principal axes 1 and 2 of the local (rotating) section (1/m).
    kappa_m : ndarray (2, n_elements, n_quad)
        Critical curvatures there.
    slipping : ndarray (2, n_elements, n_quad) of bool
        Points in slip about each principal axis.
    wire_strain, wire_stress : ndarray (n_wires, n_elements, n_quad)
        Broken wires carry zero; stress in Pa.
    dofs : ndarray
        The solution vector.
    iterations : int
    history : list of float
        Newton's residual norms of the final solve.
    axial_strain, axial_force : ndarray (n_elements, n_quad)
        ε_a = u′ + ½(v′² + w′²) and the axial force N (N).
    bending, moment : ndarray (2, n_elements, n_quad)
        (v″, w″) (1/m) and their conjugate section moments (N·m).
    EI_in_use : ndarray (2, n_elements, n_quad)
        Tangent bending stiffness on v″ and w″ (N·m²).
    nodal : dict of ndarray (n_nodes,)
        u, v, w (m) and φ (rad) at the nodes.
    layout : StrandLayout
        Mesh, quadrature and wire geometry (shared by the steps of a model).
    state : tuple
        The terms' states (slip) of the solve.
    settled : bool
        Whether the slip state settled (False: it cycled or its re-solve failed; the
        previous state was kept).
    assemblies : int
        Residual and tangent evaluations the step took.
    shifted : bool
        The solver shifted a tangent that was not positive definite
        ([`minimize`][skcable.fe.newton.minimize]): the path folds (snaps) before this step.
    outputs : dict of str to (str, ndarray)
        The terms' named results: ``name -> (kind, values)``, kind ``"point_data"`` or
        ``"cell_data"`` (`skcable.strand.fe.terms`); the writers put them in every VTK file.
    reactions : dict
        Support reactions ``{"left": {dof: value}, "right": {dof: value}}`` (N for u, v, w;
        N·m for φ and the slopes); the imposed strain's at x = L is ``force``.
    """

    strain: float
    force: float
    x: np.ndarray
    curvature: np.ndarray
    kappa_m: np.ndarray
    slipping: np.ndarray
    wire_strain: np.ndarray
    wire_stress: np.ndarray
    dofs: np.ndarray
    iterations: int
    history: list = field(default_factory=list)
    axial_strain: np.ndarray | None = None
    axial_force: np.ndarray | None = None
    bending: np.ndarray | None = None
    moment: np.ndarray | None = None
    EI_in_use: np.ndarray | None = None
    nodal: dict | None = None
    layout: StrandLayout | None = None
    state: tuple = ()
    settled: bool = True
    assemblies: int = 0
    shifted: bool = False
    outputs: dict = field(default_factory=dict)
    reactions: dict = field(default_factory=dict)

    @property
    def slip_fraction(self) -> float:
        """Fraction of the strand length in slip (about either axis)."""
        slipping = np.any(self.slipping, axis=0)
        return np.count_nonzero(slipping) / slipping.size if slipping.size else float(np.mean(slipping))

    def to_vtk(
        self, path, *, wires: bool = False, scale: float = 1.0, radial_scale: float = 1.0, fields=None
    ):
        """Write this step as a VTK file ``path`` (``.vtu`` or ``.vtk``, atomically:
        `skcable.io.write`) for ParaView: the axis with its point and cell data, the terms'
        outputs included ([`strand_mesh`][skcable.io.strand_mesh]). With ``wires``, also the
        wires as tubes ([`wire_mesh`][skcable.io.wire_mesh]) in ``<stem>_wires<suffix>``;
        ``fields(step) -> (point_data, cell_data)`` adds the user's arrays (dicts of name to
        values at the nodes or quadrature points / per element, or None). Returns the paths."""
        from pathlib import Path

        from skcable.io import write

        path = Path(path)
        out = [write(_mesh(self, False, scale, radial_scale, fields), path)]
        if wires:
            tubes = _mesh(self, True, scale, radial_scale, fields)
            out.append(write(tubes, path.with_name(path.stem + "_wires" + path.suffix)))
        return out

    def __repr__(self) -> str:
        peak = float(np.max(np.abs(self.curvature))) if self.curvature.size else 0.0
        top = float(np.max(self.wire_strain)) if self.wire_strain.size else 0.0
        shown = (
            quantity("strain", self.strain),
            quantity("force", self.force, "N"),
            quantity("slip_fraction", self.slip_fraction),
            quantity("peak_curvature", peak, "1/m"),
            quantity("max_wire_strain", top),
            quantity("iterations", self.iterations),
        )
        return f"StepResult({', '.join(shown)})"


@dataclass(repr=False)
class CapacityCurve(Shown):
    """Force–strain curve and the state at every step.

    Attributes
    ----------
    strain, force, slip_fraction : ndarray
        Per step (the origin included), N for the force.
    steps : list of StepResult
    ruptured : bool
        Whether the curve ended at a wire's rupture strain.
    chatter_steps : list of int
        Steps whose slip state did not settle (`StepResult.settled`).
    cutbacks : int
        Step halvings the solver needed.
    """

    model: PulledModel
    strain: np.ndarray
    force: np.ndarray
    slip_fraction: np.ndarray
    steps: list
    ruptured: bool
    chatter_steps: list = field(default_factory=list)
    n_steps: int = 0
    failure: str | None = None
    cutbacks: int = 0
    options: object = None
    max_force: float | None = None

    @property
    def snaps(self) -> list:
        """Strains of the steps reached past a fold of the equilibrium path (the solver had to
        shift a tangent that was not positive definite): where a softening wire law (the printed
        aluminium blend of Pino Vidal 2021, Table B.1) makes the quasi-static path snap."""
        return [float(s.strain) for s in self.steps if s.shifted]

    def __repr__(self) -> str:
        last = "rupture" if self.ruptured else "last"
        shown = [quantity(f"{last}_strain", self.strain[-1]), quantity(f"{last}_force", self.force[-1], "N")]
        try:
            shown.append(quantity("K_Leq", self.K_Leq, "N"))
        except (ZeroDivisionError, FloatingPointError, IndexError):
            shown.append("K_Leq=n/a")
        shown += [
            quantity("toughness", self.toughness, "N"),
            quantity("max_slip_fraction", np.max(self.slip_fraction)),
            quantity("cutbacks", self.cutbacks),
            quantity("snaps", len(self.snaps)),
        ]
        end = "ruptured" if self.ruptured else f"stopped: {self.failure}" if self.failure else "not ruptured"
        slip = getattr(getattr(self.model, "layout", None), "slip", "?")
        return (
            f"CapacityCurve(slip {slip!r}, {counted([len(self.steps)], 'step')}, {end}: {', '.join(shown)})"
        )

    @cached_property
    def _elastic_end(self):
        """(strain, force) where the most strained wire reaches eps_y1, interpolated between steps."""
        layout = self.model.layout
        limit = layout.peak(np.zeros((0,)), "eps_y1")[1]
        peak = np.concatenate([[0.0], [layout.peak(s.wire_strain, "eps_y1")[0] for s in self.steps]])
        beyond = np.flatnonzero(peak >= limit)
        if beyond.size == 0:
            return float(self.strain[-1]), float(self.force[-1])
        i = int(beyond[0])
        t = (limit - peak[i - 1]) / (peak[i] - peak[i - 1])
        strain = float(self.strain[i - 1] + t * (self.strain[i] - self.strain[i - 1]))
        # the force comes from the elastic side (the last elastic segment extended),
        # not from across the kink of the material law
        j = max(i - 2, 0)
        if i > 1:
            slope = (self.force[i - 1] - self.force[j]) / (self.strain[i - 1] - self.strain[j])
        else:
            slope = self.force[i] / self.strain[i]
        return strain, float(self.force[i - 1] + slope * (strain - self.strain[i - 1]))

    @property
    def elastic_limit(self) -> float:
        """Strand strain at which the first wire leaves the linear branch (eps_y1), interpolated."""
        return self._elastic_end[0]

    @property
    def K_Leq(self) -> float:
        """Equivalent linear stiffness over [0, elastic_limit] (N), eq. 4.30: the step-weighted
        mean slope over the linear-elastic range, i.e. the secant there."""
        strain, force = self._elastic_end
        return force / strain

    def restick(self, drop: float = 0.5, step: float = 0.1) -> Restick | None:
        """Where the strand re-sticks along this curve (`restick` of its strains and slip
        fractions), or None."""
        return restick(self.strain, self.slip_fraction, drop, step)

    def secant(self, strain: float) -> float:
        """Secant stiffness ``F(ε)/ε`` (N) at a strain on the curve, linear between steps.

        Eq. 4.30 over a range ``[0, ε]`` the caller chooses, e.g. one common to two models:
        ``K_Leq`` ends where this curve's first wire leaves the linear branch, and that
        strain moves with the model (a bent stick strand yields earlier than a slipping one).
        """
        if not 0 < strain <= self.strain[-1]:
            top = self.strain[-1]
            raise InputError("strain", f"must lie in (0, {top:.6g}] (the curve's range), got {strain!r}")
        return float(np.interp(strain, self.strain, self.force) / strain)

    @property
    def rupture_wires(self) -> np.ndarray:
        """Indices (into ``strand.wires()``, core first) of the wires nearest their own rupture
        strain at the last step: at rupture, the wires that break first (with several
        materials, each wire against its own material's ``eps_rupture``)."""
        return self.model.layout.critical_wires(self.steps[-1].wire_strain, "eps_rupture")

    @property
    def toughness(self) -> float:
        """Area under the force–strain curve (N), up to rupture (the first wire reaching its
        ``eps_rupture``) or the last step."""
        return float(np.trapezoid(self.force, self.strain))

    def columns(self) -> dict:
        """Per-step table (the origin included): strain, force (N), slip fraction, peak
        curvature about each principal axis (1/m) and the largest wire strain."""
        peak = np.array([[0.0, 0.0]] + [np.max(np.abs(s.curvature), axis=(1, 2)) for s in self.steps])
        wire = np.concatenate([[0.0], [np.max(s.wire_strain) for s in self.steps]])
        if self.ruptured:  # the last row was interpolated to the rupture strain of the breaking wire
            layout = self.model.layout
            own = layout.wire_eps_rupture
            first = self.rupture_wires[0]
            wire[-1] = layout.eps_rupture if own is None else float(own[first])
        return {
            "strain": self.strain,
            "force_N": self.force,
            "slip_fraction": self.slip_fraction,
            "peak_curvature_1_per_m": peak[:, 0],
            "peak_curvature_2_per_m": peak[:, 1],
            "max_wire_strain": wire,
        }

    def to_csv(self, path):
        """Write `columns` as CSV (atomically: `skcable.io._atomic.atomic_path`), read it back and check
        it holds the table to the digits written (17 significant, round-trip exact); returns the
        path."""
        from pathlib import Path

        from skcable.io._atomic import atomic_path

        path = Path(path)
        table = self.columns()
        data = np.column_stack(list(table.values()))
        with atomic_path(path) as temp:
            np.savetxt(temp, data, delimiter=",", header=",".join(table), comments="", fmt="%.17g")
        back = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
        if back.shape != data.shape or not np.array_equal(back, data, equal_nan=True):
            raise OSError(f"{str(path)!r} does not read back as the table written")
        return path

    def step_mesh(
        self, step: int, *, wires: bool = False, scale: float = 1.0, radial_scale: float = 1.0, fields=None
    ):
        """The strand (or, with ``wires``, its wires) at one step as a meshio mesh
        ([`strand_mesh`][skcable.io.strand_mesh], [`wire_mesh`][skcable.io.wire_mesh]);
        ``fields(step) -> (point_data, cell_data)`` adds the user's arrays to the axis."""
        if not -len(self.steps) <= step < len(self.steps):
            raise InputError("step", f"must index one of the {len(self.steps)} steps, got {step!r}")
        return _mesh(self.steps[step], wires, scale, radial_scale, fields)

    def to_vtk(
        self, path, *, wires: bool = False, scale: float = 1.0, radial_scale: float = 1.0, fields=None
    ):
        """Write every step as a ParaView time series ``path`` (``.pvd`` + one ``.vtu`` per step,
        time = the axial strain), with ``wires`` also ``<stem>_wires.pvd``, each step as
        `StepResult.to_vtk` writes it (``fields`` included). Returns the paths."""
        from pathlib import Path

        from skcable.io import write_series

        path = Path(path)
        times = [s.strain for s in self.steps]
        out = [write_series((self.step_mesh(i, fields=fields) for i in range(len(self.steps))), times, path)]
        if wires:
            meshes = (
                self.step_mesh(i, wires=True, scale=scale, radial_scale=radial_scale)
                for i in range(len(self.steps))
            )
            out.append(write_series(meshes, times, path.with_name(path.stem + "_wires.pvd")))
        return out

    @cached_property
    def reference(self):
        """The undamaged strand's curve with the same settings (for D_r)."""
        return capacity_curve(
            self.model.twin(), n_steps=self.n_steps, options=self.options, max_force=self.max_force
        )

    @property
    def D_r(self) -> float:
        """Damage index ``1 - U_T / U_T0`` (eq. 4.31) against the undamaged strand with the same
        model settings (`reference`); both curves must reach rupture."""
        if not (self.ruptured and self.reference.ruptured):
            raise ConvergenceError(f"D_r needs curves to rupture; this one stopped: {self.failure}")
        return 1.0 - self.toughness / self.reference.toughness


def capacity_curve(
    model,
    max_strain=None,
    n_steps=None,
    *,
    state_passes: int = 6,
    on_failure: str = "raise",
    callback=None,
    options=None,
    max_force=None,
    **newton_options,
) -> CapacityCurve:
    """Pull ``model`` step by step until a wire breaks (or ``max_strain``).

    ``n_steps`` (default 60) strain increments: half up to twice the yield strain, half growing
    geometrically from there to ``max_strain`` (default 1.5 eps_rupture), or all equal for a
    ``max_strain`` below twice the yield strain. The curve stops at the first wire rupture,
    interpolated to the strain where the most strained wire reaches its eps_rupture, and its last
    step is solved there. A model loaded by an axial force (``axial="force"``) is pulled by
    ``n_steps`` equal increments of the force up to ``max_force`` (N, required), its strains the
    mean axial strain ``(u(L) − u(0))/L``; past the largest force the strand carries, no step
    converges. A step that fails is halved, down to 1/64 of the schedule's step
    (`skcable.fe.continuation.StepControl`); the slip state is frozen in each Newton solve and
    updated between solves (at most ``state_passes``). When a step still fails,
    ``on_failure="raise"`` raises ConvergenceError and ``"stop"`` returns the converged part with
    ``failure`` set. ``callback(step, done)`` is called after every converged step with its
    `StepResult` and the fraction of the schedule done. Newton options for every step:
    ``options`` (a `skcable.fe.NewtonOptions`, default the model's) and any of its fields as
    keywords (its per-iteration ``callback`` is ``NewtonOptions.callback``, not this one).
    """
    from skcable.fe import NewtonOptions

    one_of("on_failure", on_failure, ("raise", "stop"))
    solve_options = NewtonOptions.of(model.options if options is None else options, **newton_options)
    n_steps, schedule = _schedule(model, max_strain, n_steps, state_passes, max_force)
    path = _Path(model, state_passes, solve_options)
    failure = None
    control = StepControl(schedule)  # cut, hold, grow and lift the strain increments
    for goal, smallest in control.goals():
        while path.eps < goal - 1e-15 and failure is None:
            step, target, cut, last = path.solve(control, goal, smallest)
            if step is None:
                where = "strain {:.6g}" if getattr(model, "axial", "strain") == "strain" else "force {:.6g} N"
                failure = (
                    f"no convergence beyond {where.format(path.eps)} (increment cut to 1/64 of the step)"
                )
                failure += _softening_note(model, path.steps[-1] if path.steps else None)
                failure += _last_note(model, last, target, path.state)
                if on_failure == "raise":
                    assert last is not None  # the solve that failed last
                    raise ConvergenceError("capacity_curve: " + failure, last.history) from last
                break
            control.accept(path.eps, target, cut)
            path.add(step, target)
            if callback is not None:
                callback(path.steps[-1], 1.0 if path.ruptured else path.eps / schedule[-1])
            if path.ruptured:
                break
        if path.ruptured or failure:
            break
    return CapacityCurve(
        model,
        np.array(path.strains),
        np.array(path.forces),
        np.array(path.fractions),
        path.steps,
        path.ruptured,
        path.chatter,
        n_steps,
        failure,
        control.cutbacks,
        solve_options,
        None if max_force is None else float(max_force),
    )


def _schedule(model, max_strain, n_steps, state_passes, max_force=None) -> tuple[int, np.ndarray]:
    """``n_steps`` and the load goals of `capacity_curve` after 0, the arguments checked."""
    materials = model.strand.materials
    axial = getattr(model, "axial", "strain")
    if axial == "none":
        raise InputError("model", "has no axial load (axial='none'): a curve pulls by strain or force")
    if axial == "force":
        if max_strain is not None:
            raise InputError("max_strain", "the model is pulled by force (axial='force'): give max_force")
        if max_force is None:
            raise InputError("max_force", "a model pulled by force (axial='force') needs it (N)")
        positive("max_force", max_force)
    elif max_force is not None:
        raise InputError("max_force", "the model is pulled by strain (axial='strain'): give max_strain")
    n_steps = 60 if n_steps is None else whole("n_steps", n_steps, 4)
    if max_strain is not None:
        positive("max_strain", max_strain)
        _plausible.strand_strain("max_strain", float(max_strain), [m.eps_rupture for m in materials])
    whole("state_passes", state_passes, 0)
    if axial == "force":
        return n_steps, np.linspace(0.0, float(max_force), n_steps + 1)[1:]
    top = float(max_strain) if max_strain is not None else 1.5 * min(m.eps_rupture for m in materials)
    # half the steps uniform up to twice the yield strain (where slip and yield shape the curve
    # and K_Leq is measured), half growing geometrically (no jump in step size for Newton)
    knee = 2.0 * min(m.eps_y for m in materials)
    if top <= knee:  # the whole range is the uniform part: n_steps equal increments
        return n_steps, np.linspace(0.0, top, n_steps + 1)[1:]
    uniform = np.linspace(0.0, knee, n_steps // 2 + 1)
    return n_steps, np.unique(np.concatenate([uniform, np.geomspace(knee, top, n_steps - n_steps // 2 + 1)]))[
        1:
    ]


class _Path:
    """The converged steps of a capacity curve so far (the origin first in ``strains``,
    ``forces`` and ``fractions``), the steps whose slip state did not settle, and where the
    next step starts from: the last dofs ``U`` at strain ``eps``, the step before, the state."""

    def __init__(self, model, passes: int, options):
        self.model, self.passes, self.options = model, passes, options
        self.layout = model.layout
        self.state = model.initial_state()
        self.strains, self.forces, self.fractions, self.loads = [0.0], [0.0], [0.0], [0.0]
        self.steps: list[StepResult] = []
        self.chatter: list[int] = []
        self.U: np.ndarray | None = None
        self.eps = 0.0
        self.previous: tuple[np.ndarray | None, float] = (None, 0.0)  # read once U is set
        self.ruptured = False

    def solve(self, control: StepControl, goal: float, smallest: float):
        """The next step towards ``goal``, its increment halved while the solve fails:
        ``(step, target, cut, None)``, or ``(None, target, True, error)`` with the last solve's
        `ConvergenceError` once the increment would fall below ``smallest``."""
        target = control.target(self.eps, goal)
        cut = False
        while True:
            try:
                guess = None if self.U is None else _extrapolate(self.U, self.previous, self.eps, target)
                step = self._solve(target, guess, self.state, passes=self.passes)
                return step, target, cut, None
            except ConvergenceError as exc:
                cut = True
                halved = control.cut(self.eps, target, smallest)
                if halved is None:
                    return None, target, cut, exc
                target = halved

    def _solve(self, load, guess, state, **kwargs) -> StepResult:
        """The model's step at ``load``: an imposed strain, or an axial force (``axial="force"``)."""
        kwargs.update(options=self.options, diagnose=False)  # the final failure is explained once
        if getattr(self.model, "axial", "strain") == "force":
            return self.model.solve(None, guess, state, force=load, **kwargs)
        return self.model.solve(load, guess, state, **kwargs)

    def add(self, step: StepResult, target: float) -> None:
        """Keep a converged step at strain ``target``; end the curve at the rupture strain if a
        wire reached it."""
        self.previous = (self.U, self.eps)
        self.U, self.state = step.dofs, step.state
        if not step.settled:
            self.chatter.append(len(self.steps))
        self.eps = target
        self.loads.append(target)
        self.steps.append(step)
        self.strains.append(step.strain)
        self.forces.append(step.force)
        self.fractions.append(step.slip_fraction)
        peak, rupture = self.layout.peak(step.wire_strain, "eps_rupture")
        if step.wire_strain.size and peak >= rupture:
            self._end_at_rupture(peak, rupture, step.dofs)

    def _end_at_rupture(self, peak: float, rupture: float, U: np.ndarray) -> None:
        """End the curve where the most strained wire (relative to its own material's rupture
        strain) reaches its rupture strain, and solve the last step there."""
        steps, loads = self.steps, self.loads
        before = self.layout.peak(steps[-2].wire_strain, "eps_rupture")[0] if len(steps) > 1 else 0.0
        t = (rupture - before) / (peak - before)
        for values in (self.strains, self.forces, loads):
            values[-1] = values[-2] + t * (values[-1] - values[-2])
        self.ruptured = True
        # one last state everywhere: the last step is the equilibrium at the rupture strain
        # (the force of the curve stays the interpolated one; they differ by its error)
        U_prev = self.previous[0]
        guess = None if U_prev is None else U_prev + t * (U - U_prev)
        try:
            steps[-1] = self._solve(loads[-1], guess, steps[-2].state if len(steps) > 1 else None)
        except ConvergenceError:
            pass  # keep the step beyond rupture: the curve itself ends at the rupture strain


def _mesh(step, wires: bool, scale: float, radial_scale: float, fields):
    """The meshio mesh of a step's axis (with the user's ``fields``) or, with ``wires``, its wires."""
    from skcable.io import strand_mesh, wire_mesh

    if wires:
        return wire_mesh(step, scale=scale, radial_scale=radial_scale)
    point_data, cell_data = (None, None) if fields is None else fields(step)
    return strand_mesh(step, point_data=point_data, cell_data=cell_data)


def _last_note(model, last, load, state) -> str:
    """What the last failed solve said, and what its tangent shows (`StrandModel.explain`)."""
    if last is None:
        return ""
    said = str(last.args[0]).split(" (last ")[0]
    explain = getattr(model, "explain", None)
    modes = explain(last.last, load, state) if explain is not None and last.last is not None else ""
    return f"; the last solve: {said}" + (f"; {modes}" if modes and modes not in said else "")


def _softening_note(model, step) -> str:
    """Why a curve may stop: wires inside the material law's softening range."""
    if step is None:
        return ""
    index = model.strand.wire_materials().index
    for k, material in enumerate(model.strand.materials):
        window = material.softening_range
        if window is None:
            continue
        lo, hi = window
        wires = step.wire_strain[~step.layout.wire_broken & (index == k)]
        if np.any((wires > lo) & (wires < hi)):
            break
    else:
        return ""
    return (
        f"; wires lie where the material law softens (strain {lo:.4g} to {hi:.4g}, tangent < 0),"
        " and the strand's tangent can turn singular there (a limit point of the wire law)"
    )


def _extrapolate(U, previous, eps, target):
    """Linear extrapolation from the last two converged steps (scaling after the first)."""
    U_prev, eps_prev = previous
    if U_prev is None or eps == eps_prev:
        return U * (target / eps) if eps > 0 else None
    return U + (U - U_prev) * (target - eps) / (eps - eps_prev)
