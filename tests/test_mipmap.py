"""Texture filtering (interp.mipmap) against independent references: a ray cast onto the ground
plane for the derivatives, closed forms for λ and the pyramid, and Mesa's llvmpipe for the
whole trilinear texture() (GL_LINEAR_MIPMAP_LINEAR)."""

from __future__ import annotations

import numpy as np
import pytest

from interp import mipmap
from interp.camera import Camera
from interp.raster import fragment_values, fragments
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane
from interp.texture import checker

#: Cameras the comparisons use: the lesson's, a turned one, a rolled one (depth varies along
#: rows), and one standing on the plane (near-plane clipping).
CAMERAS = {
    "filtering lesson": Camera(height=0.6, pitch=10.0),  # lesson 9's
    "lesson": LESSON_CAMERA,
    "turned": Camera(height=0.6, pitch=25.0, yaw=30.0, near=0.05),
    "rolled": Camera(height=1.0, pitch=15.0, distance=3.0, roll=30.0),
    "clipped": Camera(height=0.3, pitch=15.0, distance=1.0),
}


def scene_of(camera: Camera, width: int = 160, height: int = 120, quads: int = 1):
    return ground_plane(camera.fitted(width, height), size=LESSON_SIZE, quads=quads)


def ray_cast_uv(camera: Camera, x_w: np.ndarray, y_w: np.ndarray, width: int, height: int):
    """(u, v) of the ground point seen at window position (x_w, y_w): the ray through it meets
    y = 0. Shares nothing with the rasterizer."""
    inverse = np.linalg.inv(camera.projection @ camera.view)
    ndc = np.stack([2 * x_w / width - 1, 2 * y_w / height - 1])
    ends = []
    for z in (-1.0, 1.0):
        h = inverse @ np.stack([*ndc, np.full_like(ndc[0], z), np.ones_like(ndc[0])])
        ends.append(h[:3] / h[3])
    near, far = ends
    t = near[1] / (near[1] - far[1])
    point = near + t * (far - near)
    return point[0] / LESSON_SIZE + 0.5, 0.5 - point[2] / LESSON_SIZE


@pytest.mark.parametrize("name", ["lesson", "turned", "rolled", "clipped"])
def test_derivatives_are_those_of_the_ray_cast(name):
    camera = CAMERAS[name].fitted(160, 120)
    scene = scene_of(camera)
    frags = fragments(scene.clip, scene.uv, scene.triangles, 160, 120)
    ours = mipmap.uv_derivatives(frags)
    x = frags.column + 0.5
    y = frags.height - frags.pixel // frags.width - 0.5  # window y, up
    h = 1e-3
    for axis, (dx, dy) in enumerate(((h, 0.0), (0.0, h))):
        ahead = np.array(ray_cast_uv(camera, x + dx, y + dy, 160, 120))
        behind = np.array(ray_cast_uv(camera, x - dx, y - dy, 160, 120))
        central = (ahead - behind) / (2 * h)
        np.testing.assert_allclose(ours[axis], central, rtol=1e-5, atol=1e-9)


def test_affine_derivatives_are_constant_per_triangle_and_are_the_quad_differences():
    scene = scene_of(LESSON_CAMERA)
    frags = fragments(scene.clip, scene.uv, scene.triangles, 160, 120)
    exact = mipmap.uv_derivatives(frags, "affine")
    for piece in np.unique(frags.piece):
        mine = exact[..., frags.piece == piece]
        np.testing.assert_allclose(mine, mine[..., :1].repeat(mine.shape[-1], -1), atol=1e-15)
    np.testing.assert_allclose(mipmap.quad_derivatives(frags, "affine"), exact, atol=1e-12)


def test_perspective_derivatives_differ_from_affine_ones_except_looking_straight_down():
    tilted = scene_of(LESSON_CAMERA)
    frags = fragments(tilted.clip, tilted.uv, tilted.triangles, 160, 120)
    gap = mipmap.uv_derivatives(frags) - mipmap.uv_derivatives(frags, "affine")
    assert np.abs(gap).max() > 1e-3
    down = scene_of(Camera(height=3.0, pitch=90.0, distance=0.0))
    frags = fragments(down.clip, down.uv, down.triangles, 160, 120)
    gap = mipmap.uv_derivatives(frags) - mipmap.uv_derivatives(frags, "affine")
    assert np.abs(gap).max() < 1e-12


def test_quad_derivatives_are_differences_of_the_interpolated_values():
    # Where a whole quad is drawn by one triangle, its differences are differences of the
    # rasterizer's own per-pixel values.
    scene = scene_of(CAMERAS["turned"])
    frags = fragments(scene.clip, scene.uv, scene.triangles, 160, 120)
    uv = frags.image(fragment_values(frags).T, np.nan)  # (H, W, 2)
    piece = frags.image(frags.piece, -1)
    quads = mipmap.quad_derivatives(frags)
    at = frags.image(np.moveaxis(quads, 2, 0).reshape(len(frags.pixel), 4), np.nan)
    checked = 0
    for row in range(1, 120, 2):  # row of window y even: the quad's lower row (height even)
        for column in range(0, 160, 2):
            quad = piece[row - 1 : row + 1, column : column + 2]
            if quad.min() < 0 or np.unique(quad).size > 1:
                continue
            ddx = uv[row, column + 1] - uv[row, column]
            ddy = uv[row - 1, column] - uv[row, column]
            for r in (row - 1, row):
                for c in (column, column + 1):
                    np.testing.assert_allclose(at[r, c], [*ddx, *ddy], atol=1e-12)
            checked += 1
    assert checked > 1000


def test_level_of_detail_is_log2_of_the_longer_footprint_edge():
    assert mipmap.level_of_detail(4 / 256, 0, 0, 1 / 256, 256) == 2
    assert mipmap.level_of_detail(0, 0, 3 / 256, 4 / 256, 256) == pytest.approx(np.log2(5))
    assert mipmap.level_of_detail(-1 / 512, 0, 0, 1 / 1024, 256) == -1
    assert mipmap.level_of_detail(0, 0, 0, 0, 256) == -np.inf
    rng = np.random.default_rng(3)
    d = rng.normal(0, 0.01, (4, 100))
    rotation = np.array([[0.6, -0.8], [0.8, 0.6]])  # turning the texture leaves λ alone
    turned_x, turned_y = rotation @ d[:2], rotation @ d[2:]
    np.testing.assert_allclose(
        mipmap.level_of_detail(*d, 256), mipmap.level_of_detail(*turned_x, *turned_y, 256)
    )


def test_fast_log2_is_exact_at_powers_of_two_and_at_most_0_086_low():
    x = np.geomspace(1e-3, 1e3, 10001)
    error = np.log2(x) - mipmap.fast_log2(x)
    assert error.min() >= -1e-12
    assert error.max() == pytest.approx(1 - (1 + np.log(np.log(2))) / np.log(2), abs=1e-6)
    assert np.all(mipmap.fast_log2(2.0 ** np.arange(-5, 6)) == np.arange(-5, 6))


def test_the_pyramid_averages_and_keeps_the_mean():
    levels = mipmap.mipmap(mipmap.checker_texture(8, 64))
    assert [level.shape[0] for level in levels] == [64, 32, 16, 8, 4, 2, 1]
    for level in levels:
        assert level.mean() == 0.5
    assert set(np.unique(levels[2])) == {0.0, 1.0}  # 8 checks of 2 texels: still sharp
    assert np.all(levels[4] == 0.5)  # smaller than a check: grey


def test_nearest_sampling_of_level_0_is_the_checkerboard():
    rng = np.random.default_rng(5)
    u, v = rng.uniform(-1, 2, (2, 1000))
    level = mipmap.checker_texture(8, 256)
    np.testing.assert_array_equal(mipmap.sample_nearest(level, u, v), checker(8 * u, 8 * v))


def test_trilinear_is_continuous_in_lod_and_bilinear_below_zero():
    levels = mipmap.mipmap(mipmap.checker_texture(4, 32))
    rng = np.random.default_rng(6)
    u, v = rng.uniform(0, 1, (2, 50))
    below = mipmap.sample_trilinear(levels, u, v, np.full(50, -2.0))
    np.testing.assert_array_equal(below, mipmap.sample_linear(levels[0], u, v))
    for k in range(1, len(levels)):  # just below and at each whole level
        left = mipmap.sample_trilinear(levels, u, v, np.full(50, k - 1e-9))
        right = mipmap.sample_trilinear(levels, u, v, np.full(50, float(k)))
        np.testing.assert_allclose(left, right, atol=1e-7)
        np.testing.assert_allclose(right, mipmap.sample_linear(levels[k], u, v))


def test_filtered_images_stay_in_range_and_agree_where_magnified():
    views = mipmap.filtering_views(scene_of(LESSON_CAMERA), 160, 120, frequency=8)
    covered = views.fragments.covered
    for image in (views.nearest, views.box, views.trilinear):
        assert image[covered].min() >= 0 and image[covered].max() <= 1
    assert np.isnan(views.lod_image[~covered]).all()
    assert views.lod.min() < 0 < views.lod.max()  # magnified near, minified far


@pytest.mark.parametrize(
    ("arguments", "error", "match"),
    [
        ({"frequency": 3}, ValueError, "frequency must be a power of two"),
        ({"frequency": 512}, ValueError, "frequency must be"),
        ({"size": 100}, ValueError, "size must be a power of two"),
        ({"mode": "subdivided"}, ValueError, "mode"),
    ],
)
def test_filtering_views_rejects_bad_arguments(arguments, error, match):
    with pytest.raises(error, match=match):
        mipmap.filtering_views(scene_of(LESSON_CAMERA), 16, 12, **arguments)


def test_quads_need_an_even_height():
    scene = scene_of(LESSON_CAMERA)
    frags = fragments(scene.clip, scene.uv, scene.triangles, 16, 11)
    with pytest.raises(ValueError, match="height must be even"):
        mipmap.quad_derivatives(frags)


# ------------------------------------------------------------------------------ llvmpipe


#: llvmpipe computes in float32: its texture() agrees with the model of what it computes
#: (quad differences, fast_log2) to a few units in the fifth decimal. Lesson 9 says "to
#: 0.00008" (measured on these scenes, 8 to 64 checks: 7.7e-5 at most).
MODEL = 8e-5
#: ...and with the specification's exact λ from exact derivatives, as lesson 9 says: "on average
#: to 0.0004 to 0.003, and everywhere to better than 0.05; 1 to 9 pixels in a hundred differ by
#: more than 0.01" (measured: means 0.00037 to 0.0029, maxima 0.021 to 0.049, 0.6% to 9.4%),
#: the two approximations llvmpipe makes, which move λ "by -0.11 to +0.06" (-0.110 to +0.061).
EXACT_MEAN, EXACT_MAX, EXACT_OFF = 0.003, 0.05, 0.095
LOD_SHIFT = (-0.115, 0.065)
#: Drawn affinely, lesson 9's scene and lesson 6's agree "to 0.015 everywhere" (0.0144).
AFFINE_MAX = 0.015


def draw_both(gl, name, frequency, mode="perspective"):
    quads = 2 if name == "clipped" else 1
    scene = scene_of(CAMERAS[name], 320, 240, quads)
    views = mipmap.filtering_views(scene, 320, 240, frequency, mode=mode)
    levels = mipmap.mipmap(mipmap.checker_texture(frequency))
    image = gl.render_textured(scene.clip, scene.uv, scene.triangles, 320, 240, levels, mode)
    frags = views.fragments
    same = (frags.image(frags.triangle, -1) == image.triangle) & (image.triangle >= 0)
    assert same.sum() > 0.99 * frags.covered.sum()
    return views, levels, image, same


@pytest.mark.opengl
@pytest.mark.parametrize("name", list(CAMERAS))
@pytest.mark.parametrize("frequency", [8, 16, 32, 64])
def test_trilinear_matches_llvmpipe(gl, name, frequency):
    views, levels, image, same = draw_both(gl, name, frequency)
    theirs = image.values[..., 0]
    exact = np.abs(views.trilinear - theirs)[same]
    assert exact.mean() < EXACT_MEAN and exact.max() < EXACT_MAX
    assert np.mean(exact > 0.01) < EXACT_OFF
    # What llvmpipe computes: one λ per 2 x 2 quad, from differences, through fast_log2.
    frags = views.fragments
    lod = mipmap.llvmpipe_level_of_detail(mipmap.quad_derivatives(frags), views.size)
    shift = lod - views.lod
    assert LOD_SHIFT[0] < shift.min() and shift.max() < LOD_SHIFT[1]
    model = frags.image(mipmap.sample_trilinear(levels, *views.uv, lod), 0.5)
    assert np.abs(model - theirs)[same].max() < MODEL


@pytest.mark.opengl
@pytest.mark.parametrize("name", ["filtering lesson", "lesson"])
@pytest.mark.parametrize("frequency", [8, 64])
def test_affine_trilinear_matches_llvmpipe(gl, name, frequency):
    views, levels, image, same = draw_both(gl, name, frequency, "affine")
    theirs = image.values[..., 0]
    assert np.abs(views.trilinear - theirs)[same].max() < AFFINE_MAX
    frags = views.fragments
    lod = mipmap.llvmpipe_level_of_detail(mipmap.quad_derivatives(frags, "affine"), views.size)
    model = frags.image(mipmap.sample_trilinear(levels, *views.uv, lod), 0.5)
    assert np.abs(model - theirs)[same].max() < MODEL


@pytest.mark.opengl
def test_our_pyramid_is_what_glgeneratemipmap_makes(gl):
    levels = mipmap.mipmap(mipmap.checker_texture(16, 256))
    renderer = gl.TexturedRenderer(8, 8, levels, generate=True)
    try:
        for k, level in enumerate(levels):
            np.testing.assert_array_equal(renderer.level(k), level)
    finally:
        renderer.release()
