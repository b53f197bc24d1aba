r"""The fields of a converged line BVP at any arc length, in the plane and in space.

`LineFields` is what the plane line's solution (`skcable.mooring.line_bvp.solution`) and the line
in space's (`skcable.mooring.line_bvp.space.solution`) share: the arc lengths checked, the state
(positions, tangent, tension) through `skcable.mooring.line_bvp.discrete.DiscreteLine.state_at`,
the tension field, the weight, the tensions at the segments' ends and the samples the writers
read. Each solution adds its view of the ends: ``H`` and ``V`` in the plane, force vectors in
space.

**The equilibrium residual.** The converged discrete line satisfies its weak equations to
round-off. What it reports is that, as a field: ``ρ`` in the position space (P2, zero at the
supports) with

.. math:: \int_0^L \boldsymbol\rho\cdot\delta\mathbf r\,ds
          = \int_0^L \Big(\frac{d(T\mathbf t)}{ds} + \mathbf q\Big)\cdot\delta\mathbf r\,ds
          = -\int_0^L \big(T\,\mathbf t\cdot\delta\mathbf r' - \mathbf f\cdot\delta\mathbf r\big)\,ds
            - \sum_k P_k\,\delta r_{v,k} + \sum_i \mathbf C_i\cdot\delta\mathbf r_i

for every test field ``δr`` vanishing at the ends (``q`` all the forces on the line: ``f`` per
length, the point loads, the seabed's forces ``C_i`` at the contact nodes; the inter-element
jumps of ``T t`` included), evaluated at every quadrature point: the Galerkin projection of
``d(T t)/ds + q``. It is assembled by scikit-fem's own ``asm`` (not the solve's assembly, whose
round-off it must not share) and solved with the consistent mass matrix. `LineFields.check`
bounds it by ``1e-8 w`` (``w`` the largest weight per length), or by its round-off floor where
that is larger: 64 times the change of the rows when every dof moves by its rounding,
``ε |J| |z|`` (N), per unit of the mass matrix's row (a taut line's tension over a short
element, positions far from the origin). Beside it, `strong_residual` is the
pointwise ``|d(T t)/ds + q|`` inside the elements: not round-off but the discretisation's error
(it falls as the mesh is refined), an error indicator.

**Resolution.** `element_turning` is the angle the tangent turns within each element (the kinks
at nodes aside). An element that turns through more than a few tenths of a radian (or a short one
through more), or a weight that varies within an element, leaves the end forces off by a
discretisation error that the residual above does not see (it holds to round-off on the coarse
mesh): `LineFields.unresolved` says where
(`skcable.mooring.line_bvp.check.unresolved`, with its calibration), and the public solves warn
it (`skcable.errors.ResolutionWarning`).
"""

from __future__ import annotations

from functools import cached_property

import numpy as np

from skcable._checks import real, require, whole
from skcable.bvp.terms import CableState, term_outputs
from skcable.errors import ConvergenceError
from skcable.mooring.line_bvp.check import equilibrium_field, strong_residual, unresolved
from skcable.mooring.line_bvp.discrete import DiscreteLine, LineState
from skcable.mooring.line_bvp.fitting import LineBalance, landing, touchdown

__all__ = ["NO_EDGE", "LineFields"]

#: the failure where the balance of the hanging part has no root near the contact edge
NO_EDGE = (
    "no sign change of the vertical balance near the contact edge (its elements there may not "
    "resolve where the line leaves the seabed: give more)"
)


class LineFields:
    """The fields of a converged discrete line (module docstring): a solution sets ``problem``
    (a `skcable.mooring.line_bvp.discrete.DiscreteLine`), ``dofs`` and ``length`` (m)."""

    problem: DiscreteLine
    dofs: np.ndarray
    length: float
    state: LineState
    history: list
    #: the contact nodes' arc lengths (m) and which lie on the seabed (the final active set)
    contact_s: np.ndarray
    in_contact: np.ndarray
    #: the public function that solves it, for messages
    solver = "a line BVP"
    #: the ``n_elements`` of the solve that gave it (with ``"auto"``, the number it took:
    #: `skcable.mooring.line_bvp.resolution`; the mesh holds them and the nodes fitted at the
    #: touchdowns); None on a failure's ``last`` but for the coarser line ``"auto"`` keeps
    n_elements: int | None = None

    # --- where the line meets the seabed -------------------------------------------------------
    @property
    def anchor_on_seabed(self) -> bool:
        """Whether the anchor lies on the seabed (to 1e-12 of the length:
        ``problem.anchor_on_seabed``)."""
        return bool(self.problem.anchor_on_seabed)

    @cached_property
    def s_touchdown(self) -> float:
        """Where the line leaves the seabed for the last time towards the fairlead: the
        unstretched arc length from the anchor (m) where the suspended part's tension is tangent
        to the seabed (`skcable.mooring.line_bvp.fitting.touchdown`; without cable terms the
        vertical balance ``V_B - (W - W(s)) = H_B b'(x(s))``), a point between mesh nodes, not
        the last contact node; 0 without contact. Where only the anchor's node presses on the
        seabed, the touchdown may lie before the first node: it is sought there (0 where the
        balance has no root near the anchor)."""
        anchor_only = self.anchor_on_seabed and self.in_contact.size and self.in_contact[0]
        beyond = self.touches_beyond_anchor()
        if not (beyond or anchor_only):
            return 0.0
        s_td = touchdown(self.problem, self.dofs, self.state, from_anchor=not beyond)
        if s_td is None and beyond:
            raise ConvergenceError(f"{self.solver}: {NO_EDGE}", self.history)
        return 0.0 if s_td is None else s_td

    @cached_property
    def s_landing(self) -> float:
        """Where a line hanging from an anchor above the seabed first lands on it: the unstretched
        arc length from the anchor (m) where the part hanging from it meets the seabed
        tangentially (`skcable.mooring.line_bvp.fitting.landing`: ``W(s) - V_A = H_A b'(x(s))``
        without cable terms); 0 where the anchor lies on the seabed or nothing touches."""
        if self.anchor_on_seabed or not self.in_contact.any():
            return 0.0
        found = landing(self.problem, self.dofs, self.state)
        if found is None:
            raise ConvergenceError(f"{self.solver}: {NO_EDGE}", self.history)
        return found

    @property
    def length_on_seabed(self) -> float:
        """``s_touchdown - s_landing`` (m): the unstretched length between the first landing and
        the last touchdown (a free stretch over a bump in between included); 0 without contact."""
        if not self.in_contact.any():
            return 0.0
        return self.s_touchdown - self.s_landing

    def touches_beyond_anchor(self) -> bool:
        """Whether a node other than the anchor's lies on the seabed."""
        return bool(self.in_contact[self.contact_s > 0].any())

    def arc(self, s) -> np.ndarray:
        """``s`` (m) as an array, checked to lie on the line ``[0, length]``."""
        s = np.asarray(real("s", s), dtype=float)
        require("s", (s >= 0) & (s <= self.length), "must lie in [0, length]", s)
        return s

    def state_at(self, s) -> CableState:
        """The line's `skcable.bvp.terms.CableState` at arc lengths ``s`` (m), flattened."""
        return self.problem.state_at(self.dofs, self.arc(s).ravel())

    def positions(self, s) -> np.ndarray:
        """Position (m) at unstretched arc lengths ``s`` from the anchor: ``(*s.shape, dim)``."""
        s = self.arc(s)
        state = self.problem.state_at(self.dofs, s.ravel())
        return state.position.T.reshape(*s.shape, -1)

    def tangent(self, s) -> np.ndarray:
        """The unit tangent towards the fairlead at ``s``: ``(*s.shape, dim)``."""
        s = self.arc(s)
        a = self.problem.state_at(self.dofs, s.ravel()).a
        return (a / np.sqrt(np.sum(a * a, axis=0))).T.reshape(*s.shape, -1)

    def T_of_s(self, s):
        """The tension field (N) at unstretched arc lengths ``s`` (m): P1-DG, the value of the
        element containing ``s``, accurate to O(h²) at the nodes; `T_A` and `T_B` (the supports'
        reactions) are the accurate end values."""
        s = self.arc(s)
        return self.problem.tension_at(self.dofs, s).reshape(s.shape)[()]

    @property
    def weight(self) -> float:
        """Total weight of the line and its point loads (N, downward)."""
        problem = self.problem
        return problem.weight + float(np.sum(problem.point_values))

    def end_tensions(self, T_A: float, T_B: float) -> tuple[np.ndarray, np.ndarray]:
        """``(T_lower, T_upper)`` per segment (N): the tension field just inside each segment at
        its ends (1e-9 of its length in), the supports' reactions ``T_A`` and ``T_B`` at the
        line's ends."""
        joints = self.problem.joints
        inside = 1e-9 * np.diff(joints)
        T_lower = np.atleast_1d(np.array(self.T_of_s(joints[:-1] + inside), dtype=float))
        T_upper = np.atleast_1d(np.array(self.T_of_s(joints[1:] - inside), dtype=float))
        T_lower[0], T_upper[-1] = T_A, T_B
        return T_lower, T_upper

    def grounded_lengths(self) -> np.ndarray:
        """Each segment's length between `s_landing` and `s_touchdown` (m): its share of
        `length_on_seabed`, which they sum to; zeros without contact."""
        joints = self.problem.joints
        if not self.in_contact.any():
            return np.zeros(joints.size - 1)
        low, high = self.s_landing, self.s_touchdown
        return np.clip(np.minimum(joints[1:], high) - np.maximum(joints[:-1], low), 0.0, None)

    def sampled(self, n: int) -> tuple[np.ndarray, CableState, np.ndarray, dict]:
        """``(s, state, load, outputs)`` at ``n`` points evenly spaced in unstretched arc length:
        the state there, the distributed load (n, dim) (N/m: the weight and the cable terms'
        force, `DiscreteLine.forces_at`) and what the cable terms name (`CableTerm.outputs`, the
        points first: their force ``<Term>_force_N_per_m`` (n, dim) at least)."""
        s = np.linspace(0.0, self.length, whole("n", n, 2))
        state = self.state_at(s)
        load = self.problem.forces_at(self.dofs, s).T
        terms = self.problem.terms
        outputs = {k: np.moveaxis(np.asarray(v), -1, 0) for k, v in term_outputs(terms, state).items()}
        return s, state, load, outputs

    @cached_property
    def sensitivity(self):
        """``(K_B, K_A, dz)``: the static sensitivities to the fairlead's position at the
        converged state (`skcable.mooring.line_bvp.discrete.DiscreteLine.end_sensitivities`),
        computed once: the static stiffness and a warm start's predictor read them."""
        return self.problem.end_sensitivities(self.state)

    def tension_profile(self):
        """The P1-DG tension per element, sorted along the line: ``(s_left, s_right, T_left,
        T_right)`` (m, m, N, N)."""
        tb = self.problem.tbasis
        dofs = tb.element_dofs  # (2, ne)
        at = tb.doflocs[0][dofs]
        T = self.dofs[self.problem.dim * self.problem.N :][dofs]
        first = np.argmin(at, axis=0)
        cols = np.arange(dofs.shape[1])
        s_l, s_r = at[first, cols], at[1 - first, cols]
        T_l, T_r = T[first, cols], T[1 - first, cols]
        order = np.argsort(s_l)
        return s_l[order], s_r[order], T_l[order], T_r[order]

    @cached_property
    def _from_anchor(self) -> LineBalance:
        return LineBalance(self.problem, self.dofs, None, "a")

    def load_before(self, s) -> tuple[float, ...]:
        """The load (N) on the line over [0, s] in the residual's sense, per coordinate (the last
        one up): the weight and the point loads before s, less the cable terms' force ``∫_0^s f``
        (`skcable.mooring.line_bvp.fitting.LineBalance` from the anchor)."""
        F = self._from_anchor.forces(np.array([float(s)]))[:, 0]
        return tuple(float(v) for v in F)

    # --- the equilibrium residual (module docstring) ------------------------------------------
    @cached_property
    def _residual(self):
        return equilibrium_field(self)

    @property
    def equilibrium_residual(self) -> float:
        """The largest ``|ρ|`` (N/m) over the quadrature points (module docstring)."""
        return float(np.max(self._residual[0]))

    @property
    def residual_field(self) -> np.ndarray:
        """``|ρ|`` (N/m) at every quadrature point, (n_elements, n_points)."""
        return self._residual[0]

    @property
    def residual_bound(self) -> float:
        """The bound `check` holds the residual to (N/m): ``1e-8 w`` or its round-off floor."""
        return max(1e-8 * float(np.abs(self.problem.w_q).max()), self._residual[1])

    def check(self) -> None:
        """Raise `skcable.ConvergenceError` where `equilibrium_residual` exceeds `residual_bound`,
        or where the touchdown or the landing has no balance (`s_touchdown`, `s_landing`: a
        returned solution gives them)."""
        if not self.equilibrium_residual <= self.residual_bound:
            raise ConvergenceError(
                f"{self.solver}: the equilibrium residual {self.equilibrium_residual:.3g} N/m exceeds "
                f"{self.residual_bound:.3g} N/m",
                self.history,
            )
        self.s_touchdown, self.s_landing  # noqa: B018 (computed here: each raises where it has no root)

    @cached_property
    def element_turning(self) -> np.ndarray:
        """The angle (rad) the unit tangent turns within each element, from its first node to its
        last (the P2 position's derivative at each end, inside the element: the kinks at nodes
        left out), the elements in order along the line: ``2 atan2(|t_1 - t_0|, |t_1 + t_0|)``,
        accurate at small angles too (module docstring, resolution)."""
        problem = self.problem
        ends, middle = problem.basis.element_dofs[:2], problem.basis.element_dofs[2]
        r = self.dofs[: problem.dim * problem.N].reshape(problem.dim, problem.N)
        r0, r1, rm = r[:, ends[0]], r[:, ends[1]], r[:, middle]
        t0, t1 = 4.0 * rm - 3.0 * r0 - r1, 3.0 * r1 + r0 - 4.0 * rm  # r'(ξ) at ξ = 0 and 1
        t0, t1 = t0 / np.sqrt(np.sum(t0 * t0, axis=0)), t1 / np.sqrt(np.sum(t1 * t1, axis=0))
        apart, along = np.sqrt(np.sum((t1 - t0) ** 2, axis=0)), np.sqrt(np.sum((t1 + t0) ** 2, axis=0))
        turning = 2.0 * np.arctan2(apart, along)
        return turning[np.argsort(problem.mesh.p[0, problem.mesh.t].min(axis=0))]

    def unresolved(self) -> str:
        """Why the mesh does not resolve the line, where an element turns through a bend within
        it or its weight varies within an element (`skcable.mooring.line_bvp.check.unresolved`),
        else ``""``; computed once."""
        return self._unresolved

    @cached_property
    def _unresolved(self) -> str:
        return unresolved(self)

    @cached_property
    def strong_residual(self) -> np.ndarray:
        """``|d(T t)/ds + q|`` (N/m) inside the elements at the quadrature points, (nq, ne): the
        discretisation's error (module docstring)."""
        return strong_residual(self)
