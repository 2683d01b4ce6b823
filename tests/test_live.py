"""What makes the apps live: blitted frames equal full redraws; a burst of slider changes is
drawn once, with the newest values."""

from __future__ import annotations

import asyncio

import matplotlib.pyplot as plt
import numpy as np
import pytest

from interp import apps
from interp.apps._live import Blitter, Coalescer

#: A control of each app and a step for it.
STEPS = {
    "the_problem": ("A_w", 0.35),
    "projecting_a_line": ("B_x", -0.4),
    "st_mapping": ("w2", 0.7),
    "depth": ("w2", 3.0),
    "attributes": ("w2", 1.3),
    "approximations": ("pitch", 0.5),  # small steps: the decades of its log axes stay
    "mipmap_pyramid": ("frequency", ["8", "32", "4", "16"]),  # a dropdown: these in turn
}


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_a_blitted_frame_is_the_full_redraw_pixel_for_pixel(name):
    app = apps.ALL[name]()
    key, step = STEPS.get(name, ("pitch", 4.0))
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    for k in range(4):
        if isinstance(step, list):
            app.set(**{key: step[k]})
        else:
            app.set(**{key: app.controls[key].value + (step if k % 2 == 0 else -step / 2)})
        blitter.draw()
        blitted = np.asarray(app.figure.canvas.buffer_rgba()).copy()
        app.figure.canvas.draw()
        np.testing.assert_array_equal(blitted, np.asarray(app.figure.canvas.buffer_rgba()))
    assert blitter.blits >= 1, "the blit path was never taken"


def test_changed_limits_redraw_the_whole_figure():
    app = apps.depth()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    app.set(w2=9.0)  # the left panel only: its limits are fixed
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (1, 1)
    app.set(far=500.0)  # the right panel's x range changes
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (2, 1)


def test_a_burst_of_changes_is_drawn_once_with_the_newest_values():
    shown = []
    state = {"value": 0}
    coalescer = Coalescer(lambda: shown.append(state["value"]), settle=0.01)

    async def drag():
        for value in range(1, 31):  # thirty slider messages, faster than a frame
            state["value"] = value
            coalescer.request()
            await asyncio.sleep(0)
        await asyncio.sleep(0.05)
        state["value"] = 99  # the release, after the frame
        coalescer.request()
        await asyncio.sleep(0.05)

    asyncio.run(drag())
    assert shown == [30, 99]
    assert (coalescer.requests, coalescer.draws) == (31, 2)


def test_without_an_event_loop_each_change_draws_at_once():
    shown = []
    coalescer = Coalescer(lambda: shown.append(len(shown)))
    coalescer.request()
    coalescer.request()
    assert shown == [0, 1]


def test_an_orbit_of_3d_axes_redraws_everything_once():
    # The mouse turns a 3D view: its panes and ticks in the saved background are out of date.
    figure = plt.figure()
    ax = figure.add_subplot(projection="3d")
    (line,) = ax.plot([0, 1], [0, 1], [0, 1])
    blitter = Blitter(figure, [line])
    blitter.draw()
    ax.view_init(elev=10.0, azim=75.0)  # what dragging with the mouse does
    line.set_data_3d([0, 1], [1, 0], [0, 1])
    blitter.draw()
    assert blitter.full_draws == 2
    blitted = np.asarray(figure.canvas.buffer_rgba()).copy()
    figure.canvas.draw()
    np.testing.assert_array_equal(blitted, np.asarray(figure.canvas.buffer_rgba()))
