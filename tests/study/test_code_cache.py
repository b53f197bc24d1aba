"""The cache is keyed on the code: an entry made by other code is recomputed with a CacheWarning."""

import importlib.util
import json
import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import pytest

import skcable
from skcable import cable, study
from skcable.errors import CacheWarning
from skcable.study import fingerprint

CASES = study.grid(span=[100.0, 300.0], sag=[5.0, 30.0], w=[12.0])
PACKAGE = Path(skcable.__file__).resolve().parent


def direct_H(case):
    return cable.catenary(case["span"], 0.0, case["w"], sag=case["sag"]).H


def serial(cases, cache):
    return study.run(study.cable_solve, cases, executor="serial", cache=cache, progress=False)


def rewrite(path, **changes):
    """Rewrite an entry with ``changes``, its checksum made valid again (a well-formed entry)."""
    entry = json.loads(path.read_text()) | changes
    entry["checksum"] = study.cache.checksum(entry)
    path.write_text(json.dumps(entry))


def test_entry_of_other_code_with_another_number_is_not_returned(tmp_path, calls):
    first = serial(CASES[:1], tmp_path)
    path = tmp_path / f"{first.key[0]}.json"
    entry = json.loads(path.read_text())
    other = entry["result"] | {"outputs": entry["result"]["outputs"] | {"H": 2533.37}}
    rewrite(path, code="0" * 64, result=other)  # what other numerics wrote, under the same version
    calls.clear()
    with pytest.warns(CacheWarning, match="was computed by other code"):
        again = serial(CASES[:1], tmp_path)
    assert calls == [CASES[0]]
    assert again.H[0] == direct_H(CASES[0]) != 2533.37
    assert json.loads(path.read_text())["code"] == fingerprint.code_fingerprint(study.cable_solve)
    with warnings.catch_warnings():
        warnings.simplefilter("error", CacheWarning)  # rewritten by this code: used as it is
        serial(CASES[:1], tmp_path)


def test_an_entry_without_a_fingerprint_is_recomputed(tmp_path, calls):
    first = serial(CASES[:1], tmp_path)
    path = tmp_path / f"{first.key[0]}.json"
    entry = {k: v for k, v in json.loads(path.read_text()).items() if k != "code"} | {"schema_version": 1}
    entry["checksum"] = study.cache.checksum(entry)  # an entry of the previous skcable, well formed
    path.write_text(json.dumps(entry))
    calls.clear()
    with pytest.warns(CacheWarning, match="schema version 1"):
        serial(CASES[:1], tmp_path)
    assert calls == [CASES[0]]


def test_many_unusable_entries_are_named_three_times_and_counted_once(tmp_path):
    cases = study.grid(span=[100.0 + i for i in range(7)], sag=[5.0], w=[1.0])
    serial(cases, tmp_path)
    for path in tmp_path.glob("*.json"):
        rewrite(path, code="f" * 64)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        serial(cases, tmp_path)
    messages = [str(w.message) for w in caught if w.category is CacheWarning]
    assert len(messages) == study.cache.WARN_EACH + 1
    assert messages[-1].startswith(f"study cache: {7 - study.cache.WARN_EACH} more entries of {tmp_path}")


def copy_package(target):
    shutil.copytree(PACKAGE, target, ignore=shutil.ignore_patterns("__pycache__"))
    return target


def test_tree_fingerprint_sees_every_byte_of_the_sources_and_nothing_else(tmp_path):
    copy = copy_package(tmp_path / "skcable")
    assert fingerprint.tree_fingerprint(copy) == fingerprint.tree_fingerprint(PACKAGE)
    (copy / "__pycache__").mkdir(exist_ok=True)
    (copy / "__pycache__" / "x.cpython-311.pyc").write_bytes(b"compiled")
    (copy / ".hidden").write_text("editor state")
    assert fingerprint.tree_fingerprint(copy) == fingerprint.tree_fingerprint(PACKAGE)
    source = copy / "cable" / "__init__.py"
    text = source.read_bytes()
    source.write_bytes(text[:-1] + (b" " if text[-1:] != b" " else b"\n"))  # one byte
    assert fingerprint.tree_fingerprint(copy) != fingerprint.tree_fingerprint(PACKAGE)


def test_package_fingerprint_is_computed_once_per_process(monkeypatch):
    seen = []
    tree = fingerprint.tree_fingerprint
    monkeypatch.setattr(fingerprint, "tree_fingerprint", lambda root: seen.append(root) or tree(root))
    fingerprint.package_fingerprint.cache_clear()
    try:
        first = fingerprint.package_fingerprint()
        assert fingerprint.package_fingerprint() == first and seen == [PACKAGE]
    finally:
        fingerprint.package_fingerprint.cache_clear()


def test_another_process_of_the_same_code_has_the_same_fingerprint():
    out = subprocess.run(
        [sys.executable, "-c", "from skcable.study import fingerprint as f; print(f.package_fingerprint())"],
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    assert out.stdout.strip() == fingerprint.package_fingerprint()


def load_model(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.model


def test_a_user_models_fingerprint_follows_its_source(tmp_path):
    sources = {
        "a": "def model(x):\n    return {'y': 2 * x}\n",
        "b": "def model(x):\n    return {'y': 2 * x}\n",
        "c": "def model(x):\n    return {'y': 3 * x}\n",
    }
    models = {}
    for name, source in sources.items():
        (tmp_path / f"m_{name}.py").write_text(source)
        models[name] = load_model(tmp_path / f"m_{name}.py", f"m_{name}")
    prints = {name: fingerprint.code_fingerprint(model) for name, model in models.items()}
    assert prints["a"] == prints["b"] != prints["c"]
    assert fingerprint.package_fingerprint() not in prints.values()
    assert fingerprint.code_fingerprint(study.cable_solve) == fingerprint.package_fingerprint()
