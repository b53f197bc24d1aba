"""mkdocs-gallery settings of the skcable site (``conf_script`` in mkdocs.yml).

The examples are scripts first: each writes its files, figures included, to ``--out`` and
closes its matplotlib figures; the pyvista render is a PNG file too. So the gallery runs every
example with ``--out`` set to a fresh folder of its own and shows, after each code block,
the figures still open (mkdocs-gallery's matplotlib scraper) and every PNG file the block
wrote or rewrote in that folder, in the order of their names. The first one is the
thumbnail.
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from pathlib import Path

from mkdocs_gallery.scrapers import figure_md_or_html

_OUT: dict[str, tuple[Path, dict[Path, int]]] = {}  # example -> (its --out folder, PNGs seen)


def reset_argv(script) -> list[str]:
    """``--out`` of each example: a new empty folder."""
    out = Path(tempfile.mkdtemp(prefix=f"skcable-gallery-{script.src_py_file.stem}-"))
    atexit.register(shutil.rmtree, out, True)
    _OUT[str(script.src_py_file)] = (out, {})
    return ["--out", str(out)]


def png_files_scraper(block, script, **kwargs) -> str:
    """The PNG files the block wrote under the example's ``--out`` folder, as figures."""
    entry = _OUT.get(str(script.src_py_file))
    if entry is None:
        return ""
    out, seen = entry
    new = []
    for png in sorted(out.rglob("*.png")):
        stamp = png.stat().st_mtime_ns
        if seen.get(png) != stamp:
            seen[png] = stamp
            new.append(png)
    paths = []
    for png, target in zip(new, script.run_vars.image_path_iterator, strict=False):
        shutil.copyfile(png, target)
        paths.append(Path(target))
    # one figure per call: mkdocs-gallery 0.10's list of several figures leaves its template's
    # "%s" in the page and the images as text (docs/check_site.py catches it)
    return "\n".join(
        figure_md_or_html([path], script, fig_titles=png.stem.replace("_", " "))
        for png, path in zip(new, paths, strict=False)
    )


conf = {
    "reset_argv": reset_argv,
    "image_scrapers": ("matplotlib", png_files_scraper),
}
