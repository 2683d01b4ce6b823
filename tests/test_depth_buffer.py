"""A 24-bit depth buffer's ties, against real OpenGL (Mesa's llvmpipe through EGL).

interp's depth test compares 40-bit fixed-point depths by default; OpenGL's depth buffer has 24
bits, so triangles nearer each other than about 2**-24 tie there, and the first drawn wins. With
``depth_bits=24`` interp rounds depth as llvmpipe does and must tie where it ties.
"""

from __future__ import annotations

import numpy as np
import pytest

import interp

pytestmark = pytest.mark.opengl


SIZE = 40


@pytest.fixture(scope="module")
def renderer(gl):
    renderer = gl.Renderer(SIZE, SIZE)
    yield renderer
    renderer.release()


def nearly_coplanar(rng, n, slope):
    """n triangles on one plane ``z = p + q x + r y`` (NDC), each shifted off it by 2**-36 to
    2**-22, in float32 (what OpenGL receives). ``slope=0``: parallel to the screen."""
    p, q, r = rng.uniform(-0.5, 0.5), *(slope * rng.uniform(-1, 1, 2))
    xy = rng.uniform(-1.1, 1.1, (n, 3, 2))
    shift = rng.choice([-1, 1], (n, 1)) * 2.0 ** rng.uniform(-36, -22, (n, 1))
    z = p + q * xy[..., 0] + r * xy[..., 1] + shift
    w = rng.uniform(0.5, 2, (n, 3)) if slope else np.ones((n, 3))
    clip = np.concatenate([xy * w[..., None], (z * w)[..., None], w[..., None]], axis=2)
    clip = clip.reshape(-1, 4).astype(np.float32).astype(np.float64)
    return clip, np.zeros((3 * n, 1)), np.arange(3 * n).reshape(n, 3)


def differing(renderer, scene, depth_bits):
    """Pixels where interp shows another triangle than OpenGL."""
    frags = interp.fragments(*scene, SIZE, SIZE, depth_bits=depth_bits)
    return int((frags.image(frags.triangle, -1) != renderer.draw(*scene).triangle).sum())


def test_parallel_to_the_screen_ties_match_opengl_exactly(renderer):
    rng = np.random.default_rng(1)
    fine = 0
    for _ in range(25):
        scene = nearly_coplanar(rng, 5, slope=0.0)
        assert differing(renderer, scene, depth_bits=24) == 0
        fine += differing(renderer, scene, depth_bits=40)
    assert fine > 100  # 40 bits tell apart what OpenGL cannot


def test_sloped_nearly_coplanar_triangles_mostly_tie_as_opengl(renderer):
    # Here llvmpipe's own float32 arithmetic (plane equations evaluated per pixel) decides some
    # ties, which a double-precision rasterizer cannot reproduce: fewer pixels differ, not none
    # (measured: 318 pixels instead of 489, of 6968 drawn).
    rng = np.random.default_rng(2)
    differ = {24: 0, 40: 0}
    for _ in range(15):
        scene = nearly_coplanar(rng, 4, slope=0.3)
        for bits in differ:
            differ[bits] += differing(renderer, scene, depth_bits=bits)
    assert differ[24] < 0.7 * differ[40]


def test_depth_bits_does_not_change_well_separated_scenes():
    from helpers import random_scene

    scene = random_scene(np.random.default_rng(3), 12, behind=True)
    f24 = interp.fragments(*scene, 64, 48, depth_bits=24)
    f40 = interp.fragments(*scene, 64, 48)
    assert len(f40.pixel) > 1000
    np.testing.assert_array_equal(f24.image(f24.triangle, -1), f40.image(f40.triangle, -1))
