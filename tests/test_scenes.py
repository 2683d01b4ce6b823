"""Ground plane geometry and the checkerboard slider step."""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp.scenes import checker_views


def test_ground_plane_geometry():
    camera = interp.Camera(height=1.5, pitch=40, yaw=25, distance=2.0)
    scene = interp.ground_plane(camera, size=4.0, quads=16)
    assert scene.triangles.shape == (512, 3) and scene.clip.shape == (289, 4)
    assert scene.uv.min() == 0 and scene.uv.max() == 1
    # Undo projection and view: every vertex is on y = 0 within the square, at its (u, v).
    world = np.linalg.solve(camera.projection @ camera.view, scene.clip.T).T
    world = world[:, :3] / world[:, 3:]
    np.testing.assert_allclose(world[:, 1], 0, atol=1e-9)
    np.testing.assert_allclose(world[:, 0], (scene.uv[:, 0] - 0.5) * 4, atol=1e-9)
    np.testing.assert_allclose(world[:, 2], (0.5 - scene.uv[:, 1]) * 4, atol=1e-9)
    # Triangles tile the square: their areas in (u, v) add up to 1.
    a, b, c = (scene.uv[scene.triangles[:, k]] for k in range(3))
    cross = (b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]
    assert np.sum(np.abs(cross)) / 2 == pytest.approx(1.0)


def test_straight_down_affine_equals_correct():
    scene = interp.ground_plane(interp.Camera(height=2, pitch=90, distance=0), quads=1)
    views = checker_views(scene, 64, 64, frequency=4)
    assert views.covered.all()
    np.testing.assert_allclose(views.approximate, views.correct, atol=1e-9)
    assert views.error.max() < 1e-9


def test_tilted_camera_bends_the_affine_checkerboard():
    # One quad seen at a grazing angle: affine and correct (u, v) differ by whole texels.
    scene = interp.ground_plane(interp.Camera(height=0.5, pitch=20, distance=2.5), quads=1)
    views = checker_views(scene, 96, 96, frequency=8, filtered=False)
    seen = views.covered
    assert seen.sum() > 2000
    assert views.error[seen].max() > 1.0
    assert np.mean(views.approximate[seen] != views.correct[seen]) > 0.05
    # The correct image is what sampling the true (u, v) of each pixel gives.
    uv = views.uv_image("perspective")
    expected = interp.checkerboard(uv[..., 0], uv[..., 1], 8, covered=seen)
    np.testing.assert_array_equal(views.correct, expected)


def test_finer_tessellation_shrinks_the_affine_error():
    camera = interp.Camera(height=0.5, pitch=20, distance=2.5)
    errors = [
        checker_views(interp.ground_plane(camera, quads=n), 64, 64).error.mean() for n in (1, 4, 16)
    ]
    assert errors[0] > errors[1] > errors[2] > 0
