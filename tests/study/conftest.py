"""Shared fixtures of the study tests."""

import pytest

from skcable import study


@pytest.fixture
def calls(monkeypatch):
    """The cases computed in this process (not read from a cache) during the test."""
    computed = []
    evaluate = study.tasks.evaluate

    def counting(model, case):
        computed.append(case)
        return evaluate(model, case)

    monkeypatch.setattr(study.tasks, "evaluate", counting)
    return computed
