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
