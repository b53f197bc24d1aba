"""MkDocs hooks of the skcable site (loaded by ``hooks:`` in mkdocs.yml).

API pages (``docs/api/*.md``) document a package and its public submodules, one
``::: skcable.x`` directive each. A package shows the names it exports (its ``__all__``);
a submodule of a package documented on the same page then shows only what the package does
not export already, so no object is documented twice on a page (but for a name that is
also the submodule's, as ``skcable.fe.newton.newton``, documented with its submodule). The hook writes that
``members`` option under each plain submodule directive (a directive with options of its own
is left alone): page authors write plain directives, and a name a developer adds to a
submodule or to its package's ``__all__`` moves to the right place by itself.
"""

from __future__ import annotations

import importlib
import re

DIRECTIVE = re.compile(r"^::: (?P<name>skcable(?:\.\w+)*)\s*$")


def _public(module) -> list[str]:
    names = getattr(module, "__all__", None)
    if names is None:
        names = [
            n
            for n, v in vars(module).items()
            if not n.startswith("_") and getattr(v, "__module__", None) == module.__name__
        ]
    return list(names)


def submodule_members(name: str, documented: set[str]) -> list[str] | None:
    """The members a submodule's directive shows, or None to leave it as written.

    ``documented`` holds the modules whose directives are on the same page.
    """
    parent = name.rpartition(".")[0]
    if parent not in documented:
        return None
    module, package = importlib.import_module(name), importlib.import_module(parent)
    # a name the package exports that is also the submodule's (skcable.fe.newton.newton)
    # shadows the submodule there: its object is documented under the submodule
    exported = set(_public(package)) - {name.rpartition(".")[2]}
    return [n for n in _public(module) if n not in exported]


def with_members(markdown: str) -> str:
    """An API page's Markdown with the ``members`` option under each plain submodule directive."""
    lines = markdown.splitlines()
    documented = {m["name"] for line in lines if (m := DIRECTIVE.match(line))}
    out = []
    for i, line in enumerate(lines):
        out.append(line)
        m = DIRECTIVE.match(line)
        has_options = i + 1 < len(lines) and lines[i + 1].startswith("    ")
        if m is None or has_options:
            continue
        members = submodule_members(m["name"], documented)
        if members is not None:
            out += ["    options:", f"      members: {members if members else 'false'}"]
    return "\n".join(out) + "\n"


#: mkdocs-gallery's links that assume folder URLs (``gallery/x/``): a thumbnail's link to its
#: example (``href="x"``) and an example's figure in ``srcset="../images/..."``.
GALLERY_LINK = re.compile(r'href="(?P<name>[A-Za-z0-9_]+)"')


def as_files(markdown: str) -> str:
    """A gallery page's links for a site of files (``use_directory_urls: false``): ``href="x"``
    to ``href="x.html"``, ``srcset="../images/`` to ``srcset="images/`` (the page's own folder)."""
    markdown = GALLERY_LINK.sub(lambda m: f'href="{m["name"]}.html"', markdown)
    return markdown.replace('srcset="../images/', 'srcset="images/')


def on_page_markdown(markdown, page, config=None, **kwargs):
    if page.file.src_uri.startswith("api/"):
        return with_members(markdown)
    if page.file.src_uri.startswith("generated/gallery/") and config is not None:
        if not config.get("use_directory_urls", True):
            return as_files(markdown)
    return markdown
