"""Command line: ``skcable demo`` (the README's main job) and closed-form solvers.

Bad arguments print a one-line message naming the argument and exit with
status 2, with no traceback.
"""

from __future__ import annotations

import argparse
import json
import sys

from skcable import cable
from skcable.errors import ConvergenceError, InputError

#: Seed worked examples: (label, published value, function returning ours).
_DEMO = [
    (
        "000 ex.1 funicular T1 [kN]",
        233.04,
        lambda: cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]).T[0],
    ),
    (
        "000 ex.2 H [kN]",
        28.511,
        lambda: cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5)).H,
    ),
    ("000 ex.3 parabola H [kN]", 85743.7, lambda: cable.parabola(800, -20, 20, low=-30).H),
    ("000 ex.3 parabola S [m]", 801.408, lambda: cable.parabola(800, -20, 20, low=-30).length),
    ("000 ex.4 catenary H [kN]", 85818.7, lambda: cable.catenary(800, -20, 20, low=-30).H),
    ("000 ex.4 catenary T_A [kN]", 86418.7, lambda: cable.catenary(800, -20, 20, low=-30).T_A),
    ("000 ex.4 catenary S [m]", 801.409, lambda: cable.catenary(800, -20, 20, low=-30).length),
    ("001 ex.4 parabola Tmax [kg]", 269.26, lambda: cable.parabola(200, 0, 1, sag=20).T_max),
    ("001 ex.5 catenary T0 [kg]", 253.2649, lambda: cable.catenary(200, 0, 1, sag=20).H),
    ("001 ex.5 catenary S [m]", 205.2374, lambda: cable.catenary(200, 0, 1, sag=20).length),
]


def _demo(args) -> int:
    print(f"{'seed example':32s} {'published':>12s} {'skcable':>16s} {'rel. diff':>10s}")
    for label, published, compute in _DEMO:
        ours = float(compute())
        print(f"{label:32s} {published:12.6g} {ours:16.10g} {abs(ours / published - 1):10.1e}")
    print("(000 ex.4: the seed stopped its iteration early; full precision gives H = 85819.2 kN)")
    return 0


def _closed_form(args) -> int:
    constraint = {k: getattr(args, k) for k in ("length", "sag", "H", "low", "T_max")}
    constraint = {k: v for k, v in constraint.items() if v is not None}
    solver = {"catenary": cable.catenary, "parabola": cable.parabola}[args.command]
    sol = solver(args.span, args.dh, args.w, **constraint)
    fields = ("H", "V_A", "V_B", "T_A", "T_B", "length", "sag", "x_low", "y_low")
    values = {k: float(getattr(sol, k)) for k in fields} | {"residual": sol.residual()}
    if args.json:
        print(json.dumps(values))
    else:
        for k, v in values.items():
            print(f"{k:>9s} = {v:.10g}")
    return 0


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="skcable", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command")
    sub.add_parser("demo", help="seed worked examples: published values beside skcable's")
    for name in ("catenary", "parabola"):
        p = sub.add_parser(name, help=f"closed-form {name}")
        p.add_argument("--span", type=float, required=True)
        p.add_argument("--dh", type=float, default=0.0)
        p.add_argument("--w", type=float, required=True)
        for key in ("length", "sag", "H", "low", "T_max"):
            p.add_argument(f"--{key.replace('_', '-')}", dest=key, type=float)
        p.add_argument("--json", action="store_true")
    return parser


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.command in (None, "demo"):
            return _demo(args)
        return _closed_form(args)
    except (InputError, ConvergenceError) as exc:
        print(f"skcable: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
