"""The course website (`make site`): built offline from the student edition, every page opened in
Debian's Chromium from a local server: figures drawn, equations typeset, links that lead
somewhere, no console error, and not one request to another host.

The test builds the site exactly as `make site` does, but with two of the lessons (the first, and
the checkerboards with three figures) and a one-figure handout, in about half a minute; `make
site` runs all seven (about a minute and a half). To check a full site built already:
INTERP_SITE_HTML=build/site/html pytest tests/test_site.py.
"""

from __future__ import annotations

import functools
import html
import importlib.util
import os
import re
import threading
import urllib.parse
import urllib.request
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path

import nbformat
import numpy as np
import pytest
from browser import ARTIFACTS, ROOT
from PIL import Image

from interp import editions

pytestmark = pytest.mark.browser

pytest.importorskip("playwright.sync_api")

ALL_LESSONS = sorted((ROOT / "lessons").glob("*.ipynb"))
#: The lessons the test's site is built from (INTERP_SITE_HTML: every lesson).
LESSONS = (
    ALL_LESSONS
    if os.environ.get("INTERP_SITE_HTML")
    else [p for p in ALL_LESSONS if p.stem in ("01_the_problem", "06_checkerboards")]
)


def site_build():
    """site/build.py, imported (site/ is no package)."""
    spec = importlib.util.spec_from_file_location("site_build", ROOT / "site" / "build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The built website's HTML folder."""
    if os.environ.get("INTERP_SITE_HTML"):
        return Path(os.environ["INTERP_SITE_HTML"]).resolve()
    if not (ROOT / "site" / "node_modules" / "mathjax").exists():
        if os.environ.get("CI"):
            pytest.fail("CI must have site/node_modules (make test runs npm ci --prefix site)")
        pytest.skip("no site/node_modules: run `npm ci --prefix site` (make test does)")
    out = tmp_path_factory.mktemp("site")
    return site_build().build_site(
        out,
        repo="https://github.com/acme/interp",
        hub="https://hub.example.edu",
        lessons=LESSONS,
        handout=["st-mapping"],
    )


class _Quiet(SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:
        pass


@pytest.fixture(scope="module")
def server(site):
    handler = functools.partial(_Quiet, directory=str(site))
    httpd = ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()
    httpd.server_close()


#: A page that only sends the browser on to another (Jupyter Book's index.html). Checked
#: after "load", such a page may navigate away in the middle of the checks.
REDIRECT = re.compile(r'<meta http-equiv="refresh" content="0; url=([^"]+)"', re.IGNORECASE)


def pages(site: Path) -> list[str]:
    return sorted(p.name for p in site.glob("*.html"))


def test_the_site_has_a_page_per_lesson_and_the_handout(site):
    names = pages(site)
    assert {p.stem + ".html" for p in LESSONS} <= set(names)
    assert "index.html" in names and "intro.html" in names
    (handout,) = site.glob("_downloads/*/handout.pdf")
    assert handout.read_bytes().startswith(b"%PDF")
    assert 'href="_downloads/' in (site / "intro.html").read_text()
    (site / "mathjax" / "tex-chtml.js").resolve(strict=True)
    assert not list((site / "_static").rglob("tex-chtml.js")), "MathJax must stay out of _static"


def test_the_site_is_the_student_edition(site):
    """No solution and no written answer reaches the website; the verdicts are 'not written
    yet', as a student sees them."""
    for path in LESSONS:
        page = html.unescape(re.sub(r"<[^>]+>", "", (site / f"{path.stem}.html").read_text()))
        assert "SOLUTION" not in page and "Answers" not in page
        flat = re.sub(r"\s", "", page)
        source = nbformat.read(ROOT / "source" / "lessons" / path.name, as_version=4)
        for cell in source.cells:
            if editions.is_exercise(cell):
                body = cell.source.split(editions.BEGIN)[1].split(editions.END)[0]
                for line in body.strip().splitlines():
                    assert re.sub(r"\s", "", line) not in flat, f"{path.stem}: {line}"
            elif editions.is_answer(cell):
                answer = cell.source.split(editions.BEGIN)[1].split(editions.END)[0]
                first = answer.strip().splitlines()[0].removeprefix("- ")[:40]
                assert re.sub(r"\s", "", html.unescape(first)) not in flat, first
        assert "not written yet" in page, path.stem
        # the apps' controls need a kernel: the static pages show the figures alone
        assert "widget-view" not in (site / f"{path.stem}.html").read_text()


def test_lessons_have_launch_buttons_for_binder_and_the_hub(site):
    for path in LESSONS:
        links = {
            html.unescape(h)
            for h in re.findall(r'href="([^"]+)"', (site / f"{path.stem}.html").read_text())
        }
        binder = f"https://mybinder.org/v2/gh/acme/interp/main?urlpath=lab/tree/lessons/{path.name}"
        assert binder in links, path.stem
        hub = [
            link
            for link in links
            if link.startswith("https://hub.example.edu/hub/user-redirect/git-pull?")
        ]
        assert len(hub) == 1, path.stem
        query = urllib.parse.parse_qs(urllib.parse.urlsplit(hub[0]).query)
        assert query["repo"] == ["https://github.com/acme/interp"]
        assert query["urlpath"] == [f"lab/tree/interp/lessons/{path.name}"]
        assert query["branch"] == ["main"]


def _local_path(site: Path, url: str) -> Path:
    path = urllib.parse.unquote(urllib.parse.urlsplit(url).path).lstrip("/")
    return site / (path or "index.html")


def _ids(site: Path, page: str) -> set[str]:
    return set(re.findall(r'\bid="([^"]+)"', (site / page).read_text()))


def test_every_page_in_chromium(site, server, browser):
    problems: dict[str, list[str]] = {}
    for name in pages(site):
        page = browser.new_page(viewport={"width": 1280, "height": 900})
        found: list[str] = []
        page.on("console", lambda m, found=found: m.type == "error" and found.append(m.text))
        page.on("pageerror", lambda e, found=found: found.append(str(e)))
        page.on("requestfailed", lambda r, found=found: found.append(f"failed: {r.url}"))
        page.on(
            "response",
            lambda r, found=found: r.status >= 400 and found.append(f"{r.status}: {r.url}"),
        )

        def route(route, found=found):
            if route.request.url.startswith(server + "/"):
                route.continue_()
            else:  # record it, and never let it leave the machine
                found.append(f"request to another host: {route.request.url}")
                route.abort()

        page.route("**/*", route)
        redirect = REDIRECT.search((site / name).read_text())
        try:
            if redirect:  # index.html: it must lead to a page of the site (checked on its own)
                target = redirect.group(1)
                if not (site / target).exists():
                    found.append(f"redirects to a missing page: {target}")
                else:
                    page.goto(f"{server}/{name}", wait_until="load")
                    page.wait_for_url(f"{server}/{target}", timeout=30_000)
            else:
                page.goto(f"{server}/{name}", wait_until="load")
                found += check_page(site, page, name)
        finally:
            if found:
                ARTIFACTS.mkdir(exist_ok=True)
                page.screenshot(path=str(ARTIFACTS / f"site-{name}.png"), full_page=True)
            page.close()
        if found:
            problems[name] = found
    assert not problems, problems


def check_page(site: Path, page, name: str) -> list[str]:
    """What is wrong with one page, open in the browser."""
    found = []
    # Equations: MathJax (served by the site) typesets every one; no TeX is left showing.
    math = page.locator(".math").count()
    if math:
        page.wait_for_function(
            "() => window.MathJax && MathJax.startup && MathJax.startup.promise"
            " && document.querySelectorAll('mjx-container').length > 0",
            timeout=30_000,
        )
        page.evaluate("() => MathJax.startup.promise")
        untypeset = page.evaluate(
            "() => [...document.querySelectorAll('.math')]"
            ".filter(m => !m.querySelector('mjx-container')).map(m => m.textContent)"
        )
        found += [f"math not typeset: {m[:60]}" for m in untypeset]
    text = page.locator("article").inner_text() if page.locator("article").count() else ""
    for raw in ("$$", "\\(", "\\["):
        if raw in text:
            found.append(f"raw TeX on the page: {raw}")
    # Figures: every picture loads and shows something (not a blank rectangle).
    if name.startswith(tuple(p.stem for p in LESSONS)):
        images = page.locator(".cell_output img")
        if images.count() == 0:
            found.append("a lesson without a figure")
        for k in range(images.count()):
            image = images.nth(k)
            if not image.evaluate("i => i.complete && i.naturalWidth > 0"):
                found.append(f"figure {k} did not load")
                continue
            src = image.evaluate("i => i.src")
            alt = image.get_attribute("alt") or ""
            if len(alt) < 20 or alt.startswith("_images/"):  # the figure's title and result
                found.append(f"figure {k} has no alt text: {alt!r}")
            pixels = np.asarray(Image.open(_local_path(site, src)).convert("L"), dtype=float)
            if pixels.std() < 10:
                found.append(f"figure {k} is blank: {src}")
        if math == 0:
            found.append("a lesson without typeset equations")
    # Links inside the site lead to a page that exists, and to an anchor on it that exists.
    hrefs = page.evaluate("() => [...document.querySelectorAll('a[href]')].map(a => a.href)")
    base = page.url.rsplit("/", 1)[0] + "/"
    for href in hrefs:
        if not href.startswith(base):
            continue
        target = _local_path(site, href)
        if not target.exists():
            found.append(f"broken link: {href}")
            continue
        fragment = urllib.parse.urlsplit(href).fragment
        if fragment and target.suffix == ".html":
            if urllib.parse.unquote(fragment) not in _ids(site, target.name):
                found.append(f"broken anchor: {href}")
    return found


def test_make_site_builds_the_site_with_the_repository_and_hub():
    makefile = (ROOT / "Makefile").read_text()
    recipe = re.search(r"^site:.*\n\t(.+)$", makefile, re.M).group(1)
    assert "site/build.py site" in recipe and "--repo" in recipe and "--hub" in recipe
