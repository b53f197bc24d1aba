r"""The net load and stiffness of a mooring system, vectorised over its bodies and line ends.

`skcable.cable.lines.system` states the sums; here they are formed with NumPy over all the
bodies at once (their rotation matrices, own loads and hydrostatic stiffness) and over all the
line ends at once: an end on a body at arm :math:`\mathbf r` with force :math:`\mathbf f` and 3 × 3
stiffness :math:`K` gives the body

.. math:: \begin{pmatrix}\mathbf f\\ \mathbf r\times\mathbf f\end{pmatrix}, \qquad
    \begin{pmatrix} K & -K[\mathbf r]_\times \\ [\mathbf r]_\times K &
    -[\mathbf f]_\times[\mathbf r]_\times - [\mathbf r]_\times K[\mathbf r]_\times\end{pmatrix},

summed per body (``np.add.at``); an end at a free point adds ``f`` and ``K`` to its three dofs.
The own loads of a body, as `skcable.cable.lines.body`: weight at :math:`R\mathbf r_G`, buoyancy at
:math:`R\mathbf r_M`, heave restoring; their stiffness
:math:`K_{\theta\theta} = -[\mathbf W]_\times[R\mathbf r_G]_\times - [\mathbf B]_\times[R\mathbf r_M]_\times`,
:math:`K_{zz} = \rho g A_{WP}`. A point body is a body whose arms and angles are zero.
"""

from __future__ import annotations

import numpy as np

from skcable.cable.lines.body import RigidBody, rotation_matrix

__all__ = ["Assembler", "cross", "rotations", "skews"]


def rotations(angles) -> np.ndarray:
    """``R = Rz(yaw) Ry(pitch) Rx(roll)`` of each row ``(roll, pitch, yaw)`` of ``angles``, (n, 3, 3)."""
    c3, c2, c1 = np.cos(angles).T
    s3, s2, s1 = np.sin(angles).T
    R = np.empty((len(angles), 3, 3))
    R[:, 0, 0], R[:, 0, 1], R[:, 0, 2] = c1 * c2, c1 * s2 * s3 - c3 * s1, s1 * s3 + c1 * c3 * s2
    R[:, 1, 0], R[:, 1, 1], R[:, 1, 2] = c2 * s1, c1 * c3 + s1 * s2 * s3, c3 * s1 * s2 - c1 * s3
    R[:, 2, 0], R[:, 2, 1], R[:, 2, 2] = -s2, c2 * s3, c2 * c3
    return R


def cross(a, b) -> np.ndarray:
    """Row-wise cross products of ``(n, 3)`` arrays (`numpy.cross` without its axis handling)."""
    out = np.empty_like(a)
    out[:, 0] = a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1]
    out[:, 1] = a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2]
    out[:, 2] = a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]
    return out


def skews(v) -> np.ndarray:
    """``[v]x`` of each row of ``v`` (n, 3), shape (n, 3, 3)."""
    out = np.zeros((len(v), 3, 3))
    out[:, 0, 1], out[:, 0, 2], out[:, 1, 2] = -v[:, 2], v[:, 1], -v[:, 0]
    return out - out.transpose(0, 2, 1)


class Assembler:
    """The arrays of a system that the vectorised assembly reads (built once per layout).

    Parameters
    ----------
    bodies, points : list
        The system's bodies and points (`skcable.cable.lines.network.MooringPoint`).
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
        self.body_own = [
            (p.index, p.own_force, np.zeros((3, 3))) for p in points if p.kind == "body" and any(p.own_force)
        ]
        self._plans = {}
        # each point's body or free point, by its first dof (-1: fixed); the own loads' force scale
        self.group_start = np.where(self.kind == 1, self.free_start, -1)
        on_body = self.kind == 2
        self.group_start[on_body] = self.start[self.owner[on_body]]
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
        """The arms (global axes) of all the bodies' points, in the order of ``body_point_index``."""
        return np.einsum("mij,mj->mi", R[self.body_point_owner], self.body_point_local)

    def plan(self, index) -> dict:
        """What the assembly needs of a set of moving ends at the points ``index`` (cached: the ends
        of a system's lines are the same at every evaluation)."""
        key = tuple(index)
        if key not in self._plans:
            index = np.asarray(index, dtype=int)
            free, on_body = self.kind[index] == 1, self.kind[index] == 2
            dofs = self.free_start[index[free], None] + np.arange(3)
            owner = self.owner[index[on_body]]
            onehot = np.zeros((len(self.start), int(on_body.sum())))
            onehot[owner, np.arange(len(owner))] = 1.0
            rows = self.row[index[on_body]]
            self._plans[key] = {
                "free": free,
                "on_body": on_body,
                "dofs": dofs,
                "rows": rows,
                "onehot": onehot,
            }
        return self._plans[key]

    def assemble(self, q, R, arms, ends, cross, external, lines_only):
        """``(G, K)``: ``ends`` the moving line ends ``(point index, force (3,), stiffness (3, 3))``,
        ``cross`` the coupling blocks ``(first dof, T_a, first dof, T_b, K_ab, K_ba)``."""
        G, K = np.zeros(self.n), np.zeros((self.n, self.n))
        if not lines_only:
            ends = ends + self.body_own
        plan = self.plan([e[0] for e in ends])
        forces = np.array([e[1] for e in ends]).reshape(-1, 3)
        stiffness = np.array([e[2] for e in ends]).reshape(-1, 3, 3)
        if len(plan["dofs"]):
            dofs, free = plan["dofs"], plan["free"]
            np.add.at(G, dofs, forces[free])
            np.add.at(K, (dofs[:, :, None], dofs[:, None, :]), stiffness[free])
        on_body = plan["on_body"]
        Gb, Kb = self._body_ends(plan, forces[on_body], stiffness[on_body], arms)
        if not lines_only:
            self._own(q, R, Gb, Kb)
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
        """The ends on bodies summed per body: ``(G (n, 6), K (n, 6, 6))``."""
        nb, m = len(self.start), len(F)
        if not m:
            return np.zeros((nb, 6)), np.zeros((nb, 6, 6))
        r = arms[plan["rows"]]
        S, Sf = skews(r), skews(F)
        g = np.empty((m, 6))
        g[:, :3] = F
        g[:, 3:] = (S @ F[:, :, None])[:, :, 0]  # r x f
        KS = Kp @ S
        k = np.empty((m, 6, 6))
        k[:, :3, :3] = Kp
        k[:, :3, 3:] = -KS
        k[:, 3:, :3] = S @ Kp
        k[:, 3:, 3:] = -Sf @ S - S @ KS
        onehot = plan["onehot"]
        return onehot @ g, (onehot @ k.reshape(m, 36)).reshape(nb, 6, 6)

    def _own(self, q, R, Gb, Kb):
        """The bodies' own loads and hydrostatic stiffness, added to ``Gb``, ``Kb``."""
        if not len(self.start):
            return
        if len(self.bodies) <= 2:  # a body or two: their own methods, on floats and 3-vectors
            for i, body in enumerate(self.bodies):
                s, m = int(self.start[i]), body.n_dof
                qb = q[s : s + m]
                Gb[i, :m] += body.own_force(qb)
                Kb[i, :m, :m] += body.own_stiffness(qb)
            return
        z = q[self.start + 2]
        rG = np.einsum("nij,nj->ni", R, self.cg)
        rM = np.einsum("nij,nj->ni", R, self.metacentre)
        Gb[:, :3] += self.weight + self.buoyancy
        Gb[:, 2] -= self.heave * z
        Gb[:, 3:] += cross(rG, self.weight) + cross(rM, self.buoyancy)
        Kb[:, 2, 2] += self.heave
        Kb[:, 3:, 3:] -= skews(self.weight) @ skews(rG) + skews(self.buoyancy) @ skews(rM)

    def _scatter(self, G, K, Gb, Kb):
        if self.rigid.any():
            r6 = self.rows6
            G[r6] += Gb[self.rigid]
            K[r6[:, :, None], r6[:, None, :]] += Kb[self.rigid]
        if (~self.rigid).any():
            r3 = self.rows3
            G[r3] += Gb[~self.rigid, :3]
            K[r3[:, :, None], r3[:, None, :]] += Kb[~self.rigid, :3, :3]
