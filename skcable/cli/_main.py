"""The ``skcable`` parser, and `main`: parse, run one command, map what happened to an exit
status and one line on stderr (never a traceback), print skcable's warnings one line each."""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
import warnings

from skcable.cli import (
    _cables,
    _conductor,
    _demo,
    _examples,
    _frequencies,
    _line,
    _mooring,
    _state,
    _strand,
    _study,
)
from skcable.cli._args import Parser, given_numbers, input_message, warning_message
from skcable.cli._status import (
    EXIT_ERROR,
    EXIT_INTERRUPTED,
    EXIT_NO_CONVERGENCE,
    EXIT_STATUS,
    EXIT_USAGE,
    EXIT_WARNINGS,
    Usage,
)

__all__ = ["main", "parser"]

#: The command modules, in the order of ``skcable --help``; each has ``register(sub, command)``.
COMMANDS = (_demo, _examples, _cables, _strand, _line, _mooring, _state, _frequencies, _conductor, _study)


class _Version(argparse.Action):
    """``--version``: reads the package metadata only when asked."""

    def __call__(self, parser, namespace, values, option_string=None):
        import skcable

        print(f"skcable {skcable.__version__}")
        parser.exit(0)


def _epilog() -> str:
    import textwrap

    statuses = "\n".join(
        textwrap.fill(text, 78, initial_indent=f"  {code:3d}  ", subsequent_indent=" " * 7)
        for code, text in EXIT_STATUS.items()
    )
    sources = (
        "SI units (m, N, Pa) unless a flag says otherwise; results print their units. Sources of the "
        f"worked examples and of the strand model: {_examples.NOTES}; {_examples.GOICOLEA}; "
        f"{_examples.PINO_VIDAL}."
    )
    debug = "SKCABLE_DEBUG=1 shows the traceback of an unexpected error."
    return f"exit status:\n{statuses}\n\n{textwrap.fill(sources, 80)}\n{debug}"


def _command(subparsers, name, handler, help_text, **kw):
    p = subparsers.add_parser(name, help=help_text, description=help_text, **kw)
    p.set_defaults(handler=handler, active=p)
    p.add_argument(
        "--strict",
        action="store_true",
        help="a plausibility warning is an error: the run stops there, status 2 (default: warn, "
        f"status {EXIT_WARNINGS})",
    )
    return p


def parser() -> argparse.ArgumentParser:
    """The whole command line (argparse only: no model is imported to build it)."""
    top = Parser(
        prog="skcable",
        description="skcable: structural cables and metallic strands on scikit-fem.",
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    top.add_argument("--version", action=_Version, nargs=0, help="print the version and exit")
    sub = top.add_subparsers(dest="command", metavar="command")
    for module in COMMANDS:
        module.register(sub, _command)
    return top


def _no_handler(args) -> str:
    if args.command == "strand":
        return "strand: choose 'section' or 'capacity' (skcable strand --help)"
    if args.command == "study":
        return "study: choose 'run' (skcable study --help)"
    if args.command == "conductor":
        return "conductor: choose 'table', 'ruling-span', 'rating' or 'vibration' (skcable conductor --help)"
    return "choose a command (skcable --help)"


def _failure(args, exc: BaseException) -> tuple[int, str | None]:
    """The exit status and message of an exception that is not skcable's own."""
    if isinstance(exc, KeyboardInterrupt):
        return EXIT_INTERRUPTED, "interrupted"
    if isinstance(exc, BrokenPipeError):  # stdout closed early (`skcable examples | head -1`): stop quietly
        with contextlib.suppress(OSError, ValueError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_ERROR, None
    if os.environ.get("SKCABLE_DEBUG"):
        raise exc
    if isinstance(exc, (OverflowError, ZeroDivisionError, FloatingPointError)):
        given = given_numbers(args)
        return EXIT_USAGE, (
            f"{args.command}: these inputs are beyond double precision ({given}): {type(exc).__name__}: {exc}"
        )
    if isinstance(exc, OSError):
        return EXIT_ERROR, f"{type(exc).__name__}: {exc}"
    return EXIT_ERROR, f"internal error, please report it: {type(exc).__name__}: {exc}"


def _run(top, argv) -> tuple[int, str | None, object]:
    """Parse and run; returns the exit status, the one-line error message (or None), the args."""
    from skcable.errors import ConvergenceError, InputError, PlausibilityWarning

    try:
        args = top.parse_args(argv)
    except SystemExit as exc:  # --help, --version, or a usage error argparse printed
        return (exc.code if isinstance(exc.code, int) else EXIT_USAGE), None, None
    if not hasattr(args, "handler"):
        return EXIT_USAGE, _no_handler(args), args
    try:
        if getattr(args, "strict", False):
            warnings.simplefilter("error", PlausibilityWarning)
        return args.handler(args), None, args
    except PlausibilityWarning as exc:  # --strict
        caught = warnings.WarningMessage(exc, PlausibilityWarning, "", 0)  # as `main` records one
        return EXIT_USAGE, f"{warning_message(args, caught)} (--strict)", args
    except Usage as exc:
        return EXIT_USAGE, str(exc), args
    except InputError as exc:
        return EXIT_USAGE, input_message(args, exc), args
    except ConvergenceError as exc:
        return EXIT_NO_CONVERGENCE, f"no convergence: {exc}", args
    except (KeyboardInterrupt, Exception) as exc:  # noqa: BLE001 - no traceback, see EXIT_STATUS
        return (*_failure(args, exc), args)


def main(argv=None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); returns the exit status.

    Without arguments, prints the help and returns 2. Numpy's floating-point warnings are
    not shown (the results are checked); skcable's own warnings are one line each, naming the
    flag; a `PlausibilityWarning` turns a successful run's status into ``EXIT_WARNINGS`` (5), or,
    with ``--strict``, into a usage error (2).
    """
    top = parser()
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    if not argv:
        top.print_help()
        return EXIT_USAGE
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        status, message, args = _run(top, argv)
    from skcable.errors import PlausibilityWarning

    seen = set()
    for warning in caught:
        text = warning_message(args, warning)
        if warning.category.__module__.startswith("skcable") and text not in seen:
            seen.add(text)
            print(f"skcable: warning: {text}", file=sys.stderr)
            if issubclass(warning.category, PlausibilityWarning) and status == 0:
                status = EXIT_WARNINGS
    if message is not None:
        print(f"skcable: error: {' '.join(message.split())}", file=sys.stderr)
    return status
