"""Argument parsing of the ``skcable`` command: one-line errors, no abbreviations, unknown
flags named with the nearest known one, number types, and the flag of a library argument.

The library names the argument it refuses as its API spells it (`skcable.InputError`);
`input_message` turns that into the flag the user typed (``T_max`` -> ``--T-max``,
``n`` -> ``--damage``).
"""

from __future__ import annotations

import argparse
import difflib
import math
from decimal import Decimal

from skcable.cli._status import EXIT_USAGE

__all__ = ["Parser", "finite", "given_numbers", "input_message", "whole"]

#: Library argument names whose flag is spelled otherwise.
_FLAG_OF = {"n": "damage", "name": "preset", "n_workers": "workers"}
#: The constraint keywords of catenary() and parabola(), whose flags the CLI names.
_CONSTRAINTS = ("length", "sag", "H", "low", "T_max")


def _is_number(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def _scientific_negative(token: str) -> bool:
    return token.startswith("-") and "e" in token.lower() and _is_number(token)


def plain_negatives(args: list[str]) -> list[str]:
    """``args`` with each negative number in scientific notation (``-1.5e-05``, the way Python
    prints small floats) that argparse would take for an unknown flag (before Python 3.13: its
    error is "expected one argument") written as the same decimal number in positional notation
    (``-0.000015``: exact, the same float), or, where that is no finite float, joined to the
    flag before it (``--dh=-1e400``), so that the flag's own check refuses it by name."""
    out: list[str] = []
    for token in args:
        if not _scientific_negative(token):
            out.append(token)
        elif math.isfinite(float(token)):
            out.append(format(Decimal(token), "f"))
        elif out and out[-1].startswith("--") and "=" not in out[-1] and not _is_number(out[-1]):
            out[-1] = f"{out[-1]}={token}"
        else:
            out.append(token)
    return out


class Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2, no usage dump), no abbreviated flags,
    and unknown flags refused before any other error, with the nearest known flag."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("allow_abbrev", False)  # `--len` is not `--length`
        super().__init__(*args, **kwargs)

    def error(self, message):
        self.exit(EXIT_USAGE, f"skcable: error: {message}\n")

    def parse_known_args(self, args=None, namespace=None):
        args = plain_negatives(list(args)) if args is not None else None
        if args is not None:
            self._refuse_unknown_flags(args)
        return super().parse_known_args(args, namespace)

    def _refuse_unknown_flags(self, args: list[str]) -> None:
        """Refuse the first flag this parser does not know (up to its subcommand's name),
        suggesting the nearest one: argparse would report a missing required flag first."""
        known = self._option_string_actions
        commands = set()
        for action in self._actions:
            if isinstance(action, argparse._SubParsersAction):
                commands |= set(action.choices)
        for token in args:
            if token == "--" or token in commands:
                return
            if not token.startswith("-") or token == "-" or _is_number(token):
                continue
            flag = token.split("=", 1)[0]
            if flag not in known:
                near = nearest_flag(flag, [f for f in known if f.startswith("--")])
                hint = f"; did you mean {near[0]}?" if near else f" (see {self.prog} --help)"
                where = f"{self.prog.removeprefix('skcable ')}: " if " " in self.prog else ""
                self.error(f"{where}unknown flag {flag}{hint}")


def nearest_flag(flag: str, flags: list[str]) -> list[str]:
    """The known flag nearest ``flag``: the one equal to it but for case (``--ea`` -> ``--EA``),
    else difflib's closest, compared in lower case (``--Spam`` -> ``--span``); [] if none is near."""
    lower = {f.lower(): f for f in flags}
    if flag.lower() in lower:
        return [lower[flag.lower()]]
    near = difflib.get_close_matches(flag.lower(), list(lower), n=1)
    return [lower[near[0]]] if near else []


def finite(text: str) -> float:
    """A finite number (argparse type)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"must be a finite number, got {text!r}")
    return value


def whole(minimum: int | None = None):
    """A whole number, at least ``minimum`` (argparse type)."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number, got {text!r}") from None
        if minimum is not None and value < minimum:
            raise argparse.ArgumentTypeError(f"must be at least {minimum}, got {value}")
        return value

    return parse


def flag(active, argument: str) -> str | None:
    """The command-line flag of a library argument name, if the command has one."""
    dest = _FLAG_OF.get(argument, argument)
    for action in active._actions if active is not None else ():
        if action.dest == dest and action.option_strings:
            return max(action.option_strings, key=len)
    return None


def input_message(args, exc) -> str:
    """The one-line message of a refused argument (`skcable.InputError`), naming its flag."""
    active = getattr(args, "active", None)
    reason = str(exc).split(": ", 1)[1] if ": " in str(exc) else str(exc)
    if exc.argument == "constraint" and active is not None:  # name the flags, not the API's keywords
        for dest in _CONSTRAINTS:
            name = flag(active, dest)
            if name:
                reason = reason.replace(f" {dest},", f" {name},").replace(f" {dest} ", f" {name} ")
        reason = reason.replace("T_max", "--T-max")
        return f"{args.command}: {reason}"
    return f"{flag(active, exc.argument) or exc.argument}: {reason}"


def warning_message(args, warning) -> str:
    """A `PlausibilityWarning` names its argument as the API spells it: name its flag."""
    text = " ".join(str(warning.message).split())
    argument = getattr(warning.message, "argument", None)
    name = flag(getattr(args, "active", None), argument) if argument else None
    if argument and name and text.startswith(f"{argument}: "):
        text = f"{name}: {text[len(argument) + 2 :]}"
    return text


def given_numbers(args) -> str:
    """The numbers given on the command line, as ``--flag value`` (for an overflow's message)."""
    active = getattr(args, "active", None)
    shown = []
    for action in active._actions if active is not None else ():
        value = getattr(args, action.dest, None)
        if action.option_strings and isinstance(value, float):
            shown.append(f"{max(action.option_strings, key=len)} {value:g}")
    return ", ".join(shown)
