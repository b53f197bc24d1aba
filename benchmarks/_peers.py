"""The peer solvers, each as a function returning H, for the benchmark scripts.

Each raises ImportError (or OpenSeesPy's own error) when the peer is not installed.
Inputs: A = (0, 0), B = (span, dh) with y up; w per unstretched length; EA; unstretched length L0.
"""

from __future__ import annotations


def moorpy_H(span, dh, w, EA, L0):
    """MoorPy ``catenary()``; CB < 0 means no seabed within |CB| below A."""
    from moorpy.Catenary import catenary

    if dh >= 0:
        return catenary(span, dh, L0, EA, w, CB=-1e6, Tol=1e-12)[0]
    return catenary(span, -dh, L0, EA, w, CB=-1e6, Tol=1e-12)[0]  # mirrored: B above A


def pycatenary_H(span, dh, w, EA, L0):
    """pycatenary ``MooringLine`` with no floor."""
    from pycatenary.cable import MooringLine

    line = MooringLine(fairlead=[span, dh], anchor=[0.0, 0.0], L=L0, w=w, EA=EA, floor=False)
    line.compute_solution()
    return -line.get_fairlead_force()[0]


def opensees_catenary_cable_H(span, dh, w, EA, L0):
    """OpenSeesPy ``CatenaryCable`` element between two fixed nodes (build + solve)."""
    import openseespy.opensees as ops

    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, span, 0.0, dh)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.element("CatenaryCable", 1, 1, 2, w, EA, 1.0, L0, 0.0, 0.0, 0.0, 1e-10, 100, 0)
    return -ops.eleResponse(1, "globalForce")[0]


def available(function, *args):
    """The callable ``lambda: function(*args)`` if the peer runs here, else None."""
    try:
        function(*args)
    except Exception:  # ImportError, or a shared library missing
        return None
    return lambda: function(*args)
