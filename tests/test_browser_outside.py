"""The outside view in a real browser (JupyterLab, Debian's Chromium): in lesson 6 as students get
it, a camera slider moves the camera's image and the outside view in one step, and the mouse
orbits the outside view.
"""

from __future__ import annotations

import shutil
import time

import numpy as np
import pytest
from browser import server, steady_box
from test_browser import (  # noqa: F401 - fixtures
    assert_no_errors,
    drag_handle,
    open_and_run,
    page,
    pixels,
    slider,
    wait_until_changed,
    wait_until_drawn,
)

pytestmark = pytest.mark.browser

#: Lesson 6, whose first app is the checkerboards beside the outside view, twice: each test opens
#: its own copy, with a kernel of its own.
LESSON = "06_checkerboards.ipynb"
NOTEBOOKS = (LESSON, "06_checkerboards_orbit.ipynb")


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    workdir = tmp_path_factory.mktemp("lab-outside")
    with server("lab", workdir) as url:  # serves a copy of lessons/
        shutil.copy(workdir / "lessons" / LESSON, workdir / "lessons" / NOTEBOOKS[1])
        yield url


def regions() -> dict[str, tuple[slice, slice]]:
    """Where the outside view and the perspective-correct image are, in canvas pixels (rows
    from the top): the same app, laid out the same way, tells us."""
    import matplotlib
    import matplotlib.pyplot

    matplotlib.use("agg")
    from interp import apps

    app = apps.checkerboards_outside()  # what lesson 6 shows
    height = app.figure.bbox.height
    matplotlib.pyplot.close(app.figure)

    def of(ax, left_margin=0):
        box = ax.bbox
        return np.s_[
            int(height - box.y1) + 2 : int(height - box.y0) - 2,
            int(box.x0) + left_margin : int(box.x1) - 2,
        ]

    # The toolbar fades in over the left edge of the canvas: leave the 3D view's left part out.
    return {
        "outside": of(app.plot.outside.ax, left_margin=80),
        "image": of(app.plot.panels.axes[1]),
    }


def settled(canvas, seconds: float = 20.0) -> np.ndarray:
    """The canvas once two screenshots 0.5 s apart agree (the last frame has arrived)."""
    last = pixels(canvas)
    for _ in range(int(seconds / 0.5)):
        time.sleep(0.5)
        now = pixels(canvas)
        if np.array_equal(now, last):
            return now
        last = now
    return last


def changed(before: np.ndarray, after: np.ndarray, region) -> float:
    return float(np.mean(np.any(before[region] != after[region], axis=-1)))


def test_a_camera_slider_moves_the_image_and_the_outside_view(lab, page):  # noqa: F811
    where = regions()
    canvas = open_and_run(page, lab, NOTEBOOKS[0])
    canvas.scroll_into_view_if_needed()
    before = wait_until_drawn(canvas)
    height = slider(page, "height")
    height.scroll_into_view_if_needed()
    drag_handle(page, height, 60)
    after = wait_until_changed(canvas, before, region=where["image"])
    after = (
        wait_until_changed(canvas, before, region=where["outside"])
        if not changed(before, after, where["outside"])
        else after
    )
    assert changed(before, after, where["image"]) > 0.01, "the camera's image did not change"
    assert changed(before, after, where["outside"]) > 0.002, "the outside view did not change"
    assert_no_errors(page)


def test_the_mouse_orbits_the_outside_view(lab, page):  # noqa: F811
    where = regions()
    canvas = open_and_run(page, lab, NOTEBOOKS[1])
    canvas.scroll_into_view_if_needed()
    before = wait_until_drawn(canvas)
    box = steady_box(canvas)
    rows, columns = where["outside"]
    x = box["x"] + (columns.start + columns.stop) / 2
    y = box["y"] + (rows.start + rows.stop) / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for step in range(1, 9):  # a hand's drag: several moves
        page.mouse.move(x + 12 * step, y + 4 * step)
    page.wait_for_timeout(300)
    page.mouse.up()
    page.mouse.move(box["x"] + box["width"] - 5, box["y"] + 5)  # away, so the toolbar fades out
    wait_until_changed(canvas, before, region=where["outside"])
    after = settled(canvas)
    assert changed(before, after, where["outside"]) > 0.05, "the outside view did not turn"
    assert changed(before, after, where["image"]) == 0, "orbiting changed the camera's image"
    assert_no_errors(page)
