"""Command line of skcable.

``skcable demo`` is the README's main job: the stick and stick–slip capacity
curves of the damaged steel 9.5 mm strand written to ``results/`` (CSV,
VTK for ParaView, PNG). ``skcable examples`` (also ``seeds``) prints the
worked examples of the sources beside skcable's values; ``catenary``,
``parabola``, ``elastic-catenary`` and ``funicular`` solve one cable;
``line`` one mooring line (segments, clump weights, buoys, seabed and
friction); ``change-of-state`` and ``frequencies`` a conductor's span;
``strand section`` and ``strand capacity`` analyse a strand; ``conductor vibration``
a catalogue conductor's aeolian vibration; ``study run`` runs a study file. Every command
takes ``--json`` where it prints numbers; without it, results print with their units, arrays
as labelled columns.

One private module per command group (``_demo``, ``_examples``, ``_cables``,
``_strand``, ``_line``, ``_state``, ``_frequencies``, ``_vibration``, ``_study``, each with
``register(subparsers, command)``), each importing the library inside its
functions, so that ``skcable --help`` imports no model; shared: ``_args``
(parsing, one-line errors, flag names), ``_output`` (tables, JSON, output
paths), ``_status`` (exit statuses), ``_main`` (the parser and `main`).

Errors are one line on stderr naming the flag, never a traceback; the exit
status says what happened (`EXIT_STATUS`, also in ``skcable --help``). Output paths
are checked before computing and files are written atomically (``_output``).
"""

from skcable.cli._main import main, parser
from skcable.cli._status import (
    EXIT_CASES_FAILED,
    EXIT_ERROR,
    EXIT_INTERRUPTED,
    EXIT_NO_CONVERGENCE,
    EXIT_OK,
    EXIT_STATUS,
    EXIT_USAGE,
    EXIT_WARNINGS,
)

__all__ = [
    "EXIT_CASES_FAILED",
    "EXIT_ERROR",
    "EXIT_INTERRUPTED",
    "EXIT_NO_CONVERGENCE",
    "EXIT_OK",
    "EXIT_STATUS",
    "EXIT_USAGE",
    "EXIT_WARNINGS",
    "main",
    "parser",
]
