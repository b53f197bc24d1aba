r"""The weak forms of both cable formulations, as scikit-fem forms.

These are the reference: `skcable.bvp.graph` and
`skcable.bvp.arc` assemble the same integrals with basis values
computed once (`skcable.fe.Assembly`), and
``tests/bvp/test_bvp.py`` / ``test_arc.py`` check that both ways agree to
round-off. A user adding a term can prototype it here with ``asm``.

Graph form (unknown ``u = y - s x``, ``s = dh/span``; ``w.q`` the downward
load per horizontal length, ``w.dq_dslope``, ``w.dq_dH`` its derivatives):

.. math:: R = \int (H y' v' + q v)\,dx, \quad
          \partial R/\partial y = \int (H u' v' + q_{,y'} u' v)\,dx, \quad
          \partial R/\partial H = \int (y' v' + q_{,H} v)\,dx.

Arc form (fields x, y, T of σ; ``e = r'/|r'|``, ``n = |r'|``, ``Q`` the
load per unit σ): `arc_equilibrium_x`, `arc_equilibrium_y`,
`arc_constitutive` and the blocks of their tangent.
"""

from __future__ import annotations

from skfem import BilinearForm, LinearForm

__all__ = [
    "arc_constitutive",
    "arc_constitutive_dL0",
    "arc_equilibrium_x",
    "arc_equilibrium_y",
    "arc_geometric",
    "arc_load_dL0",
    "arc_load_position",
    "arc_tension_coupling",
    "arc_tension_mass",
    "graph_dH",
    "graph_length_gradient",
    "graph_residual",
    "graph_tangent",
]


# --- graph form ----------------------------------------------------------------
@LinearForm
def graph_residual(v, w):
    """``∫ (H y' v' + q v) dx``, ``y' = s + u'``: the weak equilibrium of the graph form."""
    return w.H * (w.s + w.u.grad[0]) * v.grad[0] + w.q * v


@BilinearForm
def graph_tangent(u, v, w):
    """``∂R/∂y``: ``∫ (H u' v' + dq/dy' u' v) dx``."""
    return w.H * u.grad[0] * v.grad[0] + w.dq_dslope * u.grad[0] * v


@LinearForm
def graph_dH(v, w):
    """``∂R/∂H``: ``∫ (y' v' + dq/dH v) dx``."""
    return (w.s + w.u.grad[0]) * v.grad[0] + w.dq_dH * v


@LinearForm
def graph_length_gradient(v, w):
    """``∂/∂y ∫ f(y') dx = ∫ f'(y') v' dx`` (the length constraint's row; ``w.df_ds = f'``)."""
    return w.df_ds * v.grad[0]


# --- arc form ------------------------------------------------------------------
@LinearForm
def arc_equilibrium_x(v, w):
    """``∫ (T e_x v' - Q_x v) dσ``."""
    return w.T * w.ex * v.grad[0] - w.Qx * v


@LinearForm
def arc_equilibrium_y(v, w):
    """``∫ (T e_y v' - Q_y v) dσ``."""
    return w.T * w.ey * v.grad[0] - w.Qy * v


@LinearForm
def arc_constitutive(v, w):
    """``∫ (n - L0 (1 + T/EA)) v dσ``."""
    return (w.n - w.L0 * (1.0 + w.T * w.compliance)) * v


@BilinearForm
def arc_geometric(u, v, w):
    """``∫ T (δ_ij - e_i e_j) / n u' v'`` for the (i, j) block given as w.P."""
    return w.T * w.P / w.n * u.grad[0] * v.grad[0]


@BilinearForm
def arc_load_position(u, v, w):
    """``-∫ (dQ_i/dx u + dQ_i/dx' u') v``."""
    return -(w.dQ_dx * u + w.dQ_dxp * u.grad[0]) * v


@BilinearForm
def arc_tension_coupling(u, v, w):
    """``∫ u e_i v'``: tension trial u, position test v."""
    return u * w.e * v.grad[0]


@BilinearForm
def arc_tension_mass(u, v, w):
    """``-∫ L0/EA u v``."""
    return -w.L0 * w.compliance * u * v


@LinearForm
def arc_load_dL0(v, w):
    """``∂R_i/∂L0`` of an equilibrium row: ``-∫ dQ_i/dL0 v``."""
    return -w.d * v


@LinearForm
def arc_constitutive_dL0(v, w):
    """``∂R_c/∂L0``: ``-∫ (1 + T/EA) v``."""
    return -(1.0 + w.T * w.compliance) * v
