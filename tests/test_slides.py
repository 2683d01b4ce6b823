"""Live lecture slides (`make slides`): the lessons as reveal.js slides through Voilà's reveal
template, one slide per `##` heading, the figures live, served without a CDN, in presentation
mode; driven in Debian's Chromium."""

from __future__ import annotations

import importlib.util
import io
import os
import re
import sys
import time

import nbformat
import numpy as np
import pytest
from browser import ARTIFACTS, ROOT, start_on_free_port, steady_box, stop
from PIL import Image

from interp import editions

LESSONS = sorted((ROOT / "lessons").glob("*.ipynb"))


def site_build():
    spec = importlib.util.spec_from_file_location("site_build", ROOT / "site" / "build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def kinds(notebook: nbformat.NotebookNode) -> list[str]:
    return [c.metadata["slideshow"]["slide_type"] for c in notebook.cells]


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.stem)
def test_slides_follow_the_lesson_structure(path):
    student = nbformat.read(path, as_version=4)
    slides = editions.slides_edition(student)
    assert [c.source for c in slides.cells] == [c.source for c in student.cells]
    headings = [c for c in student.cells if re.match(r"#{1,2} ", c.source)]
    assert kinds(slides).count("slide") == len(headings) >= 2
    for cell, kind in zip(slides.cells, kinds(slides), strict=True):
        if cell.cell_type == "code" and re.match(r"apps\.\w+\(", cell.source):
            assert kind == "subslide", "a figure has a sub-slide of its own"
        if "raise NotImplementedError" in cell.source or cell.source.startswith("%matplotlib"):
            assert kind == "skip"
    assert kinds(slides)[0] == "slide"


def test_slides_command_line(tmp_path):
    assert editions.main(["slides", "--root", str(ROOT), "--out", str(tmp_path)]) == 0
    for path in LESSONS:
        written = nbformat.read(tmp_path / path.name, as_version=4)
        assert kinds(written) == kinds(editions.slides_edition(nbformat.read(path, as_version=4)))


def test_make_slides_serves_them_live_in_presentation_mode():
    makefile = (ROOT / "Makefile").read_text()
    recipe = re.search(r"^slides:.*\n((?:\t.+\n)+)", makefile, re.M).group(1)
    assert "site/build.py slides --out build/slides" in recipe
    assert "INTERP_PRESENTATION=1" in recipe and "JUPYTER_PATH=build/slides/jupyter" in recipe
    assert "-m interp.classroom" in recipe and "--template=interp-reveal" in recipe


def test_the_template_serves_reveal_and_its_assets_itself(tmp_path):
    if not (ROOT / "site" / "node_modules" / "reveal.js").exists():
        pytest.skip("no site/node_modules: run `npm ci --prefix site` (make test does)")
    lessons = site_build().build_slides(tmp_path)
    assert sorted(p.name for p in lessons.glob("*.ipynb")) == [p.name for p in LESSONS]
    static = tmp_path / "jupyter" / "voila" / "templates" / "interp-reveal" / "static"
    for asset in (
        "revealjs/dist/reveal.css",
        "revealjs/dist/theme/white.css",
        "jquery/jquery.min.js",
        "fontawesome/css/all.min.css",
    ):
        assert (static / asset).is_file(), asset
    # Voilà's own static folder has reveal.js (its script): the assets must not shadow it
    assert not (static / "reveal.js").exists()


# --- in the browser ------------------------------------------------------------------------

#: The slide on show: reveal.js nests each slide's sub-slides in it, and marks both "present".
CURRENT = ".reveal .slides > section.present > section.present"


def pixels(element) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(element.screenshot())).convert("RGB"), dtype=int)


def wait_until(condition, seconds: float, message: str):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        value = condition()
        if value is not None and value is not False:
            return value
        time.sleep(0.3)
    raise AssertionError(message)


@pytest.fixture
def slides_server(tmp_path):
    """`make slides`: the slides of lesson 1, served as the Makefile serves them."""
    if not (ROOT / "site" / "node_modules" / "reveal.js").exists():
        if os.environ.get("CI"):
            pytest.fail("CI must have site/node_modules (make test runs npm ci --prefix site)")
        pytest.skip("no site/node_modules: run `npm ci --prefix site` (make test does)")
    lessons = site_build().build_slides(tmp_path / "slides")
    env = {
        **os.environ,
        "INTERP_PRESENTATION": "1",
        "JUPYTER_PATH": str(tmp_path / "slides" / "jupyter"),
        "JUPYTER_CONFIG_DIR": str(tmp_path / "config"),
        "JUPYTER_RUNTIME_DIR": str(tmp_path / "runtime"),
    }
    env.pop("MPLBACKEND", None)
    log = tmp_path / "voila.log"

    def command(port: int) -> list[str]:
        return [
            sys.executable, "-m", "interp.classroom", "--template=interp-reveal", "--no-browser",
            f"--port={port}", "--Voila.ip=127.0.0.1", "--Voila.port_retries=0", str(lessons),
        ]  # fmt: skip

    process, port = start_on_free_port(command, log, env)
    base = f"http://127.0.0.1:{port}"
    try:
        yield base
    finally:
        stop(process)


@pytest.mark.browser
def test_the_deck_opens_advances_and_a_slider_moves_the_figure(slides_server, browser, request):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors, elsewhere = [], []
    page.on("console", lambda m: m.type == "error" and errors.append(m.text))
    page.on("pageerror", lambda e: errors.append(str(e)))

    def route(route):
        if route.request.url.startswith(slides_server + "/"):
            route.continue_()
        else:
            elsewhere.append(route.request.url)
            route.abort()

    page.route("**/*", route)
    try:
        page.goto(f"{slides_server}/voila/render/01_the_problem.ipynb", timeout=120_000)
        page.wait_for_selector(".reveal.ready", timeout=120_000)
        page.wait_for_selector("#rendered_cells", state="visible", timeout=120_000)
        present = page.locator(CURRENT)
        assert "1. The problem" in present.text_content()
        assert "%matplotlib" not in page.locator("body").inner_text(), "no code on slides"
        # Equations are typeset (by Voilà's renderers), not left as TeX.
        page.wait_for_selector(f"{CURRENT} mjx-container", state="attached", timeout=30_000)
        assert "$" not in present.inner_text()
        page.keyboard.press("Space")
        wait_until(lambda: page.evaluate("location.hash") == "#/1", 10, "did not advance")
        assert "Projection divides by depth" in present.text_content()
        # On to the sub-slide with the figure: its canvas is live (ipympl).
        canvas = page.locator(f"{CURRENT} .jupyter-matplotlib-canvas-div canvas")
        for _ in range(6):
            if canvas.count() and canvas.first.is_visible():
                break
            page.keyboard.press("Space")
            page.wait_for_timeout(800)
        canvas = canvas.first
        canvas.wait_for(state="visible", timeout=60_000)
        assert re.fullmatch(r"#/\d+/\d+", page.evaluate("location.hash"))
        before = wait_until(
            lambda: (p := pixels(canvas)).std() > 10 and p, 60, "the figure was never drawn"
        )
        control = page.locator(f"{CURRENT} .widget-slider").first
        # presentation mode (INTERP_PRESENTATION=1) makes the apps' sliders 380 px wide
        # (three to a row on a projector), wider than the 300 px they have in a notebook
        assert control.evaluate("e => e.offsetWidth") >= 360
        readout = control.locator(".widget-readout")
        start = readout.inner_text()
        handle = control.locator(".noUi-handle")
        box = steady_box(handle)
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        for step in range(1, 6):
            page.mouse.move(x + 16 * step, y)
        page.mouse.up()
        wait_until(lambda: readout.inner_text() != start, 20, "the slider did not move")
        wait_until(
            lambda: np.abs(pixels(canvas) - before).sum() > 0, 30, "the figure did not change"
        )
        assert not errors, errors
        assert not elsewhere, f"requests to other hosts: {elsewhere}"
    except BaseException:
        ARTIFACTS.mkdir(exist_ok=True)
        page.screenshot(path=str(ARTIFACTS / f"{request.node.name}.png"))
        raise
    finally:
        page.close()
