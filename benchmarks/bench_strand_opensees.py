"""The stick strand model beside OpenSeesPy's equivalent: displacement-based fibre beams.

Steel 9.5 mm, one broken wire, 1 m, clamped at x = 0 and clamped but pulled axially at x = L.
OpenSeesPy: ``dispBeamColumn`` elements (3 Gauss-Legendre points), ``Corotational``
transformation, a fibre section per element with one fibre per intact wire at its helical
position at the element's mid-length (so the section turns with the lay from element to
element), fibre area A cos³α (the wires' axial stiffness along the strand), ``Steel01``
(E_e, yield stress E_e·ε_y, hardening E_p/E_e: the bilinear law without skcable's cubic
blend and without the wire strain factor cos²α), torsion GJ of the wires; imposed end
displacement in the same number of steps with Newton (``DisplacementControl``).
skcable: ``StrandModel(slip="none")`` on the same number of elements.

Both are timed building and solving one capacity curve to the rupture strain (40 steps;
best of 3) in this process. K_Leq: skcable's ``curve.K_Leq`` (secant where the most strained
wire reaches eps_y1); for OpenSees the secant at strand strain eps_y1. Both are also compared
at the same strand strain, 0.003, well inside the elastic range.

Run:  python benchmarks/bench_strand_opensees.py   (needs openseespy: pip install ".[bench]")
"""

from __future__ import annotations

import time

import numpy as np

from skcable import strand

STRAND = strand.preset("steel-9.5").damaged(1)
LENGTH, STEPS = 1.0, 40
TOP = 0.94 * STRAND.material.eps_rupture  # skcable's curve ruptures at 0.0772


def opensees_curve(n_elements, n_steps=STEPS, top=TOP):
    import openseespy.opensees as ops

    material, wires = STRAND.material, STRAND.wires()
    lay = STRAND.lay_lengths[0]
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    x = np.linspace(0.0, LENGTH, n_elements + 1)
    for i, xi in enumerate(x):
        ops.node(i + 1, xi, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(n_elements + 1, 0, 1, 1, 1, 1, 1)
    ops.uniaxialMaterial(
        "Steel01", 1, material.E_e * material.eps_y, material.E_e, material.E_p / material.E_e
    )
    cos = np.cos(wires.lay_angle)
    GJ = float(np.sum(np.where(wires.intact, material.G * 2 * wires.inertia * cos, 0.0)))
    ops.geomTransf("Corotational", 1, 0.0, 0.0, 1.0)
    for e in range(n_elements):
        mid = 0.5 * (x[e] + x[e + 1])
        psi = wires.psi + wires.direction * 2 * np.pi * mid / lay
        ops.section("Fiber", e + 1, "-GJ", GJ, "-noCentroid")  # the core is the beam axis
        for j in np.flatnonzero(wires.intact):
            y, z = wires.radius[j] * np.sin(psi[j]), wires.radius[j] * np.cos(psi[j])
            ops.fiber(y, z, wires.area[j] * cos[j] ** 3, 1)
        ops.beamIntegration("Legendre", e + 1, e + 1, 3)
        ops.element("dispBeamColumn", e + 1, e + 1, e + 2, 1, e + 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(n_elements + 1, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    ops.system("BandGeneral")
    ops.numberer("RCM")
    ops.constraints("Plain")
    ops.test("NormDispIncr", 1e-10, 50)
    ops.algorithm("Newton")
    ops.integrator("DisplacementControl", n_elements + 1, 1, top * LENGTH / n_steps)
    ops.analysis("Static")
    strain, force = [0.0], [0.0]
    for _ in range(n_steps):
        if ops.analyze(1) != 0:
            raise RuntimeError(f"OpenSees: no convergence after strain {strain[-1]:.4g}")
        ops.reactions()
        strain.append(ops.nodeDisp(n_elements + 1, 1) / LENGTH)
        force.append(-ops.nodeReaction(1, 1))
    return np.array(strain), np.array(force)


def skcable_curve(n_elements, n_steps=STEPS, top=TOP):
    model = strand.StrandModel(STRAND, LENGTH, n_elements=n_elements, slip="none")
    return model.capacity_curve(max_strain=top, n_steps=n_steps)


def secant_at(strain, force, limit):
    """Secant F/ε where the most strained wire (the core: ε itself) reaches ``limit``, interpolated."""
    return float(np.interp(limit, strain, force) / limit)


def best_time(fn, *args, repeat=3):
    best, out = np.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn(*args)
        best = min(best, time.perf_counter() - start)
    return best, out


def main():
    head = [
        "elements",
        "skcable [s]",
        "OpenSeesPy [s]",
        "OpenSees / skcable",
        "K_Leq skcable [kN]",
        "K_Leq OpenSees [kN]",
        "F/ε at 0.003 skcable [kN]",
        "F/ε at 0.003 OpenSees [kN]",
    ]
    print("| " + " | ".join(head) + " |")
    print("|---" * len(head) + "|")
    limit = STRAND.material.eps_y1
    for n in (16, 32, 64, 128, 256, 512):
        t_sk, curve = best_time(skcable_curve, n)
        t_os, (strain, force) = best_time(opensees_curve, n)
        K_os = secant_at(strain, force, limit)
        cells = [
            n,
            f"{t_sk:.2f}",
            f"{t_os:.2f}",
            f"{t_os / t_sk:.2f}",
            f"{curve.K_Leq / 1e3:.1f}",
            f"{K_os / 1e3:.1f}",
            f"{secant_at(curve.strain, curve.force, 0.003) / 1e3:.1f}",
            f"{secant_at(strain, force, 0.003) / 1e3:.1f}",
        ]
        print("| " + " | ".join(str(c) for c in cells) + " |")
    end = f"skcable {curve.force[-1] / 1e3:.2f} kN, OpenSees {force[-1] / 1e3:.2f} kN"
    print(f"force at strain {TOP:.4f} on {n} elements: {end}")
    # the headline: equal accuracy in F/ε(0.003) (0.5 %) takes 32 elements in skcable, 64 in OpenSees
    t_stick, _ = best_time(skcable_curve, 32)
    t_element, _ = best_time(
        lambda: strand.StrandModel(STRAND, LENGTH, n_elements=32, slip="element").capacity_curve(
            max_strain=TOP, n_steps=STEPS
        )
    )
    t_os, _ = best_time(opensees_curve, 64)
    print(
        f"equal accuracy: skcable stick 32 el. {t_stick:.3f} s, OpenSeesPy 64 el. {t_os:.3f} s: "
        f"time ratio skcable/OpenSees = {t_stick / t_os:.2f}; element rule {t_element:.3f} s "
        f"({t_element / t_stick:.2f}x stick)"
    )


if __name__ == "__main__":
    main()
