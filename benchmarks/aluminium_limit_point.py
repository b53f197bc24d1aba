"""Why the aluminium 10.1 mm, damage 1, slip="axis" capacity curve stops (docs/stability.md).

Runs it on the validation settings (1 m, 32 elements, 40 steps), then at the last converged
step prints the force over the last steps, the wire tangents (aluminium's blend softens,
``Material.softening_range``) and the smallest eigenvalues of the free tangent with the
field that carries the lowest mode.

Run:  python benchmarks/aluminium_limit_point.py
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as sla

from skcable import strand


def main():
    s = strand.preset("aluminium-10.1").damaged(1)
    model = strand.StrandModel(s, 1.0, n_elements=32, slip="axis")
    curve = model.capacity_curve(n_steps=40, on_failure="stop")
    print("stop:", curve.failure)
    print("force over the last steps [N]:", np.round(curve.force[-5:], 1))
    last = curve.steps[-1]
    _, K, state = model.assemble(last.dofs, np.asarray(last.slipping))
    tangent = s.material.tangent(state["strain"][model.alive]) / s.material.E_e
    print("softening range of the law:", s.material.softening_range)
    print(f"wire tangent / E_e at the stop: {tangent.min():.4f} to {tangent.max():.4f}")
    free = K[model.free][:, model.free]
    scale = abs(free.diagonal()).max()
    values, vectors = sla.eigsh(free, k=3, sigma=0, which="LM")
    lowest = np.zeros(model.offsets[-1])
    lowest[model.free] = vectors[:, np.argmin(values)]
    shares = {name: float(np.linalg.norm(part) ** 2) for name, part in model.split(lowest).items()}
    print("smallest eigenvalues / largest diagonal entry:", np.sort(values) / scale)
    print("lowest mode's share per field:", {k: round(v, 3) for k, v in shares.items()})


if __name__ == "__main__":
    main()
