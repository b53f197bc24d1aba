"""The layout's rules, read from the source (docs/architecture.md states them): data flows one
way (models produce results; the writers and plots consume them and import no model), the
finite-element core knows no domain, no module imports another module's private names, and
the module-level imports form no circle."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse
import scipy.sparse.csgraph

import skcable


def _tool():
    """docs/_tools/architecture.py (the page's generator), imported by path."""
    spec = importlib.util.spec_from_file_location(
        "docs_tools_architecture", ROOT / "docs/_tools/architecture.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


ROOT = Path(skcable.__file__).resolve().parents[1]
layout = _tool()
modules, imports = layout.modules, layout.imports

#: the domains, lowest first: a domain imports none after it but conductors and strand, which
#: are beside the others (conductors use the closed forms and the strand)
DOMAINS = ("skcable.cable", "skcable.bvp", "skcable.mooring", "skcable.conductors", "skcable.strand")
ABOVE = ("skcable.study", "skcable.cli")

#: the layers below the domains and the domains: what they may not import (anywhere in their files)
LAYERS = {
    "skcable.io": (*DOMAINS, *ABOVE, "skcable.plot"),
    "skcable.plot": (*DOMAINS, *ABOVE),
    "skcable.fe": (*DOMAINS, *ABOVE, "skcable.io"),
    "skcable.results": (*DOMAINS, *ABOVE),
    "skcable.errors": ("skcable.",),
    "skcable._checks": (*DOMAINS, "skcable.fe", "skcable.io"),
    "skcable.cable": ("skcable.bvp", "skcable.mooring", "skcable.conductors", "skcable.strand", *ABOVE),
    "skcable.bvp": ("skcable.mooring", "skcable.conductors", "skcable.strand", *ABOVE),
    "skcable.mooring": ("skcable.conductors", "skcable.strand", *ABOVE),
    "skcable.conductors": ("skcable.bvp", "skcable.mooring", *ABOVE),
    "skcable.strand": ("skcable.cable", "skcable.bvp", "skcable.mooring", "skcable.conductors", *ABOVE),
}


def is_module(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except ModuleNotFoundError:
        return False


@pytest.mark.parametrize("layer", sorted(LAYERS))
def test_a_layer_imports_nothing_above_it(layer):
    found = []
    for module, tree in modules().items():
        if module == layer or module.startswith(layer + "."):
            for line, target, _ in imports(module, tree):
                if target.startswith(LAYERS[layer]) and not (
                    target == layer or target.startswith(layer + ".")
                ):
                    found.append(f"{module}:{line} imports {target}")
    assert not found, found


def test_no_module_imports_another_modules_private_names():
    """``from m import _name`` only for a private submodule ``m._name``, never for a private
    function, class or constant of another module."""
    found = []
    for module, tree in modules().items():
        for line, target, names in imports(module, tree):
            if not target.startswith("skcable"):
                continue
            for name in names:
                if name.startswith("_") and not name.startswith("__") and not is_module(f"{target}.{name}"):
                    found.append(f"{module}:{line} reads {target}.{name}")
    assert not found, found


def test_the_check_sees_a_private_import():  # the test above can fail
    tree = ast.parse("from skcable.cable._catenary import _sag_over_a\nfrom skcable.cli import _demo\n")
    names = [(t, n) for _, t, ns in imports("skcable.x", tree) for n in ns]
    assert [is_module(f"{t}.{n}") for t, n in names] == [False, True]


def test_module_level_imports_form_no_circle():
    graph: dict[str, set[str]] = {}
    known = set(modules())
    for module, tree in modules().items():
        targets = set()
        for _, target, names in imports(module, tree, top_level_only=True):
            for candidate in [f"{target}.{n}" for n in names] + [target]:
                if candidate in known:
                    targets.add(candidate)
                    break
        graph[module] = targets - {module}
    # a package's __init__ importing its own submodules is how a package exports: skip those
    # edges, and look for circles through the rest
    for module in graph:
        graph[module] = {t for t in graph[module] if not t.startswith(module + ".")}
    circles = [c for c in strongly_connected(graph) if len(c) > 1]
    assert not circles, circles


def strongly_connected(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of ``graph`` (scipy's csgraph), each sorted."""
    names = sorted(set(graph) | {t for targets in graph.values() for t in targets})
    where = {name: i for i, name in enumerate(names)}
    rows = [where[v] for v, targets in graph.items() for _ in targets]
    cols = [where[t] for targets in graph.values() for t in targets]
    matrix = scipy.sparse.coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(len(names),) * 2)
    _, label = scipy.sparse.csgraph.connected_components(matrix, directed=True, connection="strong")
    return sorted(sorted(n for n, k in zip(names, label, strict=True) if k == c) for c in set(label))


def test_the_packages_form_no_circle_lazy_imports_included():
    """Between the top-level packages (and modules) of skcable, every import counts, the ones
    inside functions too: a circle there is a design's circle, whenever it runs."""
    top = {m: ".".join(m.split(".")[:2]) for m in modules()}
    graph: dict[str, set[str]] = {}
    for module, tree in modules().items():
        for _, target, names in imports(module, tree):
            if not target.startswith("skcable.") or module == "skcable":
                continue
            used = [f"{target}.{n}" for n in names if f"{target}.{n}" in top] or [target]
            for name in used:
                if name in top and top[name] != top[module]:
                    graph.setdefault(top[module], set()).add(top[name])
    circles = [c for c in strongly_connected(graph) if len(c) > 1]
    assert not circles, circles
    assert "skcable.mooring" in graph["skcable.cli"]  # the graph was read


def test_the_circle_finder_finds_a_circle():
    assert [
        c for c in strongly_connected({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) if len(c) > 1
    ] == [["a", "b", "c"]]


def test_every_module_belongs_to_a_component():
    assert not [m for m in modules() if m != "skcable" and layout.component_of(m) is None]


def test_the_documented_layout_is_the_codes():
    page = layout.PAGE.read_text(encoding="utf-8")
    assert layout.page_with_table(page) == page, "run python docs/_tools/architecture.py"
    assert "`skcable.fe` | finite-element machinery" in page and "| `skcable.io` |" in page
