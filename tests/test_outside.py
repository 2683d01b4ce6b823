"""The outside view: its geometry against the rasterizer and closed forms, and its figures
against a full redraw (blitting), the mouse and the fixed viewpoints."""

from __future__ import annotations

import io

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from interp import frustum
from interp.apps._app import App
from interp.camera import Camera
from interp.clipping import PLANES
from interp.plots.outside import VIEWS, OutsideView
from interp.plots.registry import (
    FIGURES,
    CheckerboardsOutside,
    ClippingOutside,
    OutsideViewFigure,
)
from interp.raster import fragments
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane

#: The figures with an outside view or texture filtering, by name.
OUTSIDE_FIGURES = {
    name: FIGURES[name]
    for name in (
        "outside-view",
        "checkerboards-outside",
        "texture-filtering",
        "mipmap-pyramid",
        "clipping-outside",
    )
}

CAMERAS = [
    LESSON_CAMERA,
    Camera(height=0.6, pitch=25.0, yaw=30.0, near=0.05),
    Camera(height=0.3, pitch=15.0, distance=1.0),  # on the quad: the near plane cuts
    Camera(height=0.02, pitch=10.0, near=0.05, yaw=-70.0),
    Camera(height=2.5, pitch=60.0, distance=5.0, roll=20.0),
]


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def project(camera: Camera, world: np.ndarray) -> np.ndarray:
    """Clip coordinates of world points (..., 3)."""
    homogeneous = np.concatenate([world, np.ones((*world.shape[:-1], 1))], axis=-1)
    return homogeneous @ (camera.projection @ camera.view).T


def area(triangles: np.ndarray) -> float:
    edges = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    return float(np.linalg.norm(edges, axis=1).sum() / 2)


# ------------------------------------------------------------------------------ geometry


@pytest.mark.parametrize("camera", CAMERAS, ids=range(len(CAMERAS)))
def test_sections_are_the_image_corners_at_their_depth(camera):
    camera = camera.fitted(320, 240)
    for depth in (camera.near, 1.0, 7.5):
        clip = project(camera, frustum.section(camera, depth))
        np.testing.assert_allclose(clip[:, 3], depth, rtol=1e-12)
        np.testing.assert_allclose(clip[:, :2] / clip[:, 3:], frustum.CORNERS, atol=1e-12)


@pytest.mark.parametrize("camera", CAMERAS, ids=range(len(CAMERAS)))
def test_a_pixel_ray_hits_the_quad_exactly_where_the_rasterizer_draws_it(camera):
    width, height = 96, 72
    camera = camera.fitted(width, height)
    scene = ground_plane(camera, size=LESSON_SIZE, quads=2)
    covered = fragments(scene.clip, scene.uv, scene.triangles, width, height).covered
    rays = frustum.pixel_rays(camera, width, height, per_side=12, quad_size=LESSON_SIZE)
    columns = (rays.pixel[:, 0] - 0.5).astype(int)
    rows = (height - rays.pixel[:, 1] - 0.5).astype(int)
    np.testing.assert_array_equal(rays.hits, covered[rows, columns])
    # Where a ray ends on the ground, that point projects back onto its pixel's centre.
    clip = project(camera, rays.end[rays.hits])
    window = (clip[:, :2] / clip[:, 3:] + 1) / 2 * [width, height]
    np.testing.assert_allclose(window, rays.pixel[rays.hits], atol=1e-9)
    np.testing.assert_allclose(rays.end[rays.hits, 1], 0.0, atol=1e-12)
    crossing = project(camera, rays.on_image_plane)
    np.testing.assert_allclose(crossing[:, 3], 1.0, rtol=1e-12)  # the image plane: depth 1


@pytest.mark.parametrize("camera", CAMERAS, ids=range(len(CAMERAS)))
def test_clipping_in_world_space(camera):
    camera = camera.fitted(320, 240)
    scene = ground_plane(camera, size=LESSON_SIZE, quads=3)
    clipped = frustum.clipped_in_world(scene, 320, 240)
    half = LESSON_SIZE / 2 * (1 + 1e-9)
    for pieces in (clipped.visible, clipped.cut_off, clipped.new_vertices[None]):
        np.testing.assert_allclose(pieces[..., 1], 0.0, atol=1e-9)  # all on the ground
        assert np.all(np.abs(pieces[..., [0, 2]]) <= half)  # within the quad
    # What the camera draws is inside the view volume; what the near plane cut off is before it.
    clip = project(camera, clipped.visible)
    assert np.all(clip @ PLANES.T >= -1e-9 * np.abs(clip).max())
    depth = project(camera, clipped.cut_off)[..., 3]
    assert np.all(depth <= camera.near * (1 + 1e-9))
    # Every new vertex lies on a plane of the view volume.
    clip = project(camera, clipped.new_vertices)
    on_a_plane = np.min(np.abs(clip @ PLANES.T), axis=1) <= 1e-9 * np.abs(clip).max(axis=1)
    assert on_a_plane.all()
    # The near plane's two sides share the quad out: both together are all of it, where the
    # side planes clip nothing.
    inside_sides = ground_plane(camera.fitted(320, 240), size=LESSON_SIZE, quads=3)
    sides = inside_sides.clip @ PLANES[2:].T
    if np.all(sides >= 0):
        assert area(clipped.visible) + area(clipped.cut_off) == pytest.approx(LESSON_SIZE**2)


def test_nothing_clipped_nothing_new():
    camera = Camera(height=6.0, pitch=90.0, distance=0.0, fovy=60.0)  # sees all of the quad
    clipped = frustum.clipped_in_world(ground_plane(camera, size=LESSON_SIZE, quads=2), 320, 240)
    assert len(clipped.new_vertices) == 0 and len(clipped.cut_off) == 0
    assert len(clipped.visible) == clipped.in_view == 8
    assert area(clipped.visible) == pytest.approx(LESSON_SIZE**2)


def test_reach_is_the_farthest_point_in_front_within_the_clipping_range():
    camera = Camera(height=1.0, pitch=0.0, distance=3.0, near=0.1, far=4.0)
    points = np.array([[0.0, 1.0, 1.0], [0.0, 1.0, -5.0], [0.0, 1.0, 9.0]])  # 2, 8, behind
    assert frustum.reach_of(camera, points, 1.0) == 4.0  # clamped to far
    assert frustum.reach_of(camera, points[:1], 1.0) == pytest.approx(2.0)
    assert frustum.reach_of(camera, points[2:], 3.0) == 3.0  # nothing in front


# ------------------------------------------------------------------------------ the plot


def outside(**params) -> OutsideView:
    figure = Figure()
    return OutsideView(figure.add_subplot(projection="3d"), **params)


def test_the_plot_needs_3d_axes_and_known_choices():
    with pytest.raises(TypeError, match="3D axes"):
        OutsideView(Figure().add_subplot())
    view = outside()
    with pytest.raises(ValueError, match="view must be one of"):
        view.update(view="below")
    with pytest.raises(ValueError, match="show must be one of"):
        view.update(show="wireframe")
    with pytest.raises(TypeError, match="has no parameter 'zoom'"):
        view.update(zoom=2)


def test_each_view_turns_the_axes_and_a_camera_step_keeps_an_orbit():
    view = outside()
    for name, (elev, azim) in VIEWS.items():
        view.update(view=name)
        assert view.view_angles() == (elev, azim, 0.0)
    view.ax.view_init(elev=33.0, azim=-12.0, vertical_axis="y")  # the mouse orbited
    view.update(camera=Camera(pitch=30.0))
    assert view.view_angles()[:2] == (33.0, -12.0)


def test_the_mouse_orbits_the_view():
    app = App(OutsideViewFigure)
    ax = app.plot.outside.ax
    app.figure.canvas.draw()
    before = app.plot.outside.view_angles()
    x0, y0 = ax.bbox.x0 + ax.bbox.width / 2, ax.bbox.y0 + ax.bbox.height / 2
    canvas = app.figure.canvas
    MouseEvent("button_press_event", canvas, x0, y0, button=1)._process()
    for dx in (10, 20, 40):
        MouseEvent("motion_notify_event", canvas, x0 + dx, y0 + dx / 2, button=1)._process()
    MouseEvent("button_release_event", canvas, x0 + 40, y0 + 20, button=1)._process()
    after = app.plot.outside.view_angles()
    assert after != before
    app.set(pitch=20.0)  # a slider step keeps the orbit
    assert app.plot.outside.view_angles() == after


def test_the_ground_changes_only_with_what_it_shows_and_says_so_in_the_legend():
    view = outside(frequency=8)
    label = view.legend.get_texts()[0]
    checks = view.checks.get_paths
    assert label.get_text() == "ground: 8 x 8 checks"
    view.update(camera=Camera(pitch=40.0))
    assert label.get_text() == "ground: 8 x 8 checks"
    view.update(frequency=4)
    assert label.get_text() == "ground: 4 x 4 checks"
    view.update(show="triangles", quads=3)
    assert label.get_text() == "ground: 3 x 3 quads, 18 triangles"
    assert checks is not None


def test_counts_match_the_clipping_view():
    figure = ClippingOutside(Figure(figsize=ClippingOutside.size))
    counts = figure.outside.counts
    assert counts["visible triangles"] == figure.view.counts["visible triangles"]
    assert counts["pieces"] == figure.view.counts["pieces"]
    assert counts["cut off"] > 0


# ------------------------------------------------------------------------------ the figures


@pytest.mark.parametrize("name", OUTSIDE_FIGURES)
def test_figures_fit_a_notebook_and_check_their_parameters(name):
    figure_class = OUTSIDE_FIGURES[name]
    assert figure_class.size[0] <= 9.0
    shown = figure_class(Figure(figsize=figure_class.size))
    with pytest.raises(TypeError, match=f"{name} has no parameter 'zoom'"):
        shown.update(zoom=2)
    assert shown.params == figure_class.defaults()
    assert isinstance(shown.readout(), str)


def test_the_outside_figures_tell_the_camera_sliders_apart_from_their_own():
    # The same camera sliders move the image and the outside view in one step.
    app = App(CheckerboardsOutside)
    image = app.plot.panels.correct.get_array().copy()
    eye = app.plot.outside.eye.get_data_3d()
    app.set(height=1.5)
    assert not np.array_equal(app.plot.panels.correct.get_array(), image)
    assert app.plot.outside.eye.get_data_3d()[1][0] == pytest.approx(1.5)
    assert eye[1][0] == pytest.approx(1.0)


@pytest.mark.parametrize("name", OUTSIDE_FIGURES)
def test_handouts_draw_at_print_size_byte_for_byte_the_same(name):

    from interp import figures, plots

    def svg() -> bytes:
        figure = figures.render(OUTSIDE_FIGURES[name], {})
        with io.BytesIO() as out, plots.styled():
            figure.savefig(out, format="svg", metadata=figures._metadata("svg"))
            return out.getvalue()

    assert svg() == svg()


def test_the_cut_off_pieces_are_hatched():
    """The pieces the near plane cuts off are hatched, so that they read without colour."""
    view = OutsideView(Figure().add_subplot(projection="3d"))
    assert isinstance(view.cut_off, Poly3DCollection) and view.cut_off.get_hatch() == "////"
