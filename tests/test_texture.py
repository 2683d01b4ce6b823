"""Checkerboards: exact samples, the box filter against brute-force averaging, footprints."""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp.raster import fragment_footprints, fragment_values
from interp.texture import checker


def test_nearest_samples_are_exact():
    u = np.array([[0.05, 0.15, 0.25, 0.95]])
    v = np.array([[0.05, 0.05, 0.15, 0.15]])
    np.testing.assert_array_equal(interp.checkerboard(u, v, 10), [[0, 1, 1, 0]])
    background = interp.checkerboard(u, v, 10, covered=np.array([[True, False, True, False]]))
    np.testing.assert_array_equal(background, [[0, 0.5, 1, 0.5]])


@pytest.mark.parametrize("width", [0.3, 1.0, 2.5, 7.0])
def test_box_filter_is_the_average_over_the_box(width, rng):
    p, q = rng.uniform(-5, 5, 200), rng.uniform(-5, 5, 200)
    wp, wq = np.full(200, width), rng.uniform(0, 3, 200)
    offsets = (np.arange(400) + 0.5) / 400 - 0.5  # midpoint rule over the box
    brute = checker(
        p[:, None, None] + wp[:, None, None] * offsets[None, :, None],
        q[:, None, None] + wq[:, None, None] * offsets[None, None, :],
    ).mean(axis=(1, 2))
    np.testing.assert_allclose(checker(p, q, wp, wq), brute, atol=5e-3)


def test_tiny_footprint_is_a_point_sample(rng):
    p, q = rng.uniform(-5, 5, 500), rng.uniform(-5, 5, 500)
    away = (np.abs(p - np.round(p)) > 1e-3) & (np.abs(q - np.round(q)) > 1e-3)
    filtered = checker(p, q, np.zeros(500), np.zeros(500))
    np.testing.assert_allclose(filtered[away], checker(p, q)[away], atol=1e-9)


def test_far_away_checks_blur_to_grey():
    assert checker(np.array([0.3]), np.array([0.7]), np.array([64.0]), np.array([64.0]))[0] == (
        pytest.approx(0.5, abs=1e-2)
    )


@pytest.mark.parametrize("mode", ["perspective", "affine"])
def test_footprints_are_the_derivatives_of_the_values(mode):
    # Compare with finite differences between horizontal and vertical neighbours on one triangle.
    scene = interp.ground_plane(interp.Camera(height=1.0, pitch=30, yaw=10), quads=1)
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 64, 64)
    uv = interp.interpolate(frags, mode)
    tri = frags.image(frags.triangle, -1)
    fp = frags.image(fragment_footprints(frags, mode).T, 0.0)
    dx = np.zeros_like(uv)
    dy = np.zeros_like(uv)
    dx[:, 1:-1] = (uv[:, 2:] - uv[:, :-2]) / 2
    dy[1:-1] = (uv[2:] - uv[:-2]) / 2
    same = np.zeros(tri.shape, bool)
    same[1:-1, 1:-1] = (
        (tri[1:-1, 1:-1] >= 0)
        & (tri[1:-1, :-2] == tri[1:-1, 1:-1])
        & (tri[1:-1, 2:] == tri[1:-1, 1:-1])
        & (tri[:-2, 1:-1] == tri[1:-1, 1:-1])
        & (tri[2:, 1:-1] == tri[1:-1, 1:-1])
    )
    assert same.sum() > 500
    finite = np.abs(dx) + np.abs(dy)
    np.testing.assert_allclose(fp[same], finite[same], rtol=2e-2, atol=1e-6)


def test_fragment_values_equal_interpolate():
    scene = interp.ground_plane(interp.Camera(), quads=3)
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 30, 20)
    for mode in interp.MODES:
        np.testing.assert_array_equal(
            frags.image(fragment_values(frags, mode).T, 0.0), interp.interpolate(frags, mode)
        )


def test_texel_error():
    uv = np.zeros((2, 2, 2))
    other = uv.copy()
    other[0, 0] = [0.3, 0.4]
    np.testing.assert_allclose(interp.texel_error(other, uv, 10), [[5, 0], [0, 0]])
