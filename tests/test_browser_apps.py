"""Every app of every lesson, proven in a real browser (JupyterLab and Voilà in Chromium).

For each app, after Run All in a fresh kernel: its figure is on the page, not blank, and is
the app's figure (the canvas's pixels against the same app drawn afresh in the kernel); moving
a slider with the mouse changes it, and once things settle the picture is the figure at the
slider's final value (and the readout shows that value); no error outputs, no console errors.
In lessons 1-2 the same for dragging endpoint A in the figure. Every app of
:data:`interp.apps.ALL` and every app a lesson makes (``apps.App(registry.X)`` too) is tested.

Then whether each app fits the screen it is shown on, without scrolling sideways: JupyterLab
with the file browser open at 1280x800 and at 1920x1080, and Voilà in presentation mode
(INTERP_PRESENTATION=1) at a projector's 1280x720 and at 1920x1080, where the controls' text
must also be larger than JupyterLab's 13 px.

One JupyterLab and one Voilà server for the module; each lesson is run once and its page kept
for all of its apps' tests. ``INTERP_BROWSER_REPEAT=N`` (default 2) sets how many more times
lesson 8 (the approximation lab, blank after most Run Alls before the fix) is run in fresh
kernels, to catch figures that only sometimes stay blank.

The kernels import the ``interp`` of this checkout (``browser.server`` puts it first on their
PYTHONPATH), whatever the environment has installed; a test checks that they do.
"""

from __future__ import annotations

import json
import os
import time

import pytest
from browser import (
    ARTIFACTS,
    CONTROL,
    FRAME_PROBE,
    ROOT,
    VISIBLE,
    app_root,
    base_app,
    canvas_pixels,
    endpoint_a,
    figure_canvas,
    figure_of,
    is_blank,
    kernel_interp,
    kernel_run,
    kernel_truth,
    lessons,
    mismatch,
    open_lesson,
    open_voila_apps,
    overflow,
    server,
    show_file_browser,
    shutdown_kernel,
    slider_for,
    steady_box,
    sync_api,
    wait_idle,
    write_all_apps_notebook,
)

from interp import apps

pytestmark = pytest.mark.browser

sync_api()  # skips the module without Playwright, but not in CI

#: Every lesson and the apps it makes, in order; an app a lesson makes twice is NAME@2.
LESSONS = lessons()
#: Apps of ``interp.apps.ALL`` that no lesson makes are tested from a notebook of their own.
MORE_APPS = "more_apps.ipynb"
UNUSED = [
    name for name in apps.ALL if name not in {base_app(n) for ns in LESSONS.values() for n in ns}
]
if UNUSED:
    LESSONS[MORE_APPS] = UNUSED
LESSON_OF = {name: notebook for notebook, names in LESSONS.items() for name in names}
#: Every app as made on a page (``texture_filtering`` and ``texture_filtering@2``...).
APPS = list(LESSON_OF)
#: Every app once, in lesson order (for the Voilà page).
UNIQUE = list(dict.fromkeys(base_app(name) for name in APPS))

#: At most this fraction of a figure's pixels may differ from the app drawn in the kernel.
TOLERANCE = 0.001


#: Lessons whose figures went missing after some Run Alls: run again in fresh kernels.
FLAKY_LESSONS = ("08_gpus.ipynb",)
REPEAT = int(os.environ.get("INTERP_BROWSER_REPEAT", "2"))


def test_every_app_is_tested():
    from interp.plots import registry

    assert set(apps.ALL) <= {base_app(name) for name in APPS}
    assert {base_app(name).replace("_", "-") for name in APPS} <= set(registry.FIGURES), (
        "a lesson makes an app of no known figure"
    )
    assert sorted(CONTROL) == sorted(UNIQUE), "every app needs its control in CONTROL"
    for name in UNIQUE:
        assert CONTROL[name] in figure_of(name).PARAMS


# ---------------------------------------------------------------------------------- fixtures


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """JupyterLab on a copy of the lessons, plus :data:`MORE_APPS`."""
    workdir = tmp_path_factory.mktemp("lab")
    with server("lab", workdir) as url:
        if UNUSED:
            write_all_apps_notebook(workdir / "lessons" / MORE_APPS, UNUSED)
        yield url


@pytest.fixture(scope="module")
def voila(tmp_path_factory):
    """Voilà in presentation mode on the lessons, plus ``all_apps.ipynb``: every app once, in
    the order of the lessons, on one page (Voilà lays out every notebook alike, and one page
    runs one kernel instead of ten)."""
    workdir = tmp_path_factory.mktemp("voila")
    with server("voila", workdir, env={"INTERP_PRESENTATION": "1"}) as url:
        write_all_apps_notebook(workdir / "lessons" / "all_apps.ipynb", UNIQUE)
        yield f"{url}/voila/render/all_apps.ipynb"


def new_page(context):
    page = context.new_page()
    page.console_errors = []
    page.on("console", lambda m: m.type == "error" and page.console_errors.append(m.text))
    page.on("pageerror", lambda e: page.console_errors.append(str(e)))
    # A failed resource's console message does not say which: note its address beside it.
    page.on(
        "response",
        lambda r: r.status >= 400 and page.console_errors.append(f"{r.status} {r.url}"),
    )
    return page


@pytest.fixture(scope="module")
def lesson(browser, lab):
    """``lesson(notebook)``: its page in JupyterLab after Run All in a fresh kernel (opened
    once for the module), and {app: Out number}."""
    context = browser.new_context(viewport={"width": 1500, "height": 1100})
    context.add_init_script(FRAME_PROBE)
    opened = {}

    def get(notebook):
        if notebook not in opened:
            page = new_page(context)
            opened[notebook] = (page, open_lesson(page, lab, notebook))
        # In front, as a student's page is: a tab behind another has its timers run once a
        # second and its animation frames held back (a picture shown a second late).
        opened[notebook][0].bring_to_front()
        return opened[notebook]

    yield get
    context.close()


@pytest.fixture(autouse=True)
def screenshot_on_failure(request):
    yield
    report = getattr(request.node, "report_call", None)
    page = getattr(request.node, "page_on_show", None)
    if report is not None and report.failed and page is not None and not page.is_closed():
        ARTIFACTS.mkdir(exist_ok=True)
        path = ARTIFACTS / f"{request.node.name}.png"
        page.screenshot(path=str(path), full_page=True)
        print(f"screenshot of the failing page: {path}")


# ----------------------------------------------------------------------------------- checks


def assert_is_the_apps_figure(page, canvas, count: int, when: str) -> dict[str, str]:
    """The canvas shows a picture, and it is the figure the app draws at its current values
    (``browser.kernel_truth``); if not, both pictures go to test-artifacts/.

    A picture that is not yet right gets two more chances, each after the page has been
    quiet for another second: widget messages run on a kernel subshell, whose work the
    kernel's idle status does not always show, and a busy machine may still be drawing. A
    stale or torn picture stays wrong, and fails."""
    for _chance in range(3):
        shown = canvas_pixels(canvas)
        values, truth = kernel_truth(page, count)
        wrong = mismatch(shown, truth)
        if wrong <= TOLERANCE and not is_blank(shown):
            return values
        wait_idle(page, quiet_ms=1000, timeout=60)
    assert not is_blank(shown), f"{when}: the figure is blank ({shown.shape[1]}x{shown.shape[0]})"
    if wrong > TOLERANCE:
        from PIL import Image

        ARTIFACTS.mkdir(exist_ok=True)
        tag = f"{when.replace(' ', '-')}-{count}-{time.strftime('%H%M%S')}"
        Image.fromarray(shown).save(ARTIFACTS / f"{tag}-shown.png")
        Image.fromarray(truth).save(ARTIFACTS / f"{tag}-expected.png")
    assert wrong <= TOLERANCE, (
        f"{when}: the figure shown is not the app's figure at {values} "
        f"({wrong:.1%} of pixels differ; shown {shown.shape[:2]}, drawn {truth.shape[:2]}; "
        f"both in {ARTIFACTS}/)"
    )
    return values


def assert_no_errors(page) -> None:
    scope = page.locator(VISIBLE)
    errors = scope.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]')
    assert errors.count() == 0, errors.all_inner_texts()
    tracebacks = scope.locator(".jp-OutputArea-output[data-mime-type*='error']")
    assert tracebacks.count() == 0, tracebacks.all_inner_texts()
    assert not page.console_errors, f"console errors since Run All: {page.console_errors}"


def drag_by(page, locator, dx: float, start=None, moves: int = 3, gap_ms: float = 16) -> None:
    """Press on ``locator``'s centre (or ``start``), move ``dx`` px in ``moves`` steps
    ``gap_ms`` apart, let go."""
    if start is None:
        box = steady_box(locator)
        start = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    x, y = start
    page.mouse.move(x, y)
    page.mouse.down()
    for step in range(1, moves + 1):
        page.mouse.move(x + dx * step / moves, y)
        page.wait_for_timeout(gap_ms)
    page.mouse.up()


# ------------------------------------------------------------------------------------ tests


def test_kernels_import_this_checkouts_interp(lesson, request):
    page, _ = lesson(LESSON_OF[APPS[0]])
    request.node.page_on_show = page
    assert kernel_interp(page) == ROOT, "the kernels would test another checkout's interp"


@pytest.mark.parametrize("name", APPS)
def test_app_appears_and_follows_its_control(lesson, request, name):
    page, counts = lesson(LESSON_OF[name])
    request.node.page_on_show = page
    root = app_root(page, name)
    canvas = figure_canvas(root)
    before = assert_is_the_apps_figure(page, canvas, counts[name], "after Run All")
    key = CONTROL[base_app(name)]
    param = figure_of(name).PARAMS[key]
    shown_before = canvas_pixels(canvas)
    if param.options is None:  # drag the slider's handle with the mouse
        control = slider_for(root, param.label)
        control.scroll_into_view_if_needed()
        up = float(before[key]) + 10 * param.step <= param.high
        drag_by(page, control.locator(".noUi-handle"), 30 if up else -30)
    else:  # choose the next option of the drop-down list
        control = dropdown_for(root, param.label)
        control.scroll_into_view_if_needed()
        options = [str(option) for option in param.options]
        choice = options[(options.index(before[key]) + 1) % len(options)]
        control.locator("select").select_option(label=choice)
    # Under load the new picture can come after a quiet spell: look again for up to 30 s.
    deadline = time.monotonic() + 30
    while True:
        wait_idle(page, quiet_ms=500, timeout=60)
        shown_after = canvas_pixels(canvas)
        changed = shown_after.shape != shown_before.shape or (shown_after != shown_before).any()
        if changed or time.monotonic() > deadline:
            break
    assert shown_after.shape == shown_before.shape
    assert (shown_after != shown_before).any(), f"moving {key} did not change the figure"
    after = assert_is_the_apps_figure(page, canvas, counts[name], f"after {key} moved")
    assert after[key] != before[key], f"{key}'s value did not change"
    if param.options is None:
        readout = float(control.locator(".widget-readout").inner_text())
        assert abs(readout - float(after[key])) <= param.step / 2 + 1e-9, (
            f"the slider shows {readout}, the kernel has {after[key]}"
        )
    else:
        shown = control.locator("select").evaluate("s => s.options[s.selectedIndex].text")
        assert shown == after[key], f"the list shows {shown}, the kernel has {after[key]}"
    assert_no_errors(page)


def dropdown_for(root, label: str):
    """The drop-down list of an app whose description is exactly ``label``."""
    text = root.page.get_by_text(label, exact=True)
    return root.locator(".widget-dropdown").filter(has=text).first


@pytest.mark.parametrize("name", ["the_problem", "projecting_a_line"])
def test_dragging_endpoint_a_moves_the_figure(lesson, request, name):
    page, counts = lesson(LESSON_OF[name])
    request.node.page_on_show = page
    root = app_root(page, name)
    canvas = figure_canvas(root)
    canvas.scroll_into_view_if_needed()
    before = assert_is_the_apps_figure(page, canvas, counts[name], "before dragging A")
    shown_before = canvas_pixels(canvas)
    box = steady_box(canvas)
    ax, ay, axes = endpoint_a(page, counts[name])
    dx = 40 if ax + 40 < axes[0] + axes[2] else -40
    drag_by(page, canvas, dx, start=(box["x"] + ax, box["y"] + ay))
    wait_idle(page, quiet_ms=500, timeout=60)
    assert (canvas_pixels(canvas) != shown_before).any(), "dragging A did not change the figure"
    after = assert_is_the_apps_figure(page, canvas, counts[name], "after dragging A")
    assert after["A_w"] != before["A_w"], "A's depth did not change"
    readout = slider_for(root, "A: depth w").locator(".widget-readout").inner_text()
    assert abs(float(readout) - float(after["A_w"])) <= 0.025 + 1e-9, "A's slider did not follow"
    assert_no_errors(page)


#: Kernel code: note every change of A's sliders in app ``Out[count]``, and whether the app made
#: it itself (holding its redraws, as a drag of A does) or the page sent it.
WATCH_A = """
_app = Out[{count}]
_interp_a_changes = []
_interp_a_watchers = {{}}
for _name in ("A_w", "A_x"):
    _interp_a_watchers[_name] = lambda change, app=_app, name=_name: _interp_a_changes.append(
        [name, change["new"], "app" if app._holding_depth else "page"])
    _app.controls[_name].observe(_interp_a_watchers[_name], names="value")
print(_app.coalescer.draws)
"""

#: Kernel code: stop watching (:data:`WATCH_A`) and print what was seen.
WATCHED_A = """
import json as _json
for _name, _watcher in _interp_a_watchers.items():
    Out[{count}].controls[_name].unobserve(_watcher, names="value")
print(_json.dumps(_interp_a_changes))
"""


@pytest.mark.parametrize("name", ["the_problem", "projecting_a_line"])
def test_dragging_endpoint_a_draws_each_move_once(lesson, request, name):
    """The app puts A's sliders where the page's sliders would put them (on their steps, to
    the last bit: ``interp.apps._app.on_slider``), so the page sends nothing back: the page had
    answered each move with the value snapped to the slider's step, which the app drew as a
    second frame (and one more after the mouse was let go)."""
    page, counts = lesson(LESSON_OF[name])
    request.node.page_on_show = page
    root = app_root(page, name)
    canvas = figure_canvas(root)
    canvas.scroll_into_view_if_needed()
    box = steady_box(canvas)
    ax, ay, axes = endpoint_a(page, counts[name])
    draws_before = int(kernel_run(page, WATCH_A.format(count=counts[name])))
    dx = 60 if ax + 60 < axes[0] + axes[2] else -60
    drag_by(page, canvas, dx, start=(box["x"] + ax, box["y"] + ay), moves=8, gap_ms=50)
    wait_idle(page, quiet_ms=500, timeout=60)
    changes = json.loads(kernel_run(page, WATCHED_A.format(count=counts[name])))
    draws = int(kernel_run(page, f"print(Out[{counts[name]}].coalescer.draws)")) - draws_before
    made = [c for c in changes if c[2] == "app"]
    assert len({c[1] for c in made if c[0] == "A_w"}) >= 3, f"A hardly moved: {changes}"
    assert [c for c in changes if c[2] == "page"] == [], f"the page sent values back: {changes}"
    assert draws <= len(made), f"{draws} draws for {len(made)} changes the drag made"
    readout = slider_for(root, "A: depth w").locator(".widget-readout").inner_text()
    shown = json.loads(kernel_run(page, f"print(Out[{counts[name]}].values['A_w'])"))
    assert readout == f"{shown:.2f}", (readout, shown)
    assert_no_errors(page)


def drag_back_and_forth(page, root, name: str) -> float:
    """Drag app ``name``'s first slider right, left and right again, and wait until things
    settle; the page's time (``performance.now()``) just before the first drag."""
    control = slider_for(root, figure_of(name).PARAMS[CONTROL[name]].label)
    control.scroll_into_view_if_needed()
    start = page.evaluate("performance.now()")
    for dx in (40, -40, 40):
        drag_by(page, control.locator(".noUi-handle"), dx)
    wait_idle(page, quiet_ms=800, timeout=60)
    return start


def open_lesson_copy(page, lab: str, notebook: str) -> dict[str, int]:
    """Run All in a copy of ``notebook`` on ``page`` (:func:`open_lesson`), so that it gets a
    kernel of its own: JupyterLab connects every page that opens one path to the same kernel."""
    page.goto(f"{lab}/lab?reset")
    page.wait_for_selector("#jp-main-dock-panel", timeout=60_000)
    copy = page.evaluate(
        "async (path) => (await window.jupyterapp.serviceManager.contents.copy(path, '')).path",
        notebook,
    )
    return open_lesson(page, lab, copy)


@pytest.mark.parametrize("notebook", FLAKY_LESSONS)
def test_run_all_draws_every_figure_every_time(browser, lab, request, notebook):
    """Run All in a fresh kernel, again and again: every figure appears every time. (A first
    image sent before the canvas's frontend had said it was ready used to leave it blank.)

    Each run opens its own copy of the lesson, so that it gets a kernel of its own (JupyterLab
    connects every page that opens one path to the same kernel)."""
    context = browser.new_context(viewport={"width": 1500, "height": 1100})
    context.add_init_script(FRAME_PROBE)
    failures = []
    try:
        for run in range(1, REPEAT + 1):
            page = new_page(context)
            request.node.page_on_show = page
            counts = open_lesson_copy(page, lab, notebook)
            for name in LESSONS[notebook]:
                try:
                    canvas = figure_canvas(app_root(page, name))
                    assert_is_the_apps_figure(page, canvas, counts[name], "after Run All")
                except AssertionError as error:
                    failures.append(f"run {run}, {name}: {str(error).splitlines()[0]}")
            if page.console_errors:
                failures.append(f"run {run}, console: {page.console_errors}")
            shutdown_kernel(page)
            page.close()
    finally:
        context.close()
    assert not failures, f"{len(failures)} problems in {REPEAT} runs:\n" + "\n".join(failures)


# --------------------------------------------------------------------------- fits the screen


def assert_fits(root, where: str) -> None:
    reach = overflow(root)
    assert reach["width"] > 0, f"{where}: the figure is missing (0 px wide)"
    assert reach["overflow"] <= 0, (
        f"{where}: the app reaches {reach['overflow']} px past the visible right edge "
        f"(figure {reach['width']} px wide, visible up to x = {reach['limit']}: {reach['by']})"
    )


def lab_at(page, width: int, height: int) -> None:
    page.set_viewport_size({"width": width, "height": height})
    show_file_browser(page)
    # JupyterLab lays its panels out again after a resize: wait until the notebook spans
    # the window (bar the right side bar) and has stopped moving.
    page.wait_for_function(
        f"""() => {{
            const right = document.querySelector('{VISIBLE}').getBoundingClientRect().right;
            const settled = right === window.__lastRight && right > window.innerWidth - 80;
            window.__lastRight = right;
            return settled;
        }}""",
        polling=100,
        timeout=10_000,
    )


@pytest.mark.parametrize("name", APPS)
@pytest.mark.parametrize("size", [(1280, 800), (1920, 1080)], ids=["1280x800", "1920x1080"])
def test_fits_jupyterlab_with_the_file_browser(lesson, request, name, size):
    page, _ = lesson(LESSON_OF[name])
    request.node.page_on_show = page
    lab_at(page, *size)
    assert_fits(app_root(page, name), f"JupyterLab at {size[0]}x{size[1]}, file browser open")


@pytest.fixture(scope="module")
def voila_page(browser, voila):
    """Every app in Voilà in presentation mode at 1280x720, each output tagged
    ``data-app=NAME``."""
    context = browser.new_context(viewport={"width": 1280, "height": 720})
    # Voilà's template links Font Awesome from a CDN; this machine may have no internet.
    context.route(
        "https://cdn.jsdelivr.net/npm/@fortawesome/**",
        lambda route: route.fulfill(status=200, content_type="text/css", body=""),
    )
    page = new_page(context)
    open_voila_apps(page, voila, UNIQUE)
    yield page
    context.close()


@pytest.mark.parametrize("size", [(1280, 720), (1920, 1080)], ids=["1280x720", "1920x1080"])
@pytest.mark.parametrize("name", UNIQUE)
def test_fits_voila_presentation(voila_page, request, name, size):
    page = voila_page
    request.node.page_on_show = page
    if page.viewport_size != {"width": size[0], "height": size[1]}:
        page.set_viewport_size({"width": size[0], "height": size[1]})
        page.wait_for_timeout(300)  # the page lays itself out again
    where = f"Voilà presentation at {size[0]}x{size[1]}"
    assert_fits(page.locator(f'[data-app="{name}"]').first, where)


def test_presentation_mode_enlarges_the_controls_text(voila_page):
    """JupyterLab's widgets use 13 px; presentation mode's style makes labels and readouts
    larger (``interp.apps._app.PRESENTATION_CSS``) on every app."""
    sizes = voila_page.evaluate(
        """() => Array.from(document.querySelectorAll('[data-app]')).map(app => {
            const label = app.querySelector('.widget-slider .widget-label, .widget-label');
            return [app.getAttribute('data-app'),
                    label ? parseFloat(getComputedStyle(label).fontSize) : 0];
        })"""
    )
    assert sorted(name for name, _ in sizes) == sorted(UNIQUE)
    small = {name: px for name, px in sizes if px < 18}
    assert not small, f"controls' text below 18 px in presentation mode: {small}"
