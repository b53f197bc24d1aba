"""Numpydoc docstrings with RST maths, rendered by mkdocstrings (a griffe extension).

skcable's docstrings follow scikit-fem's convention: numpydoc sections with reStructuredText
maths, ``:math:`...``` inline and ``.. math::`` blocks. mkdocstrings renders docstrings as
Markdown, where the site's ``pymdownx.arithmatex`` reads ``\\(...\\)`` inline and ``$$``
blocks. This extension rewrites each docstring before griffe parses its sections:

- ``:math:`x``` becomes ``\\(x\\)``;
- a ``.. math::`` directive (its content on the same line, on the indented lines below, or
  both; ``:label:``-style options dropped) becomes one ``$$`` block per equation (equations
  separated by a blank line), at the directive's indentation;
- a cross-reference role (``:mod:``, ``:func:``, ``:class:``, ``:meth:``, ``:attr:``,
  ``:obj:``, ``:data:``, ``:exc:``) becomes an autorefs link, ``~`` showing the last name only.

Anything else of RST in a docstring is valid Markdown already (``code``, *emphasis*, lists).

mkdocs.yml loads it as ``extensions: [docs/_tools/rst_math.py:RstMath]`` of the Python handler.
"""

from __future__ import annotations

import re

try:
    import griffe
except ImportError:  # the converter is importable (and tested) without mkdocstrings
    griffe = None

INLINE = re.compile(r":math:`([^`]+)`")
ROLE = re.compile(r":(?:py:)?(?:mod|func|class|meth|attr|obj|data|exc):`(~?)([\w.]+)`")
DIRECTIVE = re.compile(r"^(?P<indent>\s*)\.\. math::(?P<rest>.*)$")
OPTION = re.compile(r"^\s*:[\w-]+:")


def _role(m: re.Match) -> str:
    target = m[2]
    shown = target.rsplit(".", 1)[-1] if m[1] else target
    return f"[`{shown}`][{target}]"


def _inline(text: str) -> str:
    """Inline maths (which may run over a line break: joined) and roles."""
    text = INLINE.sub(lambda m: r"\(" + " ".join(m[1].split()) + r"\)", text)
    return ROLE.sub(_role, text)


def _equations(lines: list[str]) -> list[list[str]]:
    """Split the directive's content into equations at blank lines."""
    equations, current = [], []
    for line in lines:
        if line.strip():
            current.append(line)
        elif current:
            equations.append(current)
            current = []
    if current:
        equations.append(current)
    return equations


def _block(indent: str, first: str, body: list[str]) -> list[str]:
    """The ``$$`` blocks of one directive: ``first`` the text after ``::``, ``body`` below it."""
    body = [line for line in body if not OPTION.match(line)]
    width = min((len(line) - len(line.lstrip()) for line in body if line.strip()), default=0)
    content = ([first.strip()] if first.strip() else []) + [line[width:].rstrip() for line in body]
    out = [""]
    for equation in _equations(content):
        out += [f"{indent}$$", *(f"{indent}{line}" for line in equation), f"{indent}$$", ""]
    return out


def rst_to_markdown(text: str) -> str:
    """A docstring with RST maths and roles rewritten for Markdown with arithmatex."""
    lines = text.splitlines()
    out: list[str] = []
    i = 0
    while i < len(lines):
        m = DIRECTIVE.match(lines[i])
        if m is None:
            out.append(lines[i])
            i += 1
            continue
        indent, body = m["indent"], []
        i += 1
        while i < len(lines) and (
            not lines[i].strip() or len(lines[i]) - len(lines[i].lstrip()) > len(indent)
        ):
            body.append(lines[i])
            i += 1
        while body and not body[-1].strip():
            body.pop()
        if out and not out[-1].strip():
            out.pop()
        out += _block(indent, m["rest"], body)
    return _inline("\n".join(out).strip("\n")) if text.strip() else text


if griffe is not None:

    class RstMath(griffe.Extension):
        """Rewrite every docstring's RST maths and roles before its sections are parsed."""

        def on_instance(self, *, obj, **kwargs) -> None:
            if obj.docstring is not None:
                obj.docstring.value = rst_to_markdown(obj.docstring.value)
