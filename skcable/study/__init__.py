"""Parameter studies: a grid or a sample of cases over a model function, serial or on Dask.

A study is a list of cases (dicts of keyword arguments) and a model function that turns
one case into a dict of scalar outputs. `run` maps the function over the cases and
collects one row per case into a `StudyTable` (a pandas DataFrame that prints as a short
summary):

    case parameters | outputs | status ("ok" / "failed") | error | time_s | key

(an output named like a parameter gets the suffix ``_result``: a cable solved for a given
``sag`` reports the sag it reached as ``sag_result``).

- **Where it runs.** ``executor="auto"`` (the default) computes serially and moves the rest
  of the study to a local Dask cluster of processes only once that is predicted to finish
  sooner, start-up included: a small study is never slower than the serial run
  (`skcable.study.executors`). Dask and distributed are the optional extra
  ``skcable[cluster]``; without them a study runs serially and gives the same table.
- **Never hangs.** A program whose worker processes cannot re-import it (a script that
  starts its study outside ``if __name__ == "__main__":``, a program read from standard
  input) runs serially or on worker threads, with one `WorkerWarning` saying what to add
  (`skcable.study.spawn`).
- **Failures** (bad parameters, no convergence) are rows with their error; the study goes on.
- **The cache** (``cache=``): every finished case is written atomically as it ends and
  verified when read (an entry made by other code is recomputed with a `CacheWarning`); runs
  sharing a cache split the work, and an interrupted study resumes (`skcable.study.cache`,
  `skcable.study.locks`).
- **Study files** (TOML) describe a study for ``skcable study run`` (`load_study`, `run_file`).

Modules: `tasks` (the model functions, one case evaluated), `cases` (grids, samples, keys),
`fingerprint` (the code's fingerprint), `cache` and `locks`, `spawn` (can workers start?),
`executors` (serial, Dask, auto), `runner` (`run`), `table` and `files`.

Examples
--------
>>> from skcable import study
>>> cases = study.grid(span=[100.0, 200.0], sag=[5.0, 10.0, -1.0], w=[10.0])
>>> table = study.run(study.cable_solve, cases, executor="serial", progress=False)
>>> table.shape[0], table.status.tolist()
(6, ['ok', 'ok', 'failed', 'ok', 'ok', 'failed'])
>>> table.error[2]
'InputError: sag: must be > 0, got -1.0'
"""

from __future__ import annotations

import importlib
import sys
import types

from skcable.errors import CacheWarning
from skcable.study import tasks
from skcable.study.cases import case_key, describe, grid, sample
from skcable.study.executors import WorkerWarning
from skcable.study.files import TABLE_SUFFIXES, check_output, load_study, run_file
from skcable.study.locks import STALE_AFTER
from skcable.study.runner import run
from skcable.study.table import StudyTable
from skcable.study.tasks import MODELS, cable_solve, strand_capacity

__all__ = [
    "MODELS",
    "STALE_AFTER",
    "TABLE_SUFFIXES",
    "CacheWarning",
    "StudyTable",
    "WorkerWarning",
    "cable_solve",
    "case_key",
    "check_output",
    "describe",
    "grid",
    "load_study",
    "run",
    "run_file",
    "sample",
    "strand_capacity",
]

_evaluate = tasks.evaluate


class _Package(types.ModuleType):
    """Forwards ``skcable.study._evaluate = f`` (how older tests intercept the computing of a
    case) to `skcable.study.tasks.evaluate`, the function the executors call; pickles by name,
    as a module does."""

    def __setattr__(self, name, value):
        if name == "_evaluate":
            tasks.evaluate = value
        super().__setattr__(name, value)

    def __reduce__(self):
        return importlib.import_module, (self.__name__,)


sys.modules[__name__].__class__ = _Package
