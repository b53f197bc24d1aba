"""Look at the built site in a real browser, offline, and fail on what a reader would see broken.

Serves ``site/`` (after ``mkdocs build --strict``) on 127.0.0.1 and opens every page in
headless Chromium (Debian's ``chromium``, driven by Playwright's Python package without a
browser download of its own). Any request that leaves localhost is refused and reported, so
a page that needs a CDN fails here as it would offline. The check fails on

- raw TeX or RST in the rendered text (``\\(``, ``\\[``, ``$$``, ``:math:``, ``.. math::``
  outside code), a formula KaTeX could not read (``.katex-error``) or left unrendered;
- an image that did not load, a request that failed or answered 4xx/5xx, image markdown or a
  template's ``%s`` shown as text (mkdocs-gallery's list of several figures);
- a link to a page or an anchor of the site that does not exist;
- a gallery thumbnail that is mkdocs-gallery's placeholder (an example without a figure);
- a link that does not browse from ``file://`` (`offline_links`: a folder, or a missing file:
  the site is built with ``use_directory_urls: false``), or a page that does not render when
  opened from ``file://`` (the index, a theory page: screenshots ``*_file.png``);

and writes full-page screenshots of the index, a theory page with equations, an API page,
the gallery and one gallery example to ``--out`` (and, for a page with display maths, a
view around its first formula, ``*_maths.png``).

Run:  python docs/check_site.py [--site site] [--out results/site_check] [--chromium PATH]
"""

from __future__ import annotations

import argparse
import functools
import http.server
import re
import sys
import threading
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urldefrag, urlparse

SCREENSHOTS = {
    "index": "",
    "theory_mooring": "mooring.html",
    "api_strand_fe": "api/strand.fe.html",
    "gallery": "generated/gallery/",
    "gallery_strand_capacity": "generated/gallery/strand_capacity_paraview.html",
}
#: Pages opened from ``file://`` too (the site browsed offline, without a server).
FILE_PAGES = {"index_file": "index.html", "theory_mooring_file": "mooring.html"}
CHROMIUM_FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
RAW = re.compile(r"\\\(|\\\)|\\\[|\\\]|\$\$|:math:|\.\. math::|^\s*%s\s*$|!\[[^\]]*\]\(")

# the text a reader sees: no code, no scripts, no rendered maths
PAGE_STATE = r"""() => {
  const body = document.body.cloneNode(true);
  body.querySelectorAll("pre, code, script, style, .katex, .md-search, .md-sidebar")
      .forEach(e => e.remove());
  const math = [...document.querySelectorAll(".arithmatex")];
  return {
    text: body.innerText,
    mathErrors: [...document.querySelectorAll(".katex-error")].map(e => e.textContent.slice(0, 80)),
    unrendered: math.filter(e => !e.querySelector(".katex")).map(e => e.textContent.slice(0, 80)),
    math: math.length,
    rawImages: [...document.querySelectorAll("pre, code")].map(e => e.textContent)
      .filter(t => /!\[[^\]]*\]\([^)]*\)\{: \.mkd-glr/.test(t)).map(t => t.slice(0, 80)),
    images: [...document.images].map(
      i => ({src: i.currentSrc || i.src, ok: i.complete && i.naturalWidth > 0})),
    links: [...document.querySelectorAll("a[href]")].map(a => a.href),
  };
}"""


class _Ids(HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids: set[str] = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("id", "name") and value:
                self.ids.add(value)


def serve(site: Path) -> tuple[http.server.ThreadingHTTPServer, str]:
    """The site on 127.0.0.1, a free port, in a daemon thread; returns the server and its URL."""

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


def pages(site: Path) -> list[str]:
    """Every HTML page of the site, as paths relative to its root (``a/b/`` for ``a/b/index.html``)."""
    out = []
    for html in sorted(site.rglob("*.html")):
        rel = html.relative_to(site).as_posix()
        if rel == "404.html":
            continue
        out.append(rel[: -len("index.html")] if rel.endswith("index.html") else rel)
    return out


def _target_file(site: Path, path: str) -> Path:
    target = site / unquote(path).lstrip("/")
    return target / "index.html" if path.endswith("/") or target.is_dir() else target


def broken_links(site: Path, base: str, links: set[str]) -> list[str]:
    """The links of the site (same origin) to a missing file or a missing anchor."""
    problems, ids = [], {}
    for link in sorted(links):
        url, fragment = urldefrag(link)
        if not url.startswith(base):
            continue
        target = _target_file(site, urlparse(url).path)
        if not target.is_file():
            problems.append(f"broken link: {link}")
            continue
        if fragment and target.suffix == ".html":
            if target not in ids:
                parser = _Ids()
                parser.feed(target.read_text(encoding="utf-8", errors="replace"))
                ids[target] = parser.ids
            if unquote(fragment) not in ids[target]:
                problems.append(f"broken anchor: {link}")
    return problems


class _Refs(HTMLParser):
    """The relative references of a page: ``<a href>``, ``<link href>``, ``<img src>``, ``<script src>``."""

    def __init__(self):
        super().__init__()
        self.refs: list[str] = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value and (tag, name) in {("a", "href"), ("link", "href"), ("img", "src"), ("script", "src")}:
                self.refs.append(value)


def offline_links(site: Path) -> list[str]:
    """The references of every page that do not open from ``file://``: a relative one (no scheme,
    no leading ``/``) must name a file of the site, not a folder (a browser shows a folder's
    listing from ``file://``, not its ``index.html``) nor a missing file."""
    problems = []
    for html in sorted(site.rglob("*.html")):
        parser = _Refs()
        parser.feed(html.read_text(encoding="utf-8", errors="replace"))
        for ref in parser.refs:
            path = urldefrag(ref)[0].split("?")[0]
            if not path or urlparse(ref).scheme or ref.startswith(("/", "#")):
                continue
            target = (html.parent / unquote(path)).resolve()
            if target.is_dir():
                problems.append(f"{html.relative_to(site)}: link to a folder (no page from file://): {ref}")
            elif not target.is_file():
                problems.append(f"{html.relative_to(site)}: link to a missing file: {ref}")
    return problems


def file_pages(context, site: Path, out: Path) -> list[str]:
    """`FILE_PAGES` opened from ``file://`` in ``context`` (no server): each must render its title
    and its formulas, every image loaded; a screenshot of each."""
    problems = []
    for name, rel in FILE_PAGES.items():
        page = context.new_page()
        page.goto((site / rel).resolve().as_uri(), wait_until="load")
        state = page.evaluate(PAGE_STATE)
        where = f"file://{rel}"
        if not page.title():
            problems.append(f"{where}: no title: the page did not render from file://")
        problems += [f"{where}: image did not load: {i['src']}" for i in state["images"] if not i["ok"]]
        problems += [f"{where}: formula left unrendered: {t!r}" for t in state["unrendered"]]
        page.screenshot(path=str(out / f"{name}.png"), full_page=False)
        page.close()
    return problems


def examples_without_figures(site: Path) -> list[str]:
    """Gallery examples that show no figure (their thumbnail is then mkdocs-gallery's placeholder)."""
    images = site / "generated" / "gallery" / "images"
    problems = []
    for thumb in sorted((images / "thumb").glob("mkd_glr_*_thumb.png")):
        stem = thumb.name[len("mkd_glr_") : -len("_thumb.png")]
        if not any(images.glob(f"mkd_glr_{stem}_[0-9][0-9][0-9].png")):
            problems.append(f"gallery example without a figure (placeholder thumbnail): {stem}")
    if not problems and not any((images / "thumb").glob("*.png")):
        problems.append("the gallery has no thumbnails")
    return problems


def check_page(page, base: str, path: str) -> tuple[list[str], set[str], int]:
    """Open one page; returns its problems, its links and its number of formulas."""
    problems, failed = [], []
    page.on("requestfailed", lambda r: failed.append(f"request failed: {r.url} ({r.failure})"))
    page.on(
        "response",
        lambda r: failed.append(f"HTTP {r.status}: {r.url}") if r.status >= 400 else None,
    )
    page.goto(base + path, wait_until="load")
    state = page.evaluate(PAGE_STATE)
    where = "/" + path
    for line in state["text"].splitlines():
        if RAW.search(line):
            problems.append(f"{where}: raw TeX/RST or template text: {line.strip()[:100]!r}")
    problems += [f"{where}: image markdown shown as text: {t!r}" for t in state["rawImages"]]
    problems += [f"{where}: KaTeX could not read: {t!r}" for t in state["mathErrors"]]
    problems += [f"{where}: formula left unrendered: {t!r}" for t in state["unrendered"]]
    problems += [f"{where}: image did not load: {i['src']}" for i in state["images"] if not i["ok"]]
    problems += [f"{where}: {f}" for f in failed]
    return problems, set(state["links"]), state["math"]


def screenshot(page, path: Path) -> None:
    """The whole page, and where it has display maths a 1280 x 1200 view around its first."""
    page.screenshot(path=str(path), full_page=True)
    top = page.evaluate(
        "(() => { const e = document.querySelector('.katex-display');"
        " return e ? e.getBoundingClientRect().top + window.scrollY : null; })()"
    )
    if top is not None:
        clip = {"x": 0, "y": max(top - 300, 0), "width": 1280, "height": 1200}
        page.screenshot(path=str(path.with_name(path.stem + "_maths.png")), clip=clip, full_page=True)


def _external(route, refused: list[str]):
    refused.append(route.request.url)
    route.abort()


def run(site: Path, out: Path, chromium: str) -> list[str]:
    """Check every page; returns the problems (empty: the site is fine)."""
    from playwright.sync_api import sync_playwright

    server, base = serve(site)
    out.mkdir(parents=True, exist_ok=True)
    problems, links, refused, maths = [], set(), [], 0
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium, args=CHROMIUM_FLAGS)
            context = browser.new_context(viewport={"width": 1280, "height": 900}, service_workers="block")
            context.route(re.compile(r"^(?!http://127\.0\.0\.1:\d+/).*"), lambda r: _external(r, refused))
            shots = {path: name for name, path in SCREENSHOTS.items()}
            for path in pages(site):
                page = context.new_page()
                found, page_links, n_math = check_page(page, base, path)
                problems += found
                links |= page_links
                maths += n_math
                if path in shots:
                    screenshot(page, out / f"{shots[path]}.png")
                page.close()
            offline = browser.new_context(viewport={"width": 1280, "height": 900})
            problems += file_pages(offline, site, out)
            browser.close()
    finally:
        server.shutdown()
    problems += [
        f"request leaving localhost (refused, the site must render offline): {u}"
        for u in sorted(set(refused))
    ]
    problems += broken_links(site, base, links)
    problems += offline_links(site)
    problems += examples_without_figures(site)
    missing = [path for path in SCREENSHOTS.values() if not _target_file(site, path).is_file()]
    problems += [f"page to screenshot is missing: /{path}" for path in missing]
    if maths == 0:
        problems.append("no formula on any page: the maths pipeline rendered nothing")
    print(f"checked {len(pages(site))} pages, {maths} formulas, {len(links)} links; screenshots in {out}")
    return problems


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").strip().split("\n")[0])
    parser.add_argument("--site", type=Path, default=Path("site"))
    parser.add_argument("--out", type=Path, default=Path("results/site_check"))
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    args = parser.parse_args(argv)
    if not (args.site / "index.html").is_file():
        print(f"{args.site}/index.html not found: run 'mkdocs build --strict' first", file=sys.stderr)
        return 2
    if not Path(args.chromium).is_file():
        print(f"no Chromium at {args.chromium} (Debian: apt-get install chromium)", file=sys.stderr)
        return 2
    problems = run(args.site, args.out, args.chromium)
    for problem in problems:
        print(problem, file=sys.stderr)
    print(f"{len(problems)} problem(s)" if problems else "site check passed")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
