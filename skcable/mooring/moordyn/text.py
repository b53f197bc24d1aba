r"""A MoorDyn input file as MoorDyn-C reads it: its lines, its sections, its rows and numbers.

MoorDyn-C v2 (M. Hall et al., ``source/MoorDyn2.cpp``: ``findStartOfSection``,
``readFileIntoBuffers``, ``moordyn::str::split``) reads a file as follows, and so does `InputFile`:

- a **section** starts at the first line that contains ``---`` and whose upper-cased text
  *contains* one of the section's names (other words on the line do not matter:
  ``---- LINE TYPES chain studless 0.018m ----`` is the line-types section); a ``---`` line
  naming no section (the trailer ``--- need this line ---``) starts nothing;
- a table's rows start after its header line and two more (the column names and the units);
  ``OPTIONS`` and ``OUTPUT`` rows right after the header; rows run to the next line holding
  ``---``;
- a row is split on blanks, and a token holding ``#`` ends it (a comment); `InputFile` also ends
  a row at a token starting with ``!`` (MoorDyn-F's comments) and skips blank rows.

Where MoorDyn would read a file as another system than it says, `InputFile` refuses it, naming
the file, the line and the reason (`InputError` with ``path`` and ``line``): a file that does
not end with a ``---`` line (truncated: MoorDyn files end with ``--- need this line ---``), a
section header that is the file's last line, a data row where MoorDyn expects the column names,
a byte that is not UTF-8 in a token it reads, a number that is not one or overflows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from skcable.errors import InputError

__all__ = ["InputFile", "Row", "Section", "file_error", "tokens"]

#: The sections MoorDyn-C looks for, each by any of its names (MoorDyn-F's ``EXTERNAL LOADS``,
#: ``FAILURE`` and the Syrope ``SYROPE IC`` too), and whether its rows follow two header lines.
SECTIONS = {
    "LINE TYPES": (("LINE DICTIONARY", "LINE TYPES"), True),
    "ROD TYPES": (("ROD DICTIONARY", "ROD TYPES"), True),
    "BODIES": (("BODIES", "BODY LIST", "BODY PROPERTIES"), True),
    "RODS": (("RODS", "ROD LIST", "ROD PROPERTIES"), True),
    "POINTS": (
        ("POINTS", "POINT LIST", "POINT PROPERTIES", "CONNECTION PROPERTIES", "NODE PROPERTIES"),
        True,
    ),
    "LINES": (("LINES", "LINE LIST", "LINE PROPERTIES"), True),
    "SYROPE IC": (("SYROPE IC",), True),
    "EXTERNAL LOADS": (("EXTERNAL LOADS",), True),
    "FAILURE": (("FAILURE",), True),
    "OPTIONS": (("OPTIONS",), False),
    "OUTPUTS": (("OUTPUT",), False),
}


def file_error(path, line: int | None, argument: str, reason: str) -> InputError:
    """`InputError` naming ``argument``, its message ``"<file>, line <n>: <reason>"``, with the
    attributes ``path`` (the file) and ``line`` (1-based, or None for the whole file)."""
    where = f"{Path(path).name}, line {line}" if line is not None else f"{Path(path).name}"
    err = InputError(argument, f"{where}: {reason}")
    err.path, err.line = str(path), line  # type: ignore[attr-defined]
    return err


@dataclass(frozen=True)
class Row:
    """A data row: its 1-based ``line`` number and its ``tokens`` (comments cut)."""

    line: int
    tokens: tuple[str, ...]


@dataclass(frozen=True)
class Section:
    """A section found as MoorDyn finds it: ``name`` (the key of `SECTIONS`), the ``header`` line
    (1-based), the ``columns`` (the column-name tokens of a table, else empty) and its ``rows``."""

    name: str
    header: int
    columns: tuple[str, ...]
    rows: tuple[Row, ...]


def tokens(text: str) -> tuple[str, ...]:
    """MoorDyn's split: blank-separated tokens up to the first holding ``#`` (or starting with
    ``!``)."""
    out = []
    for token in text.split():
        if "#" in token:
            head = token.split("#", 1)[0]
            if head:
                out.append(head)
            break
        if token.startswith("!"):
            break
        out.append(token)
    return tuple(out)


def _looks_like_data(tokens) -> bool:
    """Whether a line MoorDyn skips as column names or units holds three numbers or more (a data
    row, which MoorDyn would drop)."""
    count = 0
    for token in tokens:
        try:
            float(token)
        except ValueError:
            continue
        count += 1
    return count >= 3


class InputFile:
    """The lines of a MoorDyn input file and its sections (module docstring).

    Parameters
    ----------
    path : str or Path
        The file. Its bytes are split into lines (``\\n``, ``\\r\\n`` or ``\\r``); each line is
        UTF-8, a byte that is not kept as an escape and refused where a token holding it is read.
    """

    def __init__(self, path):
        self.path = Path(path)
        try:
            data = self.path.read_bytes()
        except OSError as exc:
            raise InputError("path", f"{str(path)!r} cannot be read: {exc.strerror or exc}") from None
        text = data.decode("utf-8", errors="surrogateescape")
        self.lines = [line.rstrip() for line in text.replace("\r\n", "\n").replace("\r", "\n").split("\n")]
        while self.lines and not self.lines[-1].strip():
            self.lines.pop()
        self._check_end()

    def error(self, line: int | None, argument: str, reason: str) -> InputError:
        """`file_error` for this file."""
        return file_error(self.path, line, argument, reason)

    def _check_end(self) -> None:
        """A file must end with a ``---`` line that starts no section MoorDyn reads (its trailer):
        else it was cut short, and MoorDyn would read part of it as the whole."""
        if not self.lines:
            raise self.error(None, "path", "the file is empty")
        last = self.lines[-1]
        number = len(self.lines)
        if "---" not in last:
            raise self.error(
                number,
                "path",
                "the file ends without its closing '---' line (MoorDyn files end with "
                "'--- need this line ---'): it is truncated, or not a MoorDyn input file",
            )
        name = self._section_name(last)
        if name is not None:
            raise self.error(number, name, f"the {name} section's header is the file's last line: truncated")

    @staticmethod
    def _section_name(line: str):
        upper = line.upper()
        for name, (names, _) in SECTIONS.items():
            if any(n in upper for n in names):
                return name
        return None

    def front_matter(self) -> str:
        """The free text before the first ``---`` line past the first (the title rule)."""
        out = []
        for line in self.lines:
            if "---" in line:
                if self._section_name(line) is not None:
                    break
                continue
            out.append(line)
        return "\n".join(out).strip("\n")

    def section(self, name: str) -> Section | None:
        """The section ``name`` (a key of `SECTIONS`) found as MoorDyn finds it, or None."""
        names, table = SECTIONS[name]
        start = next(
            (
                k
                for k, line in enumerate(self.lines)
                if "---" in line and any(n in line.upper() for n in names)
            ),
            None,
        )
        if start is None:
            return None
        columns: tuple[str, ...] = ()
        first = start + 1
        if table:
            skipped = self.lines[start + 1 : start + 3]
            for j, text in enumerate(skipped):
                if "---" in text:
                    raise self.error(
                        start + 2 + j,
                        name,
                        "the table's column names and units (two lines) are missing: MoorDyn would "
                        "skip this line as one of them",
                    )
                if _looks_like_data(tokens(text)):
                    raise self.error(
                        start + 2 + j,
                        name,
                        "a data row where MoorDyn reads the column names or units (a table starts "
                        "with two header lines): MoorDyn would drop it",
                    )
            columns = tokens(skipped[0]) if skipped else ()
            first = start + 3
        rows = []
        for k in range(first, len(self.lines)):
            text = self.lines[k]
            if "---" in text:
                break
            words = tokens(text)
            if words:
                rows.append(Row(k + 1, words))
        return Section(name, start + 1, columns, tuple(rows))

    def sections(self) -> dict:
        """``{name: Section}`` of the sections the file has."""
        found = {name: self.section(name) for name in SECTIONS}
        return {name: s for name, s in found.items() if s is not None}

    # -- tokens -----------------------------------------------------------------------------------
    def word(self, row: Row, index: int, column: str) -> str:
        """The token ``index`` of ``row``, refused where it holds a byte that is not UTF-8."""
        token = row.tokens[index]
        try:
            token.encode("utf-8")
        except UnicodeEncodeError:
            bad = next(c for c in token if 0xDC80 <= ord(c) <= 0xDCFF)
            raise self.error(
                row.line, column, f"byte 0x{ord(bad) - 0xDC00:02x} is not UTF-8 (in {column})"
            ) from None
        return token

    def number(self, row: Row, index: int, column: str, *, text: str | None = None) -> float:
        """The token ``index`` of ``row`` (or ``text`` from it) as a finite float, refused by
        ``column`` where it is no number or overflows."""
        token = self.word(row, index, column) if text is None else text
        try:
            value = float(token)
        except ValueError:
            raise self.error(row.line, column, f"{token!r} is not a number") from None
        if not math.isfinite(value):
            reason = (
                "overflows a float"
                if token.lower().lstrip("+-") not in ("inf", "infinity", "nan")
                else "is not finite"
            )
            raise self.error(row.line, column, f"{token!r} {reason}")
        return value

    def integer(self, row: Row, index: int, column: str) -> int:
        """The token ``index`` of ``row`` as an integer, refused by ``column`` otherwise."""
        token = self.word(row, index, column)
        try:
            return int(token)
        except ValueError:
            value = self.number(row, index, column)
            if value != int(value):
                raise self.error(row.line, column, f"{token!r} is not a whole number") from None
            return int(value)

    def columns(self, row: Row, counts, section: str) -> None:
        """Refuse ``row`` unless it has one of the column ``counts``."""
        n = len(row.tokens)
        if n not in counts:
            expected = " or ".join(str(c) for c in counts)
            raise self.error(row.line, section, f"{n} columns, {expected} expected")
