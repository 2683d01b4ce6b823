"""The figure objects: the contract they share, and statements they make that must be true."""

from __future__ import annotations

import inspect
import warnings

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

import interp
from interp import plots
from interp.plots._base import Plot, label
from interp.plots.registry import BARYCENTRIC_CAMERA, FIGURES, midpoint_title
from interp.raster import viewport
from interp.scenes import LESSON_SIZE


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


PLOT_CLASSES = [
    c for c in vars(plots).values() if inspect.isclass(c) and issubclass(c, Plot) and c is not Plot
]


def make(plot_class):
    """A plot on fresh axes, small where it draws images."""
    figure = Figure()
    if plot_class in (plots.CheckerPanels,):
        return plot_class(figure.subplots(1, 3), width=16, height=12)
    if plot_class in (plots.UVImages,):
        return plot_class(figure.subplots(1, 2), width=16, height=12)
    if plot_class is plots.OutsideView:
        return plot_class(figure.add_subplot(projection="3d"), width=16, height=12)
    if plot_class is plots.FilteringPanels:
        return plot_class(figure.subplots(1, 3), width=16, height=12)
    if plot_class is plots.MipmapPyramid:
        return plot_class(figure.subplots(1, 6))
    small = {"width": 16, "height": 12}
    parameters = inspect.signature(plot_class).parameters
    return plot_class(figure.add_subplot(), **{k: v for k, v in small.items() if k in parameters})


def test_every_plot_is_a_plot():
    assert len(PLOT_CLASSES) >= 13


@pytest.mark.parametrize("plot_class", PLOT_CLASSES, ids=lambda c: c.__name__)
def test_update_rejects_unknown_names(plot_class):
    plot = make(plot_class)
    with pytest.raises(TypeError, match=f"{plot_class.__name__}.update\\(\\) has no parameter"):
        plot.update(no_such_parameter=1)
    accepted = ", ".join(plot.params)
    with pytest.raises(TypeError, match=f"it accepts: {accepted}"):
        plot.update(no_such_parameter=1)


@pytest.mark.parametrize("name", FIGURES)
def test_lesson_figures_check_names_and_ranges(name):
    figure_class = FIGURES[name]
    shown = figure_class(Figure(figsize=figure_class.size))
    with pytest.raises(TypeError, match=f"{name} has no parameter 'zoom'"):
        shown.update(zoom=2)
    param_name, param = next(iter(figure_class.PARAMS.items()))
    if param.options is None:
        with pytest.raises(ValueError, match=f"{param_name} must be in"):
            shown.update(**{param_name: param.high + 1})
    else:
        with pytest.raises(ValueError, match=f"{param_name} must be one of"):
            shown.update(**{param_name: "nonsense"})
    assert shown.params == figure_class.defaults()  # a rejected value changes nothing


def test_barycentrics_colour_is_the_weights_and_every_corner_is_in_view():
    # E1: red, green and blue corners, so R + G + B = b0 + b1 + b2 = 1 on every drawn pixel, in
    # both modes; each channel reaches nearly 1 near its corner; all three corners in the frame.
    shown = FIGURES["barycentrics"](Figure())
    for image in shown.images:
        rgb = np.asarray(image.image.get_array())
        drawn = np.any(rgb != 1.0, axis=2)
        assert drawn.sum() > 1000
        # A centre that the edge, snapped to 1/256 pixel, puts inside can have a weight a few
        # 1e-6 below 0 (weights come from the exact corners), shown clipped to 0.
        np.testing.assert_allclose(rgb[drawn].sum(axis=1), 1.0, atol=1e-5)
        assert np.all(rgb[drawn].max(axis=0) > 0.95), "each corner's colour appears"
    camera = interp.Camera(**BARYCENTRIC_CAMERA).fitted(240, 180)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=1)
    corners = viewport(scene.clip[scene.triangles[0]], 240, 180)
    assert np.all(corners[:, 0] > 0) and np.all(corners[:, 0] < 240)
    assert np.all(corners[:, 1] > 0) and np.all(corners[:, 1] < 180)
    assert len(set(np.round(scene.clip[scene.triangles[0], 3], 6))) == 3, "three depths"


def test_midpoint_title_is_true_in_every_state():
    # E2: equal depths put M in the middle of the image; the title must say so, not "not 0.5".
    shown = FIGURES["the-problem"](Figure())
    shown.update(A_w=3.0, B_w=3.0)
    title = shown.view.ax.get_title()
    assert "s = 0.500" in title and "the middle of the image (A and B equally deep)" in title
    assert "not" not in title
    shown.update(A_w=2.0, B_w=8.0)
    s_m = interp.s_from_t(0.5, 2.0, 8.0)
    assert (
        f"s = {s_m:.3f}" in shown.view.ax.get_title()
        and "not the middle" in shown.view.ax.get_title()
    )
    shown.update(A_w=3.0, B_w=3.002)  # rounds to 0.500, but is not exactly the middle
    assert "nearly the middle" in shown.view.ax.get_title()
    shown.update(A_x=-1.0, A_w=2.0, B_x=-2.0, B_w=4.0)  # A, B and the eye in line
    assert "in line" in shown.view.ax.get_title() and "s =" not in shown.view.ax.get_title()
    assert midpoint_title(shown.view) == shown.view.ax.get_title()


def test_at_the_defaults_a_is_off_the_image_plane():
    # E2: the labels A and a overlapped because A sat on the image plane.
    defaults = FIGURES["the-problem"].defaults()
    assert abs(defaults["A_w"] - defaults["d"]) >= 0.5


@pytest.mark.parametrize("name", ["approximations", "clipping", "checkerboards", "depth"])
def test_a_figure_depends_only_on_its_values_not_on_history(name):
    # With nothing in view the approximation lab kept the previous camera's axes.
    figure_class = FIGURES[name]
    nothing = {"pitch": -10.0, "height": 4.0} if "pitch" in figure_class.PARAMS else {"w2": 50.0}
    detour = {"pitch": 60.0, "height": 2.0} if "pitch" in figure_class.PARAMS else {"w2": 0.3}
    direct = figure_class(Figure(figsize=figure_class.size), **nothing)
    travelled = figure_class(Figure(figsize=figure_class.size), **detour)
    travelled.update(**nothing)
    for a, b in zip(direct.figure.axes, travelled.figure.axes, strict=True):
        assert a.get_xlim() == b.get_xlim() and a.get_ylim() == b.get_ylim()
        assert a.get_title() == b.get_title()
        for la, lb in zip(a.lines, b.lines, strict=True):
            np.testing.assert_array_equal(la.get_xydata(), lb.get_xydata())


def test_contour_lines_skip_masked_nan_and_infinite_pixels():
    """``contour_segments`` follows a level where the image has values, and nowhere where it
    is masked (whatever lies under the mask), NaN or infinite."""
    from interp.plots.checker import contour_segments

    ramp = np.tile(np.linspace(0.0, 1.0, 11), (4, 1))  # column / 10
    image = np.ma.masked_array(ramp, mask=np.zeros(ramp.shape, bool))
    image[:, 7:9] = np.ma.masked  # under the mask: 0.7 and 0.8, crossing 0.75
    image.data[:, 9] = np.nan
    image.data[:, 10] = np.inf
    lines = contour_segments(image, [0.5, 0.75, 0.95])
    assert len(lines) == 1
    np.testing.assert_allclose(lines[0][:, 0], 5.0)  # x = column 5, where the ramp is 0.5


def test_labels_start_on_whole_pixels_within_half_a_pixel_of_annotate():
    """A label (``interp.plots._base.label``) is ``annotate``'s text moved to the nearest whole
    pixel, wherever its point is, on linear and log axes alike."""
    rng = np.random.default_rng(7)
    for scale in ("linear", "log"):
        ax = FigureCanvasAgg(Figure(dpi=100)).figure.subplots()
        ax.set_xscale(scale)
        ax.set_xlim(0.1, 10)
        ax.set_ylim(0, 1)
        renderer = ax.figure.canvas.get_renderer()
        for x, y in zip(rng.uniform(0.1, 10, 50), rng.uniform(0, 1, 50), strict=True):
            ours = label(ax, "N=4", (x, y), (4, 2))
            theirs = ax.annotate("N=4", (x, y), xytext=(4, 2), textcoords="offset points")
            ours_box, theirs_box = (a.get_window_extent(renderer) for a in (ours, theirs))
            shift = ours_box.p0 - theirs_box.p0
            assert np.all(np.abs(shift) <= 0.5)
            assert np.allclose(ours_box.size, theirs_box.size)
            anchor = ours.get_transform().transform(ours.xyann)
            assert np.allclose(anchor, np.round(anchor), rtol=0, atol=1e-9)
            assert np.allclose(anchor - shift, theirs.get_transform().transform(theirs.xyann))
            # Clipped (or not) as annotate's, so as far outside the axes.
            assert ours.get_clip_on() == theirs.get_clip_on()
            assert ours.get_clip_box() is theirs.get_clip_box()
            assert ours.get_clip_path() is theirs.get_clip_path()
            tight = ours.get_tightbbox(renderer).p0 - theirs.get_tightbbox(renderer).p0
            assert np.all(np.abs(tight) <= 0.5)
    with pytest.raises(TypeError, match="arrowprops"):
        label(ax, "N=4", (1, 0.5), (4, 2), arrowprops={})


def test_a_label_reaches_outside_its_axes_as_annotate_does():
    """A label at the axes' corner is drawn beyond it (annotate does not clip), and a label at
    a position that is not finite draws nothing, without an error (as annotate)."""
    figure = FigureCanvasAgg(Figure(figsize=(2, 2), dpi=100)).figure
    ax = figure.add_axes((0.1, 0.1, 0.6, 0.6))
    label(ax, "ABC", (0.99, 0.99), (6, 4), color="black")
    label(ax, "N", (np.nan, 0.5), (4, 2), annotation_clip=False)
    label(ax, "N", (0.5, np.inf), (4, 2), annotation_clip=False)
    figure.canvas.draw()
    pixels = np.asarray(figure.canvas.buffer_rgba())[..., :3].min(axis=2)
    top = round(figure.bbox.height - ax.bbox.y1)  # the axes' top edge, in rows from the top
    right = round(ax.bbox.x1)
    assert (pixels[: top - 2, right + 2 :] < 128).sum() > 20  # ink above and right of it


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        ((0.0, 1.0), (-0.25, 1.25)),
        ((0.0, 2.4e-166), (-2.5e-10, 2.5e-10)),  # all but 0 (found by the slider fuzz)
        ((-3.0, 0.5), (-3.75, 1.25)),  # scale 3: grid 5/4
        ((1e6, 1e6 + 1), (750000.0, 1250000.0)),  # close together: shown so
    ],
)
def test_fit_y_puts_the_ends_on_the_grid_of_a_quarter_of_the_scale(values, expected):
    from interp.plots._style import fit_y

    ax = plt.subplots()[1]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no singular limits, no numpy warning
        fit_y(ax, *values)
    assert ax.get_ylim() == pytest.approx(expected, rel=1e-12)
