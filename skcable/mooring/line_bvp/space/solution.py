"""The solution of a line in space: end forces, contact, fields, equilibrium residual, stiffness.

Its fields, equilibrium residual and check are the plane line's
(`skcable.mooring.line_bvp.fields`).
"""

from __future__ import annotations

import numpy as np

from skcable._checks import whole
from skcable._show import Shown
from skcable.mooring.line_bvp.contact import anchor_split
from skcable.mooring.line_bvp.fields import LineFields
from skcable.mooring.line_bvp.space.problem import LineProblem3D
from skcable.mooring.line_bvp.space.stiffness import FairleadStiffness, fairlead_stiffness_3d

__all__ = ["LineBVP3DSolution"]

EPS = float(np.finfo(float).eps)


class LineBVP3DSolution(LineFields, Shown):
    """Solution of `skcable.mooring.line_bvp.space.solve_line_bvp_3d`.

    Attributes
    ----------
    anchor, fairlead : ndarray (3,)
        The ends (m), z up.
    force_on_anchor, force_on_fairlead : ndarray (3,)
        The forces the line exerts on its anchor and its fairlead (N, global axes); where the
        anchor lies on the seabed, the seabed under it takes its push.
    T_A, T_B : float
        Their magnitudes (N): the end tensions.
    length : float
        Unstretched length (m).
    contact_s, contact_xyz : ndarray
        Arc length (m) and position (n, 3) (m) of every contact node, along the line.
    normal_force, gap : ndarray
        Seabed normal force ``N_i >= 0`` (N) and height above the seabed (m) of each.
    contact_force : ndarray (n, 3)
        The seabed's force on the line at each contact node, friction included (N).
    in_contact : ndarray of bool
        The nodes on the seabed (the final active set).
    slack_end : float
        The end ``s0`` (m) of the slack stretch near the anchor, where friction holds the line
        with its tension zero (`skcable.mooring.line_bvp.space.problem.LineProblem3D.lay_slack`;
        0: none). The anchor then carries nothing: the seabed holds the stretch, the anchor's
        node included (`anchor_seabed_force`, and `slack_seabed_force` on the others' nodes).
    slack_seabed_force : ndarray (3,)
        The seabed's force on the slack stretch's nodes but the anchor's (N; zero without one).
    s_touchdown, s_landing, length_on_seabed : float
        Where the line leaves the seabed for the last time towards the fairlead, where a line
        hanging from an anchor above the seabed first lands on it (unstretched arc lengths from
        the anchor, m: where the hanging part's force is tangent to the seabed, between mesh
        nodes, as the plane line's; `skcable.mooring.line_bvp.fields.LineFields`), and the
        length between them; 0 without contact.
    history, iterations
        Newton's merit per iteration of the last solve.
    problem, state
        The discrete line (`skcable.mooring.line_bvp.space.problem.LineProblem3D`) and its state.
    model : object
        The model that solved it (`LineBVP3D`; None from `solve_line_bvp_3d`).
    """

    model: object | None = None
    problem: LineProblem3D
    solver = "solve_line_bvp_3d"

    def __init__(self, problem, z, history, state):
        self.problem, self.dofs, self.state = problem, z, state
        self.anchor, self.fairlead, self.length = problem.anchor, problem.fairlead, problem.L
        self.history = [float(h) for h in history]
        self.iterations = len(self.history) - 1
        self.friction = problem.friction
        S_A, S_B = (np.array(v, dtype=float) for v in problem.reactions(state.R0))
        self._contact()
        #: the seabed's force on the slack stretch's nodes but the anchor's (N, 3-vector: its
        #: weight and the drag on it, held there, and the friction at its end's node, which holds
        #: that node's share of the first tensioned element, about μ w h / 6, vanishing with the
        #: mesh; zero without a stretch)
        self.slack_seabed_force = np.zeros(3)
        if problem.slack_end > 0:  # the seabed holds the slack stretch, the anchor's node too
            S_A, self.anchor_seabed_force = np.zeros(3), S_A
            N, nodes = problem.N, problem.laid_nodes
            self.slack_seabed_force = np.array([state.R0[k * N + nodes].sum() for k in range(3)])
        elif self.anchor_on_seabed:
            bed, a = problem.seabed, self.anchor
            grad = bed.gradient(a[0], a[1])
            chord = self.xyz(np.array(min(problem.L, self.mesh_size))) - a
            S_A, self.anchor_seabed_force, _ = anchor_split(S_A, grad, chord, problem.friction)
        self.force_on_anchor, self.force_on_fairlead = -S_A + 0.0, -S_B  # (+ 0.0: no -0 of a slack anchor)
        self.T_A, self.T_B = float(np.linalg.norm(S_A)), float(np.linalg.norm(S_B))

    @property
    def slack_end(self) -> float:
        """The end of the slack stretch (m; 0: none; class docstring)."""
        return self.problem.slack_end

    @property
    def mesh_size(self) -> float:
        """The shortest element (m)."""
        return float(np.min(np.diff(np.sort(self.problem.mesh.p[0]))))

    def _contact(self):
        problem, terms = self.problem, self.state.terms
        self.anchor_seabed_force = np.zeros(3)
        if terms is None:
            self.contact_s, self.contact_xyz = np.zeros(0), np.zeros((0, 3))
            self.normal_force, self.gap = np.zeros(0), np.zeros(0)
            self.contact_force, self.in_contact = np.zeros((0, 3)), np.zeros(0, dtype=bool)
            return
        rows, N, z = problem.contact_rows, problem.N, self.dofs
        i = rows.nodes
        self.contact_s = problem.basis.doflocs[0][i]
        self.contact_xyz = np.column_stack([z[i], z[N + i], z[2 * N + i]])
        normal, friction = rows.forces(terms)
        self.normal_force = terms.lam * np.sqrt(terms.friction[1])  # λ|n|, signed off the seabed
        self.contact_force = (normal + friction).T
        self.gap, self.in_contact = terms.gap, terms.active

    # --- fields (`skcable.mooring.line_bvp.fields.LineFields`: state_at, tangent, T_of_s, weight) -----
    def xyz(self, s) -> np.ndarray:
        """Position (m) at unstretched arc lengths ``s`` from the anchor: ``(*s.shape, 3)``."""
        return self.positions(s)

    def profile(self, n: int = 101) -> np.ndarray:
        """The line at ``n`` points evenly spaced in unstretched arc length: ``(n, 3)`` (m)."""
        return self.xyz(np.linspace(0.0, self.length, whole("n", n, 2)))

    def profile_with_tension(self, n: int = 101):
        """``(points (n, 3), tension (n,))`` at ``n`` points evenly spaced in unstretched arc
        length (what `skcable.io.lines_mesh` reads)."""
        s = np.linspace(0.0, self.length, whole("n", n, 2))
        return self.xyz(s), np.asarray(self.T_of_s(s), dtype=float)

    def tensions(self):
        """One row per segment (pandas DataFrame): ``segment, length, T_lower, T_upper``
        (N; `LineFields.end_tensions`) and ``grounded_length`` (m, its share of
        `length_on_seabed`, between `s_landing` and `s_touchdown`: `LineFields.grounded_lengths`,
        the plane line's)."""
        import pandas as pd

        joints = self.problem.joints
        T_l, T_u = self.end_tensions(self.T_A, self.T_B)
        return pd.DataFrame(
            {
                "segment": np.arange(joints.size - 1),
                "length": np.diff(joints),
                "T_lower": T_l,
                "T_upper": T_u,
                "grounded_length": self.grounded_lengths(),
            }
        )

    # --- stiffness ----------------------------------------------------------------------------
    def stiffness(self, kind: str = "static") -> FairleadStiffness:
        """The fairlead stiffness ``∂S_B/∂r_B`` (N/m, 3 × 3, global axes; `kind` ``"static"`` or
        ``"dynamic"``: `skcable.mooring.line_bvp.space.stiffness`)."""
        return fairlead_stiffness_3d(self, kind)

    # --- output -----------------------------------------------------------------------------------
    def samples(self, n: int = 201) -> dict:
        """The line at ``n`` points evenly spaced in unstretched arc length: ``s`` (m), ``xyz``
        (n, 3) (m), ``tension`` (N), ``tangent`` (n, 3), ``load`` (n, 3) (N/m, the distributed
        force: weight, drag, the terms') and ``outputs`` (the terms' named point data, (n, 3))."""
        s, state, load, outputs = self.sampled(n)
        return {
            "s": s,
            "xyz": state.position.T,
            "tension": np.asarray(state.T, dtype=float),
            "tangent": (state.a / np.sqrt(np.sum(state.a * state.a, axis=0))).T,
            "load": load,
            "outputs": outputs,
        }

    def to_vtk(self, path, n: int = 201):
        """Write the line as a VTK polyline of ``n`` points (point data ``tension_N``,
        ``tangent``, ``load_N_per_m`` and the terms' outputs, the current's drag
        ``CurrentDrag_force_N_per_m``), atomically through `skcable.io.write`; returns the path."""
        import meshio

        from skcable.io import write

        samples = self.samples(n)
        points = samples["xyz"]
        cells = np.column_stack([np.arange(len(points) - 1), np.arange(1, len(points))])
        data = {
            "tension_N": samples["tension"],
            "tangent": samples["tangent"],
            "load_N_per_m": samples["load"],
        }
        data.update(samples["outputs"])
        return write(meshio.Mesh(points, [("line", cells)], point_data=data), path)

    def __repr__(self):
        Fa, Fb = self.force_on_anchor, self.force_on_fairlead
        return (
            f"LineBVP3DSolution({self.problem.mesh.t.shape[1]} elements: force_on_fairlead=[{Fb[0]:.9g}, "
            f"{Fb[1]:.9g}, {Fb[2]:.9g}] N, force_on_anchor=[{Fa[0]:.9g}, {Fa[1]:.9g}, {Fa[2]:.9g}] N, "
            f"T_A={self.T_A:.9g} N, T_B={self.T_B:.9g} N, length={self.length:.9g} m, "
            f"{int(self.in_contact.sum())} nodes on the seabed"
            + (f", slack stretch to s = {self.slack_end:.6g} m" if self.slack_end > 0 else "")
            + f", iterations={self.iterations})"
        )
