"""The lessons in a real browser: JupyterLab and Voilà, driven through Debian's Chromium.

A failing test saves a screenshot in test-artifacts/. With INTERP_SCREENSHOTS=1 the tests also
refresh the README's screenshots in docs/screenshots/.
"""

from __future__ import annotations

import io
import os
import shutil
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from browser import (
    ARTIFACTS,
    ROOT,
    SCREENSHOTS,
    server,
    start_on_free_port,
    steady_box,
    stop,
    sync_api,
)
from matplotlib.figure import Figure
from PIL import Image

from interp.plots import registry

pytestmark = pytest.mark.browser

sync_api()  # skips the module without Playwright, but not in CI

#: The notebook JupyterLab shows (it keeps the others in the page, hidden).
VISIBLE = ".jp-NotebookPanel:not(.lm-mod-hidden)"


@pytest.fixture
def page(browser, request):
    page = browser.new_page(viewport={"width": 1500, "height": 1100})
    page.console_errors = []
    page.on("console", lambda m: m.type == "error" and page.console_errors.append(m.text))
    page.on("pageerror", lambda e: page.console_errors.append(str(e)))
    # A failed resource's console message does not say which: note its address beside it.
    page.on(
        "response",
        lambda r: r.status >= 400 and page.console_errors.append(f"{r.status} {r.url}"),
    )
    yield page
    report = getattr(request.node, "report_call", None)
    if report is not None and report.failed:
        ARTIFACTS.mkdir(exist_ok=True)
        path = ARTIFACTS / f"{request.node.name}.png"
        page.screenshot(path=str(path), full_page=True)
        print(f"screenshot of the failing page: {path}")
    page.close()


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    with server("lab", tmp_path_factory.mktemp("lab")) as url:
        yield url


def pixels(element) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(element.screenshot())).convert("RGB"), dtype=int)


def wait_until_changed(element, before: np.ndarray, region=np.s_[:, :], seconds=20.0):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        now = pixels(element)
        if now.shape != before.shape or np.abs(now[region] - before[region]).sum() > 0:
            return now
        time.sleep(0.2)
    raise AssertionError("the figure's pixels did not change")


def wait_until_drawn(element, seconds=30.0) -> np.ndarray:
    """Wait for the canvas to show a picture (not a blank rectangle) that has settled."""
    deadline = time.monotonic() + seconds
    last = None
    while time.monotonic() < deadline:
        now = pixels(element)
        if now.std() > 10 and last is not None and np.array_equal(now, last):
            return now
        last = now
        time.sleep(0.3)
    raise AssertionError("the figure was never drawn")


#: The notebook on show has a kernel that is connected and idle: safe to run cells.
KERNEL_READY = """() => {
    const panel = window.jupyterapp && window.jupyterapp.shell.currentWidget;
    const kernel = panel && panel.sessionContext && panel.sessionContext.session
        && panel.sessionContext.session.kernel;
    return !!kernel && kernel.connectionStatus === 'connected' && kernel.status === 'idle';
}"""


def open_and_run(page, base: str, notebook: str):
    page.goto(f"{base}/lab/tree/{notebook}?reset")  # a fresh workspace: only this notebook
    page.wait_for_selector(".jp-Notebook", timeout=60_000)
    page.wait_for_function(KERNEL_READY, timeout=90_000)
    page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
    canvas = page.locator(f"{VISIBLE} .jupyter-matplotlib-canvas-div canvas").first
    canvas.wait_for(state="visible", timeout=90_000)
    return canvas


def slider(page, description: str, scope: str = VISIBLE):
    label = page.locator(".widget-label", has_text=description)
    return page.locator(f"{scope} .widget-slider", has=label).first


def drag_handle(page, control, dx: float) -> None:
    handle = control.locator(".noUi-handle")
    box = steady_box(handle)
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for step in range(1, 6):  # dragging: several moves, as a hand would
        page.mouse.move(x + dx * step / 5, y)
    page.mouse.up()


def assert_no_errors(page) -> None:
    errors = page.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]')
    assert errors.count() == 0, errors.all_inner_texts()
    assert page.locator(".jp-RenderedText[data-mime-type*='error']").count() == 0
    assert not page.console_errors, page.console_errors


def save_screenshot(page, name: str, canvas=None) -> None:
    """With INTERP_SCREENSHOTS=1, save the app around ``canvas`` (or the page) for the README."""
    if os.environ.get("INTERP_SCREENSHOTS") != "1":
        return
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    path = str(SCREENSHOTS / f"{name}.png")
    if canvas is None:
        page.screenshot(path=path)
    else:
        app = canvas.locator("xpath=ancestor::div[contains(@class, 'jp-OutputArea-output')]")
        app.first.scroll_into_view_if_needed()
        app.first.screenshot(path=path)


def test_checkerboard_lesson_moves_with_its_camera_slider(lab, page):
    canvas = open_and_run(page, lab, "06_checkerboards.ipynb")
    before = wait_until_drawn(canvas)
    save_screenshot(page, "checkerboards", canvas)
    pitch = slider(page, "pitch (deg)")
    pitch.scroll_into_view_if_needed()
    value_before = pitch.locator(".widget-readout").inner_text()
    drag_handle(page, pitch, 25)
    wait_until_changed(canvas, before)
    # The first change seen can be a few pixels (the page scrolled to the slider): measure the
    # picture once it has settled.
    after = wait_until_drawn(canvas)
    assert pitch.locator(".widget-readout").inner_text() != value_before
    assert np.mean(np.any(after != before, axis=2)) > 0.05, "too little of the figure changed"
    assert_no_errors(page)


def test_dragging_an_endpoint_moves_the_linked_panels(lab, page):
    from interp import apps

    canvas = open_and_run(page, lab, "02_projecting_a_line.ipynb")
    canvas.scroll_into_view_if_needed()
    before = wait_until_drawn(canvas)
    # Where A is drawn: the same app, laid out the same way, tells us (figure pixels, y up).
    app = apps.projecting_a_line()
    a_w, a_x = -app.plot.view.points["A"][1], app.plot.view.points["A"][0]
    px, py = app.plot.view.ax.transData.transform((a_w, a_x))
    height = app.figure.bbox.height
    target_w, target_x = 5.0, 3.0
    tx, ty = app.plot.view.ax.transData.transform((target_w, target_x))
    box = steady_box(canvas)
    readout = slider(page, "A: depth w").locator(".widget-readout")
    start = readout.inner_text()
    page.mouse.move(box["x"] + px, box["y"] + height - py)
    page.mouse.down()
    for step in range(1, 9):
        f = step / 8
        page.mouse.move(box["x"] + px + f * (tx - px), box["y"] + height - (py + f * (ty - py)))
    page.wait_for_timeout(300)  # a hand rests before letting go
    page.mouse.up()
    # The kernel handles the motion events in order: wait for the last one to arrive.
    page.wait_for_function(
        "([el, target]) => Math.abs(parseFloat(el.innerText) - target) < 0.3",
        arg=[readout.element_handle(), target_w],
        timeout=20_000,
    )
    assert readout.inner_text() != start
    # The linked panels are the right two thirds (the toolbar fades in over the left one).
    third = before.shape[1] // 3
    after = wait_until_changed(canvas, before, region=np.s_[:, third:])
    for panel in (np.s_[:, third : 2 * third], np.s_[:, 2 * third :]):
        assert np.abs(after[panel] - before[panel]).sum() > 0, "a linked panel did not move"
    save_screenshot(page, "projecting_a_line", canvas)
    assert_no_errors(page)


def test_voila_shows_figures_and_sliders_without_code(tmp_path, page):
    # Voilà's lab template links Font Awesome from a CDN, and this machine has no internet:
    # answer those two requests with an empty stylesheet, so that the console must stay free
    # of every other error.
    page.route(
        "https://cdn.jsdelivr.net/npm/@fortawesome/**",
        lambda route: route.fulfill(status=200, content_type="text/css", body=""),
    )
    with server("voila", tmp_path, "06_checkerboards.ipynb") as url:
        page.goto(url)
        canvas = page.locator(".jupyter-matplotlib-canvas-div canvas").first
        canvas.wait_for(state="visible", timeout=120_000)
        before = wait_until_drawn(canvas)
        text = page.locator("body").inner_text()
        assert "Checkerboards" in text and "Try this" in text  # the prose is there
        for code in (
            "apps.checkerboards_outside()",
            "%matplotlib widget",
            "import interp",
            "def checker",
        ):
            assert code not in text, f"Voilà shows code: {code}"
        drag_handle(page, slider(page, "height", scope="body"), 80)  # Voilà: one page
        wait_until_changed(canvas, before)
        # Screen readers: the key result as live text (as in JupyterLab).
        assert page.get_by_role("slider").count() >= 10
        assert page.locator(".interp-readout[role=status]").count() >= 2
        save_screenshot(page, "voila")
        assert not page.console_errors, page.console_errors


def kernel_processes(pid: int) -> int:
    """How many ipykernel processes the server with process id ``pid`` has started."""
    count = 0
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
            cmdline = (entry / "cmdline").read_bytes()
        except OSError:
            continue
        parent = int(stat.rsplit(")", 1)[1].split()[1])
        if parent == pid and b"ipykernel" in cmdline:
            count += 1
    return count


def wait_for_kernels(pid: int, condition, seconds: float = 60.0) -> int:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        count = kernel_processes(pid)
        if condition(count):
            return count
        time.sleep(0.5)
    raise AssertionError(f"kernel count stayed at {kernel_processes(pid)}")


def late_once(seconds: float):
    """A route handler that holds the first request it sees for ``seconds``, then lets every
    request through (the page's other requests wait behind the first)."""
    held = []

    def handle(route) -> None:
        if not held:
            held.append(route.request.url)
            time.sleep(seconds)
        route.continue_()

    return handle


def test_classroom_server_culls_closed_pages_and_caps_kernels(tmp_path, browser):
    """`make present` runs Voilà through interp.classroom: a closed tab's kernel goes away, and
    no more than --max-kernels run at once (Voilà alone keeps one per page ever opened). The
    idle time is short (3 s): a page that takes longer than that to connect after its cells
    ran still gets its figure (its kernel waits for it; test_classroom tests the wait)."""
    lessons = tmp_path / "lessons"
    shutil.copytree(ROOT / "lessons", lessons)
    path = [str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])]  # this checkout's interp
    env = {
        **os.environ,
        "JUPYTER_CONFIG_DIR": str(tmp_path / "config"),
        "PYTHONPATH": os.pathsep.join(path),
    }
    env.pop("MPLBACKEND", None)
    log = tmp_path / "voila.log"

    def command(port: int) -> list[str]:
        return [
            sys.executable, "-m", "interp.classroom", "--idle", "3", "--interval", "1",
            "--max-kernels", "2", "--no-browser", f"--port={port}", "--Voila.ip=127.0.0.1",
            "--Voila.port_retries=0", str(lessons / "03_the_st_mapping.ipynb"),
        ]  # fmt: skip

    process, port = start_on_free_port(command, log, env)
    url = f"http://127.0.0.1:{port}/"
    try:
        opened = []
        for k in range(2):  # two students keep their pages open: two kernels
            page = browser.new_page()
            response = page.goto(url, timeout=120_000)
            try:
                page.locator(".jupyter-matplotlib-canvas-div canvas").first.wait_for(
                    timeout=120_000
                )
            except Exception as error:
                message = (
                    f"page {k + 1}: {response.status}, no figure; Voilà said:\n"
                    f"{log.read_text()[-3000:]}"
                )
                raise AssertionError(message) from error
            opened.append(page)
        assert kernel_processes(process.pid) == 2
        # A third page would pass the cap, and every kernel has a page: refused, not started.
        third = browser.new_page()
        response = third.goto(url, timeout=120_000)
        assert response.status == 503 and "The server is full (2 pages are open)" in third.content()
        third.close()
        assert kernel_processes(process.pid) == 2
        for page in opened:  # the students close their tabs
            page.close()
        wait_for_kernels(process.pid, lambda n: n == 0, seconds=60)
        # Pages opened and closed one after another never leave more than the cap behind. The
        # first gets its scripts 6 s late, as on a busy machine (they load after the cells
        # ran): its kernel, idle and unconnected past --idle, waits for it.
        for k in range(3):
            page = browser.new_page()
            if k == 0:
                page.route("**/*.js", late_once(seconds=6))
            page.goto(url, timeout=120_000)
            figure = page.locator(".jupyter-matplotlib-canvas-div canvas").first
            try:
                figure.wait_for(timeout=120_000)
            except Exception as error:
                message = f"no figure; Voilà said:\n{log.read_text()[-3000:]}"
                raise AssertionError(message) from error
            page.close()
            assert kernel_processes(process.pid) <= 2
        wait_for_kernels(process.pid, lambda n: n == 0, seconds=60)
    finally:
        stop(process)


# --- figures a screen reader can follow ------------------------------------------------------


def kernel_readout(figure_class, **params) -> str:
    """The readout the same figure gives in the kernel, at the defaults changed by ``params``."""
    values = {name: param.default for name, param in figure_class.PARAMS.items()} | params
    return figure_class(Figure(figsize=figure_class.size), **values).readout()


def wait_for_new_text(locator, old: str, seconds: float = 20.0) -> str:
    """The locator's text once it differs from ``old`` (the widget replaces its element)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        text = locator.inner_text()
        if text != old:
            return text
        time.sleep(0.2)
    raise AssertionError(f"the readout still says {old!r}")


def shown_at_first(figure_class, name: str) -> bool:
    """Whether an app's control ``name`` is on show before any tab is chosen: an app with
    more than ``ROWS_OF_CONTROLS`` controls shows its camera's first (``controls_panel``)."""
    from interp.apps._app import ROWS_OF_CONTROLS
    from interp.plots.params import CAMERA_RANGES

    return len(figure_class.PARAMS) <= ROWS_OF_CONTROLS or name in CAMERA_RANGES


def test_the_readout_is_live_text_that_follows_a_slider(lab, page):
    canvas = open_and_run(page, lab, "06_checkerboards.ipynb")
    wait_until_drawn(canvas)
    readout = page.locator(f"{VISIBLE} .interp-readout").first
    assert readout.get_attribute("role") == "status"  # announced when it changes...
    assert readout.get_attribute("aria-live") == "polite"  # ...without interrupting
    before = readout.inner_text()
    assert before == kernel_readout(registry.CheckerboardsOutside)  # lesson 6's first app
    assert page.get_by_role("slider").count() >= 10
    # The dropdowns are named by their labels (a <label for=...> beside a <select>).
    dropdowns = page.locator(f"{VISIBLE} .widget-dropdown select:visible")
    named = [
        page.get_by_role("combobox", name=param.label, exact=True).count()
        for figure_class in (registry.CheckerboardsOutside, registry.UVImagesFigure)
        for name, param in figure_class.PARAMS.items()
        if param.options and shown_at_first(figure_class, name)
    ]
    assert dropdowns.count() == sum(named) and all(named), named
    # The pitch slider (the second of the first app), moved with keys.
    pitch = page.get_by_role("slider").nth(1)
    start = float(pitch.get_attribute("aria-valuenow"))
    pitch.focus()
    for _ in range(5):
        page.keyboard.press("ArrowRight")
    after = wait_for_new_text(readout, before)
    value = float(pitch.get_attribute("aria-valuenow"))
    assert value > start
    # Settled: the text is the kernel's words at the slider's final value.
    deadline = time.monotonic() + 20
    while readout.inner_text() != kernel_readout(registry.CheckerboardsOutside, pitch=value):
        assert time.monotonic() < deadline, (after, value)
        time.sleep(0.2)
    assert_no_errors(page)
