"""The approximation lab's measurements, against drawing what they describe."""

import dataclasses

import numpy as np
import pytest

from interp import approximation
from interp.approximation import _affine_on_quads, tessellation_costs
from interp.plots.gpu import LAB_CAMERA
from interp.raster import fragment_values, fragments
from interp.scenes import LESSON_SIZE, ground_plane
from interp.texture import _texel_error

WIDTH, HEIGHT = 192, 144

#: The lab's camera, and cameras that stress the lookup: steep and flat, turned, rolled, and
#: one standing over the plane, whose near plane cuts triangles with corners behind the eye.
CAMERAS = {
    "lab": LAB_CAMERA,
    "steep": dataclasses.replace(LAB_CAMERA, pitch=40.0, roll=0.0),
    "grazing": dataclasses.replace(LAB_CAMERA, height=0.3, pitch=5.0, yaw=30.0),
    "over the plane": dataclasses.replace(LAB_CAMERA, distance=0.5, pitch=30.0, yaw=-20.0),
}


def drawn(camera, quads):
    """The plane cut into quads x quads quads, drawn by the rasterizer: its fragments, their
    affine and their exact (u, v)."""
    scene = ground_plane(camera, LESSON_SIZE, quads)
    frags = fragments(scene.clip, scene.uv, scene.triangles, WIDTH, HEIGHT)
    return scene, frags, fragment_values(frags, "affine"), fragment_values(frags, "perspective")


def test_the_camera_over_the_plane_has_corners_behind_the_eye():
    camera = CAMERAS["over the plane"].fitted(WIDTH, HEIGHT)
    for quads in (1, 2):
        scene, frags, _, _ = drawn(camera, quads)
        shown = np.unique(frags.clipped.source[frags.piece])
        assert np.any(scene.clip[scene.triangles[shown], 3] < 0)  # drawn, but cut


@pytest.mark.parametrize("name", CAMERAS)
@pytest.mark.parametrize("quads", [1, 2, 8, 32])
def test_affine_on_quads_is_what_the_rasterizer_draws(name, quads):
    camera = CAMERAS[name].fitted(WIDTH, HEIGHT)
    plane, whole, _, exact = drawn(camera, 1)
    _, frags, affine, _ = drawn(camera, quads)
    mine, triangle = _affine_on_quads(exact, plane.clip[:3, 3], quads)
    # The same pixels, but for a few on the plane's outline (its corners, snapped, differ).
    shared, here, there = np.intersect1d(whole.pixel, frags.pixel, return_indices=True)
    assert len(whole.pixel) - len(shared) <= 2 and len(frags.pixel) - len(shared) <= 2
    # Where both give a pixel to the same triangle, both are that triangle's affine (u, v).
    theirs = frags.clipped.source[frags.piece[there]]
    same = triangle[here] == theirs
    assert np.abs(mine[:, here][:, same] - affine[:, there][:, same]).max() < 1e-9
    # Elsewhere the pixel is on an edge, to the rasterizer's snapping of corners to 1/256 of a
    # pixel: the neighbour's (u, v) differs by about (its change per pixel) / 256.
    assert np.mean(~same) < 0.005
    step = np.abs(frags.barycentric_dx).max() + np.abs(frags.barycentric_dy).max()
    assert np.abs(mine[:, here][:, ~same] - affine[:, there][:, ~same]).max(initial=0) < step / 64
    assert quads > 1 or np.all(same)


@pytest.mark.parametrize("name", CAMERAS)
def test_tessellation_costs_are_those_of_drawing_the_quads(name):
    camera = CAMERAS[name]
    costs = tessellation_costs(camera, WIDTH, HEIGHT, 8)
    for n, divides, error in zip(
        costs.setting, costs.divides_per_pixel, costs.mean_error, strict=True
    ):
        scene, frags, affine, exact = drawn(camera.fitted(WIDTH, HEIGHT), int(n))
        drawn_triangles = np.unique(frags.clipped.source[frags.piece])
        vertices = len(np.unique(scene.triangles[drawn_triangles]))
        assert divides == pytest.approx(vertices / len(frags.pixel), rel=2e-3)
        assert error == pytest.approx(np.mean(_texel_error(affine, exact, 8)), rel=1e-3)


def test_straight_down_affine_is_exact():
    """Looking straight down every point is at one depth: affine is perspective-correct."""
    camera = dataclasses.replace(LAB_CAMERA, height=3.0, pitch=90.0, distance=0.0, roll=0.0)
    costs = tessellation_costs(camera, WIDTH, HEIGHT, 8)
    assert np.all(costs.mean_error < approximation.EXACT)
