"""Every fenced Python block of ``README.md`` and ``docs/*.md`` runs.

A page is one test. Its Python blocks (fences opened with ```` ```python ```` or ```` ```py ````)
run in order in one namespace, as a reader pastes them one after the other into a fresh
interpreter, in a temporary working directory (files a block writes land there) with the
matplotlib backend ``Agg``. A traceback names the page and its line numbers: each block is
compiled with the page as its file name and its lines where the page has them.

A block that is not meant to run says so on the line just before its fence (blank lines
between are allowed) with an HTML comment, which Markdown renders as nothing::

    <!-- docs-test: skip (needs a running Dask scheduler) -->
    ```python
    table = study.run(study.strand_capacity, cases, scheduler="tcp://host:8786")
    ```

The reason in parentheses is required. A skipped block is not run and the next blocks of the
page do not see its names, so keep skipped blocks few and self-contained.

A ``DeprecationWarning`` that a line of a page triggers (a renamed function or argument called
there) fails the page: the docs use the current names.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import pkgutil
import re
import warnings
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
MARKDOWN = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>`{3,}|~{3,})\s*(?P<info>[^\s`]*)")
MARKER = re.compile(r"^\s*<!--\s*docs-test:\s*(?P<word>\S+)\s*(?:\((?P<reason>[^)]*)\))?\s*-->\s*$")
PYTHON = {"python", "py", "python3"}


@dataclass(frozen=True)
class Block:
    """One fenced Python block: its page, first code line (1-based), source and skip reason."""

    page: Path
    line: int
    source: str
    skip: str | None


def _marker(lines: list[str], fence_index: int, page: Path) -> str | None:
    """The skip reason written just before the fence at ``fence_index``, or None."""
    i = fence_index - 1
    while i >= 0 and not lines[i].strip():
        i -= 1
    if i < 0 or not lines[i].lstrip().startswith("<!-- docs-test"):
        return None
    m = MARKER.match(lines[i])
    if m is None or m["word"] != "skip" or not (m["reason"] or "").strip():
        raise ValueError(
            f"{page.name}:{i + 1}: a docs-test marker reads "
            f"'<!-- docs-test: skip (reason) -->', got {lines[i]!r}"
        )
    return m["reason"].strip()


def python_blocks(page: Path) -> list[Block]:
    """The fenced Python blocks of a Markdown page, in order (other fences are passed over)."""
    lines = page.read_text(encoding="utf-8").splitlines()
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if m is None:
            i += 1
            continue
        fence, start = m["fence"], i
        close = re.compile(rf"^ {{0,3}}{fence[0]}{{{len(fence)},}}\s*$")
        i += 1
        while i < len(lines) and not close.match(lines[i]):
            i += 1
        if m["info"].lower() in PYTHON:
            body = [
                line[len(m["indent"]) :] if line.startswith(m["indent"]) else line
                for line in lines[start + 1 : i]
            ]
            blocks.append(Block(page, start + 2, "\n".join(body) + "\n", _marker(lines, start, page)))
        i += 1
    return blocks


def run_page(blocks: list[Block]) -> dict:
    """Run the blocks of one page in one namespace; returns the namespace.

    A ``DeprecationWarning`` raised on a line of the page (a deprecated name called there,
    ``stacklevel`` pointing at the caller) is an error.
    """
    namespace: dict = {"__name__": "__main__"}
    with warnings.catch_warnings():
        warnings.filterwarnings("error", category=DeprecationWarning, module="__main__")
        for block in blocks:
            if block.skip is not None:
                continue
            code = compile("\n" * (block.line - 1) + block.source, str(block.page), "exec")
            exec(code, namespace)  # the documented code is what this test runs
    return namespace


PAGES = [page for page in MARKDOWN if python_blocks(page)]


def _page_id(page: Path) -> str:
    return page.relative_to(ROOT).as_posix()


def test_the_pages_have_python_blocks():
    assert ROOT / "README.md" in PAGES and len(PAGES) >= 10


@pytest.mark.parametrize("page", PAGES, ids=_page_id)
def test_every_python_block_runs(page, tmp_path, monkeypatch):
    blocks = python_blocks(page)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    try:
        run_page(blocks)
    finally:
        plt.close("all")


# --- the extractor itself --------------------------------------------------------------------


def test_extractor_reads_fences_markers_and_line_numbers(tmp_path):
    page = tmp_path / "page.md"
    page.write_text(
        "# t\n\n```python\nx = 1\n```\n\n```bash\nls\n```\n\n"
        "<!-- docs-test: skip (needs a cluster) -->\n\n```python\nraise SystemExit\n```\n"
        "- item\n\n  ```py\n  y = x + 1\n  ```\n~~~python\n```\nz = 3\n~~~\n",
        encoding="utf-8",
    )
    blocks = python_blocks(page)
    assert [(b.line, b.skip) for b in blocks] == [(4, None), (14, "needs a cluster"), (19, None), (22, None)]
    assert blocks[2].source == "y = x + 1\n"
    assert blocks[3].source == "```\nz = 3\n"
    namespace = run_page(blocks[:3])
    assert namespace["y"] == 2


def test_a_failing_block_is_reported_at_its_page_line(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("text\n\n```python\na = 1\nb = undefined_name\n```\n", encoding="utf-8")
    with pytest.raises(NameError) as info:
        run_page(python_blocks(page))
    frame = info.traceback[-1]
    assert Path(frame.path) == page and frame.lineno + 1 == 5


def test_a_marker_without_a_reason_is_refused(tmp_path):
    page = tmp_path / "page.md"
    page.write_text("<!-- docs-test: skip -->\n```python\nx = 1\n```\n", encoding="utf-8")
    with pytest.raises(ValueError, match="docs-test: skip"):
        python_blocks(page)


def test_a_deprecated_call_on_a_page_fails_it(tmp_path):
    page = tmp_path / "page.md"
    page.write_text(
        "```python\nimport warnings\n\n"
        "def old():\n    warnings.warn('old is new now', DeprecationWarning, stacklevel=2)\n\n"
        "old()\n```\n",
        encoding="utf-8",
    )
    with pytest.raises(DeprecationWarning, match="old is new now"):
        run_page(python_blocks(page))


# --- the API reference: every public module, its maths converted ------------------------------


def _tool(name: str):
    """A module of docs/_tools (the site's build tools), imported by path."""
    spec = importlib.util.spec_from_file_location(
        f"docs_tools_{name}", ROOT / "docs" / "_tools" / f"{name}.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def public_modules() -> list[str]:
    """skcable's modules with no private part in their dotted name (the root and __main__ aside)."""
    import skcable

    return sorted(
        m.name
        for m in pkgutil.walk_packages(skcable.__path__, "skcable.")
        if not any(part.startswith("_") for part in m.name.split("."))
    )


def test_every_public_module_has_its_api_entry_and_every_package_its_page():
    """A public package or top-level module has a page ``docs/api/<name without skcable.>.md``
    in the nav; every public module is a ``:::`` directive of an API page."""
    directives = set()
    for page in (ROOT / "docs" / "api").glob("*.md"):
        directives |= set(re.findall(r"^::: (skcable[\w.]*)\s*$", page.read_text(encoding="utf-8"), re.M))
    modules = public_modules()
    assert not set(modules) - directives, f"public modules without an API entry: {set(modules) - directives}"
    nav = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    for name in modules:
        if pkgutil.resolve_name(name).__spec__.submodule_search_locations or name.count(".") == 1:
            page = f"api/{name.removeprefix('skcable.')}.md"
            assert (ROOT / "docs" / page).is_file() and page in nav, (name, page)


@pytest.mark.parametrize(
    ("rst", "markdown"),
    [
        (r"the strain :math:`\varepsilon_a` and :math:`a`", r"the strain \(\varepsilon_a\) and \(a\)"),
        (":math:`a +\n    b` over lines", r"\(a + b\) over lines"),
        (
            "See :mod:`skcable.cable` and :func:`~skcable.cable.catenary`.",
            "See [`skcable.cable`][skcable.cable] and [`catenary`][skcable.cable.catenary].",
        ),
        ("text\n\n.. math:: x = 1\n\nafter", "text\n\n$$\nx = 1\n$$\n\nafter"),
        (
            "is\n\n.. math:: a = b\n          + c,\n\nwith",
            "is\n\n$$\na = b\n+ c,\n$$\n\nwith",
        ),
        (
            "Notes\n-----\n.. math::\n    :label: eq\n\n"
            "    D = \\begin{pmatrix} 1 \\\\ 2\n    \\end{pmatrix}\n\n    E = 1\nend",
            "Notes\n-----\n\n$$\nD = \\begin{pmatrix} 1 \\\\ 2\n\\end{pmatrix}\n$$\n\n$$\nE = 1\n$$\n\nend",
        ),
        (
            "1. item\n   .. math:: F = 1\n\n   (more)",
            "1. item\n\n   $$\n   F = 1\n   $$\n\n   (more)",
        ),
    ],
)
def test_rst_maths_become_arithmatex_markdown(rst, markdown):
    assert _tool("rst_math").rst_to_markdown(rst) == markdown


def test_no_docstring_keeps_rst_maths_after_the_conversion():
    """Every docstring of the package, converted, has no RST maths or role left, and its
    ``$$`` and ``\\(``/``\\)`` delimiters pair up."""
    convert = _tool("rst_math").rst_to_markdown
    seen = 0
    for name in ["skcable", *public_modules(), *_private_modules()]:
        module = importlib.import_module(name)
        for obj in [module, *vars(module).values()]:
            for doc in _docstrings(obj, name):
                text = convert(doc)
                seen += doc.count(":math:") + doc.count(".. math::")
                assert not re.search(r":math:|\.\. math::|:(mod|func|class|meth|attr):`", text), (name, text)
                assert text.count("$$") % 2 == 0 and text.count(r"\(") == text.count(r"\)"), (name, text)
    assert seen > 50  # the package does write its equations in RST


def _private_modules() -> list[str]:
    import skcable

    public = set(public_modules())
    return [
        m.name
        for m in pkgutil.walk_packages(skcable.__path__, "skcable.")
        if m.name not in public and m.name != "skcable.__main__"
    ]


def _docstrings(obj, module_name: str):
    if isinstance(obj, type) and obj.__module__ == module_name:
        yield from (inspect.getdoc(v) for v in [obj, *vars(obj).values()] if inspect.getdoc(v))
    elif (inspect.isfunction(obj) and obj.__module__ == module_name) or inspect.ismodule(obj):
        if obj.__doc__ and (not inspect.ismodule(obj) or obj.__name__ == module_name):
            yield inspect.getdoc(obj)


def test_the_api_hook_documents_a_submodule_with_what_its_package_does_not_export():
    hooks = _tool("hooks")
    page = "# t\n\n::: skcable.fe\n\n::: skcable.fe.assembly\n\n::: skcable.fe.newton\n\n::: skcable.plot\n"
    out = hooks.with_members(page)
    import importlib

    package = importlib.import_module("skcable.fe")

    def rest(name):  # what the module exports and its package does not
        return sorted(set(importlib.import_module(name).__all__) - set(package.__all__))

    assert f"::: skcable.fe.assembly\n    options:\n      members: {rest('skcable.fe.assembly')}\n" in out
    assert "StrainAssembly" not in out.split("::: skcable.fe.assembly")[1].split(":::")[0]
    # skcable.fe exports newton (a function) over its submodule's name: shown with the submodule
    members = sorted([*rest("skcable.fe.newton"), "newton"])
    assert f"::: skcable.fe.newton\n    options:\n      members: {members}\n" in out
    assert "::: skcable.plot\n\n" in out or out.endswith("::: skcable.plot\n")  # no package on the page
    assert "::: skcable.fe\n\n" in out
