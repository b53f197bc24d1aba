r"""A body moored by lines: static equilibrium and the stiffness of the mooring system.

Lines run from fixed anchors to the body's fairleads; each hangs in its vertical
plane (`skcable.cable.lines.line3d`). At body position :math:`\mathbf q` the net
generalised force on the body is

.. math:: \mathbf G(\mathbf q) = \sum_i \begin{pmatrix}\mathbf f_i \\
    \mathbf r_i\times\mathbf f_i\end{pmatrix} + \mathbf G_\text{own}(\mathbf q)
    + \begin{pmatrix}\mathbf F_\text{ext}\\ \mathbf M_\text{ext}\end{pmatrix},

with :math:`\mathbf f_i` the force of line *i* on its fairlead, :math:`\mathbf r_i` its
arm from the body's reference point (global axes), :math:`\mathbf G_\text{own}` the
body's weight, buoyancy and heave restoring (`skcable.cable.lines.body`) and a
constant external force and moment (global axes, moment about the reference
point). Static equilibrium :math:`\mathbf G = 0` is found by
`skcable.cable.lines.equilibrium` (Newton's method, a start from slack lines, the
stable branch).

The stiffness of the mooring system,
:math:`K = -\partial\mathbf G/\partial(\mathbf x, \delta\boldsymbol\theta)`, is taken
with respect to a translation and a small rotation vector about global axes (as
MoorPy's ``Body.getStiffnessA``, M. Hall, NREL):

.. math:: K = \sum_i \begin{pmatrix} K_i & -K_i[\mathbf r_i]_\times \\
    [\mathbf r_i]_\times K_i & -[\mathbf f_i]_\times[\mathbf r_i]_\times
    - [\mathbf r_i]_\times K_i [\mathbf r_i]_\times \end{pmatrix} + K_\text{own},

:math:`K_i` the 3x3 fairlead stiffness of line *i*. The term
:math:`-[\mathbf f_i]_\times[\mathbf r_i]_\times` (the change of moment arm under
tension) makes :math:`K` unsymmetric where the line forces have a net moment.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

import numpy as np

from skcable._checks import positive, real, scalar
from skcable.cable.lines.body import PointBody, RigidBody
from skcable.cable.lines.equilibrium import MooringEquilibrium, solve_equilibrium
from skcable.cable.lines.line3d import Line3D, line_3d, point, solve_in_space, takes_start
from skcable.errors import InputError

__all__ = ["MooringEquilibrium", "MooringSystem"]


def _line_list(lines) -> list:
    """``lines`` as a list of line models: a sequence of them (a list, a tuple), not one model,
    a string, a mapping or a scalar; else `InputError` naming ``lines``."""
    if callable(getattr(lines, "solve", None)):
        raise InputError("lines", "is one line model: give a list of them, one per anchor (e.g. [line] * 3)")
    if isinstance(lines, (str, bytes, Mapping)) or not isinstance(lines, Iterable):
        raise InputError(
            "lines", f"must be a list of line models, one per anchor, got {type(lines).__name__}"
        )
    return list(lines)


class MooringSystem:
    """A body held by lines from fixed anchors.

    Parameters
    ----------
    body : RigidBody or PointBody
        The moored body; a `RigidBody` carries the fairleads (body axes), a
        `PointBody` takes every line at its point.
    lines : sequence of line models
        One per anchor: objects with ``solve(span, dh)`` (see
        `skcable.cable.lines.line3d`); anchor A of the model is the anchor, B the fairlead.
        A model whose ``solve`` also takes ``start=`` (`skcable.cable.Line`) is
        warm-started from its previous solution in the equilibrium iterations; the
        others are solved from their own start each time.
    anchors : array_like, shape (n, 3)
        Anchor points in global axes (m), z up.
    depth : float, optional
        Water depth (m), > 0: the seabed is the plane z = -depth. Used to draw the
        seabed (VTK) only; each line model holds its own seabed height.

    Examples
    --------
    >>> from skcable import cable
    >>> import numpy as np
    >>> angles = np.radians([0.0, 120.0, 240.0])
    >>> anchors = np.column_stack([800 * np.cos(angles), 800 * np.sin(angles), np.full(3, -200.0)])
    >>> fairleads = np.column_stack([20 * np.cos(angles), 20 * np.sin(angles), np.full(3, -10.0)])
    >>> chain = cable.Line([cable.Segment(850.0, 1000.0, 5e8)], seabed=0.0)
    >>> system = cable.MooringSystem(cable.RigidBody(fairleads, waterplane_area=500.0), [chain] * 3, anchors)
    >>> eq = system.equilibrium(force=(1e5, 0.0, 0.0))
    >>> bool(eq.offset[0] > 0), bool(abs(eq.offset[1]) < 1e-6)
    (True, True)
    """

    def __init__(self, body, lines, anchors, *, depth=None):
        if not isinstance(body, (RigidBody, PointBody)):
            raise InputError("body", f"must be a RigidBody or a PointBody, got {type(body).__name__}")
        lines = _line_list(lines)
        for i, model in enumerate(lines):
            if not callable(getattr(model, "solve", None)):
                raise InputError("lines", f"line {i} ({type(model).__name__}) has no solve(span, dh) method")
        if not lines:
            raise InputError("lines", "give at least one line")
        anchors = real("anchors", anchors)
        if np.shape(anchors) != (len(lines), 3):
            raise InputError(
                "anchors",
                f"must be one point (x, y, z) per line, shape ({len(lines)}, 3), "
                f"got shape {np.shape(anchors)}",
            )
        anchors = np.array(anchors, dtype=float)
        if isinstance(body, RigidBody) and len(body.fairleads) != len(lines):
            raise InputError(
                "body", f"has {len(body.fairleads)} fairleads for {len(lines)} lines: give one per line"
            )
        self.body, self.lines, self.anchors = body, lines, anchors
        self._warm = [takes_start(model) for model in lines]
        self.depth = None if depth is None else scalar("depth", positive("depth", depth))

    @property
    def n_dof(self) -> int:
        return self.body.n_dof

    def _position(self, name, position):
        return np.zeros(self.n_dof) if position is None else self.body.check_position(name, position)

    def _loads(self, force, moment):
        force = point("force", force)
        moment = point("moment", moment)
        if self.n_dof == 3:
            if np.any(moment != 0):
                raise InputError("moment", "a point body takes no moment: leave it out or use a RigidBody")
            return force
        return np.concatenate([force, moment])

    def solve_lines(self, position, start=None) -> list[Line3D]:
        """Every line solved with the body at ``position`` (m, rad).

        ``start``: the lines solved at another position (a list of `Line3D`, one per
        line), each model that takes a warm start starting from its own (see
        `skcable.cable.Line.solve`: the same solution as without it, to round-off).
        Without it, a line whose model was solved for an earlier line of this call
        (lines of one model, e.g. a spread mooring) starts from that solution.
        """
        q = self._position("position", position)
        return self._solve_lines(q, start)

    def _solve_lines(self, q, start):
        fairleads = self.body.fairlead_positions(q, len(self.lines))
        if start is None:
            start = [None] * len(self.lines)
        elif len(start) != len(self.lines) or not all(isinstance(s, Line3D) for s in start):
            raise InputError("start", f"must be a list of {len(self.lines)} Line3D, one per line")
        reach = fairleads - self.anchors
        spans = [math.hypot(x, y) for x, y, _ in reach.tolist()]
        extent = np.maximum(np.abs(reach).max(1), 1.0)
        if not (np.isfinite(fairleads).all() and (np.array(spans) > 1e-9 * extent).all()):
            # line_3d's checks raise the error, naming the point
            pairs = zip(self.anchors, fairleads, strict=True)
            return [line_3d(model, a, b) for model, (a, b) in zip(self.lines, pairs, strict=True)]
        solved, latest = [], {}
        for model, a, b, r, previous, warm in zip(
            self.lines, self.anchors, fairleads, spans, start, self._warm, strict=True
        ):
            if warm and previous is None:  # another line of the same model, solved just now
                previous = latest.get(id(model))
            line = solve_in_space(model, a, b, r, previous if warm else None)
            latest[id(model)] = line
            solved.append(line)
        return solved

    def evaluate(self, q, external, *, lines_only=False, start=None):
        """Net force ``G(q)`` (N, N m), stiffness ``K(q)`` and the solved lines at the checked
        position ``q`` (a float array of ``n_dof``) under the ``external`` load (``n_dof``
        values), the lines warm-started from the lines ``start`` (a list of `Line3D`), if given.

        ``lines_only``: ``G`` and ``K`` of the lines alone (no own loads, no external load)."""
        lines = self._solve_lines(q, start)
        forces = np.array([line.force_on_fairlead for line in lines])
        stiffnesses = np.array([line.stiffness() for line in lines])
        G, K = self.body.add_lines(self.body.arms(q), forces, stiffnesses)
        if not lines_only:
            G = G + self.body.own_force(q) + external
            K = K + self.body.own_stiffness(q)
        return G, K, lines

    def net_force(self, position, *, force=(0.0, 0.0, 0.0), moment=(0.0, 0.0, 0.0)) -> np.ndarray:
        """Net force (N) and moment (N m, about the reference point) on the body at ``position``:
        lines, own loads and the external ``force`` and ``moment``, global axes."""
        return self.evaluate(self._position("position", position), self._loads(force, moment))[0]

    def stiffness(self, position, *, lines_only=False) -> np.ndarray:
        """Stiffness ``-∂G/∂(x, rotation vector)`` at ``position`` (N/m, N, N m/rad), (n_dof, n_dof).

        ``lines_only``: the lines alone (MoorPy's ``lines_only=True``); otherwise the
        body's hydrostatic stiffness is added.
        """
        q = self._position("position", position)
        return self.evaluate(q, 0.0, lines_only=lines_only)[1]

    def equilibrium(
        self,
        *,
        force=(0.0, 0.0, 0.0),
        moment=(0.0, 0.0, 0.0),
        start=None,
        tol: float = 1e-10,
        max_iter: int = 60,
    ) -> MooringEquilibrium:
        """Static equilibrium of the body under a constant external force and moment.

        Parameters
        ----------
        force, moment : array_like, shape (3,)
            External force (N) and moment (N m, about the reference point), global axes.
        start : array_like or MooringEquilibrium, optional
            Starting position, ``(x, y, z, roll, pitch, yaw)`` (m, rad) for a rigid
            body, ``(x, y, z)`` for a point body; default all zeros. Or an earlier
            equilibrium of this system (e.g. under a nearby load): its position, and
            its lines as warm starts of the first line solves.
        tol : float
            Convergence when the net force over the force scale (the largest of the
            fairlead tensions, the weight, the buoyancy and the external force), and
            the net moment over force scale times the largest arm, are below ``tol``.
        max_iter : int
            Newton iterations at most.

        Returns
        -------
        MooringEquilibrium
            With ``stable`` and the stiffness ``eigenvalues``: an unstable equilibrium (a
            negative eigenvalue) is passed over for a stable one where the restarts find it
            (`skcable.cable.lines.equilibrium`), else returned with a `PlausibilityWarning`.

        Raises
        ------
        InputError
            Bad arguments, or a starting position where a line cannot be solved.
        ConvergenceError
            No equilibrium within ``max_iter`` iterations, or slack lines that stay slack
            along the net force (a direction the mooring and the hydrostatics do not
            restrain); carries the history of the scaled residual.

        Notes
        -----
        Lines that start slack on the seabed (the slack in a heap: no horizontal stiffness)
        are first pulled taut along the net force (`skcable.cable.lines.equilibrium`).
        Each trial position solves every line warm-started from its solution at the
        last accepted position (models that take ``start=``, see `solve_lines`);
        a warm-started line has the cold solution to round-off, so the iterates are
        those of cold solves.
        """
        external = self._loads(force, moment)
        warm_lines = None
        if isinstance(start, MooringEquilibrium):
            if start.system is not self:
                raise InputError("start", "is the equilibrium of another MooringSystem")
            q, warm_lines = start.position.copy(), start.lines
        else:
            q = self._position("start", start)
        tol = scalar("tol", positive("tol", tol))
        if isinstance(max_iter, bool) or not isinstance(max_iter, (int, np.integer)) or max_iter < 1:
            raise InputError("max_iter", f"must be an integer >= 1, got {max_iter!r}")
        return solve_equilibrium(self, q, external, warm_lines, tol, max_iter)
