"""interp.rasterize against real OpenGL: Mesa's llvmpipe through EGL, via moderngl.

CI installs libegl1 and libgl1-mesa-dri, so there these tests run and must pass; elsewhere
they are skipped only if no OpenGL context can be made.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

import interp
from interp.raster import SUBPIXELS

from helpers import random_scene

pytestmark = pytest.mark.opengl

#: llvmpipe interpolates in float32: values agree to a few units in the sixth decimal.
FLOAT32 = 5e-5
#: Pixels allowed to show a different triangle (none has, so far).
FEW_PIXELS = 3


@pytest.fixture(scope="module")
def gl():
    try:
        from interp import opengl

        opengl.context()
    except (ImportError, RuntimeError) as error:
        if os.environ.get("CI"):
            pytest.fail(f"CI must have OpenGL (EGL + Mesa): {error}")
        pytest.skip(f"no OpenGL here: {error}")
    return opengl


def agreement(ours, theirs, values, gl_values, atol):
    """Pixels where both drew the same triangle must agree; return the disagreeing count."""
    same = (ours == theirs) & (ours >= 0)
    np.testing.assert_allclose(values[same], gl_values[same], rtol=0, atol=atol)
    return int((ours != theirs).sum())


def test_renderer_is_llvmpipe(gl):
    assert "llvmpipe" in gl.renderer() or os.environ.get("CI") is None


@pytest.mark.parametrize("seed", range(6))
def test_smooth_matches_opengl_with_clipping(gl, seed):
    rng = np.random.default_rng(seed)
    clip, attributes, triangles = random_scene(rng, 12, behind=True)
    width, height = 96, 72
    frags = interp.fragments(clip, attributes, triangles, width, height)
    values = interp.interpolate(frags, "perspective")
    image = gl.render(clip, attributes, triangles, width, height, "perspective")
    ours = frags.image(frags.triangle, -1)
    differ = agreement(ours, image.triangle, values, image.values, atol=FLOAT32)
    # llvmpipe works in float32 and clips in its own way: allow a few edge pixels to differ.
    assert differ <= FEW_PIXELS, f"{differ} pixels show another triangle"
    np.testing.assert_allclose(
        frags.image(frags.depth, 1.0)[ours == image.triangle],
        image.depth[ours == image.triangle],
        atol=1e-5,
    )


@pytest.mark.parametrize("seed", range(6))
def test_noperspective_matches_opengl_inside_the_view_volume(gl, seed):
    # llvmpipe computes noperspective wrongly on triangles its clipper touches, so compare
    # affine only on triangles inside the view volume.
    rng = np.random.default_rng(50 + seed)
    clip, attributes, triangles = random_scene(rng, 40)
    w = clip[:, 3:4]
    inside = np.all(np.abs(clip[:, :3]) <= 0.999 * w, axis=1)
    triangles = triangles[inside[triangles].all(axis=1)]
    assert len(triangles) >= 5
    width, height = 96, 72
    frags = interp.fragments(clip, attributes, triangles, width, height)
    values = interp.interpolate(frags, "affine")
    image = gl.render(clip, attributes, triangles, width, height, "affine")
    ours = frags.image(frags.triangle, -1)
    differ = agreement(ours, image.triangle, values, image.values, atol=FLOAT32)
    assert differ <= FEW_PIXELS


def test_fill_rule_and_ties_match_opengl_exactly(gl):
    # Vertices on the half-pixel grid put many pixel centres exactly on edges; triangles at
    # equal depths test the draw-order tie-break. (Sloped ones could differ where two depths
    # are closer than a 24-bit depth buffer resolves.) Must match pixel for pixel.
    rng = np.random.default_rng(7)
    width = height = 13
    for _ in range(150):
        window = rng.integers(0, 2 * width + 1, (9, 2)) / 2
        ndc = window / [width, height] * 2 - 1
        z = rng.choice([-0.5, 0.0, 0.5], (3, 1)).repeat(3, axis=0)  # flat: ties are exact
        clip = np.hstack([ndc, z, np.ones((9, 1))])
        triangles = np.arange(9).reshape(3, 3)
        frags = interp.fragments(clip, np.zeros((9, 1)), triangles, width, height)
        image = gl.render(clip, np.zeros((9, 1)), triangles, width, height)
        np.testing.assert_array_equal(frags.image(frags.triangle, -1), image.triangle)


def test_ground_plane_matches_opengl(gl):
    scene = interp.ground_plane(interp.Camera(height=0.6, pitch=25, yaw=30, near=0.05))
    width, height = 160, 120
    for mode in ("perspective", "affine"):
        frags = interp.fragments(scene.clip, scene.uv, scene.triangles, width, height)
        values = interp.interpolate(frags, mode)
        if mode == "affine":  # only triangles inside the view volume, as above
            keep = np.all(np.abs(scene.clip[:, :3]) <= scene.clip[:, 3:4], axis=1)
            triangles = scene.triangles[keep[scene.triangles].all(axis=1)]
            frags = interp.fragments(scene.clip, scene.uv, triangles, width, height)
            values = interp.interpolate(frags, mode)
        else:
            triangles = scene.triangles
        image = gl.render(scene.clip, scene.uv, triangles, width, height, mode)
        ours = frags.image(frags.triangle, -1)
        differ = agreement(ours, image.triangle, values, image.values, atol=FLOAT32)
        assert differ <= FEW_PIXELS
        assert (ours >= 0).sum() > 1000


def test_subpixel_precision_is_llvmpipes():
    assert SUBPIXELS == 256
