"""``skcable examples`` (also ``seeds``): the sources' worked examples beside skcable's values."""

from __future__ import annotations

__all__ = ["GOICOLEA", "NOTES", "PINO_VIDAL", "register"]

NOTES = 'the lecture notes "Cables"'
GOICOLEA = 'J.M. Goicolea, "Cálculo de cables", UPM, 2012'
PINO_VIDAL = 'S. Pino Vidal, "Rigidez a flexión en cables: análisis numérico", Universidad de Chile, 2021'


def _examples():
    """Worked examples of the sources: (source, label, published value, function returning ours)."""
    from skcable import cable

    return [
        (
            NOTES,
            "ex. 1 funicular T1 [kN]",
            233.04,
            lambda: cable.funicular((20, 2), [5, 6, 6, 5], [(5, -75), (10, -100), (5, -75)]).T[0],
        ),
        (
            NOTES,
            "ex. 2 funicular H [kN]",
            28.511,
            lambda: cable.funicular_vertical(10, -1, [(1, 50), (3, 30), (7, 40)], through=(3, -5)).H,
        ),
        (NOTES, "ex. 3 parabola H [kN]", 85743.7, lambda: cable.parabola(800, -20, 20, low=-30).H),
        (NOTES, "ex. 3 parabola S [m]", 801.408, lambda: cable.parabola(800, -20, 20, low=-30).length),
        (NOTES, "ex. 4 catenary H [kN]", 85818.7, lambda: cable.catenary(800, -20, 20, low=-30).H),
        (NOTES, "ex. 4 catenary T_A [kN]", 86418.7, lambda: cable.catenary(800, -20, 20, low=-30).T_A),
        (NOTES, "ex. 4 catenary S [m]", 801.409, lambda: cable.catenary(800, -20, 20, low=-30).length),
        (GOICOLEA, "ex. 4 parabola Tmax [kg]", 269.26, lambda: cable.parabola(200, 0, 1, sag=20).T_max),
        (GOICOLEA, "ex. 5 catenary T0 [kg]", 253.2649, lambda: cable.catenary(200, 0, 1, sag=20).H),
        (GOICOLEA, "ex. 5 catenary S [m]", 205.2374, lambda: cable.catenary(200, 0, 1, sag=20).length),
    ]


def _run(args) -> int:
    from skcable.cli._status import EXIT_OK

    print(f"{'worked example':28s} {'published':>12s} {'skcable':>16s} {'rel. diff':>10s}")
    source = None
    for where, label, published, compute in _examples():
        if where != source:
            source = where
            print(f"{source[0].upper()}{source[1:]}:")
        ours = float(compute())
        print(f"  {label:26s} {published:12.10g} {ours:16.10g} {abs(ours / published - 1):10.1e}")
    note = "ex. 4: the published iteration stopped early; full precision gives H = 85819.2 kN"
    print(f"({NOTES[0].upper()}{NOTES[1:]}, {note})")
    return EXIT_OK


def register(sub, command) -> None:
    command(
        sub,
        "examples",
        _run,
        f"worked examples of {NOTES} and of {GOICOLEA}: published values beside skcable's",
        aliases=["worked-examples", "seeds"],
    )
