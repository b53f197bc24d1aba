"""Figures of results: matplotlib for curves, pyvista (off screen) for the deformed strand.

Every function draws on the given ``ax`` (or a new figure) and returns the
axes, so figures compose; `render_strand` writes a PNG. SI units on
the axes (the strain is dimensionless, forces in kN for readability).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from skcable._checks import positive
from skcable.errors import InputError

__all__ = [
    "cable_profile",
    "capacity_curves",
    "curvature_along",
    "moment_curvature",
    "mooring_overview",
    "mooring_plan",
    "mooring_profiles",
    "render_strand",
    "secant_stiffness",
    "slip_fraction",
    "strand_caption",
]


def _axes(ax):
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    return plt.figure(figsize=(6.4, 4.0), layout="constrained").add_subplot()


def _labels(items, labels):
    if labels is None:
        return [None] * len(items)
    if len(labels) != len(items):
        raise InputError("labels", f"needs one label per curve: {len(items)}, got {len(labels)}")
    return list(labels)


def cable_profile(solution, ax=None, *, n: int = 201, tension: bool = True):
    """Profile y(x) of a cable solution (m) and, on its own axis (right, from 0), its tension (kN);
    one legend names the three curves.

    The tension axis starts at 0: on a catenary the tension is linear in the height
    (``T = H + w (y - y_0)``), and a twin axis scaled to its own range drew it exactly on the
    profile."""
    ax = _axes(ax)
    samples = solution.samples(n)
    x, y = samples["xy"].T
    lines = ax.plot(x, y, color="C0", label="profile y(x)")
    lines += ax.plot([0, float(solution.span)], [0, float(solution.dh)], ":", color="0.5", label="chord")
    ax.set(xlabel="x [m]", ylabel="y [m]")
    if tension:
        twin = ax.twinx()
        T = samples["tension"] / 1e3
        lines += twin.plot(x, T, "--", color="C3", label="tension T(x) (right axis)")
        twin.set_ylim(0.0, 1.15 * float(np.max(T)))
        twin.set_ylabel("tension [kN]", color="C3")
        twin.tick_params(axis="y", colors="C3")
    ax.legend(lines, [line.get_label() for line in lines], loc="lower right")
    return ax


def capacity_curves(curves, labels=None, ax=None):
    """Axial force (kN) against imposed axial strain of one or more capacity curves."""
    curves = list(curves)
    ax = _axes(ax)
    for curve, label in zip(curves, _labels(curves, labels), strict=True):
        ax.plot(curve.strain, curve.force / 1e3, label=label or _describe(curve))
        if curve.ruptured:
            ax.plot(curve.strain[-1], curve.force[-1] / 1e3, "x", color=ax.lines[-1].get_color())
    ax.set(xlabel="axial strain [-]", ylabel="axial force [kN]", title="capacity curve (x: rupture)")
    ax.legend()
    return ax


def slip_fraction(curves, labels=None, ax=None):
    """Fraction of the strand length in slip (%) against axial strain."""
    curves = list(curves)
    ax = _axes(ax)
    for curve, label in zip(curves, _labels(curves, labels), strict=True):
        ax.plot(curve.strain, 100 * curve.slip_fraction, label=label or _describe(curve))
    ax.set(xlabel="axial strain [-]", ylabel="length in slip [%]", ylim=(-2, 102))
    ax.legend()
    return ax


def secant_stiffness(curves, labels=None, ax=None, *, at: float | None = None):
    """Secant stiffness F/(EA ε) against the axial strain (log scale) of
    capacity curves, with the fraction of the length in slip (%, dashed, right axis) and the
    strain where each slipping strand re-sticks (dotted, `CapacityCurve.restick`).

    ``EA`` is each curve's model's (the damaged section's), so 1 is a straight strand that
    does not bend; the value is ``curve.secant(ε) / EA`` (eq. 4.30 over ``[0, ε]``, Pino Vidal
    2021). Slipping wires soften the strand at small strain, where the stick and stick–slip
    force curves lie on top of each other. ``at``: a strain at which the value of every curve
    that reaches it is marked and printed in the legend.
    """
    curves = list(curves)
    ax = _axes(ax)
    twin = None
    for curve, label in zip(curves, _labels(curves, labels), strict=True):
        label = label or _describe(curve)
        eps, EA = curve.strain[1:], curve.model.EA
        reached = at is not None and eps.size > 0 and 0 < at <= eps[-1]
        if reached:
            label += f": {curve.secant(at) / EA:.3f} at ε = {at:g}"
        (line,) = ax.plot(eps, [curve.secant(e) / EA for e in eps], label=label)
        colour = line.get_color()
        if reached:
            ax.plot(at, curve.secant(at) / EA, "o", color=colour)
        if np.max(curve.slip_fraction) > 0:
            twin = twin or ax.twinx()
            twin.plot(eps, 100 * curve.slip_fraction[1:], "--", color=colour, lw=1)
        found = curve.restick()
        if found is not None:
            ax.axvline(found.strain_after, color=colour, ls=":", lw=1)
            ax.annotate(
                f"re-sticks: slip {100 * found.fraction_before:.0f} % → {100 * found.fraction_after:.0f} %"
                f"\nat ε = {found.strain_before:.4f}–{found.strain_after:.4f}",
                (found.strain_after, 0.05),
                xycoords=("data", "axes fraction"),
                xytext=(-4, 0),
                textcoords="offset points",
                ha="right",
                fontsize="small",
                color=colour,
            )
    if twin is not None:
        twin.set(ylabel="length in slip [%] (dashed)", ylim=(-2, 102))
    ax.set(
        xscale="log",
        xlabel="axial strain [-]",
        ylabel="secant stiffness F / (EA ε) [-]",
        title="slip softens the strand at small strain",
    )
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="lower left", fontsize="small")
    return ax


def curvature_along(curve, step: int = -1, ax=None):
    """Principal curvatures (1/m) along the strand at one step, with ±κ_m."""
    ax = _axes(ax)
    result = curve.steps[step]
    x = result.x.ravel()
    order = np.argsort(x)
    for axis in (0, 1):
        line = ax.plot(x[order], result.curvature[axis].ravel()[order], label=f"κ about axis {axis + 1}")
        ax.plot(x[order], result.kappa_m[axis].ravel()[order], "--", color=line[0].get_color(), lw=0.8)
    ax.set(xlabel="x [m]", ylabel="curvature [1/m]", title=f"axial strain {result.strain:.4g} (dashed: κ_m)")
    ax.legend()
    return ax


def moment_curvature(law, kappa=None, ax=None):
    """Bending moment (N·m) against curvature (1/m) about both principal axes of a BendingLaw."""
    ax = _axes(ax)
    if kappa is None:
        kappa = np.linspace(0.0, 4.0 * float(np.max(law.kappa_m)), 401)
    for axis in (0, 1):
        ax.plot(kappa, law.moment(kappa, axis), label=f"axis {axis + 1}")
    ax.set(xlabel="curvature [1/m]", ylabel="moment [N·m]")
    ax.legend()
    return ax


def _describe(curve) -> str:
    model = curve.model
    names = {"none": "stick", "axis": "stick–slip (axis)", "element": "stick–slip (element)"}
    return names.get(model.slip.name, f"stick–slip ({model.slip!r})")


def strand_caption(scale: float, xscale: float, strain: float) -> str:
    """The caption `render_strand` prints on its picture: the scales it drew at, the strain."""
    if scale == 1.0 and xscale == 1.0:
        scales = "true scale"
    else:
        scales = f"not to scale: length x {xscale:g}, displacements x {scale:g}"
    return f"{scales}; axial strain {strain:.4g}; colour: wire stress [MPa], broken wires grey"


def render_strand(
    curve, path, *, step: int = -1, scale: float = 10.0, xscale: float = 0.05, window=(1600, 600)
) -> Path:
    """Off-screen pyvista picture of the wires on the deformed axis, coloured by
    wire stress, broken wires grey; written atomically as a PNG, returns its path.

    ``scale`` magnifies the displacements, ``xscale`` shortens the axis so that a
    metre-long strand of a few millimetres fits one picture: both are printed on the
    picture (`strand_caption`; ``scale = xscale = 1`` is true scale) and kept in the PNG's
    ``Description`` text.
    """
    import matplotlib.image
    import pyvista as pv
    from vtkmodules.vtkCommonCore import vtkLogger

    from skcable.io._atomic import atomic_path

    positive("scale", scale)
    positive("xscale", xscale)
    # without a display VTK tries X first and warns before falling back to off-screen
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)

    wires = curve.step_mesh(step, wires=True, scale=scale)
    segments = wires.cells[0].data
    broken = wires.cell_data["broken"][0].astype(bool)
    stress = wires.cell_data["wire_stress_MPa"][0]
    radius = float(np.min(curve.steps[step].layout.wire_size))
    plotter = pv.Plotter(off_screen=True, window_size=list(window))
    for chosen, style in (
        (~broken, {"scalars": "wire stress [MPa]"}),
        (broken, {"color": "grey", "opacity": 0.4}),
    ):
        if not np.any(chosen):
            continue
        lines = np.column_stack([np.full(chosen.sum(), 2), segments[chosen]]).ravel()
        tubes = pv.PolyData(wires.points * [xscale, 1.0, 1.0], lines=lines)
        tubes.cell_data["wire stress [MPa]"] = stress[chosen]
        plotter.add_mesh(tubes.tube(radius=radius), **style)
    caption = strand_caption(scale, xscale, curve.steps[step].strain)
    plotter.add_text(caption, position="upper_left", font_size=10, color="black", name="caption")
    plotter.view_xy()
    plotter.camera.elevation = 20
    plotter.enable_parallel_projection()
    plotter.reset_camera(bounds=None)
    plotter.camera.zoom(1.6)
    image = plotter.screenshot(None, return_img=True)
    plotter.close()
    path = Path(path)
    with atomic_path(path) as temp:
        matplotlib.image.imsave(temp, image, format="png", metadata={"Description": caption})
    return path


def _line_frame(line):
    """A solved line's first end and its horizontal unit vector towards the other end."""
    start = getattr(line, "a", None)
    start = line.anchor if start is None else start
    return np.asarray(start, dtype=float), np.asarray(line.direction, dtype=float)


def _numbered_lines(result) -> list:
    """``(number in the system, line)`` of each line of ``result``; `InputError` if it has none."""
    lines = list(result.lines)
    if not lines:
        raise InputError("result", "has no lines to plot")
    return list(zip(getattr(result, "line_indices", range(len(lines))), lines, strict=True))


def _largest_tension(line) -> float:
    ends = getattr(line, "end_forces", None)
    ends = np.array([line.force_on_anchor, line.force_on_fairlead]) if ends is None else ends
    return float(np.linalg.norm(ends, axis=1).max())


def mooring_profiles(result, ax=None, *, n: int = 201, depth=None):
    """Profile of each line of a mooring system in its own vertical plane: height z (m) against the
    horizontal distance from its first end (its anchor, or end a) (m), coloured by line, with the
    seabed (``result.depth``, or ``depth``) as a line. Reads ``result.lines`` (each line's
    ``profile(n)``, its first end and ``direction``, its end forces)."""
    ax = _axes(ax)
    depth = getattr(result, "depth", None) if depth is None else depth
    reach = 0.0
    for i, line in _numbered_lines(result):
        xyz = line.profile(n)
        start, e = _line_frame(line)
        r = (xyz[:, :2] - start[:2]) @ e[:2]
        reach = max(reach, float(r.max()))
        ax.plot(
            r, xyz[:, 2], color=f"C{i % 10}", label=f"line {i}: T_max = {_largest_tension(line) / 1e3:.0f} kN"
        )
    if depth is not None:
        ax.axhline(-float(depth), color="0.4", lw=0.8, ls="--", label="seabed")
    ax.set(xlabel="horizontal distance along the line [m]", ylabel="z [m]", xlim=(0.0, 1.02 * reach))
    ax.legend(loc="upper left", fontsize="small")
    return ax


def mooring_plan(result, ax=None, *, n: int = 101):
    """Plan view of a mooring system at equilibrium: each line from above (coloured by line, its
    grounded part drawn thicker where it lies on the seabed), the anchors (triangles), the free
    points (circles) and each body's points (joined around its reference point, a cross), in m.
    Reads ``result.lines`` (``profile(n)``), ``result.points`` and ``result.bodies``."""
    ax = _axes(ax)
    depth = getattr(result, "depth", None)
    for i, line in _numbered_lines(result):
        xyz = line.profile(n)
        ax.plot(xyz[:, 0], xyz[:, 1], color=f"C{i % 10}", lw=1.2, label=f"line {i}")
        if depth is not None:
            down = np.abs(xyz[:, 2] + float(depth)) < 1e-6 * max(1.0, float(depth))
            ax.plot(
                np.where(down, xyz[:, 0], np.nan),
                np.where(down, xyz[:, 1], np.nan),
                color=f"C{i % 10}",
                lw=3.0,
            )
    points = list(getattr(result, "points", []))
    for kind, marker, label in (("fixed", "^", "anchors"), ("free", "o", "free points")):
        xy = np.array([p.position[:2] for p in points if p.kind == kind]).reshape(-1, 2)
        if len(xy):
            ax.plot(xy[:, 0], xy[:, 1], marker, color="k", ms=5, ls="none", label=label)
    for state in getattr(result, "bodies", []):
        ax.plot(*state.offset[:2], "x", color="k", ms=8)
        local = np.asarray(getattr(state, "local_points", np.zeros((0, 3))))
        if len(local) > 1:
            xy = (state.offset + local @ np.asarray(state.rotation).T)[:, :2]
            order = np.argsort(np.arctan2(*(xy - state.offset[:2]).T[::-1]))
            ring = xy[np.r_[order, order[:1]]]
            ax.plot(ring[:, 0], ring[:, 1], color="0.2", lw=1.0)
    ax.set(xlabel="x [m]", ylabel="y [m]", aspect="equal")
    ax.legend(loc="best", fontsize="small")
    return ax


def mooring_overview(result, *, n: int = 101):
    """A figure of a mooring system at equilibrium: its plan view (`mooring_plan`) beside the lines'
    profiles (`mooring_profiles`); returns the figure."""
    import matplotlib.pyplot as plt

    fig, (plan, side) = plt.subplots(1, 2, figsize=(12.0, 5.0))
    mooring_plan(result, plan, n=n)
    mooring_profiles(result, side, n=n)
    fig.tight_layout()
    return fig
