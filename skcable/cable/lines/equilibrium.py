r"""The static equilibrium of a moored body: Newton's method, a start from slack lines, stability.

At body position :math:`\mathbf q` the net generalised force :math:`\mathbf G(\mathbf q)` on the
body (`skcable.cable.lines.system`) vanishes at equilibrium. Newton's method runs with the
analytic Jacobian :math:`\partial\mathbf G/\partial\mathbf q = -K\,T` (``K`` the stiffness of the
mooring system and the body, ``T`` the map of Euler-angle increments to rotation vectors),
each step capped at a quarter of the shortest anchor radius and 0.2 rad, backtracking on
the scaled residual (`skcable.fe.newton`).

**Slack lines.** Where the lines lie slack on the seabed (their slack in a heap, ``H = 0``)
the stiffness has no horizontal term: :math:`K` is singular and Newton has no step. The
free directions are the null space of the scaled Jacobian (singular values below
:math:`10^{-11}` of the largest); the net force's component in it, :math:`\mathbf d`, pushes
the body. Along the ray :math:`\mathbf q + t\,\mathbf d` the force along it,
:math:`g(t) = \mathbf G(\mathbf q + t\mathbf d)\cdot\mathbf d`, stays positive while the
lines are slack and falls once they take the load: ``t`` is doubled until :math:`g < 0`,
the root bracketed (Brent's method) and Newton resumes from there. With no net force
in the free directions the step is the least-squares one (a neutral direction).

**Stability.** A static equilibrium is stable where the stiffness is positive definite:
the eigenvalues of the symmetric part of :math:`K` in consistent units (rotations times
the largest fairlead arm, N/m) are all positive (a potential at a minimum; K.-J. Bathe,
"Finite Element Procedures", 1996, §6.5.2, on stability from the tangent stiffness).
An equilibrium with a negative eigenvalue (a capsized body, say) is passed over: Newton is
run again from the start with the body upright and from the equilibrium pushed both ways
along the unstable mode, and the first stable equilibrium is returned. When none is
found the unstable one is returned with ``stable=False`` and a `PlausibilityWarning`.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from skcable._show import counted, quantity
from skcable.errors import ConvergenceError, InputError, PlausibilityWarning
from skcable.fe import newton

__all__ = ["MooringEquilibrium", "solve_equilibrium", "stiffness_eigenvalues"]

#: Singular values of the scaled Jacobian below this fraction of the largest: a free direction.
_SINGULAR = 1e-11
#: Eigenvalues below ``-_UNSTABLE`` times the largest magnitude: an unstable equilibrium.
_UNSTABLE = 1e-8


def _units(system) -> tuple[np.ndarray, float]:
    """Consistent units of the dofs (1 for translations, the largest arm for rotations) and the arm."""
    fairleads = getattr(system.body, "fairleads", np.zeros(1))
    arm = max(1.0, float(np.abs(fairleads).max()))
    return np.concatenate([np.ones(3), np.full(system.n_dof - 3, arm)]), arm


def stiffness_eigenvalues(system, K) -> np.ndarray:
    """Eigenvalues (ascending, N/m) of the symmetric part of the stiffness ``K`` of ``system`` in
    consistent units: rotations times the largest fairlead arm (`_units`)."""
    units, _ = _units(system)
    scaled = K / units[:, None] / units[None, :]
    return np.linalg.eigvalsh(0.5 * (scaled + scaled.T))


def is_stable(eigenvalues) -> bool:
    """Whether no eigenvalue is negative beyond round-off (``-1e-8`` of the largest magnitude)."""
    scale = float(np.abs(eigenvalues).max())
    return bool(eigenvalues[0] >= -_UNSTABLE * scale)


class _Newton:
    """One Newton solve of a system's equilibrium (module docstring): the problem's callables."""

    def __init__(self, system, external, tol, max_iter):
        self.system, self.external, self.tol, self.max_iter = system, external, tol, max_iter
        self.units, self.arm = _units(system)
        body = system.body
        self.body_scale = max(np.abs(body.weight[2]), body.buoyancy[2], np.linalg.norm(external[:3]))
        self.lines = None  # the lines of the last accepted state: warm starts of the trials
        self.cap = None  # the step cap, from the start (`step_cap`)

    def scaled(self, G, lines) -> np.ndarray:
        """The net load over the force scale, moments also over the arm."""
        scale = max(self.body_scale, max(line.tension_at_fairlead for line in lines), 1e-300)
        g = G / scale
        g[3:] /= self.arm
        return g

    def assemble(self, position):
        """(net load G, stiffness K, lines, position); the lines start from the last accepted ones."""
        return (*self.system.evaluate(position, self.external, start=self.lines), position)

    def norm(self, state) -> float:
        return float(np.linalg.norm(self.scaled(state[0], state[2])))

    def jacobian(self, state) -> np.ndarray:
        """``-∂G/∂q`` at ``state``."""
        return state[1] @ self.system.body.rate_map(state[3])

    def increment(self, state) -> np.ndarray:
        G, _, lines, position = state
        jac = self.jacobian(state)
        _, singular, vh = np.linalg.svd(jac / self.units[:, None] / self.units[None, :])
        self.lines = lines  # Newton steps from this state: the trials start from its lines
        if not singular[-1] > _SINGULAR * singular[0]:
            return self.slack_step(state, vh[singular <= _SINGULAR * singular[0]])
        dq = np.linalg.solve(jac, G)
        return dq * min(1.0, float(np.min(self.cap / np.maximum(np.abs(dq), 1e-300))))

    def step_cap(self, position) -> np.ndarray:
        """A quarter of the shortest horizontal fairlead-anchor distance, 0.2 rad."""
        system = self.system
        reach = system.anchors[:, :2] - system.body.fairlead_positions(position, len(system.lines))[:, :2]
        span_min = float(np.hypot(reach[:, 0], reach[:, 1]).min())
        return np.concatenate([np.full(3, 0.25 * span_min), np.full(self.system.n_dof - 3, 0.2)])

    def slack_step(self, state, null) -> np.ndarray:
        """The step along the free directions ``null`` (rows, scaled dofs) to where the lines take
        the net force's component in them (module docstring); raises where there is none."""
        G, _, _, position = state
        r = G / self.units
        push = null.T @ (null @ r)
        if not np.linalg.norm(push) > 1e-12 * np.linalg.norm(r):  # no force along the free directions
            raise ConvergenceError(
                "mooring equilibrium: the stiffness is singular (a direction neither the lines nor the "
                "hydrostatics restrain: add waterplane_area, a metacentre or lines)",
                [self.norm(state)],
            )
        direction = push / np.linalg.norm(push)  # scaled dofs, |direction| = 1
        ray = direction / self.units
        t = _ray_root(self, position, ray, direction, float(self.cap[0]), self.norm(state))
        return t * ray

    def along(self, t, position, ray, direction) -> float:
        """``g(t)``: the scaled net load at ``position + t ray`` along ``direction`` (a trial that no
        line can reach counts as pulling back, -inf)."""
        try:
            G = self.assemble(position + t * ray)[0]
        except (InputError, ConvergenceError):
            return -math.inf
        return float((G / self.units) @ direction) / max(self.body_scale, 1e-300)

    def run(self, position, lines=None):
        """`skcable.fe.newton` from ``position`` (the ``lines`` as warm starts of the first solves)."""
        self.lines = lines
        self.cap = self.step_cap(position)
        return newton(
            self.assemble,
            position,
            norm=self.norm,
            increment=self.increment,
            tol=self.tol,
            max_iter=self.max_iter,
            max_halvings=20,
            stagnation_window=self.max_iter,  # no stagnation rule: a capped step may gain slowly
            name="mooring equilibrium",
            rejects=(InputError, ConvergenceError),  # a line that cannot reach a trial position
        )


def _ray_root(solve, position, ray, direction, reach, norm) -> float:
    """The distance ``t`` along ``ray`` where ``g(t)`` (`_Newton.along`) changes sign: doubled from
    ``1e-3 reach`` until ``g < 0`` (at most ``2**20`` times that), then Brent's method; ``norm``
    is the scaled residual at ``position`` (the history of the error, if there is no sign change)."""
    from scipy.optimize import brentq

    args = (position, ray, direction)
    lo, t = 0.0, 1e-3 * reach
    for _ in range(21):
        g = solve.along(t, *args)
        if g <= 0:
            break
        lo, t = t, 2.0 * t
    else:
        raise ConvergenceError(
            "mooring equilibrium: the lines are slack and stay slack along the net force (nothing "
            "restrains the body in that direction: add lines, waterplane_area or a metacentre)",
            [norm],
        )
    return brentq(_along_capped, lo, t, args=(solve, *args), xtol=1e-9 * t, rtol=1e-12)


def _along_capped(t, solve, position, ray, direction) -> float:
    """`_Newton.along`, at least -1 (finite for Brent's method)."""
    return max(solve.along(t, position, ray, direction), -1.0)


def solve_equilibrium(system, position, external, lines, tol, max_iter):
    """`skcable.cable.MooringSystem.equilibrium` on checked arguments: Newton from ``position``
    (the ``lines`` of an earlier equilibrium as warm starts, or None), the stable branch
    preferred (module docstring). Returns a `MooringEquilibrium`."""
    solve = _Newton(system, external, tol, max_iter)
    try:
        result = solve.run(position, lines)
    except ConvergenceError as err:
        if "no descent" not in str(err):
            raise
        raise ConvergenceError(
            "mooring equilibrium: the line search found no descent (the residual stalls: the loads "
            "may exceed what the mooring can hold, or the start is too far)",
            err.history,
        ) from None
    eigenvalues = stiffness_eigenvalues(system, result.state[1])
    passed = []
    if not is_stable(eigenvalues):
        passed.append(result.x.copy())
        for start in _restarts(system, position, result, solve):
            try:
                other = solve.run(start)
            except (ConvergenceError, InputError):
                continue
            other_eig = stiffness_eigenvalues(system, other.state[1])
            if is_stable(other_eig):
                result, eigenvalues = other, other_eig
                break
            passed.append(other.x.copy())
    G, K, lines, _ = result.state
    eq = MooringEquilibrium(system, result.x, external, G, K, lines, result.history, eigenvalues, passed)
    if not eq.stable:
        reason = (
            f"the mooring equilibrium found is unstable (stiffness eigenvalue {eigenvalues[0]:.3g} N/m < 0, "
            f"heel {eq.heel:.3g} rad) and no stable one was found from the restarts: check the body's "
            "metacentre, centre of gravity and the start"
        )
        warnings.warn(PlausibilityWarning("start", reason), stacklevel=3)
    return eq


def _restarts(system, position, result, solve):
    """Starts of the search for a stable branch: the start upright (rotations zeroed), then the
    unstable equilibrium pushed both ways along its most unstable mode."""
    starts = []
    if system.n_dof == 6 and np.any(position[3:] != 0):
        upright = position.copy()
        upright[3:] = 0.0
        starts.append(upright)
    units, _ = _units(system)
    scaled = result.state[1] / units[:, None] / units[None, :]
    mode = np.linalg.eigh(0.5 * (scaled + scaled.T))[1][:, 0] / units
    cap = solve.step_cap(result.x)
    size = float(np.min(cap / np.maximum(np.abs(mode), 1e-300)))
    starts += [result.x + size * mode, result.x - size * mode]
    return starts


class MooringEquilibrium:
    """A moored body in static equilibrium (`MooringSystem.equilibrium`).

    Attributes
    ----------
    system : MooringSystem
    position : ndarray
        ``(x, y, z, roll, pitch, yaw)`` (m, rad) of a rigid body, ``(x, y, z)`` of a point.
    offset : ndarray, shape (3,)
        Displacement of the reference point from the origin (m).
    angles : ndarray, shape (3,)
        Roll, pitch, yaw (rad); zeros for a point body.
    heel : float
        Angle between the body's z axis and the vertical (rad).
    lines : list of Line3D
        Each line at equilibrium.
    fairlead_forces, anchor_forces : ndarray, shape (n, 3)
        Force of each line on its fairlead and on its anchor (N), global axes.
    residual : ndarray
        Net force and moment left on the body (N, N m).
    history : list of float
        Scaled residual at each Newton iteration.
    eigenvalues : ndarray
        Eigenvalues of the symmetric part of the stiffness in consistent units (rotations
        times the largest fairlead arm), N/m, ascending (`stiffness_eigenvalues`).
    stable : bool
        Whether none of them is negative beyond round-off: a stable equilibrium.
    unstable_found : list of ndarray
        Positions of the unstable equilibria passed over on the way to this one.
    """

    def __init__(self, system, q, external, G, K, lines, history, eigenvalues=None, unstable_found=()):
        self.system, self.position, self.external, self.residual = system, q, external, G
        self._K, self.lines, self.history = K, lines, history
        self.offset = q[:3].copy()
        self.angles = q[3:].copy() if len(q) == 6 else np.zeros(3)
        R = system.body.rotation(q)
        self.heel = float(np.arccos(np.clip(R[2, 2], -1.0, 1.0)))
        self.fairlead_forces = np.array([line.force_on_fairlead for line in lines])
        self.anchor_forces = np.array([line.force_on_anchor for line in lines])
        self.fairleads = np.array([line.fairlead for line in lines])
        self.anchors = system.anchors
        self.depth = system.depth
        self.rotation = R
        self.eigenvalues = stiffness_eigenvalues(system, K) if eigenvalues is None else eigenvalues
        self.stable = is_stable(self.eigenvalues)
        self.unstable_found = list(unstable_found)
        for name in ("position", "residual", "fairlead_forces", "anchor_forces", "eigenvalues"):
            if not np.isfinite(getattr(self, name)).all():
                raise ConvergenceError(f"mooring equilibrium: non-finite {name}", history)

    def stiffness(self, *, lines_only: bool = False) -> np.ndarray:
        """Stiffness of the mooring system at equilibrium, ``-∂G/∂(x, rotation vector)``
        (N/m, N/rad, N m/rad), shape (n_dof, n_dof); ``lines_only`` leaves out the
        body's hydrostatics (see `MooringSystem.stiffness`)."""
        if lines_only:  # from the lines at equilibrium, no new line solve
            body, q = self.system.body, self.position
            stiffnesses = np.array([line.stiffness() for line in self.lines])
            return body.add_lines(body.arms(q), self.fairlead_forces, stiffnesses)[1]
        return self._K.copy()

    def tensions(self):
        """Tension table: each line's per-segment table (its model's ``tensions()``) with
        the line's number in front, plus its fairlead and anchor forces (N)."""
        import pandas as pd

        frames = []
        for i, line in enumerate(self.lines):
            table = line.tensions().copy()
            table.insert(0, "line", i)
            table["H"], table["V_B"], table["H_A"], table["V_A"] = line.H, line.V_B, line.H_A, line.V_A
            table["T_fairlead"] = line.tension_at_fairlead
            frames.append(table)
        return pd.concat(frames, ignore_index=True)

    def to_vtk(self, path, n: int = 101):
        """Write the lines (tension as point data), the seabed patch and the body to a
        ``.vtu``/``.vtk`` file, atomically (see `skcable.io.mooring_mesh`); returns the path."""
        from skcable.io import write_mooring

        return write_mooring(self, path, n)

    def __repr__(self):
        note = "" if self.stable else ", UNSTABLE"
        shown = ", ".join(
            (
                quantity("offset", self.offset, "m"),
                quantity("angles", self.angles, "rad"),
                quantity("heel", self.heel, "rad"),
                quantity("T_fairlead", [line.tension_at_fairlead for line in self.lines], "N"),
                quantity("min_eigenvalue", self.eigenvalues[0], "N/m"),
                quantity("iterations", len(self.history) - 1),
            )
        )
        return f"MooringEquilibrium({counted([len(self.lines)], 'line')}: {shown}{note})"
