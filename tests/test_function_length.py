"""No function in ``skcable/`` is longer than 80 lines of code (issue 21).

A line of code is a source line that holds a token of code: blank lines, comments and
docstrings (of the module, classes and functions) do not count; every line of a statement,
of a multi-line call or of a string that is not a docstring does. A function's length runs
from its ``def`` line to its last line, nested functions and classes included.

`KNOWN` lists the functions in files another branch is rewriting now, with the branch: remove
an entry when that branch lands (the test then fails on an entry whose function is gone or no
longer too long).
"""

import ast
import io
import tokenize
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "skcable"
MAX_LINES = 80

#: ``"path::qualified name"`` -> the branch rewriting that file now.
KNOWN: dict[str, str] = {}

_NOT_CODE = {
    tokenize.COMMENT,
    tokenize.NL,
    tokenize.NEWLINE,
    tokenize.INDENT,
    tokenize.DEDENT,
    tokenize.ENCODING,
    tokenize.ENDMARKER,
}
_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)


def _docstring_lines(tree: ast.Module) -> set[int]:
    lines: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, *_SCOPES)) and node.body:
            first = node.body[0]
            if (
                isinstance(first, ast.Expr)
                and isinstance(first.value, ast.Constant)
                and isinstance(first.value.value, str)
            ):
                lines.update(range(first.lineno, (first.end_lineno or first.lineno) + 1))
    return lines


def code_lines(source: str) -> set[int]:
    """The line numbers (1-based) of ``source`` that hold code (module docstring)."""
    docstrings = _docstring_lines(ast.parse(source))
    lines: set[int] = set()
    for token in tokenize.generate_tokens(io.StringIO(source).readline):
        if token.type in _NOT_CODE:
            continue
        lines.update(row for row in range(token.start[0], token.end[0] + 1) if row not in docstrings)
    return lines


def function_lengths(source: str) -> list[tuple[str, int, int]]:
    """``(qualified name, def line, lines of code)`` of every function in ``source``."""
    code = code_lines(source)
    out = []

    def visit(node: ast.AST, prefix: str) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, _SCOPES):
                name = f"{prefix}{child.name}"
                if not isinstance(child, ast.ClassDef):
                    end = child.end_lineno or child.lineno
                    out.append((name, child.lineno, len(code & set(range(child.lineno, end + 1)))))
                visit(child, name + ".")
            else:
                visit(child, prefix)

    visit(ast.parse(source), "")
    return out


def _package_lengths() -> dict[str, tuple[int, int]]:
    """``"path::qualified name" -> (def line, lines of code)`` over the package."""
    lengths = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        where = path.relative_to(PACKAGE.parent).as_posix()
        for name, line, count in function_lengths(path.read_text(encoding="utf-8")):
            lengths[f"{where}::{name}"] = (line, count)
    return lengths


def test_no_function_is_longer_than_80_lines_of_code():
    long = {key: value for key, value in _package_lengths().items() if value[1] > MAX_LINES}
    offenders = [
        f"{key.split('::')[0]}:{line} {key.split('::')[1]}: {count} lines of code"
        for key, (line, count) in sorted(long.items())
        if key not in KNOWN
    ]
    assert not offenders, f"longer than {MAX_LINES} lines of code:\n" + "\n".join(offenders)


def test_every_known_exception_is_still_one():
    lengths = _package_lengths()
    stale = [
        f"{key} (branch {branch}): "
        + ("gone" if key not in lengths else f"{lengths[key][1]} lines now")
        + "; remove it from KNOWN"
        for key, branch in KNOWN.items()
        if key not in lengths or lengths[key][1] <= MAX_LINES
    ]
    assert not stale, "\n".join(stale)


SAMPLE = '''"""Module docstring."""


def outer(a):
    """Docstring,
    on two lines."""
    # a comment

    b = (
        a + 1
    )
    text = """not a docstring:
    two more lines"""

    def inner():
        """Inner docstring."""
        return b  # a trailing comment

    class Local:
        """Class docstring."""

        x = 1

    return inner, text, Local


@staticmethod
def single(): return 1
'''


@pytest.mark.parametrize(
    ("name", "line", "count"),
    [
        # def outer; "b = (", "a + 1", ")"; the string's two lines; def inner; return b;
        # class Local; x = 1; return: 11 (the decorator of `single` is not its line)
        ("outer", 4, 11),
        ("outer.inner", 15, 2),
        ("single", 28, 1),
    ],
)
def test_the_counter_counts_code_lines_only(name, line, count):
    assert (name, line, count) in function_lengths(SAMPLE)


def test_the_counter_sees_a_long_function():
    body = "".join(f"    x{i} = {i}\n" for i in range(MAX_LINES))
    source = f'def f():\n    """Doc."""\n{body}    # comment\n\n    return 0\n'
    assert function_lengths(source) == [("f", 1, MAX_LINES + 2)]
