"""Markdown tables shared by the benchmark scripts' reports, and the sections of the docs they write."""

from __future__ import annotations

from pathlib import Path

from skcable.io._atomic import write_text


def markdown_table(header, rows) -> list[str]:
    """The lines of a markdown table: ``header``, its separator, then each of ``rows`` (cells
    written with ``str``)."""
    lines = ["| " + " | ".join(map(str, header)) + " |", "|" + "---|" * len(header)]
    return lines + ["| " + " | ".join(map(str, row)) + " |" for row in rows]


def counts_table(column, values, outcomes, counts) -> list[str]:
    """The markdown table of ``counts[(value, outcome)]`` (0 where missing): one row per value of
    ``values`` under the heading ``column``, one column per outcome of ``outcomes``."""
    return markdown_table(
        [column, *outcomes], [[value, *(counts.get((value, o), 0) for o in outcomes)] for value in values]
    )


def write_section(page: Path, name: str, lines, new_page: str = "") -> Path:
    """Replace what lies between the markers ``<!-- name:begin -->`` and ``<!-- name:end -->`` of
    ``page`` with ``lines`` (the section appended, markers and all, where the page has none;
    ``new_page`` the text of a page that does not exist yet), the other sections left as they
    are; atomically (`skcable.io._atomic.write_text`). Returns ``page``."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    text = page.read_text(encoding="utf-8") if page.exists() else new_page
    block = "\n".join([begin, *lines, end])
    if begin in text and end in text:
        head, rest = text.split(begin, 1)
        text = head + block + rest.split(end, 1)[1]
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    return write_text(page, text)
