"""Markdown tables shared by the benchmark scripts' reports."""

from __future__ import annotations


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
