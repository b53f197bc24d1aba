"""The solution of a line BVP: end forces, contact, touchdown, and the fields along the line."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from skcable.mooring.line_bvp.contact import anchor_split
from skcable.mooring.line_bvp.fields import LineFields
from skcable.mooring.line_bvp.problem import LineProblem, LineState
from skcable.mooring.line_bvp.stiffness import fairlead_stiffness
from skcable.results import ProfileMixin

__all__ = ["LineBVPSolution"]


class LineBVPSolution(LineFields, ProfileMixin):
    """Solution of `solve_line_bvp`; a `skcable.results.CableResult`.

    Attributes
    ----------
    H_B, V_B : float
        Horizontal and upward vertical reaction at the fairlead B (N).
    H : float
        ``H_B``: the horizontal tension of the suspended part, B's (as for the closed-form
        lines on a seabed, `skcable.cable.elastic_catenary(seabed=)`): friction on the seabed
        takes some of it before A, so ``H_A`` may be smaller.
    H_A, V_A : float
        Horizontal and upward vertical reaction at the anchor A (N).
    T_A, T_B : float
        End tensions (N), ``hypot(H_A, V_A)`` and ``hypot(H_B, V_B)``: the support reactions,
        more accurate than the tension field at the ends (`T_of_s`).
    length : float
        Unstretched length (m).
    contact_s, contact_xy : ndarray
        Arc length from A (m) and position (m) of every contact node.
    normal_force : ndarray
        Seabed normal force ``N_i >= 0`` at each contact node (N).
    contact_force : ndarray (n, 2)
        Force of the seabed on the line at each contact node, friction
        included (N): ``λ_i (n_i - μ t_i)`` where the line slides, on a slack
        stretch near the anchor the friction that holds its tangential weight
        (none on a flat seabed).
    gap : ndarray
        Height of each contact node above the seabed (m), ``>= 0`` to round-off.
    in_contact : ndarray of bool
        The nodes on the seabed (the final active set).
    s_touchdown, x_touchdown : float
        Where the line leaves the seabed for the last time towards B: the
        unstretched arc length from A (m) at which the suspended part's
        vertical balance ``V_B - ∫_s^L w - ΣP = H b'(x(s))`` holds (a point
        between mesh nodes, not the last contact node), and its abscissa; 0
        without contact.
    s_landing : float
        Where a line hanging from an anchor above the seabed first lands
        (the balance of the part hanging from A, as for ``s_touchdown``); 0
        when A lies on the seabed.
    length_on_seabed : float
        ``s_touchdown - s_landing`` (m): the unstretched length between the
        first landing and the last touchdown (where the line lifts off a bump
        in between, that free stretch is included).
    history, iterations
        Newton's merit per iteration.
    problem : LineProblem
        The discrete line it solves (mesh, bases, loads, contact rows).
    state : LineState
        Residual and tangents at the solution.
    """

    #: ``slack_solver(s0)``: the line re-solved with its slack stretch ending at ``s0`` (set by
    #: the solver that made it; `stiffness` needs it where the line has a slack stretch)
    slack_solver: Callable[[float], LineBVPSolution] | None = None
    #: the `LineBVP` model that solved it (None from `solve_line_bvp`)
    model: object | None = None
    problem: LineProblem
    solver = "solve_line_bvp"

    def __init__(self, problem: LineProblem, z, history, state: LineState):
        self.problem, self.dofs, self.state = problem, z, state
        self.span, self.dh, self.length = problem.span, problem.dh, problem.L
        self.mesh, self.basis = problem.mesh, problem.basis
        self.history = [float(h) for h in history]
        self.iterations = len(self.history) - 1
        self.friction = problem.friction
        H_A, V_A, H_B, V_B = (float(v) for v in problem.reactions(state.R0))
        self.H, self.V_B, self.H_B = H_B, V_B, H_B
        i, N = problem.contact, problem.N  # along the line
        self.contact_s = problem.basis.doflocs[0][i]
        self.contact_xy = np.column_stack([z[i], z[N + i]])
        if i.size:
            H_A, V_A = self._contact(H_A, V_A)
        else:
            self.normal_force, self.gap = np.zeros(0), np.zeros(0)
            self.contact_force, self.in_contact = np.zeros((0, 2)), np.zeros(0, dtype=bool)
        self.H_A, self.V_A = H_A, V_A

    def _contact(self, H_A, V_A):
        """The seabed's forces per contact node (the anchor's node first, when A lies on the
        seabed, whose push the seabed takes from the anchor); the anchor's reaction."""
        problem = self.problem
        rows, terms = problem.contact_rows, self.state.terms
        assert rows is not None and terms is not None, "a line on a seabed"
        normal, friction = rows.forces(terms)
        bp, gap, lam, active = terms.slope, terms.gap, terms.lam, terms.active
        force = (normal + friction).T
        if self.anchor_on_seabed:
            # the seabed under the anchor takes the anchor's downward push, friction included; on
            # a slack stretch, friction holds the anchor node's own load along the seabed as it
            # does the stretch's other nodes' (`LineProblem`'s held loads; Jonkman's H_A = 0 on a
            # slope too: the anchor was left that share, O(h), 305 N of a 529 N pull on 64
            # elements in the differential survey's scene 2:53), the anchor what the tension pulls
            slope = float(problem.seabed.slope(np.array([0.0]))[0])
            S = np.array([-H_A, V_A])
            held = np.zeros(2)
            if problem.slack_end > 0:
                along = np.array([1.0, slope]) / np.sqrt(1.0 + slope * slope)
                held = (problem.external[problem.N + problem.end_a] * along[1]) * along
            mu_a = problem.friction if problem.slack_end == 0 else 0.0
            S_A, seabed, lam_a = anchor_split(S - held, [slope], (1.0, slope), mu_a)
            seabed = seabed + held
            H_A, V_A = -float(S_A[0]), float(S_A[1])
            self.contact_s = np.concatenate([[0.0], self.contact_s])
            self.contact_xy = np.vstack([[0.0, 0.0], self.contact_xy])
            bp, gap = np.concatenate([[slope], bp]), np.concatenate([[0.0], gap])
            lam, active = np.concatenate([[lam_a], lam]), np.concatenate([[lam_a > 0], active])
            force = np.vstack([seabed, force])
        self.normal_force = lam * np.sqrt(1.0 + bp * bp)
        self.contact_force = force
        self.gap, self.in_contact = gap, active
        return H_A, V_A

    @property
    def T_A(self):
        return float(np.hypot(self.H_A, self.V_A))

    @property
    def T_B(self):
        return float(np.hypot(self.H, self.V_B))

    @property
    def EA(self):
        """The smallest axial stiffness of the segments (N; None where all are inextensible):
        the line's largest strain is at most ``max(T_A, T_B)/EA``."""
        stiff = [seg.EA for seg in self.problem.segments if seg.EA is not None]
        return float(min(stiff)) if stiff else None

    def fields(self):
        """The dofs of ``x``, ``y`` (P2, m) and ``T`` (P1-DG, N)."""
        N = self.problem.N
        return self.dofs[:N], self.dofs[N : 2 * N], self.dofs[2 * N :]

    def xy(self, s):
        """Position (x, y) (m) at unstretched arc length ``s`` from A, array ``(..., 2)``."""
        return self.positions(s)

    def tension(self, s):
        """Tension (N) at unstretched arc length ``s`` (P1-DG: the value of the element containing s)."""
        return self.T_of_s(s)

    def angle(self, s):
        """Angle of the line to the horizontal (rad) at ``s`` (an array, 1-D at least)."""
        a = self.problem.state_at(self.dofs, np.atleast_1d(self.arc(s)).ravel()).a
        return np.arctan2(a[1], a[0])

    def seabed_slope_at(self, s):
        """The seabed's slope ``b'`` under the line at arc length ``s`` (m)."""
        x = self.xy(np.array(s))[0]
        return float(self.problem.seabed.slope(np.array([x]))[0])

    @property
    def x_touchdown(self):
        s_td = self.s_touchdown
        return float(self.xy(np.array(s_td))[0]) if s_td > 0 else 0.0

    def residual(self):
        """Largest scaled residual (forces over the total load, stretch over the length)."""
        return self.state.merit

    # --- the result protocol (skcable.results) ---------------------------------------------
    def x_of_s(self, s):
        """Abscissa (m) at unstretched arc length ``s`` (m) from A."""
        return self.xy(s)[..., 0]

    def y_of_s(self, s):
        """Height above A (m) at unstretched arc length ``s`` (m) from A."""
        return self.xy(s)[..., 1]

    def stiffness(self) -> np.ndarray:
        """Fairlead stiffness ``∂(H_B, V_B)/∂(span, dh)`` (N/m), 2 × 2, rows (H_B, V_B), columns
        (span, dh), the anchor fixed: from the converged tangent by the implicit function
        theorem (`skcable.mooring.line_bvp.stiffness`)."""
        return fairlead_stiffness(self, self.slack_solver)

    def round_off(self) -> float:
        """An estimate of the relative round-off in ``H_B`` (dimensionless): the positions carry
        ε times their size each, so the n elements' geometry carries about ``n ε`` of the span
        and of dh, which H amplifies by ``|∂ ln H/∂ ln span|`` and ``|∂ ln H/∂ ln dh|``:
        ``n ε (|K_HH| span + |K_HV| |dh|)/H_B`` (`stiffness`). Negligible on ordinary lines; an
        inextensible line within 1e-9 of its chord (its H conditioned 5e8 by its length) carries
        1e-6 on 64 elements, which this bounds within a factor of ten (7e-6), and more on finer
        meshes, where the closed forms `cable.catenary` and `mooring.Line` do not."""
        K = self.stiffness()
        spread = abs(K[0, 0]) * self.span + abs(K[0, 1]) * abs(self.dh)
        return float(self.mesh.t.shape[1] * np.finfo(float).eps * spread / abs(self.H_B))

    def tensions(self):
        """One row per segment (pandas DataFrame): ``segment, length, T_lower, T_upper, H_lower,
        H_upper`` (SI), the tension and horizontal tension at its ends towards A and B (the
        support reactions at A and B, the tension field inside the segment at the joints), and
        ``grounded_length``, its length on the seabed (m, `LineFields.grounded_lengths`)."""
        import pandas as pd

        joints = self.problem.joints
        T_l, T_u = self.end_tensions(self.T_A, self.T_B)
        inside = 1e-9 * np.diff(joints)
        H_l = T_l * np.cos(self.angle(joints[:-1] + inside))
        H_u = T_u * np.cos(self.angle(joints[1:] - inside))
        H_l[0], H_u[-1] = self.H_A, self.H_B
        return pd.DataFrame(
            {
                "segment": np.arange(joints.size - 1),
                "length": np.diff(joints),
                "T_lower": T_l,
                "T_upper": T_u,
                "H_lower": H_l,
                "H_upper": H_u,
                "grounded_length": self.grounded_lengths(),
            }
        )

    def samples(self, n: int = 201) -> dict:
        """The line at ``n`` points evenly spaced in unstretched arc length (the input of
        `to_vtk`): ``xy`` (n, 2) (m), ``tension`` (N, the field), ``angle`` (rad above the
        horizontal), ``load`` (n, 2), the distributed load in N per metre of unstretched line,
        y up (the weight and the cable terms' force; point loads and the seabed's forces not
        included), and ``outputs``, what the cable terms name (`CableTerm.outputs`: their
        force ``<Term>_force_N_per_m`` (n, 2) at least; empty without terms)."""
        s, state, load, outputs = self.sampled(n)
        a = state.a
        xy, tension = state.position.T, np.asarray(state.T, dtype=float)
        return {
            "xy": xy,
            "tension": tension,
            "angle": np.arctan2(a[1], a[0]),
            "load": load,
            "outputs": outputs,
        }

    def to_frame(self, n: int = 201):
        """``n`` profile samples evenly spaced in unstretched arc length (pandas DataFrame):
        columns ``s`` (m), ``x``, ``y`` (m) and ``T`` (N) (`skcable.results.ProfileMixin`), then
        the cable terms' outputs (``samples()["outputs"]``), a vector as ``<name>_x`` and
        ``<name>_y``."""
        outputs = self.samples(n)["outputs"] if self.problem.terms else {}
        return ProfileMixin.frame_with_outputs(self, n, outputs)

    def to_vtk(self, path, n: int = 201):
        """Write the line as a VTK polyline (`skcable.io.cable_mesh`: tension, tangent, angle,
        load as point data); returns the path."""
        from skcable.io import cable_mesh, write

        return write(cable_mesh(self, n), path)

    def __repr__(self):
        return (
            f"LineBVPSolution(span={self.span:g}, dh={self.dh:g}, {self.mesh.t.shape[1]} elements: "
            f"H_B={self.H_B:.9g}, V_B={self.V_B:.9g}, H_A={self.H_A:.9g}, V_A={self.V_A:.9g}, "
            f"T_A={self.T_A:.9g}, T_B={self.T_B:.9g}, length={self.length:.9g}, "
            f"{int(self.in_contact.sum())} nodes on the seabed, iterations={self.iterations})"
        )
