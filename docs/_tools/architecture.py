"""The package's layout read from its source: which component imports which.

A component is one of `COMPONENTS` (a package or a module of one concern); a module belongs
to the longest component its dotted name starts with. ``python docs/_tools/architecture.py``
rewrites the table of docs/architecture.md between its markers; ``tests/test_architecture.py``
fails when the page and the code disagree, or when a module belongs to no component.
"""

from __future__ import annotations

import ast
import sys
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "skcable"
PAGE = ROOT / "docs" / "architecture.md"
BEGIN, END = "<!-- layout:begin -->", "<!-- layout:end -->"

#: every component and its concern, in the order of the page (lowest layer first)
COMPONENTS = {
    "skcable.errors": "the exceptions and warnings every layer raises",
    "skcable._checks": "argument checks: finite reals, positives, integers, exactly-one-of",
    "skcable._xp": "one formula, two back ends (math for scalars, NumPy for arrays)",
    "skcable._plausible": "the limits of plausible inputs and answers, their reasons and sources",
    "skcable._budget": "the iteration and time budget of a search, its best point kept",
    "skcable._show": "``name=value unit`` for the reprs of results",
    "skcable._lazy": "lazy public names of a package (PEP 562)",
    "skcable._newton2": "the damped two-unknown Newton of every closed form on two unknowns",
    "skcable._eigen": "the lowest modes of a small banded symmetric pencil",
    "skcable.results": "the result protocol of every 2-D cable solution",
    "skcable.fe": "finite-element machinery without physics: assembly, linear solves, Newton, "
    "terms, tangent checks, continuation",
    "skcable._moved": "the module paths and names of 0.2.0 that moved, served for one release",
    "skcable.cable": "suspended cables in closed form: funicular, parabola, catenary, elastic "
    "catenary, stiffness, end conditions, surfaces",
    "skcable.cable.seabed": "one elastic line on a flat or sloped seabed, in closed form",
    "skcable.bvp": "cables as boundary-value problems on scikit-fem, their loads and terms, "
    "currents, and the choice of the cheapest model",
    "skcable.mooring.segments": "multi-segment lines with clump weights and buoys",
    "skcable.mooring.line_bvp": "the mooring line as a boundary-value problem, in its plane (seabed "
    "contact, friction, slack) and in space (current drag, bathymetry, axial laws, 3 x 3 stiffness), "
    "each solver falling back on the other",
    "skcable.mooring": "mooring lines and systems: lines in the sea, axial laws, bathymetry, "
    "moored bodies, MoorDyn files",
    "skcable.conductors": "overhead-line conductors: change of state, ruling span, frequencies, "
    "whole lines, rating, fatigue, catalogue",
    "skcable.strand": "strand sections, damage, wire materials, the stick/slip bending law, capacity curves",
    "skcable.strand.fe": "the strand finite element: term protocol, slip laws, supports, loads, "
    "foundations, the model",
    "skcable.io": "writers and readers: VTK for ParaView, CSV series, atomic files",
    "skcable.plot": "figures of results (matplotlib, pyvista)",
    "skcable.study": "parameter studies: cases, cache, runner, Dask, tables",
    "skcable.cli": "the command line, one module per command group",
    "skcable.__main__": "``python -m skcable``",
}


def module_name(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@cache
def modules() -> dict[str, ast.Module]:
    """Every module of the package, parsed."""
    return {module_name(p): ast.parse(p.read_text(encoding="utf-8")) for p in sorted(PACKAGE.rglob("*.py"))}


def is_package(module: str) -> bool:
    return (ROOT / module.replace(".", "/") / "__init__.py").is_file()


def imported(module: str, node: ast.ImportFrom) -> str:
    """The absolute name of the module that ``node`` (in ``module``) imports from."""
    if not node.level:
        return node.module or ""
    base = module.split(".")
    base = base if is_package(module) else base[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def imports(module: str, tree: ast.AST, top_level_only: bool = False):
    """``(line, imported module, imported names)`` of the imports in ``tree``: all of them, or
    those that run when the module loads (its body, guarded ones included)."""
    nodes = ast.walk(tree) if not top_level_only else _module_level(tree)
    for node in nodes:
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield node.lineno, alias.name, ()
        elif isinstance(node, ast.ImportFrom):
            yield node.lineno, imported(module, node), tuple(a.name for a in node.names)


def _module_level(tree: ast.AST):
    for node in getattr(tree, "body", ()):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            continue  # read by type checkers only
        if isinstance(node, (ast.If, ast.Try, ast.With)):
            yield from _module_level(ast.Module(body=[*ast.iter_child_nodes(node)], type_ignores=[]))
        else:
            yield node


def component_of(module: str) -> str | None:
    """The longest component that ``module`` is or lies in."""
    found = [c for c in COMPONENTS if module == c or module.startswith(c + ".")]
    return max(found, key=len) if found else None


def component_graph() -> dict[str, set[str]]:
    """Which components each component imports (anywhere in its files: a lazy import is a use)."""
    graph: dict[str, set[str]] = {c: set() for c in COMPONENTS}
    for module, tree in modules().items():
        source = component_of(module)
        for _, target, names in imports(module, tree):
            if not target.startswith("skcable"):
                continue
            candidates = [f"{target}.{n}" for n in names if f"{target}.{n}" in modules()] or [target]
            for candidate in candidates:
                used = component_of(candidate)
                if used and source and used != source and used != "skcable":
                    graph[source].add(used)
    return graph


def table() -> str:
    """The markdown table of the components, their concerns and what they use."""
    graph = component_graph()
    present = [c for c in COMPONENTS if any(component_of(m) == c for m in modules())]
    rows = ["| component | concern | uses |", "|---|---|---|"]
    for name in present:
        uses = ", ".join(f"`{u.removeprefix('skcable.')}`" for u in sorted(graph[name], key=present.index))
        rows.append(f"| `{name}` | {COMPONENTS[name]} | {uses or '—'} |")
    return "\n".join(rows)


def page_with_table(text: str) -> str:
    head, rest = text.split(BEGIN)
    _, tail = rest.split(END)
    return f"{head}{BEGIN}\n{table()}\n{END}{tail}"


if __name__ == "__main__":
    new = page_with_table(PAGE.read_text(encoding="utf-8"))
    tmp = PAGE.with_suffix(".md.tmp")
    tmp.write_text(new, encoding="utf-8")
    tmp.replace(PAGE)
    sys.stdout.write(f"{PAGE.relative_to(ROOT)}: layout table regenerated\n")
