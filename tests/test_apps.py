"""Every app, driven without a browser: move controls, compare what is shown with interp."""

from __future__ import annotations

import os
import time

import ipywidgets as widgets
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from matplotlib.backend_bases import MouseEvent

import interp
from interp import approximation, apps
from interp.apps._app import on_slider
from interp.plots.gpu import LAB_CAMERA
from interp.plots.registry import RESOLUTIONS
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, checker_views

from helpers import shown_arrays


def snapshot(figure):
    return [a.copy() for a in shown_arrays(figure)]


def camera_values(**changes):
    values = {
        k: getattr(LESSON_CAMERA, k) for k in ("height", "pitch", "yaw", "distance", "fovy", "near")
    }
    return {**values, **changes}


def test_the_problem_shows_where_the_midpoints_go():
    app = apps.the_problem()
    app.set(A_x=-1.0, A_w=2.0, B_x=2.0, B_w=6.0, d=1.5)
    view = app.plot.view
    np.testing.assert_allclose(view.segment.get_xydata(), [[2.0, -1.0], [6.0, 2.0]])
    t = interp.t_from_s(0.5, 2.0, 6.0)
    expected_C = np.array([-1.0, -2.0]) + t * (np.array([2.0, -6.0]) - [-1.0, -2.0])
    np.testing.assert_allclose(view.markers["C"].get_xydata()[0], [-expected_C[1], expected_C[0]])
    np.testing.assert_allclose(view.plane.get_xdata(), [1.5, 1.5])
    s_m = interp.s_from_t(0.5, 2.0, 6.0)
    assert f"s = {s_m:.3f}" in view.ax.get_title()


def test_projecting_a_line_links_all_three_panels():
    app = apps.projecting_a_line()
    before = snapshot(app.figure)
    app.set(A_w=1.0, B_w=9.0, samples=5)
    after = snapshot(app.figure)
    assert any(
        b.shape != a.shape or not np.allclose(b, a) for b, a in zip(before, after, strict=True)
    )
    s = np.linspace(0, 1, 101)
    np.testing.assert_allclose(
        app.plot.strip.correct.get_ydata(), interp.lerp_perspective(0.0, 1.0, 1.0, 9.0, s)
    )
    samples = (np.arange(5) + 0.5) / 5
    np.testing.assert_allclose(
        app.plot.curve.samples.get_ydata(), interp.t_from_s(samples, 1.0, 9.0)
    )
    assert len(app.plot.view.fan.get_segments()) == 5


def test_dragging_an_endpoint_moves_every_linked_panel():
    app = apps.projecting_a_line()
    app.figure.canvas.draw()
    ax = app.plot.view.ax
    start = app.plot.view.points["A"]
    before = app.plot.strip.correct.get_ydata().copy()

    def mouse(name, w, x):
        px, py = ax.transData.transform((w, x))
        event = MouseEvent(name, app.figure.canvas, px, py, button=1)
        app.figure.canvas.callbacks.process(name, event)

    mouse("button_press_event", -start[1], start[0])
    mouse("motion_notify_event", 6.0, 1.0)
    mouse("button_release_event", 6.0, 1.0)
    assert app.controls["A_w"].value == pytest.approx(6.0, abs=0.05)
    assert app.controls["A_x"].value == pytest.approx(1.0, abs=0.05)
    np.testing.assert_allclose(
        app.plot.view.points["A"], [app.controls["A_x"].value, -app.controls["A_w"].value]
    )
    assert not np.allclose(app.plot.strip.correct.get_ydata(), before)
    np.testing.assert_allclose(
        app.plot.strip.correct.get_ydata(),
        interp.lerp_perspective(
            0.0, 1.0, app.controls["A_w"].value, app.controls["B_w"].value, np.linspace(0, 1, 101)
        ),
    )
    mouse("motion_notify_event", 2.0, 0.0)  # released: no longer dragging
    assert app.controls["A_w"].value == pytest.approx(6.0, abs=0.05)
    # The release point counts even if the moves before it were lost on the way.
    mouse("button_press_event", 6.0, 1.0)
    mouse("button_release_event", 4.0, -2.0)
    assert app.controls["A_w"].value == pytest.approx(4.0, abs=0.05)
    assert app.controls["A_x"].value == pytest.approx(-2.0, abs=0.05)


#: What Chromium's slider (noUiSlider in JupyterLab, ipywidgets 8) made of values the kernel
#: set on A's sliders while A was dragged (its range and step; the kernel's value; the page's),
#: read from the values the page sent back before the kernel copied its arithmetic.
PAGE_SNAPPED = [
    ((0.5, 9.5, 0.05), 7.743134378535013, 7.75),
    ((0.5, 9.5, 0.05), 7.920408336474697, 7.9),
    ((0.5, 9.5, 0.05), 8.097682294414382, 8.1),  # not 0.5 + 152 * 0.05 = 8.100000000000001
    ((0.5, 9.5, 0.05), 8.274956252354064, 8.25),
    ((0.5, 9.5, 0.05), 8.452230210293749, 8.450000000000001),
    ((0.5, 9.5, 0.05), 2.19161264709465, 2.2),
    ((0.5, 9.5, 0.05), 3.2330427441091176, 3.25),
    ((-4.5, 4.5, 0.05), -1.4600975459955992, -1.4499999999999993),
    # Edge cases, from noUiSlider's own code (copied from the page's bundle) run in node by a
    # reviewer: a value one ulp below a half step (JavaScript rounds it down, floor(x + 0.5)
    # does not), and a value a hair below the top, which the page takes as 100 %.
    ((0.1, 0.6, 0.5), 0.35, 0.1),
    ((0.1, 0.95, 0.2), 0.19999999999999998, 0.1),
    ((0.001, 2.5, 0.01), 0.005999999999999999, 0.001),
    ((-1.0, 1.0, 0.15), 0.9999999999999999, 1.0),
    ((-9.0, -2.0, 0.3), -2.0000000000000004, -2.0),
]


@pytest.mark.parametrize(("bounds", "value", "page"), PAGE_SNAPPED)
def test_an_endpoint_is_put_where_the_pages_slider_puts_it(bounds, value, page):
    low, high, step = bounds
    slider = widgets.FloatSlider(min=low, max=high, step=step)
    assert on_slider(slider, value) == page  # the very same number: the page sends nothing back


def test_an_endpoint_dragged_goes_on_its_sliders_steps_and_draws_once_a_step():
    app = apps.the_problem()
    app.figure.canvas.draw()
    ax = app.plot.view.ax
    start = app.plot.view.points["A"]

    def mouse(name, w, x):
        px, py = ax.transData.transform((w, x))
        app.figure.canvas.callbacks.process(name, MouseEvent(name, app.figure.canvas, px, py, 1))

    mouse("button_press_event", -start[1], start[0])
    draws = app.coalescer.draws
    mouse("motion_notify_event", 6.013, 1.0)
    assert app.values["A_w"] == 6.0 and app.coalescer.draws == draws + 1
    mouse("motion_notify_event", 6.02, 1.01)  # the same steps: nothing to draw
    mouse("button_release_event", 6.02, 1.01)
    assert app.coalescer.draws == draws + 1
    for name in ("A_w", "A_x"):
        slider = app.controls[name]
        steps = (app.values[name] - slider.min) / slider.step
        assert steps == pytest.approx(round(steps), abs=1e-9)


def test_st_mapping_marks_the_derived_peak():
    app = apps.st_mapping()
    app.set(w1=1.0, w2=9.0)
    assert app.plot.gap.peak.get_xydata()[0] == pytest.approx([0.75, 0.5])
    np.testing.assert_allclose(
        app.plot.family.current.get_ydata(), interp.t_from_s(np.linspace(0, 1, 201), 1.0, 9.0)
    )


def test_depth_app_curves():
    app = apps.depth()
    app.set(w1=2.0, w2=20.0, near=0.5, far=50.0, buffer="fixed24")
    ndc = app.plot.across.curves["NDC z"].get_ydata()
    np.testing.assert_allclose(ndc, np.linspace(0, 1, 101), atol=1e-12)  # straight
    w, step = app.plot.precision.lines[0].get_data()
    np.testing.assert_allclose(step, interp.depth_resolution(w, 0.5, 50.0, "fixed24"))


def test_attributes_app_curves():
    app = apps.attributes()
    app.set(a1=0.2, a2=-0.4, w1=2.0, w2=8.0, behind=-3.0, near=0.25)
    s = np.linspace(0, 1, 101)
    np.testing.assert_allclose(
        app.plot.line.lines["perspective-correct"].get_ydata(),
        interp.lerp_perspective(0.2, -0.4, 2.0, 8.0, s),
    )
    a_c = interp.mistakes.clip_vertex_attribute(0.2, -0.4, 2.0, -3.0, 0.25)
    np.testing.assert_allclose(
        app.plot.clip.right.get_ydata(), interp.lerp_perspective(0.2, a_c, 2.0, 0.25, s)
    )


@pytest.mark.parametrize("make, whole", [(apps.colour_quad, True), (apps.barycentrics, False)])
def test_colour_images_are_rasterize_output(make, whole):
    app = make()
    app.set(**camera_values(pitch=40.0, height=1.5))
    image = app.plot.images[1]
    camera = interp.Camera(**camera_values(pitch=40.0, height=1.5)).fitted(
        image.width, image.height
    )
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=1)
    triangles = scene.triangles if whole else scene.triangles[:1]
    colours, covered = interp.rasterize(
        scene.clip, interp.plots.attributes.CORNER_COLOURS, triangles, image.width, image.height
    )
    np.testing.assert_allclose(image.image.get_array()[covered], colours[covered])


def test_checkerboards_show_checker_views():
    app = apps.checkerboards()
    app.set(
        **camera_values(pitch=30.0, yaw=20.0),
        frequency=12.0,
        resolution="160 x 120",
        quads=2,
        mode="subdivided",
        span=8,
        filtered="nearest",
    )
    camera = interp.Camera(**camera_values(pitch=30.0, yaw=20.0)).fitted(160, 120)
    views = checker_views(
        interp.ground_plane(camera, LESSON_SIZE, quads=2),
        160,
        120,
        12.0,
        filtered=False,
        mode="subdivided",
        span=8,
    )
    panels = app.plot.panels
    np.testing.assert_array_equal(panels.approximate.get_array(), views.approximate)
    np.testing.assert_array_equal(panels.correct.get_array(), views.correct)
    np.testing.assert_array_equal(panels.error.get_array(), views.error)
    assert panels.axes[0].get_title() == "exact every 8 px"


def test_uv_images_are_masked_where_nothing_is_drawn():
    app = apps.uv_images()
    app.set(**camera_values(yaw=45.0), mode="affine")
    u = app.plot.uv.images[0].get_array()
    assert np.ma.isMaskedArray(u) and u.mask.any() and (~u.mask).any()
    assert 0 <= u.min() and u.max() <= 1


def test_clipping_counts_the_pieces():
    app = apps.clipping()
    app.set(**camera_values(height=0.02, pitch=10.0, near=0.01, distance=0.0))
    assert app.plot.view.counts["pieces"] > app.plot.view.counts["visible triangles"]
    assert str(app.plot.view.counts["pieces"]) in app.plot.view.ax.get_title()


def test_approximation_lab_plots_the_costs():
    app = apps.approximations()
    values = {**camera_values(), "roll": 30.0}
    app.set(**values)
    camera = interp.Camera(**{**LAB_CAMERA.__dict__, **values})
    spans = approximation.span_costs(camera, 192, 144)
    x, y = app.plot.lab.spans.get_data()
    np.testing.assert_allclose(x, spans.divides_per_pixel[1:])
    np.testing.assert_allclose(y, spans.mean_error[1:])


def test_the_lab_labels_the_points_inside_its_axes_as_the_toolbar_zooms_and_pans():
    """A label shows while its point is inside the axes (what matplotlib's annotation_clip
    checks on every draw): after a redraw every plotted point has a label there; zoomed in,
    only the points left inside; back out, all again."""
    app = apps.approximations()
    lab = app.plot.lab
    ax = lab.ax
    points = {
        (float(x), float(y))
        for line in (lab.spans, lab.tessellation)
        for x, y in zip(*line.get_data(), strict=True)
    }

    def labelled() -> set[tuple[float, float]]:
        return {tuple(map(float, note.xy)) for note in lab.notes.values() if note.get_visible()}

    assert len(points) >= 8
    assert labelled() == points
    full = ax.get_xlim(), ax.get_ylim()
    xs = sorted(x for x, _ in points)
    low, high = xs[2] / 1.01, xs[-3] * 1.01
    ax.set_xlim(low, high)  # as the toolbar's zoom: limits, no redraw
    inside = {(x, y) for x, y in points if low <= x <= high}
    assert 0 < len(inside) < len(points)
    assert labelled() == inside
    ax.set_xlim(*full[0])
    ax.set_ylim(*full[1])
    assert labelled() == points


def test_presentation_mode_makes_bigger_apps():
    apps.presentation(True)
    try:
        big = apps.st_mapping()
    finally:
        apps.presentation(False)
    small = apps.st_mapping()
    assert big.figure.get_size_inches()[0] > small.figure.get_size_inches()[0]
    assert int(big.controls["w1"].layout.width[:-2]) > int(small.controls["w1"].layout.width[:-2])


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_every_figure_fits_a_laptop_and_a_projector(name):
    # 848 px of output on a 1280 x 800 laptop with JupyterLab's file browser open; a 1280 x 720
    # projector in presentation mode (the browser tests check the pages themselves).
    from interp.apps._app import FIT, FIT_PRESENTATION

    width, height = apps.ALL[name]().figure.get_size_inches()
    assert width <= FIT[0] <= 8.48 and height <= FIT[1]
    apps.presentation(True)
    try:
        width, height = apps.ALL[name]().figure.get_size_inches()
    finally:
        apps.presentation(False)
    assert width <= FIT_PRESENTATION[0] and height <= FIT_PRESENTATION[1]


def test_unknown_control_is_named():
    with pytest.raises(TypeError, match="no control named 'pitchh'"):
        apps.checkerboards().set(pitchh=3)


def test_static_display_shows_the_figure_once_and_updates_it(monkeypatch):
    shown = []

    class Handle:
        def update(self, obj, metadata=None):
            shown.append(("update", obj, metadata))

    def fake_display(obj, display_id=False, metadata=None):
        shown.append(("display", obj, metadata))
        return Handle() if display_id else None

    monkeypatch.setattr("interp.apps._app.display", fake_display)
    app = apps.st_mapping()
    app._ipython_display_()
    assert [kind for kind, *_ in shown] == ["display"] * 3
    # the picture, the result as text, the controls: no script
    assert shown[0][1] is app.figure and isinstance(shown[2][1], widgets.Widget)
    alt = shown[0][2]["image/png"]["alt"]
    assert alt.startswith(app.plot.title) and app.plot.readout() in alt  # the picture's alt text
    assert shown[1][1]._repr_html_() == app.readout.value  # the result as text
    app.controls["w2"].value = 7.0
    updates = [entry for entry in shown if entry[0] == "update"]
    assert updates[0][1] is app.figure and "alt" in updates[0][2]["image/png"]


def control_values(control):
    if isinstance(control, widgets.Dropdown):
        return st.sampled_from([o[1] if isinstance(o, tuple) else o for o in control.options])
    if isinstance(control, widgets.IntSlider):
        return st.integers(control.min, control.max)
    if isinstance(control, widgets.FloatLogSlider):
        return st.floats(control.min, control.max).map(lambda e: 10.0**e)
    return st.floats(control.min, control.max)


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_any_slider_values_show_clean_figures(name):
    app = apps.ALL[name]()
    if "resolution" in app.controls:
        app.set(resolution="160 x 120")  # keep the fuzz quick; resolutions are tested above
    strategy = st.fixed_dictionaries(
        {key: control_values(c) for key, c in app.controls.items() if key != "resolution"}
    )
    extremes = [
        {
            k: (c.min if hasattr(c, "min") else c.value)
            for k, c in app.controls.items()
            if k != "resolution"
        },
        {
            k: (c.max if hasattr(c, "max") else c.value)
            for k, c in app.controls.items()
            if k != "resolution"
        },
    ]

    def check(values):
        app.set(**values)
        for array in shown_arrays(app.figure):
            assert np.all(np.isfinite(array)), name

    for values in extremes:  # every slider at its minimum, then at its maximum
        check(
            {
                k: (10.0**v if isinstance(app.controls[k], widgets.FloatLogSlider) else v)
                for k, v in values.items()
            }
        )

    @settings(max_examples=12 if name == "approximations" else 30, deadline=None)
    @given(strategy)
    def fuzz(values):
        check(values)

    fuzz()


def test_resolutions_offered_are_valid():
    for width, height in RESOLUTIONS.values():
        assert 0 < width <= 4096 and 0 < height <= 4096


@pytest.mark.parametrize(
    "name",
    [
        "checkerboards",
        "checkerboards_outside",
        "clipping",
        "clipping_outside",
        "colour_quad",
        "outside_view",
        "texture_filtering",
        "uv_images",
    ],
)
@pytest.mark.parametrize(
    "camera",
    [
        {"height": 0.0, "pitch": 0.0},  # the camera in the plane, looking along it
        {"height": 0.001, "pitch": -10.0, "near": 0.001},  # grazing, near at its minimum
        {"height": -0.5, "pitch": 30.0},  # below the plane, looking at its underside
        {"height": 4.0, "pitch": 90.0, "distance": 0.0},  # straight down
        {"height": 0.5, "distance": 0.0, "pitch": 5.0, "near": 0.001},  # above the centre
    ],
    ids=["in-plane", "grazing", "below", "straight-down", "inside"],
)
def test_extreme_cameras_show_clean_figures(name, camera):
    app = apps.ALL[name]()
    if "resolution" in app.controls:
        app.set(resolution="160 x 120")
    app.set(**camera)
    for array in shown_arrays(app.figure):
        assert np.all(np.isfinite(array))


@pytest.mark.parametrize("name", sorted(apps.ALL))
def test_a_step_computes_on_one_thread(name):
    """Each app's steps run on the thread that asks for them, without BLAS's helper threads: on
    the course's 2-core machine, shared with the browser that shows the frames, OpenBLAS's
    threads (which spin for a while after each product they share) took the CPU the page
    needed. One (43200 x 4) @ (4 x 4) product in lesson 7's ray cast cost its drag half its
    pictures a second in Chromium (22.4 -> 11.9), with the kernel alone a little faster."""
    app = apps.ALL[name]()
    steps = [  # each slider across its range (each choice of an app without sliders)
        {key: value}
        for key, control in app.controls.items()
        if hasattr(control, "min")
        for value in slider_values(control, 6)
    ] or [{key: value} for key, control in app.controls.items() for value in control.options]
    app.set(**steps[0])  # made and drawn once before timing

    def move_every_slider():
        for values in steps:
            app.set(**values)

    here, elsewhere = cpu_here_and_elsewhere(move_every_slider)
    assert elsewhere <= 0.05 * here + 0.005, (
        f"{name}: {1000 * elsewhere:.0f} ms of CPU on other threads, {1000 * here:.0f} ms on this"
    )


def slider_values(control: widgets.Widget, count: int) -> list:
    """``count`` values spread over a slider's range, as it takes them."""
    spread = np.linspace(control.min, control.max, count)
    if isinstance(control, widgets.FloatLogSlider):
        return [float(10.0**e) for e in spread]
    if isinstance(control, widgets.IntSlider):
        return sorted({round(float(v)) for v in spread})
    return [float(v) for v in spread]


def cpu_here_and_elsewhere(work) -> tuple[float, float]:
    """The CPU seconds ``work()`` took on this thread, and on the process's other threads."""
    process, thread = time.process_time(), time.thread_time()
    work()
    here = time.thread_time() - thread
    return here, time.process_time() - process - here


@pytest.mark.skipif(
    (os.cpu_count() or 1) < 2 or os.environ.get("OPENBLAS_NUM_THREADS") == "1",
    reason="numpy's BLAS has one thread here: no helper threads to see",
)
def test_the_one_thread_check_sees_blas_threads():
    """The check above can fail: the product that once slowed lesson 7 shows up on other
    threads."""
    rays, to_world = np.ones((43200, 4)), np.arange(16.0).reshape(4, 4)
    # Times a transposed matrix, as the rays' ends were unprojected (numpy hands that to BLAS).
    here, elsewhere = cpu_here_and_elsewhere(lambda: [rays @ to_world.T for _ in range(300)])
    assert elsewhere > 0.05 * here + 0.005, (here, elsewhere)
