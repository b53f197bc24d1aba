"""Whether worker processes can start from this program, so that a study never hangs.

Dask's local cluster starts its workers with multiprocessing's *spawn* method: every worker
is a new Python that re-imports the program's main module (as ``__mp_main__``) before it
takes work. That goes wrong in two ways:

- a script that starts its study at module level, outside ``if __name__ == "__main__":``
  (how a snippet is usually saved), starts it again in every worker: the workers take the
  cases' locks and wait for each other, and the study hangs;
- a program read from standard input (``python -``) or given as a string has no file to
  re-import: the workers die as they start.

`main_problem` tells, before any worker starts, which of these applies (the script's
source is parsed to see whether the line running the study lies inside the guard).
A notebook, ``python -c`` or an interactive session has no main file, spawns nothing to
re-import, and is fine (Dask ships the functions defined there by value), and so is
``python -m package`` (multiprocessing does not re-import a package's ``__main__``).
`reimporting_main` is the backstop inside a worker: it tells that the study is being
started by the re-import itself.
"""

from __future__ import annotations

import ast
import os
import sys
import threading

__all__ = ["GUARD", "guarded", "main_problem", "reimporting_main"]

#: What a script must put its study under.
GUARD = 'if __name__ == "__main__":'


def _stack(thread_id: int | None = None):
    frame = sys._getframe(1) if thread_id is None else sys._current_frames().get(thread_id)
    while frame is not None:
        yield frame
        frame = frame.f_back


def _module_frame(namespace: dict):
    """The frame running the module code of ``namespace`` (main thread first), or None."""
    threads: list[int | None] = [None] if threading.current_thread() is threading.main_thread() else []
    threads.append(threading.main_thread().ident)
    for thread in threads:
        for frame in _stack(thread):
            if frame.f_code.co_name == "<module>" and frame.f_globals is namespace:
                return frame
    return None


def _is_guard(test: ast.expr) -> str | None:
    """``"=="`` or ``"!="`` if ``test`` compares ``__name__`` with ``"__main__"``."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1):
        return None
    sides = [test.left, test.comparators[0]]
    names = [isinstance(s, ast.Name) and s.id == "__name__" for s in sides]
    mains = [isinstance(s, ast.Constant) and s.value == "__main__" for s in sides]
    if not (any(names) and any(mains)):
        return None
    return {ast.Eq: "==", ast.NotEq: "!="}.get(type(test.ops[0]))


def guarded(source: str, line: int) -> bool:
    """Whether ``line`` (1-based) of ``source`` lies in the ``__name__ == "__main__"`` branch of an
    ``if`` (False elsewhere, or if the source does not parse).

    Examples
    --------
    >>> guarded('x = 1\\nif __name__ == "__main__":\\n    run()\\n', 3)
    True
    >>> guarded('x = 1\\nrun()\\n', 2)
    False
    """
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        return False
    for node in ast.walk(tree):
        if not isinstance(node, ast.If):
            continue
        kind = _is_guard(node.test)
        branch = node.body if kind == "==" else node.orelse if kind == "!=" else []
        if branch and branch[0].lineno <= line <= (branch[-1].end_lineno or branch[-1].lineno):
            return True
    return False


def _unguarded_line(main, path: str) -> int | None:
    frame = _module_frame(vars(main))
    if frame is None:
        return None  # the module code has finished (a callback): nothing to tell
    try:
        with open(path, encoding="utf-8") as handle:
            source = handle.read()
        code = compile(source, path, "exec", dont_inherit=True)
        same = code.co_code == frame.f_code.co_code and list(code.co_lines()) == list(frame.f_code.co_lines())
    except (OSError, UnicodeDecodeError, SyntaxError, ValueError):
        return None  # a zip application, an unreadable file: the backstop decides
    if not same:
        return None  # the file was edited since it started: its lines say nothing
    return None if guarded(source, frame.f_lineno) else frame.f_lineno


def main_problem(method: str = "spawn") -> str | None:
    """Why worker processes started by ``method`` (``"fork"`` re-imports nothing) cannot start from
    this program, in one sentence saying what is wrong and what to add; None if they can.
    """
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if method == "fork" or main is None or path is None:
        return None
    name = getattr(getattr(main, "__spec__", None), "name", None)
    if name is not None:
        return None if name == "__main__" or name.endswith(".__main__") else _unguarded(main, path)
    if not os.path.isfile(path):
        return (
            f"the program comes from {path}, which worker processes cannot re-import; "
            f"save it as a .py file with the study under `{GUARD}`"
        )
    return _unguarded(main, path)


def _unguarded(main, path: str) -> str | None:
    line = _unguarded_line(main, path)
    if line is None:
        return None
    return (
        f"{path} runs the study at line {line} outside `{GUARD}`, so every worker process "
        f"would run it again; put the study under `{GUARD}`"
    )


def reimporting_main() -> bool:
    """Whether this process is a spawned worker re-importing the program's main module: module
    code run as ``__mp_main__`` (the name multiprocessing gives the main module it re-imports in
    a child) is on the stack. A study started then is the parent's, started again by its
    unguarded script: it must not run.
    """
    return any(
        frame.f_code.co_name == "<module>" and frame.f_globals.get("__name__") == "__mp_main__"
        for frame in _stack()
    )
