"""The built site browses from ``file://`` (issue 31): mkdocs builds pages as files
(``use_directory_urls: false``), and `docs/check_site.py`'s `offline_links` fails a link to a
folder or a missing file (the browser check itself runs in .ci/run after ``mkdocs build``)."""

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _check_site():
    spec = importlib.util.spec_from_file_location("check_site", ROOT / "docs" / "check_site.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_mkdocs_builds_pages_as_files():
    lines = [line.split("#")[0].strip() for line in (ROOT / "mkdocs.yml").read_text().splitlines()]
    assert "use_directory_urls: false" in lines


def test_a_folder_link_does_not_browse_offline(tmp_path):
    (tmp_path / "api").mkdir()
    (tmp_path / "api" / "index.html").write_text("<html></html>")
    (tmp_path / "mooring.html").write_text('<a href="api/index.html#x">ok</a><img src="img/a.png">')
    (tmp_path / "index.html").write_text(
        '<a href="mooring.html">ok</a> <a href="api/">folder</a> <a href="https://x.org/">out</a>'
        ' <a href="#top">anchor</a> <script src="missing.js"></script>'
    )
    problems = _check_site().offline_links(tmp_path)
    assert problems == [
        "index.html: link to a folder (no page from file://): api/",
        "index.html: link to a missing file: missing.js",
        "mooring.html: link to a missing file: img/a.png",
    ]
