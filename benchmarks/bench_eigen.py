"""The small eigenproblems against a hand-written scipy solve of the same matrices.

- ``conductors.natural_frequencies(300, 0, 10, 3e7, sag=6)`` (the pinned scene; 287 DOFs a plane)
  and the same with ``n_modes=20`` (959 DOFs): the whole call, static catenary, assembly and
  checks included, against ``scipy.linalg.eigh(K, M, subset_by_index=[0, n - 1])`` (values and
  vectors, as skcable returns both) of its in-plane and out-of-plane matrices
  (``result.stiffness_in_plane``, ``.mass``, ...);
- ``strand.strand_bending_frequencies`` of steel 9.5 mm with one broken wire, 1 kN, 1 m,
  clamped (the pinned scene; 190 DOFs, a stick and a slip solve): the whole call against
  ``eigh`` of the two Hermite-element matrices ``EI K_b + N K_g``, ``m M`` assembled here with
  scikit-fem on the same mesh.

Each measure is timed in this one process, interleaved (skcable, then the hand-written solve),
with the BLAS threads as they come (threadpoolctl reports them) and limited to one; the table
gives the medians of ``--repeats`` runs and their ratio (target: <= 1 on both settings).

Accuracy: the largest relative deviation of each solver's eigenvalues from a 40-digit
Rayleigh-quotient iteration (mpmath, on the band with Sherman-Morrison for the in-plane term)
of the same matrices.

Run:  python benchmarks/bench_eigen.py [--repeats 31] [--no-write]
      writes the section between <!-- eigen:begin --> and <!-- eigen:end --> of
      docs/speed_targets.md (appended if absent; the rest of the page is left as it is)
"""

from __future__ import annotations

import argparse
import functools
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import mpmath as mp
import numpy as np
import scipy
from scipy.linalg import eigh
from skfem import Basis, BilinearForm, ElementLineHermite, MeshLine
from skfem.helpers import dd, ddot
from skfem.models import laplace, mass
from threadpoolctl import threadpool_info, threadpool_limits

from skcable import conductors, strand

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "speed_targets.md"
sys.path.insert(0, str(ROOT / "benchmarks"))

from _tables import write_section  # noqa: E402

STRAND_SCENE = dict(N=1e3, length=1.0, mass_per_length=0.45)


@BilinearForm
def _bending(u, v, p):  # ∫ w'' v'' (the geometric ∫ w' v' and the mass ∫ w v: skfem.models)
    return ddot(dd(u), dd(v))


def cable_case(n_modes):
    """The call, the hand-written solve of the matrices it returns, those matrices as
    (band part, mass, rank-one part or None), and the call's eigenvalues."""

    def call():
        return conductors.natural_frequencies(300.0, 0.0, 10.0, 3e7, sag=6.0, n_modes=n_modes)

    r = call()
    coupling = r.stiffness_in_plane - r.stiffness_out_of_plane
    planes = [(r.stiffness_out_of_plane, r.mass, coupling), (r.stiffness_out_of_plane, r.mass, None)]
    dense = [(r.stiffness_in_plane, r.mass), (r.stiffness_out_of_plane, r.mass)]

    def hand(values_only=False):
        return [eigh(K, M, subset_by_index=[0, n_modes - 1], eigvals_only=values_only) for K, M in dense]

    ours = [(2 * np.pi * r.f_in_plane) ** 2, (2 * np.pi * r.f_out_of_plane) ** 2]
    return call, hand, planes, ours


def strand_case():
    section = strand.preset("steel-9.5").damaged(1).section()

    def call():
        return strand.strand_bending_frequencies(section, **STRAND_SCENE)

    r = call()
    basis = Basis(MeshLine(np.linspace(0.0, STRAND_SCENE["length"], 97)), ElementLineHermite())
    free = basis.complement_dofs(basis.get_dofs().all())
    B, G, M = (form.assemble(basis)[free][:, free].toarray() for form in (_bending, laplace, mass))
    M = STRAND_SCENE["mass_per_length"] * M
    planes = [(EI * B + STRAND_SCENE["N"] * G, M, None) for EI in (section.EI_stick[0], section.EI_slip[0])]

    def hand(values_only=False):
        return [eigh(K, M, subset_by_index=[0, 5], eigvals_only=values_only) for K, M, _ in planes]

    ours = [(2 * np.pi * r.stick.f) ** 2, (2 * np.pi * r.slip.f) ** 2]
    return call, hand, planes, ours


def timed(functions, repeats):
    """Medians (s) of ``functions`` run in turn ``repeats`` times, and the median of the ratios
    of the first to each other in each turn (runs next to each other see the same load on a
    shared machine)."""
    for function in functions:  # warm caches and imports
        function()
    turns = []
    for _ in range(repeats):
        times = []
        for function in functions:
            start = time.perf_counter()
            function()
            times.append(time.perf_counter() - start)
        turns.append(times)
    medians = [statistics.median(column) for column in zip(*turns, strict=True)]
    ratios = [statistics.median(t[0] / t[j] for t in turns) for j in range(1, len(functions))]
    return medians, ratios


# --- the 40-digit reference ------------------------------------------------------------
def _mp_band(A, p):
    """Rows of the band of ``A`` (half-bandwidth ``p``) as dicts column: mpf."""
    n = A.shape[0]
    return [{j: mp.mpf(float(A[i, j])) for j in range(max(0, i - p), min(n, i + p + 1))} for i in range(n)]


def _matvec(rows, x):
    return [mp.fsum(v * x[j] for j, v in row.items()) for row in rows]


def _band_solve(rows, rhs, p):
    """Gaussian elimination on the band, without pivoting (40 digits absorb its growth)."""
    n = len(rows)
    rows = [dict(row) for row in rows]
    x = list(rhs)
    for k in range(n):
        for i in range(k + 1, min(n, k + p + 1)):
            factor = rows[i][k] / rows[k][k]
            for j in range(k, min(n, k + p + 1)):
                rows[i][j] -= factor * rows[k][j]
            x[i] -= factor * x[k]
    for k in range(n - 1, -1, -1):
        x[k] = (x[k] - mp.fsum(v * x[j] for j, v in rows[k].items() if j > k)) / rows[k][k]
    return x


def reference(K, M, start, p):
    """Eigenvalues of (K, M) to 40 digits: Rayleigh-quotient iteration on the band from
    ``start`` (eigenvalues, vectors)."""
    with mp.workdps(40):
        Kr, Mr = _mp_band(K, p), _mp_band(M, p)
        out = []
        for value, vector in zip(*start, strict=True):
            x, mu = [mp.mpf(float(v)) for v in vector], mp.mpf(float(value))
            for _ in range(3):
                rows = [{j: Kr[i][j] - mu * Mr[i][j] for j in Kr[i]} for i in range(len(Kr))]
                y = _band_solve(rows, _matvec(Mr, x), p)
                norm = mp.sqrt(mp.fsum(u * v for u, v in zip(y, _matvec(Mr, y), strict=True)))
                x = [u / norm for u in y]
                mu = mp.fsum(u * v for u, v in zip(x, _matvec(Kr, x), strict=True))
            out.append(mu)
        return np.array([float(v) for v in out])


def deviations(planes, ours, p):
    """Largest relative deviation of skcable's and the hand-written eigenvalues from the 40-digit
    reference on the band planes, and between the two solvers on a plane with a rank-one term
    (``K + coupling``, rounded, is no band plus an exact rank one that the reference could take)."""
    from_reference, between = [0.0, 0.0], 0.0
    for (K, M, coupling), lam in zip(planes, ours, strict=True):
        full = K if coupling is None else K + coupling
        hand, vectors = eigh(full, M, subset_by_index=[0, len(lam) - 1])
        if coupling is not None:
            between = max(between, float(np.max(np.abs(lam / hand - 1))))
            continue
        exact = reference(K, M, (hand, vectors.T), p)
        from_reference[0] = max(from_reference[0], float(np.max(np.abs(lam / exact - 1))))
        from_reference[1] = max(from_reference[1], float(np.max(np.abs(hand / exact - 1))))
    return (*from_reference, between)


CASES = {
    "`natural_frequencies(300, 0, 10, 3e7, sag=6)`, 2 × 287 DOFs, 6 modes": (lambda: cable_case(6), 2),
    "the same, `n_modes=20`, 2 × 959 DOFs": (lambda: cable_case(20), 2),
    "`strand_bending_frequencies`, steel 9.5 d1, 1 kN, 1 m, 2 × 190 DOFs": (strand_case, 3),
}


def measure(repeats, accuracy=True):
    """Rows of the table: (case, threads, skcable s, hand s, ratio), and the accuracy rows."""
    default = max((lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"), default=1)
    rows, accurate = [], []
    for name, (make, p) in CASES.items():
        call, hand, planes, ours = make()
        for label, limit in ((f"default ({default})", None), ("1", 1)):
            with threadpool_limits(limit):
                (t_call, t_vectors, t_values), ratios = timed(
                    [call, hand, functools.partial(hand, True)], repeats
                )
            rows.append((name, label, t_call, t_vectors, ratios[0], t_values, ratios[1]))
        if accuracy:
            accurate.append((name, *deviations(planes, ours, p)))
    return rows, accurate


def render(rows, accurate, repeats):
    lines = [
        "## Small eigenproblems",
        "",
        f"Generated by `python benchmarks/bench_eigen.py --repeats {repeats}` on {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}, NumPy {np.__version__}, SciPy "
        f"{scipy.__version__}: medians of {repeats} runs in one process, skcable and the hand-written solves "
        "in turn; each ratio is the median of skcable's time over the other's in each turn. The "
        "hand-written solve is `scipy.linalg.eigh(K, M, subset_by_index=[0, n - 1])` of the same "
        "matrices, one call a stiffness, with its eigenvectors (skcable returns the mode shapes) and "
        "without; skcable's time is the whole call (static state, assembly, solve, checks). Target: "
        "ratio <= 1 on every thread setting.",
        "",
        "| call | BLAS threads | skcable | `eigh`, with vectors | ratio | `eigh`, values only | ratio |",
        "|---|---|---|---|---|---|---|",
    ]
    lines += [
        f"| {n} | {t} | {1e3 * a:.2f} ms | {1e3 * b:.2f} ms | {r:.2f} | {1e3 * c:.2f} ms | {q:.2f} |"
        for n, t, a, b, r, c, q in rows
    ]
    if accurate:
        lines += [
            "",
            "Accuracy: the largest relative deviation of the eigenvalues from a 40-digit Rayleigh-quotient "
            "iteration (mpmath) on the band of the same matrices (the cable: its out-of-plane plane); "
            "the in-plane cable stiffness, a band plus a rounded rank-one term, is compared between the "
            "two solvers.",
            "",
            "| call | skcable | hand-written `eigh` | in plane, skcable against `eigh` |",
            "|---|---|---|---|",
        ]
        lines += [f"| {n} | {a:.1e} | {b:.1e} | {f'{c:.1e}' if c else '-'} |" for n, a, b, c in accurate]
    return "\n".join(lines) + "\n"


def write_docs(text):
    """The section between the markers replaced (appended with them where absent), atomically
    (`_tables.write_section`)."""
    notice = "<!-- written by benchmarks/bench_eigen.py: do not edit by hand -->"
    write_section(DOCS, "eigen", [notice, "", *text.rstrip("\n").split("\n")])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=31, help="interleaved runs per measure (default: 31)")
    parser.add_argument("--no-accuracy", action="store_true", help="skip the 40-digit reference (a minute)")
    parser.add_argument("--no-write", action="store_true", help="print only, leave docs/speed_targets.md")
    args = parser.parse_args(argv)
    text = render(*measure(args.repeats, not args.no_accuracy), args.repeats)
    print(text)
    if not args.no_write:
        write_docs(text)


if __name__ == "__main__":
    main()
