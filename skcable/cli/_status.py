"""Exit statuses of the ``skcable`` command, and the usage error that maps to status 2."""

from __future__ import annotations

__all__ = [
    "EXIT_CASES_FAILED",
    "EXIT_ERROR",
    "EXIT_INTERRUPTED",
    "EXIT_NO_CONVERGENCE",
    "EXIT_OK",
    "EXIT_STATUS",
    "EXIT_USAGE",
    "EXIT_WARNINGS",
    "Usage",
]

EXIT_OK, EXIT_CASES_FAILED, EXIT_USAGE, EXIT_NO_CONVERGENCE, EXIT_ERROR, EXIT_INTERRUPTED = 0, 1, 2, 3, 4, 130
#: Solved, with plausibility warnings: 5, since 3 already means "did not converge" (a script's
#: test of 3 keeps its meaning).
EXIT_WARNINGS = 5
#: Exit statuses of ``skcable``.
EXIT_STATUS = {
    EXIT_OK: "done",
    EXIT_CASES_FAILED: "a study ran but some of its cases failed (listed; the table says why)",
    EXIT_USAGE: "bad usage: a bad or unknown flag, value or study file, an output path that cannot be "
    "written or would overwrite a file without --force (all checked before computing), or no command "
    "(the help is printed)",
    EXIT_NO_CONVERGENCE: "a computation did not converge; what converged is printed and written",
    EXIT_ERROR: "a file could not be written, or an unexpected error (a bug: please report it)",
    EXIT_WARNINGS: "solved, with warnings: data or an answer that no real cable fits (a unit slip, a strain "
    "no material survives, an anchor pulled up, a body out of the water), each printed as one "
    "'skcable: warning: ...' line; --strict makes the first an error (status 2: the run stops there)",
    EXIT_INTERRUPTED: "interrupted (Ctrl-C); a study's finished cases stay in its cache",
}


class Usage(Exception):
    """A usage error whose message is complete (exit status 2)."""
