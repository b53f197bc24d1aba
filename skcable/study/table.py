"""A study's table: one row per case, as a pandas DataFrame that prints as a short summary.

Columns: the case's parameters, its outputs (an output named like a parameter gets the
suffix ``_result``: a cable solved for a given ``sag`` reports the sag it reached as
``sag_result``), ``status`` (``"ok"`` / ``"failed"``), ``error`` (the first line of the
error, ``""`` when ok), ``time_s`` (s the case took) and ``key`` (its cache key).

Examples
--------
>>> record = {"outputs": {"H": 2.0, "sag": 1.0}, "status": "ok", "error": "", "time_s": 0.1}
>>> table = make_table([{"span": 9.0, "sag": 1.0}], ["k"], {"k": record}, model="m.cable")
>>> list(table.columns)
['span', 'sag', 'H', 'sag_result', 'status', 'error', 'time_s', 'key']
>>> print(repr(table).splitlines()[0])
skcable study of cable: 1 cases, 1 ok, 0 failed
"""

from __future__ import annotations

import pandas as pd

__all__ = ["StudyTable", "make_table"]


class StudyTable(pd.DataFrame):
    """A study's table (module docstring): a pandas DataFrame that prints as a short summary.

    ``repr`` (what a prompt shows) is `summary`: a header with the number of cases, ok and
    failed, then at most 10 rows and 8 columns, without ``time_s`` and ``key``. The full
    table: ``table.to_string()``; ``attrs`` holds ``model`` (the model's name),
    ``from_cache`` (cases read from the cache) and ``executor`` (where the others ran) after
    `skcable.study.run`.
    """

    @property
    def _constructor(self):
        return StudyTable

    def summary(self) -> str:
        """The header line, at most 10 rows and 8 columns, and a line giving the table's size."""
        model = str(self.attrs.get("model", "")).rsplit(".", 1)[-1]
        head = f"skcable study{' of ' + model if model else ''}: {len(self)} cases"
        if "status" in self.columns:
            failed = int((self["status"] != "ok").sum())
            head += f", {len(self) - failed} ok, {failed} failed"
        shown = pd.DataFrame(self).drop(columns=["time_s", "key"], errors="ignore")
        body = shown.to_string(max_rows=10, min_rows=10, max_cols=8, max_colwidth=28)
        tail = f"[{len(self)} rows x {len(self.columns)} columns: the full table is table.to_string()]"
        return f"{head}\n{body}\n{tail}"

    def __repr__(self) -> str:
        return self.summary()


def make_table(
    cases: list[dict], keys: list[str], results: dict, model: str = "", from_cache: int = 0
) -> StudyTable:
    """The `StudyTable` of a study, one row per case of ``cases`` in their order (a case listed
    twice gets two rows): ``keys`` are their keys in the same order, ``results`` maps key ->
    result record (`skcable.study.tasks.evaluate`'s shape); ``model`` (the model's name) and
    ``from_cache`` (cases read from the cache) go to ``attrs``.
    """
    rows = []
    for case, key in zip(cases, keys, strict=True):
        result = results[key]
        outputs = {(f"{k}_result" if k in case else k): v for k, v in result["outputs"].items()}
        meta = {"status": result["status"], "error": result["error"], "time_s": result["time_s"], "key": key}
        rows.append(case | outputs | meta)
    table = StudyTable(rows)
    table.attrs.update(model=model, from_cache=from_cache)
    return table
