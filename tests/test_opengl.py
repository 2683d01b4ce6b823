"""interp.rasterize against real OpenGL: Mesa's llvmpipe through EGL, via moderngl.

CI installs libegl1 and libgl1-mesa-dri, so there these tests run and must pass; elsewhere
they are skipped only if no OpenGL context can be made.
"""

from __future__ import annotations

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


def draw_both(gl, clip, attributes, triangles, width, height, mode):
    """Draw with interp and with OpenGL; assert they agree; return both.

    Pixels showing the same triangle must agree to float32 precision, in value and depth, and
    at most FEW_PIXELS may show a different triangle.
    """
    frags = interp.fragments(clip, attributes, triangles, width, height)
    values = interp.interpolate(frags, mode)
    image = gl.render(clip, attributes, triangles, width, height, mode)
    ours = frags.image(frags.triangle, -1)
    same = (ours == image.triangle) & (ours >= 0)
    np.testing.assert_allclose(values[same], image.values[same], rtol=0, atol=FLOAT32)
    depth = frags.image(frags.depth, 1.0)
    np.testing.assert_allclose(depth[same], image.depth[same], rtol=0, atol=1e-5)
    differ = int((ours != image.triangle).sum())
    assert differ <= FEW_PIXELS, f"{differ} pixels show another triangle"
    return frags, image


def inside_view_volume(clip, triangles, margin=0.999):
    """The triangles no clipper touches: every vertex within ``-w < x, y, z < w``."""
    inside = np.all(np.abs(clip[:, :3]) <= margin * clip[:, 3:4], axis=1)
    return triangles[inside[triangles].all(axis=1)]


def test_renderer_is_llvmpipe(gl):
    # The exact comparisons here (fill rule, draw-order ties, 8 subpixel bits) are llvmpipe's.
    # Against another OpenGL they would test a different rasterizer, so this fails anywhere,
    # not only in CI; Mesa picks llvmpipe with LIBGL_ALWAYS_SOFTWARE=1.
    renderer = gl.renderer()
    assert "llvmpipe" in renderer, f"OpenGL here is {renderer!r}, not Mesa's llvmpipe"


@pytest.mark.parametrize("seed", range(6))
def test_smooth_matches_opengl_with_clipping(gl, seed):
    clip, attributes, triangles = random_scene(np.random.default_rng(seed), 12, behind=True)
    assert np.any(clip[:, 2] < -clip[:, 3]), "the scene should need near-plane clipping"
    frags, _ = draw_both(gl, clip, attributes, triangles, 96, 72, "perspective")
    assert len(frags.pixel) > 500


@pytest.mark.parametrize("seed", range(6))
def test_noperspective_matches_opengl_inside_the_view_volume(gl, seed):
    # llvmpipe computes noperspective wrongly on triangles its clipper touches, so compare
    # affine only on triangles inside the view volume.
    clip, attributes, triangles = random_scene(np.random.default_rng(50 + seed), 40)
    triangles = inside_view_volume(clip, triangles)
    assert len(triangles) >= 5
    frags, _ = draw_both(gl, clip, attributes, triangles, 96, 72, "affine")
    assert len(frags.pixel) > 500


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
    scene = interp.ground_plane(height=0.6, pitch=25, yaw=30, near=0.05)
    frags, _ = draw_both(gl, scene.clip, scene.uv, scene.triangles, 160, 120, "perspective")
    assert len(frags.pixel) > 10000
    inside = inside_view_volume(scene.clip, scene.triangles, margin=1.0)
    frags, _ = draw_both(gl, scene.clip, scene.uv, inside, 160, 120, "affine")
    assert len(frags.pixel) > 1000


def test_subpixel_precision_is_llvmpipes():
    assert SUBPIXELS == 256
