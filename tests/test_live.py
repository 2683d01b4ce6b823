"""What makes the apps live: blitted frames equal full redraws; a burst of slider changes is
drawn once, with the newest values."""

from __future__ import annotations

import asyncio
import itertools
import platform
import sys
import threading
import time
import warnings

import ipywidgets as widgets
import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest

from interp import apps
from interp.apps import _live
from interp.apps._glyphs import keep_glyphs
from interp.apps._live import Blitter, Coalescer
from interp.apps._samples import SampledImage, keep_samples
from interp.plots import styled
from interp.plots._base import Backdrop

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


def assert_is_full_redraw(figure) -> None:
    """The figure's canvas shows, pixel for pixel, what drawing the whole figure gives."""
    shown = np.asarray(figure.canvas.buffer_rgba()).copy()
    figure.canvas.draw()
    np.testing.assert_array_equal(shown, np.asarray(figure.canvas.buffer_rgba()))


def blit_each(app, name: str, values, blitter: Blitter | None = None) -> Blitter:
    """Set ``app``'s control ``name`` to each of ``values`` in turn, blitting after each, and
    check that every frame is the full redraw; the blitter (unless given, a new one, drawn
    first)."""
    if blitter is None:
        blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
        blitter.draw()
    for value in values:
        app.set(**{name: value})
        blitter.draw()
        assert_is_full_redraw(app.figure)
    return blitter


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_a_blitted_frame_is_the_full_redraw_pixel_for_pixel(name):
    app = apps.ALL[name]()
    key, step = STEPS.get(name, ("pitch", 4.0))
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
    blitter.draw()
    for k in range(4):
        if isinstance(step, list):
            app.set(**{key: step[k]})
        else:
            app.set(**{key: app.controls[key].value + (step if k % 2 == 0 else -step / 2)})
        blitter.draw()
        assert_is_full_redraw(app.figure)
    assert blitter.blits >= 1, "the blit path was never taken"


def sweep(control: widgets.Widget, count: int = 4) -> list:
    """``count`` values across a slider's range, as it takes them: up, down and up again, and
    back to where it was."""
    spread = np.linspace(control.min, control.max, count)
    if isinstance(control, widgets.FloatLogSlider):
        values = [float(10.0**e) for e in spread]
    elif isinstance(control, widgets.IntSlider):
        values = [round(float(v)) for v in spread]
    else:
        values = [float(v) for v in spread]
    return values + values[-2::-1] + values[1:] + [control.value]


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_a_background_brought_back_is_the_full_redraw(name):
    """Every slider of every app swept up, down and up again across its range: each frame,
    drawn over a new background, over the one in use or over one kept for an earlier setting,
    is the full redraw pixel for pixel."""
    app = apps.ALL[name]()
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
    blitter.draw()
    for key, control in app.controls.items():
        if hasattr(control, "min"):
            blit_each(app, key, sweep(control), blitter)


@pytest.mark.parametrize("told", [True, False], ids=["backdrop", "no-backdrop"])
def test_a_slider_dragged_back_across_a_new_colour_scale_draws_the_colour_bar_once(told):
    """Lesson 6's error scale changes between pitch 40 and 50 (its largest error's nice
    ceiling): the first crossing draws the colour bar alone over the base (the figure's
    backdrop; a blitter not told of it redraws the whole figure), the ones after it put back
    the background kept for each side. Every frame is the full redraw."""
    app = apps.checkerboards_outside()
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop if told else None)
    blitter.draw()
    scales = []
    for pitch in (40.0, 50.0, 40.0, 50.0, 40.0):
        app.set(pitch=pitch)
        blitter.draw()
        scales.append(app.figure.axes[-1].get_ylim())  # the colour bar's
        assert_is_full_redraw(app.figure)
    assert scales[0] != scales[1] and scales[::2] == [scales[0]] * 3
    expected = (1, 4, 1) if told else (2, 4, 0)
    assert (blitter.full_draws, blitter.blits, blitter.backdrops) == expected
    assert len(blitter.kept) == 2


def shows_the_full_redraw(figure) -> bool:
    """Whether the canvas shows what drawing the whole figure gives (and then it does)."""
    shown = np.asarray(figure.canvas.buffer_rgba()).copy()
    figure.canvas.draw()
    return np.array_equal(shown, np.asarray(figure.canvas.buffer_rgba()))


@pytest.mark.parametrize("name", ["colour_quad", "the_problem", "checkerboards_outside"])
def test_a_figure_resized_and_back_is_drawn_whole(name):
    """Axes of a fixed aspect (images, a 3D box) are placed anew only by a full draw: a
    background kept at a size the figure comes back to was put back under axes still placed
    for the other size (125247 wrong pixels in lesson 5's colour quad)."""
    app = apps.ALL[name]()
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
    blitter.draw()
    width, height = app.figure.get_size_inches()
    app.figure.set_size_inches(width * 1.1, height * 0.9)  # as ipympl's handle_resize does
    app.set(**{STEPS.get(name, ("pitch",))[0]: app.plot.params[STEPS.get(name, ("pitch",))[0]]})
    blitter.draw()
    app.figure.set_size_inches(width, height)
    blitter.draw()
    assert shows_the_full_redraw(app.figure)
    assert blitter.full_draws == 3


def test_a_change_made_from_a_cell_is_not_undone_by_a_kept_background(monkeypatch):
    """A cell changes a label; a slider then comes back to a setting whose background was
    kept from before the cell: the label must stay (909 pixels were the old picture)."""
    app = apps.st_mapping()
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))
    app.set(w2=4.0)
    app.set(w2=9.0)  # another scale of the gap's axis: a second background
    app.figure.axes[0].set_xlabel("a label of the teacher's")
    app.set(w2=4.0)
    assert shows_the_full_redraw(app.figure)
    app.set(w2=9.0)
    assert shows_the_full_redraw(app.figure)


def test_kept_backgrounds_stay_within_their_memory(monkeypatch):
    monkeypatch.setattr(_live, "KEPT_BACKGROUNDS", 3 * 4 * 200 * 100)  # three of 200 x 100
    figure = plt.figure(figsize=(2, 1), dpi=100)
    (line,) = figure.subplots().plot([0, 1])
    blitter = Blitter(figure, [line])
    for top in range(2, 8):
        figure.axes[0].set_ylim(0, top)
        blitter.draw()
        assert_is_full_redraw(figure)
    assert len(blitter.kept) == 3 and blitter.full_draws == 6
    figure.axes[0].set_ylim(0, 5)  # kept: put back
    blitter.draw()
    assert blitter.full_draws == 6
    figure.axes[0].set_ylim(0, 2)  # forgotten: drawn again
    blitter.draw()
    assert blitter.full_draws == 7
    assert_is_full_redraw(figure)


def test_enlarging_the_footprints_redraws_only_what_changes():
    """Lesson 9's "footprints drawn x" slider changes the footprints and the texture panel's
    title, not the texture: each of its steps is a blit, pixel for pixel the full redraw. (The
    legend quoted the scale: each step was a full redraw, 20 ms against 3 in the kernel, and
    the slider's steps 43-55 ms in Chromium, against 37-39 since.)"""
    app = apps.texture_filtering()
    blitter = blit_each(app, "scale", (9.0, 16.0, 32.0, 1.0))
    assert (blitter.full_draws, blitter.blits) == (1, 4)
    assert app.figure.axes[0].get_title() == "footprints in the texture, drawn 1x"
    app.set(frequency="16")  # the texture itself changes: then the whole figure is drawn
    blitter.draw()
    assert blitter.full_draws == 2
    assert_is_full_redraw(app.figure)


def assert_draws_alike(kept, plain, name: str) -> None:
    """Two instances of app ``name``, at three settings of its first slider (or as made, if it
    has none), draw the same figure pixel for pixel.

    The two are first given the same axes positions: constrained layout places the axes of two
    identical figures up to a rounding apart (5.7e-14 px measured, in lesson 2's middle axes,
    with some hash seeds), which moves a dashed line enough to change a few of its antialiased
    pixels by a level or two; what is compared here is how text is drawn."""
    for mine, theirs in zip(plain.figure.axes, kept.figure.axes, strict=True):
        mine.set_position(theirs.get_position(original=True), which="both")
    control = next((n for n, c in kept.controls.items() if hasattr(c, "min")), None)
    settings = [{}]
    if control is not None:
        slider = kept.controls[control]
        kind = type(slider.value)
        settings = [{control: kind(v)} for v in np.linspace(slider.min, slider.max, 3)]
    for values in settings:
        for app in (kept, plain):
            app.set(**values)
            app.figure.canvas.draw()
        np.testing.assert_array_equal(
            np.asarray(kept.figure.canvas.buffer_rgba()),
            np.asarray(plain.figure.canvas.buffer_rgba()),
            err_msg=f"{name} at {values}",
        )


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_kept_glyphs_draw_text_as_matplotlib_does(name):
    """A live figure's text comes from kept layouts and glyph pictures (``_glyphs``): every
    app, at three settings of its first slider, is the figure matplotlib draws alone, pixel
    for pixel (rotated axis labels, mathtext and titles included)."""
    kept, plain = apps.ALL[name](), apps.ALL[name]()
    if not keep_glyphs(kept.figure.canvas.get_renderer(), kept.figure):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no glyphs are kept")
    assert_draws_alike(kept, plain, name)
    assert kept.figure.canvas.get_renderer().glyphs, "no glyph was kept"
    plt.close(kept.figure)
    plt.close(plain.figure)


def _plain_images(figure) -> None:
    """Draw the figure's images as matplotlib does (undo :func:`keep_samples`)."""
    for ax in figure.axes:
        for image in ax.images:
            if isinstance(image, SampledImage):
                image.__class__ = matplotlib.image.AxesImage


#: The apps whose figures show raster images that change (``test_the_image_apps_are_these``).
IMAGE_APPS = (
    "barycentrics",
    "checkerboards",
    "checkerboards_outside",
    "clipping",
    "clipping_outside",
    "colour_quad",
    "linear_on_screen",
    "mipmap_pyramid",
    "shader",
    "texture_filtering",
    "uv_images",
)


def test_the_image_apps_are_these():
    shown = {
        name
        for name, make in apps.ALL.items()
        if any(isinstance(a, matplotlib.image.AxesImage) for a in make().plot.dynamic or ())
    }
    assert shown == set(IMAGE_APPS)


@pytest.mark.parametrize("name", IMAGE_APPS)
def test_kept_samples_draw_images_as_matplotlib_does(name):
    """A live figure's changing images are picked from a kept map (``_samples``): every app,
    at three settings of its first slider, is the figure matplotlib draws, pixel for pixel."""
    kept, plain = apps.ALL[name](), apps.ALL[name]()
    _plain_images(plain.figure)
    images = [a for a in kept.plot.dynamic if isinstance(a, matplotlib.image.AxesImage)]
    if not all(keep_samples(image) for image in images):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no samples are kept")
    assert_draws_alike(kept, plain, name)
    assert any(picks is not None for i in images for picks in i.samples.values()), (
        "no image was drawn from a kept map"
    )


def _random_image(rng, kept: bool):
    """A figure with one image of random shape, kind, values, mask, place and way of
    drawing; the same for the same state of ``rng``."""
    figure = matplotlib.figure.Figure(figsize=rng.uniform(1, 5, 2), dpi=rng.choice([72, 100, 150]))
    matplotlib.backends.backend_agg.FigureCanvasAgg(figure)
    ax = figure.add_axes([*rng.uniform(0, 0.3, 2), *rng.uniform(0.3, 0.7, 2)])
    h, w = rng.integers(1, rng.choice([90, 400]), 2)  # larger ones often shown smaller
    kind = rng.choice(["scalar", "rgb", "rgba"])
    data = {"scalar": rng.normal(size=(h, w)), "rgb": rng.uniform(size=(h, w, 3))}.get(
        kind, np.dstack([rng.uniform(size=(h, w, 3)), rng.choice([0.0, 0.4, 1.0], (h, w))])
    )
    if rng.uniform() < 0.4:
        data = np.where(rng.uniform(size=data.shape) < 0.2, np.nan, data)
    if rng.uniform() < 0.3:
        data = data.astype(np.float32)
    if rng.uniform() < 0.3:  # masked where there are values (as the apps mask blank pixels)
        hidden = rng.uniform(size=data.shape[:2]) < 0.3
        data = np.ma.masked_array(data, np.broadcast_to(hidden[..., None], data.shape)
                                  if data.ndim == 3 else hidden)  # fmt: skip
    options = {
        "interpolation": "nearest",
        "origin": rng.choice(["upper", "lower"]),
        "interpolation_stage": rng.choice(["auto", "data", "rgba"]),
        "aspect": rng.choice(["auto", "equal"]),
    }
    if kind == "scalar":
        options["cmap"] = rng.choice(["viridis", "gray", "RdBu"])
        if rng.uniform() < 0.7:
            options |= {"vmin": -1.0, "vmax": rng.uniform(0, 2)}
    if rng.uniform() < 0.5:
        x0, y0 = rng.uniform(-5, 5, 2)
        options["extent"] = (x0, x0 + rng.choice([-1, 1]) * rng.uniform(1, 9), y0, y0 + 3)
    image = ax.imshow(data, **options)
    if kind == "scalar" and rng.uniform() < 0.3:  # limits set from the whole image when drawn
        image.norm.vmin = image.norm.vmax = None
    if rng.uniform() < 0.3:  # the image reaches past the axes, clipped
        ax.set_xlim(*np.sort(rng.uniform(-3, 60, 2)))
    if kept:
        keep_samples(image)
    return figure, image


def test_kept_samples_draw_random_images_as_matplotlib_does():
    """Images of random shapes, kinds (values, RGB, RGBA with see-through pixels), masks (NaN
    or masked values), origins, extents, stages, sizes and clipping: picked from the kept map
    or drawn by matplotlib, the same pixels as matplotlib's alone. Kept maps of images shown on
    fewer screen pixels than they have are picked before they are coloured, the others after."""
    if not keep_samples(matplotlib.image.AxesImage(matplotlib.figure.Figure().add_subplot())):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no samples are kept")
    picked = fewer = 0
    for seed in range(60):
        (kept, image), (plain, _) = (
            _random_image(np.random.default_rng(seed), kept=True),
            _random_image(np.random.default_rng(seed), kept=False),
        )
        for figure in (kept, plain):
            figure.canvas.draw()
        np.testing.assert_array_equal(
            np.asarray(kept.canvas.buffer_rgba()),
            np.asarray(plain.canvas.buffer_rgba()),
            err_msg=f"seed {seed}",
        )
        maps = [picks for picks in image.samples.values() if picks is not None]
        picked += bool(maps)
        fewer += any(picks.size < image.get_array().shape[0] * image.get_array().shape[1]
                     for picks in maps)  # fmt: skip
    assert picked >= 30, f"only {picked} of 60 images were drawn from a kept map"
    assert fewer >= 10, f"only {fewer} of 60 images were picked before they were coloured"


def test_changed_limits_redraw_the_whole_figure():
    figure, ax = plt.subplots()
    (line,) = ax.plot([0, 1], [0, 1])
    ax.set_xlim(0, 2)
    blitter = Blitter(figure, [line])
    blitter.draw()
    line.set_ydata([1, 0])  # only the dynamic line: a blit
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (1, 1)
    ax.set_xlim(0, 3)  # the axis, in the background, changes
    blitter.draw()
    assert (blitter.full_draws, blitter.blits) == (2, 1)
    assert_is_full_redraw(figure)


def two_panels_with_a_backdrop(text_at: tuple[float, float]):
    """A figure of two axes: on the left a dynamic line, and a backdrop of a line, a
    label placed at ``text_at`` (axes fraction, unclipped) and the left title; its state."""
    figure = plt.figure(figsize=(4, 2), dpi=100)
    left, right = figure.subplots(1, 2, gridspec_kw={"wspace": 0.6})  # apart: see below
    right.plot([0, 1], [1, 0])
    right.set_title("right")
    (moving,) = left.plot([0, 1], [0, 1], zorder=3)
    (ground,) = left.plot([0, 1], [0.5, 0.5], zorder=1)
    label = left.annotate("slope 0", text_at, xycoords="axes fraction", zorder=1.5)
    left.set_title("left", zorder=2)
    shown = {"slope": 0}

    def tilt(slope: float) -> None:
        ground.set_ydata([0.5 - slope, 0.5 + slope])
        label.set_text(f"slope {slope}")
        shown["slope"] = slope

    backdrop = Backdrop([ground, label], lambda: shown["slope"])
    return figure, moving, tilt, backdrop, (ground, label, left.title)


def test_a_backdrop_change_is_drawn_over_the_base_and_matches_the_full_redraw():
    figure, moving, tilt, backdrop, expected_middle = two_panels_with_a_backdrop((0.1, 0.8))
    blitter = Blitter(figure, [moving], backdrop)
    blitter.draw()
    assert blitter.base[2][:3] == list(expected_middle)  # in draw order; then the spines
    for k, slope in enumerate([0.1, 0.2, 0.1, 0.3]):
        moving.set_ydata([k / 4, 1 - k / 4])
        tilt(slope)
        blitter.draw()
        assert_is_full_redraw(figure)
    moving.set_ydata([0.2, 0.9])  # the dynamic line alone
    blitter.draw()
    assert_is_full_redraw(figure)
    # 0.1 came back once (kept); 0.2 and 0.3 were drawn over the base.
    assert (blitter.full_draws, blitter.backdrops, blitter.blits) == (1, 3, 2)


def test_a_backdrop_reaching_into_another_axes_redraws_the_whole_figure():
    """The label stands out of the left axes into the right one, which a full draw paints
    after it: drawn over the base it would cover the right axes' line. So the figure is
    drawn whole for each change, and only once each (not first over the base)."""
    figure, moving, tilt, backdrop, _ = two_panels_with_a_backdrop((0.9, 0.5))
    blitter = Blitter(figure, [moving], backdrop)
    blitter.draw()
    assert blitter.base is None
    renders = []
    original = _live.FigureCanvasAgg.draw
    try:
        _live.FigureCanvasAgg.draw = lambda canvas: (renders.append(1), original(canvas))[1]
        for slope in (0.1, 0.2):
            tilt(slope)
            blitter.draw()
            assert len(renders) in (1, 2) and renders.count(1) == len(renders)
            renders.clear()
            assert_is_full_redraw(figure)
    finally:
        _live.FigureCanvasAgg.draw = original
    assert (blitter.full_draws, blitter.backdrops) == (3, 0)


@pytest.mark.parametrize("legend_at", ["center right", "center left"])
def test_a_backdrop_reaching_an_axes_without_frame_meets_only_what_it_holds(legend_at):
    """An axes drawn without frame and axis (lesson 6's holds the outside view's legend)
    draws nothing but what it holds: a backdrop label reaching into its empty part is drawn
    over the base; one reaching its legend makes the figure drawn whole. Each frame is the
    full redraw pixel for pixel."""
    figure = plt.figure(figsize=(6, 2), dpi=100)
    left, right = figure.subplots(1, 2, gridspec_kw={"wspace": 0.6})
    right.axis("off")
    right.plot([], [], label="entry")
    right.legend(loc=legend_at)
    (moving,) = left.plot([0, 1], [0, 1], zorder=3)
    label = left.annotate("slope 0, and then more", (0.9, 0.5), xycoords="axes fraction")
    shown = {"slope": 0}
    blitter = Blitter(figure, [moving], Backdrop([label], lambda: shown["slope"]))
    blitter.draw()
    renderer = figure.canvas.get_renderer()
    assert label.get_window_extent(renderer).x1 > right.bbox.x0, "the label must reach right"
    for slope in (1, 2):
        label.set_text(f"slope {slope}, and then more")
        shown["slope"] = slope
        blitter.draw()
        assert_is_full_redraw(figure)
    alone = legend_at == "center right"
    assert (blitter.full_draws, blitter.backdrops) == ((1, 2) if alone else (3, 0))


def test_lesson_4s_precision_plot_keeps_its_axes_for_every_slider():
    """The precision panel's axes and legend stay for every near plane, far plane and buffer
    the sliders reach (a curve moves, not the axes under it), so every step of those controls
    is a blit, the full redraw pixel for pixel. Before, each step of near or far redrew the
    whole figure (92 and 100 ms a step in the kernel, against 13 and 12 now)."""
    app = apps.depth()
    precision = app.plot.precision
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
    blitter.draw()
    blit_each(app, "buffer", [*app.controls["buffer"].options, "float32"], blitter)
    for name in ("near", "far"):
        blit_each(app, name, sweep(app.controls[name], count=6), blitter)
        assert precision.ax.get_xlim() == precision.DEPTHS
        assert precision.ax.get_ylim() == precision.STEPS
    app.set(near=1.0, far=5.0)  # ten times the near plane lies beyond the far one
    blitter.draw()
    assert_is_full_redraw(app.figure)
    labels = [t.get_text() for t in precision.ax.get_legend().get_texts()]
    assert labels == ["near = n", "near = n / 10"]
    assert precision.lines[1].get_xydata().size == 0
    assert blitter.full_draws == 2  # the first draw, and the legend that lost a curve


def test_a_live_readout_is_shown_once_the_figure_stops_changing(monkeypatch):
    """A live app draws every step at once, but shows its readout (the result in words, a live
    region for screen readers) once no step has come for ``READOUT_DELAY``: after a burst of
    steps that lasts longer than the delay, once, the words for the last; a single step, once,
    after the delay. Without an event
    loop (a script), and for a static figure, the readout follows at once."""
    from interp.apps import _app

    # Five times the app's delay: a step of the burst (every fifth of it) stalled for 0.1 s on
    # a loaded CI machine, and the readout came in the middle of the burst.
    monkeypatch.setattr(_app, "READOUT_DELAY", 5 * _app.READOUT_DELAY)
    READOUT_DELAY = _app.READOUT_DELAY
    app = apps.st_mapping()
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))  # drawn as a live one
    shown = []
    app.readout.observe(lambda change: shown.append(change["new"]), names="value")

    def words(**values):  # the readout of the same app, static, at these values
        with monkeypatch.context() as static:
            static.setattr(apps.App, "live", property(lambda self: False))
            other = apps.st_mapping()
            other.set(**values)
        return other.readout.value

    async def steps(values, gap):
        for w2 in values:
            app.set(w2=w2)
            await asyncio.sleep(gap)
        drawn = app.blitter.blits + app.blitter.full_draws
        assert shown == [], "the readout changed while the steps came"
        await asyncio.sleep(2 * READOUT_DELAY)
        return drawn

    assert app.values["w2"] not in (2.0, 5.0, 7.0)
    burst = [2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 6.0, 6.5, 3.0, 4.0, 4.5, 5.0]  # longer than the delay
    drawn = asyncio.run(steps(burst, READOUT_DELAY / 5))
    assert drawn >= len(burst)  # every step was drawn at once
    assert shown == [words(w2=5.0)]
    shown.clear()
    asyncio.run(steps([7.0], 0.0))
    assert shown == [words(w2=7.0)]
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
    the event loop's next turn, not ``settle`` seconds later (4 ms of every step before)."""
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


def test_two_threads_drawing_one_figure_take_turns(monkeypatch):
    """ipykernel 7 handles widget messages on a subshell thread beside the main one (JupyterLab
    4.6 sends comm messages over subshells by default): a slider's redraw, ipympl's own full
    draw and a cell's ``app.set`` can run at the same moment. Every blitted frame must still be
    a whole picture of one state, equal to a full redraw at that state."""
    app = apps.st_mapping()
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))  # blit, as with ipympl
    canvas = app.figure.canvas
    values = [4.0, 5.07, 5.6, 4.5, 6.1, 3.2, 2.0]  # limits and title change along the way
    truth = {}
    for value in values:
        app.set(w2=value)
        canvas.draw()
        truth[value] = np.asarray(canvas.buffer_rgba()).copy()
    frames = []
    blit = canvas.blit

    def recording_blit(bbox=None):  # the moment ipympl would encode and send a frame
        frames.append((app.values["w2"], np.asarray(canvas.buffer_rgba()).copy()))
        blit(bbox)

    canvas.blit = recording_blit
    stop = threading.Event()

    def full_draws():  # as ipympl's 'draw' and 'refresh' messages do, on another thread
        while not stop.is_set():
            canvas.draw()
            time.sleep(0.001)

    other = threading.Thread(target=full_draws)
    other.start()
    try:
        for value in values:
            app.set(w2=value)
    finally:
        stop.set()
        other.join()
    assert len(frames) == len(values)
    torn = [value for value, frame in frames if not np.array_equal(frame, truth[value])]
    assert not torn, f"{len(torn)} of {len(frames)} frames were torn (w2 = {torn})"


def test_a_frame_before_any_view_is_ready_keeps_the_static_picture():
    """``app.set(...)`` in the cell that makes the app, under ``%matplotlib widget``, draws
    before the browser has a view; ipympl then keeps a static picture (its data URL) from the
    frame's pixels. It used to fail with "ValueError: cannot write empty image"."""
    import base64
    import io

    import matplotlib
    from matplotlib.figure import Figure
    from PIL import Image

    from interp.apps._live import WHOLE_FRAMES, cheap_frames

    backend = matplotlib.get_backend()
    try:
        from ipympl.backend_nbagg import new_figure_manager_given_figure
    finally:
        plt.switch_backend(backend)  # importing ipympl's backend makes it pyplot's
    figure = Figure(figsize=(2, 1))
    figure.add_subplot().plot([0, 1])
    with warnings.catch_warnings():  # ipympl's toolbar passes traitlets an argument it warns of
        warnings.simplefilter("ignore", DeprecationWarning)
        new_figure_manager_given_figure(1, figure)
    canvas = figure.canvas
    assert canvas.syncing_data_url  # no view yet
    cheap_frames(canvas)
    assert WHOLE_FRAMES in canvas._dom_classes  # the page may decode its frames off-thread
    canvas.draw()  # sends a frame
    picture = Image.open(io.BytesIO(base64.b64decode(canvas._data_url))).convert("RGBA")
    np.testing.assert_array_equal(np.asarray(picture), np.asarray(canvas.buffer_rgba()))


def test_a_fast_endpoint_drag_is_drawn_once_with_the_newest_position():
    """The browser sends a mouse move every 33 ms; each drawn in turn left seconds of stale
    frames after release (make bench-browser: 12-24 s for lessons 1-2). Moves that arrive
    while a frame is pending are absorbed, as slider changes are."""
    from matplotlib.backend_bases import MouseEvent

    app = apps.projecting_a_line()
    app.figure.canvas.draw()
    ax = app.plot.view.ax
    drawn = []
    refresh = app.refresh

    def counted_refresh():
        drawn.append(app.controls["A_w"].value)
        refresh()

    app.refresh = app.coalescer._draw = counted_refresh

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


def test_a_step_asks_for_no_full_redraw(monkeypatch):
    """Under ``%matplotlib widget`` pyplot is interactive, and its auto-draw turned every
    changed artist into ``draw_idle`` (219 for one step of lesson 3's app): ipympl forwards
    each to the browser, which asks back for a full redraw after the blitted frame."""
    app = apps.st_mapping()
    requests = []
    monkeypatch.setattr(app.figure.canvas, "draw_idle", lambda *a, **k: requests.append(1))
    interactive = plt.isinteractive()
    plt.ion()
    try:
        app.set(w2=5.0)
    finally:
        plt.interactive(interactive)
    assert requests == []


def test_a_blitted_step_leaves_nothing_for_pyplot_to_redraw(monkeypatch):
    """After each widget message the kernel handles (every slider step, every mouse move),
    ``%matplotlib widget`` has pyplot redraw every figure still marked stale: ipympl forwards
    the request to the browser, which asks back for a full redraw. So a blitted step must leave
    its figure marked up to date, or every step costs a second, full redraw (an endpoint drag
    in lesson 1 then left 2.5-6.5 s of stale frames behind in ``make bench-browser``)."""
    from matplotlib._pylab_helpers import Gcf

    app = apps.st_mapping()
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))  # blit, as with ipympl
    app.figure.canvas.draw()  # as the browser's first frame does
    requests = []
    monkeypatch.setattr(app.figure.canvas, "draw_idle", lambda *a, **k: requests.append(1))
    for w2 in (5.0, 6.0):
        app.set(w2=w2)
        Gcf.draw_all()  # what pyplot runs after each message the kernel handles
    assert app.blitter.blits >= 1, "the blit path was never taken"
    assert requests == []


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
    assert_is_full_redraw(figure)


@pytest.mark.parametrize("by", ["isal", "zlib"])
@pytest.mark.parametrize("rows", ["none", "up"])
@pytest.mark.parametrize("shape", [(1, 1), (7, 13), (250, 820)])
def test_a_live_frame_decodes_to_the_figure_pixel_for_pixel(shape, rows, by, monkeypatch):
    """The frames are PNG files written by the package (``png``), not by PIL: PIL's decoder
    (and so any browser's) must read back exactly the pixels, transparency included, with
    either row filter ("up" wraps around modulo 256 in random pixels), deflated by ISA-L or,
    where it is not installed, by zlib."""
    import io
    import zlib

    from PIL import Image

    from interp.apps import _live
    from interp.apps._live import png

    if by == "zlib":
        monkeypatch.setattr(_live, "deflate", zlib.compress)
    else:
        try:
            from isal.isal_zlib import compress
        except ImportError:
            if sys.platform == "linux" and platform.machine() in ("x86_64", "aarch64"):
                raise  # pyproject.toml installs ISA-L here
            pytest.skip("no ISA-L wheel for this platform: its frames are deflated by zlib")
        assert _live.deflate is compress

    rgba = np.random.default_rng(shape[1]).integers(0, 256, (*shape, 4), dtype=np.uint8)
    if shape == (250, 820):  # a real frame: the checkerboard app's figure
        app = apps.checkerboards()
        app.figure.canvas.draw()
        rgba = np.asarray(app.figure.canvas.buffer_rgba())
        assert rgba.shape[:2] == shape
    decoded = Image.open(io.BytesIO(png(rgba, rows=rows)))
    assert decoded.mode == "RGBA"
    np.testing.assert_array_equal(np.asarray(decoded), rgba)


def test_frames_are_written_with_the_filter_that_makes_them_smaller():
    """A figure of gradients (the colour quad) is sent with "up" rows, a figure of flat
    colours (the checkerboards) unfiltered; each choice is the smaller file, made again
    every ``trial`` frames, and a frame between trials uses the last choice."""
    from interp.apps._live import FrameFilter, png

    for name, best in (("colour_quad", "up"), ("checkerboards_outside", "none")):
        app = apps.ALL[name]()
        app.figure.canvas.draw()
        rgba = np.asarray(app.figure.canvas.buffer_rgba()).copy()
        sizes = {rows: len(png(rgba, rows=rows)) for rows in ("none", "up")}
        assert min(sizes, key=sizes.get) == best, sizes
        frames = FrameFilter(trial=3)
        assert frames.png(rgba) == png(rgba, rows=best) and frames.rows == best
        flat = np.full_like(rgba, 255)  # the next frames: no trial, the choice stays
        assert frames.png(flat) == png(flat, rows=best)
        assert frames.png(flat) == png(flat, rows=best)
        assert frames.png(flat) == png(flat, rows="none")  # a trial: unfiltered, no larger
        assert frames.rows == "none"


def test_a_kept_legend_is_the_legend_drawn_again_with_a_curve_behind_it(monkeypatch):
    """An opaque legend above a changing curve is drawn once and then put back as a picture;
    with the curve passing right behind it, and across its edge, the frame must still be the
    full redraw, and the legend must not have been laid out and drawn again."""
    from matplotlib.legend import Legend

    with styled():
        figure = plt.figure(figsize=(3, 2))
        ax = figure.add_subplot()
        (curve,) = ax.plot([0, 1], [0.9, 0.9], label="a curve")
        ax.plot([0, 1], [0, 1], label="a static line", zorder=1)  # under the curve
        legend = ax.legend(loc="upper left")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
    blitter = Blitter(figure, [curve])
    blitter.draw()
    draws = []
    draw = Legend.draw
    monkeypatch.setattr(Legend, "draw", lambda self, r: (draws.append(1), draw(self, r))[1])
    box = ax.transAxes.inverted().transform(legend.get_window_extent())
    for y in np.linspace(box[0, 1] - 0.05, box[1, 1] + 0.05, 7):  # below, through, above it
        curve.set_ydata([y, 1 - y])
        blitter.draw()
        monkeypatch.setattr(Legend, "draw", draw)  # the full redraw's legend is not counted
        assert_is_full_redraw(figure)
        monkeypatch.setattr(Legend, "draw", lambda self, r: (draws.append(1), draw(self, r))[1])
    assert blitter.blits == 7
    assert draws == [], "the legend was drawn again instead of put back"


def test_a_title_drawn_as_before_is_put_back_and_a_changed_one_drawn(monkeypatch):
    """A title above its axes that looks as when last drawn is put back as a picture, not
    rendered again (matplotlib renders text glyph by glyph: 2-9 ms a title); the frame is still
    the full redraw, and a title whose text changed is drawn anew."""
    from matplotlib.text import Text

    with styled():
        figure = plt.figure(figsize=(4, 2))
        left, right = figure.subplots(1, 2, gridspec_kw={"wspace": 0.6})  # apart: see below
        (curve,) = left.plot([0, 1], [0, 1])
        left.set_title("a title that stays")
        right.set_title("step 0")
        figure.get_layout_engine().execute(figure)
        figure.set_layout_engine("none")  # frozen, as in the apps
    blitter = Blitter(figure, [curve, left.title, right.title])
    blitter.draw()
    drawn = []
    draw = Text.draw

    def counted(self, renderer):
        drawn.append(self.get_text())
        return draw(self, renderer)

    for step in range(1, 4):
        curve.set_ydata([0, 1 - step / 4])
        right.set_title(f"step {step}")
        monkeypatch.setattr(Text, "draw", counted)
        blitter.draw()
        monkeypatch.setattr(Text, "draw", draw)
        assert_is_full_redraw(figure)
    assert blitter.blits == 3
    assert "a title that stays" not in drawn
    assert [t for t in drawn if t.startswith("step")] == ["step 1", "step 2", "step 3"]


def test_a_title_changing_on_every_step_is_not_checked_for_keeping(monkeypatch):
    """Lesson 1's title quotes s, so it changes on every step: the check that a title's box is
    free (which measures every label the blit draws, 8 ms a step there) is only worth doing
    for a title that stayed the same; the frames are still the full redraws."""
    app = apps.the_problem()
    blitter = Blitter(app.figure, app.plot.dynamic, app.plot.backdrop)
    blitter.draw()
    checks = []
    alone = Blitter._alone
    monkeypatch.setattr(
        Blitter, "_alone", lambda self, *a: (checks.append(a[0].get_text()), alone(self, *a))[1]
    )
    for step, w in enumerate((2.5, 3.0, 3.5, 4.0)):  # the title quotes s, which moves with w_A
        app.set(A_w=w)
        blitter.draw()
        assert_is_full_redraw(app.figure)
        assert checks == [], f"step {step}: the changed title's box was checked"
    assert blitter.blits == 4


def test_a_change_made_from_a_cell_still_gets_pyplots_full_redraw(monkeypatch):
    """A cell that changes the figure itself (a label) and then moves a control: the blit's
    background does not know the label, so pyplot's full redraw after the cell must come."""
    from matplotlib._pylab_helpers import Gcf

    app = apps.st_mapping()
    monkeypatch.setattr(apps.App, "live", property(lambda self: True))
    app.figure.canvas.draw()
    requests = []
    monkeypatch.setattr(app.figure.canvas, "draw_idle", lambda *a, **k: requests.append(1))
    app.figure.axes[0].set_xlabel("a label of the teacher's")
    app.set(w2=5.0)
    Gcf.draw_all()
    assert requests == [1]


def test_a_label_reaching_into_a_kept_titles_box_is_drawn():
    """Lesson 2's title depends on the depths only; with A high up (x = 4.5) its label reaches
    into the title's box: putting back the title's picture erased the label's tip."""
    app = apps.projecting_a_line()
    blitter = blit_each(app, "A_x", (4.5, 4.0, 0.0, 4.5))
    assert blitter.blits == 4


def test_a_label_that_follows_a_changing_curve_into_a_title_box_is_drawn():
    """A static label placed relative to a changing artist (``xycoords=curve``) moves with it
    though nothing in the background changes; where it reaches is measured on every frame,
    so a kept title's picture never covers it (a reviewer's case: 117 pixels wrong when its
    reach was kept per background)."""
    with styled():
        figure = plt.figure(figsize=(3, 2.4), dpi=100)
        ax = figure.add_subplot()
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title("a title that stays")
        (curve,) = ax.plot([0.3, 0.7], [0.1, 0.1])
        ax.annotate(
            "NOTE", xy=(0.5, 1), xycoords=curve, xytext=(0, 4), textcoords="offset points",
            ha="center", va="bottom", fontsize=14, annotation_clip=False, clip_on=False,
        )  # fmt: skip
        figure.get_layout_engine().execute(figure)
        figure.set_layout_engine("none")  # frozen, as in the apps
    blitter = Blitter(figure, [curve])
    blitter.draw()
    for y in (0.1, 0.1, 1.05):
        curve.set_ydata([y, y])
        blitter.draw()
        assert_is_full_redraw(figure)
    assert blitter.blits == 3


def test_a_legend_placed_best_moves_with_the_curves():
    """``loc="best"`` (matplotlib's default) moves a legend away from the curves as they
    move: such a legend is drawn on every blit, not kept."""
    with styled():
        figure = plt.figure(figsize=(3, 2))
        ax = figure.add_subplot()
        (curve,) = ax.plot([0, 1], [0.9, 0.9], label="a curve")
        ax.legend()
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
    blitter = Blitter(figure, [curve])
    blitter.draw()
    for y in (0.1, 0.5, 0.9):
        curve.set_ydata([y, y])
        blitter.draw()
        assert_is_full_redraw(figure)
    assert blitter.legends == {}


@pytest.mark.parametrize(
    "hinting", ["default", "force_autohint", "no_autohint", "auto", "native", "no_hinting"]
)
def test_kept_glyphs_measure_text_as_matplotlib_does(hinting):
    """A live renderer measures text from kept layouts and glyph boxes (``_glyphs``): width,
    height and descent equal matplotlib's ``FT2Font.set_text`` measure, for random strings
    (Greek, symbols, a glyph no font has, a ligature) in three families, bold and italic, five
    sizes and three resolutions; without hinting, by matplotlib's own measure."""
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.font_manager import FontProperties

    if not keep_glyphs(RendererAgg(10, 10, 100)):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no glyphs are kept")
    rng = np.random.default_rng(len(hinting))
    letters = list("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 .,:;!?()[]|/")
    letters += [*"-+=*&%'\"ΔλθπΣ≤≥→°·…é", "\u00d7", "\u2212", "\ufb01", "\u6f22"]
    measured = 0
    with matplotlib.rc_context({"text.hinting": hinting}), warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # "Glyph ... missing from font(s)"
        for dpi in (72, 100, 200):
            kept, plain = RendererAgg(10, 10, dpi), RendererAgg(10, 10, dpi)
            keep_glyphs(kept)
            for family in ("DejaVu Sans", "DejaVu Serif", "DejaVu Sans Mono"):
                for size in (5.0, 8.33, 10.0, 12.0, 14.4):
                    prop = FontProperties(
                        family=family,
                        size=size,
                        weight=rng.choice(["normal", "bold"]),
                        style=rng.choice(["normal", "italic"]),
                    )
                    for _ in range(4):
                        text = "".join(rng.choice(letters, rng.integers(1, 30)))
                        assert kept.get_text_width_height_descent(text, prop, False) == (
                            plain.get_text_width_height_descent(text, prop, False)
                        ), (text, family, size, dpi)
                        measured += 1
            # Unhinted, set_text's sub-pixel pen differs from the layout's: matplotlib measures.
            assert bool(kept.boxes) == (hinting != "no_hinting")
    assert measured == 180


@pytest.mark.parametrize("hinting", ["default", "force_autohint", "no_hinting"])
def test_digits_swapped_lay_text_out_as_matplotlib_does(hinting):
    """A string that differs from one laid out before only in its digits (a title quoting a
    slider's value) is laid out by swapping the digits' glyphs (``_glyphs``): every glyph,
    font and place equal matplotlib's own layout of it, for titles like the apps', four
    families, regular and bold italic, three sizes and two resolutions. In the apps' font
    (DejaVu Sans) the swap is what gave them (matplotlib was asked only for the first string of
    each shape and the checks), except in a string with a ligature (ffi), whose glyphs are not
    one a character; STIX bold italic kerns a comma before some digits, and there a string is
    laid out by matplotlib again."""
    from matplotlib.backends.backend_agg import RendererAgg, get_hinting_flag
    from matplotlib.font_manager import FontProperties

    from interp.apps import _glyphs

    if not keep_glyphs(RendererAgg(10, 10, 100)):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no glyphs are kept")
    titles = [
        "M, the middle of AB, shows at s = 0.523",
        "|Δ(u, v)| in texels (max 1.25)",
        "d = \u22123.5, w = (2.0, 10.00)",
        "level 3: 64²",
        "7",
        "x1y2z3 ffi 12",
        "40°, 1/2, 12:30 [9]",
    ]
    rng = np.random.default_rng(len(hinting))
    asked = []
    real = _glyphs._layout
    swapped = {}
    with matplotlib.rc_context({"text.hinting": hinting}), warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # cmr10 has no bold
        for dpi, family, size, look in itertools.product(
            (100, 200),
            ("DejaVu Sans", "DejaVu Serif", "STIXGeneral", "cmr10"),
            (8.33, 10.0, 14.4),
            (("normal", "normal"), ("bold", "italic")),
        ):
            kept = RendererAgg(10, 10, dpi)
            keep_glyphs(kept)
            prop = FontProperties(family=family, size=size, weight=look[0], style=look[1])
            font = kept._prepare_font(prop)
            for title in titles:
                kept._laid_out(font, title, size, None, None)
                texts = {title}
                while len(texts) < 7:  # six new strings, each laid out once
                    texts.add(
                        "".join(str(rng.integers(10)) if c in "0123456789" else c for c in title)
                    )
                for text in sorted(texts - {title}):
                    asked.clear()
                    _glyphs._layout = lambda *args: asked.append(args[1]) or real(*args)
                    try:
                        laid_out = kept._laid_out(font, text, size, None, None)
                    finally:
                        _glyphs._layout = real
                    want = real(font, text, get_hinting_flag(), None, None)
                    assert laid_out == [(i.ft_object, i.glyph_index, i.x, i.y) for i in want]
                    swapped[(family, look, dpi, size, text)] = text not in asked
    assert len(swapped) == 2 * 4 * 3 * 2 * len(titles) * 6
    for (family, _, *_, text), swap in swapped.items():
        if family == "DejaVu Sans":
            assert swap == ("ffi" not in text), (family, text)
    assert not all(
        swap
        for (family, look, *_, text), swap in swapped.items()
        if family == "STIXGeneral" and look[0] == "bold" and "," in text
    )
    assert sum(swapped.values()) > 0.8 * len(swapped)


def test_digits_are_not_swapped_where_the_font_kerns_them(monkeypatch):
    """Where a digit beside some character would move the next glyph (a font that kerns "T7"
    and "7)", here made up over DejaVu Sans), a string differing in that digit is laid out by
    matplotlib again, with the kerning; beside other characters digits are still swapped."""
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.font_manager import FontProperties

    from interp.apps import _glyphs

    if not keep_glyphs(RendererAgg(10, 10, 100)):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no glyphs are kept")
    real = _glyphs._layout
    asked = []

    class Moved:  # a layout item, moved by dx
        def __init__(self, item, dx):
            self.char, self.ft_object = item.char, item.ft_object
            self.glyph_index, self.x, self.y = item.glyph_index, item.x + dx, item.y

    def kerning(font, s, *rest):  # "T7" and "7)" kerned by a pixel each
        asked.append(s)
        items, shift = [], 0.0
        for k, item in enumerate(real(font, s, *rest)):
            shift -= 1.0 if s[k - 1 : k + 1] in ("T7", "7)") else 0.0
            items.append(Moved(item, shift))
        return items

    monkeypatch.setattr(_glyphs, "_layout", kerning)
    flags = _glyphs.get_hinting_flag()
    for text, kerned in (("T5 x7 (5)", False), ("T7 x5 (5)", True), ("T5 x5 (7)", True)):
        kept = RendererAgg(10, 10, 100)
        keep_glyphs(kept)
        font = kept._prepare_font(FontProperties(family="DejaVu Sans", size=10))
        first = kept._laid_out(font, "T5 x5 (5)", 10.0, None, None)
        laid_out = kept._laid_out(font, text, 10.0, None, None)
        assert (text in asked) == kerned, text  # laid out again only beside T or )
        want = kerning(font, text, flags, None, None)
        assert laid_out == [(i.ft_object, i.glyph_index, i.x, i.y) for i in want]
        assert (laid_out[-1][2] == first[-1][2] - 1.0) == kerned  # the last glyph moved


def test_kept_font_heights_lay_text_out_as_matplotlib_does():
    """A live renderer answers a line's least ascent and descent, which matplotlib reads from
    the font's tables for every text it lays out, from what it read the first time: text laid
    out with it has matplotlib's extent to the last bit, for three fonts, bold and italic,
    five sizes, three resolutions, one and two lines, also measured at another dpi
    (``get_window_extent(dpi=...)``, which sets the figure's for a moment); a change of the
    rcParams that resolve a family to a font is a new font (not the kept one); and without
    the figure, matplotlib works the heights out itself."""
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.figure import Figure
    from matplotlib.font_manager import FontProperties

    if not keep_glyphs(RendererAgg(10, 10, 100)):
        pytest.skip(f"matplotlib {matplotlib.__version__} is not 3.11: no glyphs are kept")
    compared = 0
    for dpi in (72, 100, 200):
        figure = Figure(dpi=dpi)
        kept, plain = RendererAgg(10, 10, dpi), RendererAgg(10, 10, dpi)
        keep_glyphs(kept, figure)
        for family in ("DejaVu Sans", "STIXGeneral", "cmr10"):  # three kinds of metrics
            for size in (5.0, 8.33, 10.0, 12.0, 14.4):
                for weight, style in (("normal", "normal"), ("bold", "italic")):
                    prop = FontProperties(family=family, size=size, weight=weight, style=style)
                    for text in ("Ag", "two\nlines"):
                        label = figure.text(0.3, 0.4, text, fontproperties=prop)
                        assert kept._get_font_height_metrics(prop)[0] is not None
                        # Extents are the layout's bounds, moved to the text's place.
                        assert label.get_window_extent(kept).bounds == (
                            label.get_window_extent(plain).bounds
                        ), (text, family, size, dpi)
                        label._renderer = kept  # what a measure at another dpi uses
                        at_150 = label.get_window_extent(dpi=150).bounds
                        label._renderer = plain
                        assert at_150 == label.get_window_extent(dpi=150).bounds
                        compared += 1
    assert compared == 180
    sans = FontProperties(family="sans-serif", size=10)
    kept = RendererAgg(10, 10, 100)
    keep_glyphs(kept)
    assert kept._get_font_height_metrics(sans) == (None, None, None)  # no figure: matplotlib's
    keep_glyphs(kept, Figure(dpi=100))
    first = kept._get_font_height_metrics(sans)
    with matplotlib.rc_context({"font.sans-serif": ["STIXGeneral"]}):
        assert kept._get_font_height_metrics(sans) != first  # STIX's own
        plain = RendererAgg(10, 10, 100)
        label = Figure(dpi=100).text(0.5, 0.5, "Ag", fontproperties=sans)
        assert label.get_window_extent(kept).bounds == label.get_window_extent(plain).bounds
    assert kept._get_font_height_metrics(sans) == first


def _ipympl_app(make, ratio: float, scales: bool):
    """``make()``'s app on an ipympl canvas, as in a page of device pixel ratio ``ratio``: its
    view said it is ready (and got a frame, at ratio 1), then told the kernel its ratio and
    asked for the full draw that follows; with ``scales``, it has also said that it scales
    frames of a lower ratio. And the list every frame sent from then on goes to: (the
    controls' values when it was sent, its pixels decoded)."""
    import io

    from PIL import Image

    backend = matplotlib.get_backend()
    try:
        with warnings.catch_warnings():  # ipympl's toolbar passes traitlets an argument it warns of
            warnings.simplefilter("ignore", DeprecationWarning)
            plt.switch_backend("module://ipympl.backend_nbagg")
            app = make()
    finally:
        plt.switch_backend(backend)
    canvas = app.figure.canvas
    assert app.live
    canvas.syncing_data_url = False  # as ipympl's handler of "initialized" does; then the app's:
    app._canvas_message(canvas, {"type": "initialized"}, [])  # a frame at ratio 1
    canvas.handle_event({"type": "set_device_pixel_ratio", "device_pixel_ratio": ratio})
    canvas.draw()  # the full draw the page then asks for
    if scales:  # the page's message, through ipympl's and matplotlib's handlers
        canvas._handle_message(canvas, {"type": "interp_scaled_frames"}, [])
    assert canvas.interp_scaled_frames is scales
    frames = []
    canvas.send_binary = lambda data: frames.append(
        (dict(app.values), np.asarray(Image.open(io.BytesIO(data))))
    )
    return app, frames


def _drawn_afresh(make, values: dict, ratio: float) -> np.ndarray:
    """The figure of another ``make()`` app at ``values``, drawn whole at device pixel ratio
    ``ratio`` by matplotlib alone."""
    other = make()
    other.set(**values)
    other.figure.canvas._set_device_pixel_ratio(ratio)
    other.figure.canvas.draw()
    return np.asarray(other.figure.canvas.buffer_rgba())


def _drag(app, name: str, values, gap: float, settle: float = 0.2) -> None:
    """Move control ``name`` through ``values``, ``gap`` seconds apart, as a page's messages
    do, in a running event loop; then wait ``settle`` seconds for the figure to settle."""

    async def moves():
        for value in values:
            app.controls[name].value = value
            await asyncio.sleep(gap)
        await asyncio.sleep(settle)

    asyncio.run(moves())


@pytest.mark.parametrize(
    ("make", "name", "drags"),
    [
        (apps.checkerboards, "pitch", [[10.0, 12.0, 14.0, 16.0, 18.0, 20.0]]),
        # Legends kept as pictures, and limits that change (the background is drawn again) or
        # not: the second drag ends where the first did, so the last sharp frame puts back the
        # legends kept at the end of the first, after live frames that drew them at ratio 1.
        (apps.st_mapping, "w2", [[3.0, 3.5, 4.0, 4.5, 5.0, 6.14], [5.0, 4.0, 6.0, 6.14]]),
    ],
    ids=["checkerboards", "st_mapping"],
)
def test_a_hidpi_drag_sends_live_frames_at_ratio_1_and_a_sharp_one_when_it_stops(
    make, name, drags, monkeypatch
):
    """On a screen of device pixel ratio 2 whose page scales frames up, a drag's first step is
    drawn sharp (ratio 2), the steps that follow it at ratio 1 (a quarter of the pixels), and
    once they stop the figure once more at ratio 2. Every frame is the figure at its values
    drawn afresh by matplotlib at the frame's ratio, pixel for pixel; afterwards the canvas
    draws at ratio 2 again (pyplot's and ipympl's own draws see the screen's ratio)."""
    from interp.apps import _app

    app, frames = _ipympl_app(make, ratio=2, scales=True)
    # A series of steps, and the wait for the sharp frame, as long as a stalled test machine
    # may need: a pause of 50 ms between two steps would make the second the first of another.
    app.coalescer._idle = 0.5
    monkeypatch.setattr(_app, "SHARPEN", 0.5)
    width, height = app.figure.canvas.get_width_height()  # in the page's (CSS) pixels
    sharp, live = (2 * height, 2 * width), (height, width)
    for values in drags:
        first = len(frames)
        _drag(app, name, values, gap=0.005, settle=1.5)
        sizes = [frame.shape[:2] for _, frame in frames[first:]]
        assert sizes[0] == sharp and sizes[-1] == sharp, sizes
        assert live in sizes and set(sizes) == {sharp, live}, sizes
        assert sizes[1:-1] == [live] * (len(sizes) - 2), sizes  # sharp again only at the end
        assert frames[-1][0][name] == values[-1]
    for step, (shown, frame) in enumerate(frames):
        ratio = 2 if frame.shape[:2] == sharp else 1
        np.testing.assert_array_equal(
            frame, _drawn_afresh(make, shown, ratio), err_msg=f"frame {step} at {shown}"
        )
    assert app.figure.canvas.device_pixel_ratio == 2 and app.figure.dpi == 200
    assert not app.figure.stale


@pytest.mark.parametrize(("ratio", "scales"), [(2, False), (1, True)])
def test_live_frames_are_sharp_where_the_page_does_not_scale_them_or_needs_no_scaling(
    ratio, scales
):
    """A page that has not said it scales frames up (another ipympl, or a page that has not
    decoded a frame of ours yet) gets every frame at its own ratio, and so does a screen of
    ratio 1: one frame a step, no extra one."""
    app, frames = _ipympl_app(apps.st_mapping, ratio=ratio, scales=scales)
    _drag(app, "w2", [2.0, 2.5, 3.0, 3.5], gap=0.005)
    width, height = app.figure.canvas.get_width_height()
    assert {frame.shape[:2] for _, frame in frames} == {(ratio * height, ratio * width)}
    assert len(frames) == app.coalescer.draws


def test_a_page_that_appears_gets_sharp_frames_until_it_says_it_scales_them():
    """A page reloaded while the kernel runs shows the apps' figures again, but does not run
    their page script again (it scales nothing): its view's "initialized" message makes the
    frames sharp until a page says again that it scales them up."""
    app, frames = _ipympl_app(apps.st_mapping, ratio=2, scales=True)
    canvas = app.figure.canvas
    canvas._handle_message(canvas, {"type": "initialized"}, [])
    app._canvas_message(canvas, {"type": "initialized"}, [])
    assert not canvas.interp_scaled_frames
    _drag(app, "w2", [2.0, 2.5, 3.0, 3.5], gap=0.005)
    width, height = canvas.get_width_height()
    assert {frame.shape[:2] for _, frame in frames} == {(2 * height, 2 * width)}


def test_a_control_let_go_draws_its_last_value_sharp_at_once(monkeypatch, caplog):
    """The page says when a control is let go (a mouse button or a key up) while the figure
    shows a live frame of a lower ratio. The control's last value, which ipywidgets often sends
    after that message, is then drawn at the screen's ratio at once: no live frame of it, no
    wait for the sharp one. A drag after that is live again."""
    from interp.apps import _app

    app, frames = _ipympl_app(apps.st_mapping, ratio=2, scales=True)
    canvas = app.figure.canvas
    app.coalescer._idle = 0.5  # a series, however slow the machine (see the test above)
    monkeypatch.setattr(_app, "SHARPEN", 0.5)
    monkeypatch.setattr(_app, "RELEASED", 5.0)
    width, height = canvas.get_width_height()
    sharp, live = (2 * height, 2 * width), (height, width)

    async def drag_then_let_go():
        for value in (3.0, 3.5, 4.0, 4.5):
            app.controls["w2"].value = value
            await asyncio.sleep(0.005)
        await asyncio.sleep(0.05)  # the live frames are drawn; the sharp one is not due yet
        # The page's message, through ipympl's handler (no "unhandled message") and the app's.
        canvas._handle_custom_msg({"type": "interp_released"}, [])
        released = len(frames)
        app.controls["w2"].value = 5.0  # the last value, sent after the release
        await asyncio.sleep(1.0)
        return released

    released = asyncio.run(drag_then_let_go())
    sizes = [frame.shape[:2] for _, frame in frames]
    assert sizes[0] == sharp and set(sizes[1:released]) == {live}, sizes
    assert sizes[released:] == [sharp], sizes  # one frame after the release: sharp, at once
    assert frames[-1][0]["w2"] == 5.0
    np.testing.assert_array_equal(frames[-1][1], _drawn_afresh(apps.st_mapping, frames[-1][0], 2))
    assert not [r for r in caplog.records if "Unhandled message" in r.getMessage()]
    monkeypatch.setattr(_app, "RELEASED", 0.2)
    time.sleep(0.3)  # longer than RELEASED after the release: a drag is live again
    first = len(frames)
    _drag(app, "w2", [4.0, 3.5, 3.0], gap=0.005, settle=1.0)
    assert live in [frame.shape[:2] for _, frame in frames[first:]]


def test_dragging_an_attribute_in_lesson_5_moves_the_axes_only_at_grid_lines():
    """Lesson 5's attribute axes put their ends on a grid of a quarter of the curves' scale
    (here 0.25), a fifth of a spacing beyond the curves. Dragging a1 from 0 to 0.4 in the
    slider's steps (a2 = 1), the lowest curve (a1, at s = 0) crosses -0.25 + 0.05 and then
    0 + 0.05: the axes change twice, so the figure is drawn whole three times in 41 frames,
    each frame the full redraw. Before, the ends followed a tenth of the span (a hundredth
    once it fell below 1): 35 of 48 steps redrew the whole figure, 54 ms a step in the kernel
    against 8."""
    app = apps.attributes()
    blitter = blit_each(app, "a1", [round(0.01 * k, 2) for k in range(41)])
    assert blitter.full_draws == 3
    assert [ax.get_ylim() for ax in app.figure.axes] == [(0.25, 1.25)] * 2


def test_two_legends_of_one_axes_in_a_backdrop_are_drawn_over_the_base():
    """Two legends fixed in one axes, both in the backdrop: the second is checked against the
    first (drawn before it, in its axes) before its picture is put back; each frame is the
    full redraw pixel for pixel. (The first was once kept as its box, not as itself, and
    checking the second failed.)"""
    figure = plt.figure(figsize=(4, 2), dpi=100)
    ax = figure.subplots()
    (moving,) = ax.plot([0, 1], [0, 1], zorder=6)  # above the legends: they are the middle
    (a,) = ax.plot([], [], label="a 0")
    (b,) = ax.plot([], [], label="b")
    first = ax.legend(handles=[a], loc="upper left")
    ax.add_artist(first)
    second = ax.legend(handles=[b], loc="lower right")
    shown = {"n": 0}
    blitter = Blitter(figure, [moving], Backdrop([first, second], lambda: shown["n"]))
    blitter.draw()
    for n in (1, 2, 1):
        first.get_texts()[0].set_text(f"a {n}")
        shown["n"] = n
        blitter.draw()
        assert_is_full_redraw(figure)
    assert blitter.base is not None and second in blitter.base[2]
    assert blitter.full_draws == 1 and blitter.backdrops + blitter.blits == 3
