r"""The net load and stiffness of a mooring system, vectorised over its bodies and line ends.

`skcable.mooring.system` states the sums; here they are formed with NumPy over all the
bodies at once (their rotation matrices, own loads and hydrostatic stiffness) and over all the
line ends at once: an end on a body at arm :math:`\mathbf r` with force :math:`\mathbf f` and 3 × 3
stiffness :math:`K` gives the body, with :math:`T = [I, -[\mathbf r]_\times]` (3 × 6),

.. math:: T^T\mathbf f = \begin{pmatrix}\mathbf f\\ \mathbf r\times\mathbf f\end{pmatrix}, \qquad
    T^T K T - \begin{pmatrix} 0 & 0 \\ 0 & [\mathbf f]_\times[\mathbf r]_\times\end{pmatrix}
    = \begin{pmatrix} K & -K[\mathbf r]_\times \\ [\mathbf r]_\times K &
    -[\mathbf f]_\times[\mathbf r]_\times - [\mathbf r]_\times K[\mathbf r]_\times\end{pmatrix},

summed per body (one product with a 0/1 matrix of the ends' bodies); an end at a free point adds
``f`` and ``K`` to its three dofs (``np.add.at``). The own loads of a body, as
`skcable.mooring.body`, are ends of no stiffness: its weight :math:`\mathbf W` at
:math:`R\mathbf r_G` and its buoyancy :math:`\mathbf B` at :math:`R\mathbf r_M` (their arms
formed with the points', `Assembler.body_arms`), whose geometric terms are the hydrostatic
:math:`K_{\theta\theta} = -[\mathbf W]_\times[R\mathbf r_G]_\times - [\mathbf B]_\times[R\mathbf r_M]_\times`;
then the heave restoring, :math:`-\rho g A_{WP} z` and :math:`K_{zz} = \rho g A_{WP}`, and the
own loads of a body whose loads change with its pose (its ``posed_loads(q)``: a rod's buoyancy,
`skcable.mooring.rod.RodBody`). A point body is a body whose arms and angles are zero.
"""

from __future__ import annotations

import numpy as np

from skcable.mooring.body import RigidBody, rotation_matrix, skews

__all__ = ["Assembler", "rotations"]

#: ``[v]x`` flattened: ``skews(v).reshape(n, 9) = v @ _SKEW`` (``+ 0.0``: no signed zeros).
_SKEW = skews(np.eye(3)).reshape(3, 9) + 0.0
#: ``T = [I, -[r]x]`` flattened (3 x 6), its rotation columns: ``r @ _MINUS_SKEW_T``.
_MINUS_SKEW_T = np.zeros((3, 18))
_MINUS_SKEW_T.reshape(3, 3, 6)[:, :, 3:] = -_SKEW.reshape(3, 3, 3)
_EYE3 = np.eye(3)


def rotations(angles) -> np.ndarray:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` of each row ``(roll, pitch, yaw)`` of ``angles``, (n, 3, 3)."""
    c3, c2, c1 = np.cos(angles).T
    s3, s2, s1 = np.sin(angles).T
    R = np.empty((len(angles), 3, 3))
    R[:, 0, 0], R[:, 0, 1], R[:, 0, 2] = c1 * c2, c1 * s2 * s3 - c3 * s1, s1 * s3 + c1 * c3 * s2
    R[:, 1, 0], R[:, 1, 1], R[:, 1, 2] = c2 * s1, c1 * c3 + s1 * s2 * s3, c3 * s1 * s2 - c1 * s3
    R[:, 2, 0], R[:, 2, 1], R[:, 2, 2] = -s2, c2 * s3, c2 * c3
    return R


class Assembler:
    """The arrays of a system that the vectorised assembly reads (built once per layout).

    Parameters
    ----------
    bodies, points : list
        The system's bodies and points (`skcable.mooring.network.MooringPoint`).
    layout : Layout
        Their dofs.
    """

    def __init__(self, bodies, points, layout):
        self.n = layout.n_dof
        nb = len(bodies)
        self.bodies = list(bodies)
        self.rigid = np.array([isinstance(b, RigidBody) for b in bodies], dtype=bool)
        self.start = np.array(layout.body_start, dtype=int)
        self.rows6 = self.start[self.rigid, None] + np.arange(6)
        self.rows3 = self.start[~self.rigid, None] + np.arange(3)
        self.xyz_dofs = self.start[:, None] + np.arange(3)
        self.weight = np.array([b.weight for b in bodies]).reshape(nb, 3)
        self.buoyancy = np.array([b.buoyancy for b in bodies]).reshape(nb, 3)
        self.heave = np.array([b.heave_stiffness for b in bodies])
        zero = np.zeros(3)
        self.cg = np.array([getattr(b, "center_of_gravity", zero) for b in bodies]).reshape(nb, 3)
        self.metacentre = np.array([getattr(b, "metacentre", zero) for b in bodies]).reshape(nb, 3)
        # each point: its kind (0 fixed, 1 free, 2 on a body), the first dof of a free point or the
        # body's number, and its row among the bodies' points
        self.kind = np.array([{"fixed": 0, "free": 1, "body": 2}[p.kind] for p in points], dtype=int)
        self.owner = np.full(len(points), -1)
        self.row = np.full(len(points), -1)
        self.free_start = np.full(len(points), -1)
        for j, s in layout.point_start.items():
            self.free_start[j] = s
        rows = 0
        for i, idx in enumerate(layout.body_points):
            self.owner[idx] = i
            self.row[idx] = np.arange(rows, rows + len(idx))
            rows += len(idx)
        self.body_point_index = np.concatenate(
            [np.asarray(idx, dtype=int) for idx in layout.body_points] or [np.zeros(0, dtype=int)]
        ).astype(int)
        self.body_point_owner = np.concatenate(
            [np.full(len(idx), i, dtype=int) for i, idx in enumerate(layout.body_points)]
            or [np.zeros(0, dtype=int)]
        ).astype(int)
        self.body_point_local = np.concatenate([layout.local[i] for i in range(nb)] or [np.zeros((0, 3))])
        self.free_own = [
            (layout.point_start[p.index], p.own_force)
            for p in points
            if p.kind == "free" and any(p.own_force)
        ]
        on_bodies = [p for p in points if p.kind == "body" and any(p.own_force)]
        self.body_own_index = np.array([p.index for p in on_bodies], dtype=int)
        # the own loads as ends of no stiffness: the bodies' points', then each body's weight at its
        # centre of gravity and buoyancy at its metacentre (arms: the rows after the points')
        n_points = len(self.body_point_local)
        self.own_rows = n_points + np.arange(2 * nb)
        own = [p.own_force for p in on_bodies] + [
            v for i in range(nb) for v in (self.weight[i], self.buoyancy[i])
        ]
        self.own_forces = np.array(own, dtype=float).reshape(-1, 3)
        self.arm_local = np.concatenate(
            [self.body_point_local, np.stack([self.cg, self.metacentre], axis=1).reshape(-1, 3)]
        )
        self.arm_owner = np.concatenate([self.body_point_owner, np.repeat(np.arange(nb), 2)]).astype(int)
        self._plans = {}
        # bodies with own loads that change with their pose (`skcable.mooring.rod.RodBody`'s buoyancy)
        self.posed = [(i, b) for i, b in enumerate(bodies) if callable(getattr(b, "posed_loads", None))]
        # each point's body or free point, by its first dof (-1: fixed); the own loads' force scale
        self.group_start = np.where(self.kind == 1, self.free_start, -1)
        on_body = self.kind == 2
        self.group_start[on_body] = self.start[self.owner[on_body]]
        self.groups = np.unique(self.group_start[self.group_start >= 0])  # the bodies and points held
        self.group_xyz = self.groups[:, None] + np.arange(3)  # their translation dofs
        scales = [abs(b.weight[2]) for b in bodies] + [b.buoyancy[2] for b in bodies]
        scales += [float(np.abs(p.own_force).max()) for p in points]
        self.own_scale = max(scales, default=0.0)

    def frames(self, q) -> tuple[np.ndarray, np.ndarray]:
        """The bodies' positions ``(n, 3)`` and rotation matrices ``(n, 3, 3)`` at the dofs ``q``."""
        nb = len(self.start)
        xyz = q[self.xyz_dofs]
        if nb == 1:  # one body: its own rotation matrix, on floats
            R = rotation_matrix(*q[self.rows6[0, 3:]].tolist()) if self.rigid[0] else np.eye(3)
            return xyz, R[None]
        angles = np.zeros((nb, 3))
        if self.rigid.any():
            angles[self.rigid] = q[self.rows6[:, 3:]]
        return xyz, rotations(angles)

    def body_arms(self, R) -> np.ndarray:
        """The arms (global axes) of all the bodies' points, in the order of ``body_point_index``,
        then of each body's centre of gravity and metacentre (rows `own_rows`)."""
        return np.einsum("mij,mj->mi", R[self.arm_owner], self.arm_local)

    def plan(self, index, own: bool) -> dict:
        """What the assembly needs of a set of moving ends at the points ``index`` (cached: the ends
        of a system's lines are the same at every evaluation), with the bodies' own loads (``own``)
        as ends of no stiffness: their weight at the centre of gravity, their buoyancy at the
        metacentre, and the own loads of their points."""
        key = (tuple(index), own)
        if key not in self._plans:
            index = np.asarray(index, dtype=int)
            extra = self.body_own_index if own else np.zeros(0, dtype=int)
            points = np.concatenate([index, extra]).astype(int)
            free, on_body = self.kind[points] == 1, self.kind[points] == 2
            dofs = self.free_start[points[free], None] + np.arange(3)
            rows = self.row[points[on_body]]
            owner = self.owner[points[on_body]]
            if own:  # weight and buoyancy of each body
                rows = np.concatenate([rows, self.own_rows]).astype(int)
                owner = np.concatenate([owner, np.repeat(np.arange(len(self.start)), 2)]).astype(int)
            onehot = np.zeros((len(self.start), len(rows)))
            onehot[owner, np.arange(len(owner))] = 1.0
            self._plans[key] = {
                "free": np.flatnonzero(free[: len(index)]),
                "on_body": np.flatnonzero(on_body[: len(index)]),
                "dofs": dofs,
                "rows": rows,
                "onehot": onehot,
                "extra": self.own_forces if own else np.zeros((0, 3)),
                "extra_K": np.zeros((len(self.own_forces) if own else 0, 3, 3)),
                "all_on_body": bool(on_body[: len(index)].all()),
                "one": len(self.start) == 1 and self.rigid[0] and self.n == 6 and not len(dofs),
            }
        return self._plans[key]

    def assemble(self, q, R, arms, index, forces, stiffness, cross, external, lines_only):
        """``(G, K)``: the moving line ends at the points ``index`` with their forces ``(m, 3)`` and
        stiffnesses ``(m, 3, 3)``, ``cross`` the coupling blocks ``(first dof, T_a, first dof, T_b,
        K_ab, K_ba)``."""
        plan = self.plan(index, not lines_only)
        free = plan["free"]
        if len(free):
            G, K = np.zeros(self.n), np.zeros((self.n, self.n))
            dofs = plan["dofs"]
            np.add.at(G, dofs, forces[free])
            np.add.at(K, (dofs[:, :, None], dofs[:, None, :]), stiffness[free])
        if not plan["all_on_body"]:
            on_body = plan["on_body"]
            forces, stiffness = forces[on_body], stiffness[on_body]
        Gb, Kb = self._body_ends(plan, forces, stiffness, arms)
        if not lines_only and len(self.start):  # heave restoring
            Gb[:, 2] -= self.heave * q[self.start + 2]
            Kb[:, 2, 2] += self.heave
        if not lines_only:
            for i, body in self.posed:  # own loads of the pose, and their stiffness
                s = int(self.start[i])
                g, k = body.posed_loads(q[s : s + body.n_dof])
                Gb[i] += g
                Kb[i] += k
        if plan["one"]:  # one rigid body, no free point: its dofs are the system's
            G, K = Gb[0], Kb[0]
        else:
            if not len(free):
                G, K = np.zeros(self.n), np.zeros((self.n, self.n))
            self._scatter(G, K, Gb, Kb)
        for sa, Ta, sb, Tb, K_ab, K_ba in cross:
            ka, kb = Ta.shape[1], Tb.shape[1]
            K[sa : sa + ka, sb : sb + kb] += Ta.T @ K_ab @ Tb
            K[sb : sb + kb, sa : sa + ka] += Tb.T @ K_ba @ Ta
        if not lines_only:
            G += external
            for s, f in self.free_own:
                G[s : s + 3] += f
        return G, K

    def _body_ends(self, plan, F, Kp, arms):
        """The ends on bodies (and the own loads, where ``plan`` has them) summed per body:
        ``(G (n, 6), K (n, 6, 6))``, as ``T^T f`` and ``T^T K T - [f]x[r]x`` with
        ``T = [I, -[r]x]`` (module docstring)."""
        nb = len(self.start)
        extra = plan["extra"]
        if len(extra):
            F = np.concatenate([F, extra])
            Kp = np.concatenate([Kp, plan["extra_K"]])
        m = len(F)
        if not m:
            return np.zeros((nb, 6)), np.zeros((nb, 6, 6))
        r = arms[plan["rows"]]
        T = (r @ _MINUS_SKEW_T).reshape(m, 3, 6)
        T[:, :, :3] = _EYE3
        Tt = T.transpose(0, 2, 1)
        g = (Tt @ F[:, :, None]).reshape(m, 6)  # (f, r x f)
        k = Tt @ (Kp @ T)
        k[:, 3:, 3:] -= (F @ _SKEW).reshape(m, 3, 3) @ (r @ _SKEW).reshape(m, 3, 3)
        onehot = plan["onehot"]
        return onehot @ g, (onehot @ k.reshape(m, 36)).reshape(nb, 6, 6)

    def _scatter(self, G, K, Gb, Kb):
        if self.rigid.any():
            r6 = self.rows6
            G[r6] += Gb[self.rigid]
            K[r6[:, :, None], r6[:, None, :]] += Kb[self.rigid]
        if (~self.rigid).any():
            r3 = self.rows3
            G[r3] += Gb[~self.rigid, :3]
            K[r3[:, :, None], r3[:, None, :]] += Kb[~self.rigid, :3, :3]
