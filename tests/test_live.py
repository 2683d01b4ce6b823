"""What makes the apps live: every blitted frame is the figure as matplotlib saves it, pixel for
pixel; small slider steps blit; a burst of slider changes is drawn once, with the newest
values."""

from __future__ import annotations

import asyncio
import io

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np
import pytest

from interp import apps
from interp.apps._blit import Blitter, Coalescer, layers
from interp.plots import registry

#: Apps the lessons make with ``apps.App(registry.X)`` rather than a function of apps.ALL.
EXTRA = {"linear_on_screen_figure": registry.LinearOnScreen, "shader_figure": registry.Shader}


def make(name: str) -> apps.App:
    return apps.App(EXTRA[name]) if name in EXTRA else apps.ALL[name]()


ALL = sorted(apps.ALL) + sorted(EXTRA)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def saved(figure) -> np.ndarray:
    """The figure as ``savefig`` renders it, at its own size: every artist drawn in its
    order, animated or not, by a path the blitter takes no part in."""
    buffer = io.BytesIO()
    stale = figure.stale
    figure.savefig(buffer, format="rgba", dpi="figure")
    figure.stale = stale  # saving sets the dpi back, which marks the figure changed: it is not
    width, height = figure.canvas.get_width_height(physical=True)
    return np.frombuffer(buffer.getvalue(), np.uint8).reshape(height, width, 4)


def assert_shows_the_figure(figure) -> None:
    shown = np.asarray(figure.canvas.buffer_rgba())
    truth = saved(figure)
    differ = np.count_nonzero((shown != truth).any(axis=-1))
    assert differ == 0, f"{differ} pixels differ from the figure as saved"


def sweep(control: widgets.Widget, count: int = 4) -> list:
    """``count`` values across a control's range as it takes them (every option of a
    drop-down), then back to where it was."""
    if isinstance(control, widgets.Dropdown):
        return [*control.options, control.value]
    spread = np.linspace(control.min, control.max, count)
    if isinstance(control, widgets.FloatLogSlider):
        values = [float(10.0**e) for e in spread]
    elif isinstance(control, widgets.IntSlider):
        values = [round(float(v)) for v in spread]
    else:
        values = [float(v) for v in spread]
    return [*values, control.value]


def small_step(control: widgets.Widget) -> float:
    """One step of a slider up from where it is (down at the top of its range)."""
    if isinstance(control, widgets.FloatLogSlider):
        return float(10 ** (np.log10(control.value) + control.step))
    up = control.value + control.step
    return up if up <= control.max else control.value - control.step


@pytest.mark.parametrize("name", ALL)
def test_every_frame_over_every_slider_is_the_figure_as_saved(name):
    """Every control of every app swept across its range: each frame, blitted or drawn
    whole, is the figure as ``savefig`` renders it, pixel for pixel."""
    app = make(name)
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    assert_shows_the_figure(app.figure)
    for key, control in app.controls.items():
        for value in sweep(control):
            app.set(**{key: value})
            blitter.draw()
            assert_shows_the_figure(app.figure)
    assert blitter.blits + blitter.full_draws == 1 + sum(
        len(sweep(c)) for c in app.controls.values()
    )


#: Sliders whose every step changes the figure's static parts (a colour bar's scale, the
#: image's shape, the legend's label for the ground): a full draw each time is right.
RESCALING = {
    (app, key)
    for app in ("checkerboards", "checkerboards_outside", "outside_view", "clipping_outside")
    for key in ("frequency", "quads")
}


@pytest.mark.parametrize("name", ALL)
def test_a_small_step_of_any_slider_is_blitted(name):
    """A key press on any slider (one step up, one down) changes only the figure's dynamic
    artists: it is blitted, never drawn whole (a full draw is what made steps slow)."""
    app = make(name)
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    for key, control in app.controls.items():
        if isinstance(control, widgets.Dropdown) or (name, key) in RESCALING:
            continue
        start = control.value
        full = blitter.full_draws
        for value in (small_step(control), start):
            app.set(**{key: value})
            blitter.draw()
        assert blitter.full_draws == full, f"{key}: a step drew the whole figure"
    assert_shows_the_figure(app.figure)


def test_the_layer_drawn_each_frame_starts_at_the_first_changing_artist():
    """Below the first changing artist of an axes (its patch, a fixed curve under it) stays
    in the background; from it on (spines, a text above) everything is drawn again in order,
    and only those are marked animated."""
    figure, ax = plt.subplots()
    (below,) = ax.plot([0, 1], [1, 0], zorder=1)
    (curve,) = ax.plot([0, 1], [0, 1], zorder=2)
    note = ax.text(0.5, 0.5, "above", zorder=3)
    drawn = layers(figure, [curve])
    assert drawn[0] is curve
    assert note in drawn and below not in drawn
    assert all(spine in drawn for spine in ax.spines.values())
    Blitter(figure, [curve])
    assert curve.get_animated() and note.get_animated() and not below.get_animated()


def test_changed_limits_draw_the_whole_figure_once():
    """New axis limits change the ticks in the background: that step is drawn whole, and the
    next small step is blitted again."""
    app = apps.st_mapping()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    limits = app.plot.gap.ax.get_ylim()
    app.set(w2=40.0)  # a far larger gap: a new y range
    blitter.draw()
    assert app.plot.gap.ax.get_ylim() != limits
    assert (blitter.full_draws, blitter.blits) == (2, 0)
    assert_shows_the_figure(app.figure)
    app.set(w2=40.1)
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (2, 1)
    assert_shows_the_figure(app.figure)


def test_a_change_made_from_a_cell_is_shown_at_the_next_step():
    """A student changes the figure from a cell (a label of a static axes): the background no
    longer holds it, so the next step draws everything."""
    app = apps.st_mapping()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    app.plot.gap.ax.set_xlabel("my label")
    app.set(w2=app.controls["w2"].value + 0.1)
    blitter.draw()
    assert blitter.full_draws == 2
    assert_shows_the_figure(app.figure)


def test_a_resized_figure_is_drawn_whole():
    app = apps.the_problem()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    app.figure.set_size_inches(5.0, 4.0)
    app.set(A_w=app.controls["A_w"].value + 0.05)
    blitter.draw()
    assert blitter.full_draws == 2
    assert_shows_the_figure(app.figure)


def test_a_slider_step_after_an_orbit_shows_the_new_viewpoint():
    """The mouse turns the outside view's 3D axes (its ground, panes and ticks are in the
    background): the next step shows the camera from the new viewpoint over the new
    background, and the steps after it are blitted again."""
    app = apps.outside_view()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    assert app.plot.outside.ax not in blitter.layers
    assert app.plot.outside.eye in blitter.layers
    app.plot.outside.ax.view_init(elev=5.0, azim=60.0, vertical_axis="y")
    app.set(pitch=20.0)
    blitter.draw()
    assert_shows_the_figure(app.figure)
    blits = blitter.blits
    app.set(pitch=21.0)
    blitter.draw()
    assert blitter.blits == blits + 1
    assert_shows_the_figure(app.figure)


def test_a_figure_that_cannot_name_its_changing_artists_is_drawn_whole():
    figure, ax = plt.subplots()
    (curve,) = ax.plot([0, 1], [0, 1])
    blitter = Blitter(figure, None)
    blitter.draw()
    curve.set_ydata([1, 0])
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (2, 0)
    assert_shows_the_figure(figure)


def test_saving_a_figure_leaves_its_background_alone():
    """``savefig`` draws too (at 300 dpi, say): the background saved for blitting is the
    screen's, not the file's."""
    app = apps.st_mapping()
    blitter = Blitter(app.figure, app.plot.dynamic)
    blitter.draw()
    app.figure.savefig(io.BytesIO(), format="png", dpi=300)
    app.set(w2=app.controls["w2"].value + 0.1)
    blitter.draw()  # the dpi set back marks the figure changed: one full draw
    app.set(w2=app.controls["w2"].value + 0.1)
    blitter.draw()
    assert blitter.blits == 1
    assert_shows_the_figure(app.figure)


def test_a_live_readout_is_shown_once_the_figure_stops_changing(monkeypatch):
    """A live app draws every step at once, but shows its readout (the result in words, a live
    region for screen readers) once no step has come for ``READOUT_DELAY``: after a burst of
    steps, once, the words for the last. Without an event loop (a script), at once."""
    from interp.apps import _app

    monkeypatch.setattr(_app, "READOUT_DELAY", 0.5)
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))
    app = apps.st_mapping()
    shown = []
    app.readout.observe(lambda change: shown.append(change["new"]), names="value")

    def words(**values):  # the readout of another app at these values
        other = apps.st_mapping()
        other.set(**values)
        return other.readout.value

    async def steps(values, gap):
        for w2 in values:
            app.set(w2=w2)
            await asyncio.sleep(gap)
        assert shown == [], "the readout changed while the steps came"
        await asyncio.sleep(1.0)

    burst = [2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 6.0, 6.5, 3.0, 4.0, 4.5, 5.0]
    asyncio.run(steps(burst, 0.02))
    assert shown == [words(w2=5.0)]
    shown.clear()
    app.set(w2=2.0)  # no event loop: at once
    assert shown == [words(w2=2.0)]


def test_a_burst_of_changes_is_drawn_once_with_the_newest_values():
    """The first message after a pause is drawn at once; the rest of the burst, which came
    while it was drawn, once, with the newest value; the release too."""
    shown = []
    state = {"value": 0}
    coalescer = Coalescer(lambda: shown.append(state["value"]), settle=0.01, idle=1.0)

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
    assert shown == [1, 30, 99]
    assert (coalescer.requests, coalescer.draws) == (31, 3)


def test_a_change_after_a_pause_is_drawn_without_waiting():
    """A key press on a slider after a pause: no message can be waiting, so the draw comes at
    the event loop's next turn, not ``settle`` seconds later."""
    shown = []
    coalescer = Coalescer(lambda: shown.append(1), settle=10.0, idle=0.0)

    async def press():
        coalescer.request()
        coalescer.request()  # within the same message: one draw
        await asyncio.sleep(0)
        return list(shown)

    assert asyncio.run(press()) == [1]
    assert (coalescer.requests, coalescer.draws) == (2, 1)


def test_without_an_event_loop_each_change_draws_at_once():
    shown = []
    coalescer = Coalescer(lambda: shown.append(len(shown)))
    coalescer.request()
    coalescer.request()
    assert shown == [0, 1]


def test_a_fast_endpoint_drag_is_drawn_once_with_the_newest_position():
    """Mouse moves that arrive while a frame is pending are absorbed, as slider changes are:
    drawing each in turn would leave seconds of stale frames after the mouse is let go."""
    from matplotlib.backend_bases import MouseEvent

    app = apps.projecting_a_line()
    app.figure.canvas.draw()
    ax = app.plot.view.ax
    drawn = []
    refresh = app.refresh

    def counted_refresh():
        drawn.append(app.controls["A_w"].value)
        refresh()

    app.coalescer = Coalescer(counted_refresh)

    def mouse(name, w, x):
        px, py = ax.transData.transform((w, x))
        app.figure.canvas.callbacks.process(name, MouseEvent(name, app.figure.canvas, px, py, 1))

    async def drag():
        start = app.plot.view.points["A"]
        mouse("button_press_event", -start[1], start[0])
        for k in range(1, 21):  # twenty moves that queued up while a frame was drawn
            mouse("motion_notify_event", 2.0 + 0.2 * k, start[0])
        mouse("button_release_event", 6.0, start[0])
        await asyncio.sleep(0.05)

    asyncio.run(drag())
    assert drawn == [pytest.approx(6.0, abs=0.05)]
    assert app.plot.view.points["A"][1] == pytest.approx(-app.controls["A_w"].value)


def test_a_live_step_draws_nothing_more_for_pyplot(monkeypatch):
    """Under ``%matplotlib widget`` pyplot redraws every figure marked stale after a cell;
    a blitted step leaves its figure up to date, so nothing asks the browser for a second,
    full redraw (ipympl's ``draw_idle``)."""
    from matplotlib._pylab_helpers import Gcf

    monkeypatch.setattr(apps.App, "live", property(lambda self: True))
    app = apps.st_mapping()
    requests = []
    monkeypatch.setattr(app.figure.canvas, "draw_idle", lambda *a, **k: requests.append(1))
    for w2 in (5.0, 5.1):
        app.set(w2=w2)
        Gcf.draw_all()
    assert app.blitter.blits >= 1
    assert requests == []
