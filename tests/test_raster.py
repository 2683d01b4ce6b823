"""interp.rasterize against an independent ray-cast reference, and exact special cases."""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp import raster
from interp.raster import MODES, SUBPIXELS

from helpers import random_scene
from reference import render


def compare(clip, attributes, triangles, width, height, mode, atol=1e-9):
    """Assert rasterize agrees with the reference on every unambiguous pixel; return counts.

    Coverage is decided on positions snapped to 1/256 pixel, so pixels whose answer changes when
    nudged by 1/64 pixel are ambiguous and skipped; values and depth come from the exact
    positions and must agree to rounding.
    """
    ref = render(clip, triangles, width, height)
    frags = interp.fragments(clip, attributes, triangles, width, height)
    values, covered = interp.rasterize(clip, attributes, triangles, width, height, mode=mode)
    seen = frags.image(frags.triangle, -1)
    clear = ~ref.ambiguous
    assert np.array_equal(seen[clear], ref.triangle[clear]), "visible triangle differs"
    assert np.array_equal(covered, seen >= 0)
    expected = ref.values(attributes, triangles, mode)
    both = clear & covered
    np.testing.assert_allclose(values[both], expected[both], rtol=0, atol=atol)
    np.testing.assert_allclose(
        frags.image(frags.depth, 1.0)[both], ref.depth[both], rtol=0, atol=atol
    )
    assert np.all(values[~covered] == 0)
    return int(both.sum()), int(ref.ambiguous.sum())


def on_grid_scene(rng, n, width, height):
    """Triangles inside the view volume whose window coordinates lie on the subpixel grid,
    so snapping changes nothing and the answer must be exact."""
    window = rng.integers(0, SUBPIXELS * np.array([width, height]) + 1, (3 * n, 2)) / SUBPIXELS
    ndc = window / [width, height] * 2 - 1
    w = 2.0 ** rng.integers(0, 4, (3 * n, 1))  # powers of two keep x/w exact
    z = rng.uniform(-0.9, 0.9, (3 * n, 1))
    clip = np.hstack([ndc * w, z * w, w])
    return clip, rng.uniform(0, 1, (3 * n, 2)), np.arange(3 * n).reshape(-1, 3)


@pytest.mark.parametrize("mode", ["perspective", "affine"])
@pytest.mark.parametrize("seed", range(6))
def test_exact_on_the_subpixel_grid(mode, seed):
    rng = np.random.default_rng(seed)
    clip, attributes, triangles = on_grid_scene(rng, 6, 40, 30)
    checked, ambiguous = compare(clip, attributes, triangles, 40, 30, mode)
    assert checked > 100 and ambiguous < 0.1 * 40 * 30


@pytest.mark.parametrize("mode", ["perspective", "affine"])
@pytest.mark.parametrize("seed", range(8))
def test_random_scenes_with_clipping(seed, mode):
    # In affine mode this checks the noperspective values clipping gives its new vertices:
    # the reference has no clipper, only the unclipped triangle's screen-space barycentrics.
    rng = np.random.default_rng(100 + seed)
    clip, attributes, triangles = random_scene(rng, 8, behind=True)
    assert np.any(clip[:, 2] < -clip[:, 3]), "the scene should need near-plane clipping"
    checked, ambiguous = compare(clip, attributes, triangles, 48, 36, mode)
    assert checked > 200 and ambiguous < 0.15 * 48 * 36


@pytest.mark.parametrize("mode", ["perspective", "affine"])
def test_camera_inside_a_plane_and_vertices_behind_it(mode):
    # A ground plane seen from 5 mm above: vertices behind the camera, triangles through the
    # near plane. Only clipping in clip space makes this right.
    camera = interp.Camera(height=0.005, pitch=30, distance=0.0, near=0.002)
    scene = interp.ground_plane(camera, quads=4)
    assert np.any(scene.clip[:, 3] < 0) and np.any(scene.clip[:, 2] < -scene.clip[:, 3])
    checked, _ = compare(scene.clip, scene.uv, scene.triangles, 40, 40, mode)
    assert checked > 600


def test_quad_columns_follow_t_from_s_exactly():
    # The top edge three times as far as the bottom: along a column, v is t_from_s(s, 1, 3).
    clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [3, 3, 0, 3], [-3, 3, 0, 3]]
    uv = [[0, 0], [1, 0], [1, 1], [0, 1]]
    quad = [[0, 1, 2], [0, 2, 3]]
    values, covered = interp.rasterize(clip, uv, quad, 16, 16)
    assert covered.all()
    s = (np.arange(16)[::-1] + 0.5) / 16
    for column in range(16):
        np.testing.assert_allclose(values[:, column, 1], interp.t_from_s(s, 1.0, 3.0), atol=1e-12)
    affine, _ = interp.rasterize(clip, uv, quad, 16, 16, mode="affine")
    np.testing.assert_allclose(affine[:, 3, 1], s, atol=1e-12)


def test_both_windings_give_the_same_image(rng):
    clip, attributes, triangles = random_scene(rng, 10)
    forward = interp.rasterize(clip, attributes, triangles, 32, 24)
    backward = interp.rasterize(clip, attributes, triangles[:, ::-1], 32, 24)
    np.testing.assert_array_equal(forward[1], backward[1])
    np.testing.assert_allclose(forward[0], backward[0], atol=1e-12)


def test_shared_edges_are_drawn_exactly_once(rng):
    # A fan of triangles around a centre, with vertices on the half-pixel grid so that many
    # pixel centres fall exactly on the shared edges. Angles step by about 2 pi / 7 (never more
    # than pi), so the triangles tile the fan without overlapping.
    width = height = 24
    centre = np.array([width / 2, height / 2])
    for _ in range(30):
        angles = np.arange(7) * 2 * np.pi / 7 + rng.uniform(-0.2, 0.2, 7)
        radii = rng.uniform(5, 11, 7)
        ring = np.round(2 * (centre + radii[:, None] * np.c_[np.cos(angles), np.sin(angles)])) / 2
        window = np.vstack([centre, ring])
        clip = np.hstack([window / [width, height] * 2 - 1, np.zeros((8, 1)), np.ones((8, 1))])
        fan = [[0, 1 + i, 1 + (i + 1) % 7] for i in range(7)]
        counts = sum(
            interp.rasterize(clip, np.zeros((8, 1)), [t], width, height)[1].astype(int) for t in fan
        )
        assert counts.max() <= 1, "a pixel on a shared edge was drawn twice"
        union = interp.rasterize(clip, np.zeros((8, 1)), fan, width, height)[1]
        np.testing.assert_array_equal(union, counts == 1)
        # No holes: every pixel centre strictly inside the fan's outline is drawn.
        inside = _inside_polygon(ring, width, height)
        assert union[inside].all(), "a pixel inside the fan was skipped"


@pytest.mark.parametrize("flip", [False, True], ids=["ccw", "cw"])
@pytest.mark.parametrize("diagonal", ["/", "\\"])
def test_fill_rule_owns_left_and_bottom_edges(diagonal, flip):
    # Derived by hand, no OpenGL needed. A square with corners on the pixel centres (0.5, 0.5)
    # and (3.5, 3.5) (window coordinates, y up), cut along a diagonal into two triangles.
    # Mesa's rule gives a triangle the centres on its left edges and horizontal bottom edges,
    # so the square's left and bottom sides are drawn and its right and top sides are not:
    # exactly the 3 x 3 centres (0.5 .. 2.5)^2, each once. With the triangle
    # (0.5, 0.5), (3.5, 0.5), (0.5, 3.5) on its own: the centres on its left and bottom edges,
    # none on its diagonal x + y = 4.
    corners = np.array([[0.5, 0.5], [3.5, 0.5], [3.5, 3.5], [0.5, 3.5]])
    halves = [[0, 1, 3], [1, 2, 3]] if diagonal == "/" else [[0, 1, 2], [0, 2, 3]]
    if flip:
        halves = [t[::-1] for t in halves]
    clip = np.hstack([corners / 4 * 2 - 1, np.zeros((4, 1)), np.ones((4, 1))])
    covers = [interp.rasterize(clip, np.zeros((4, 1)), [t], 4, 4)[1] for t in halves]
    expected = np.zeros((4, 4), bool)
    expected[1:, :3] = True  # window rows y = 0, 1, 2 are image rows 3, 2, 1
    np.testing.assert_array_equal(covers[0].astype(int) + covers[1], expected)
    if diagonal == "/":
        lower_left = [[0, 0, 0, 0], [1, 0, 0, 0], [1, 1, 0, 0], [1, 1, 1, 0]]
        np.testing.assert_array_equal(covers[0], np.array(lower_left, bool))


def _inside_polygon(ring, width, height):
    """Pixel centres strictly inside a convex-or-star polygon around the image centre."""
    cols, rows = np.meshgrid(np.arange(width) + 0.5, height - (np.arange(height) + 0.5))
    centre = np.array([width / 2, height / 2])
    inside = np.zeros((height, width), bool)
    for a, b in zip(ring, np.roll(ring, -1, axis=0), strict=True):
        # strictly inside triangle (centre, a, b), or on its spokes (shared with neighbours)
        def side(p, q, x, y):
            return (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])

        s1, s2, s3 = (
            side(centre, a, cols, rows),
            side(a, b, cols, rows),
            side(b, centre, cols, rows),
        )
        inside |= (s1 >= 0) & (s2 > 0) & (s3 >= 0)
    return inside & ((cols != centre[0]) | (rows != centre[1]))


@pytest.mark.parametrize("chunk", [1, 37, 300])
def test_depth_test_in_small_chunks(monkeypatch, chunk):
    # The depth test handles CHUNK fragments at a time (4 million by default, more than any
    # other test draws). With small chunks, overlapping triangles put the fragments competing
    # for one pixel into different chunks: the result must be the reference's, and identical
    # to one chunk's.
    clip, attributes, triangles = random_scene(np.random.default_rng(21), 30, behind=True)
    whole = interp.fragments(clip, attributes, triangles, 48, 36)
    monkeypatch.setattr(raster, "CHUNK", chunk)
    chunked = interp.fragments(clip, attributes, triangles, 48, 36)
    drawn = sum(interp.fragments(clip, attributes, [t], 48, 36).covered.sum() for t in triangles)
    assert drawn > 10 * chunk, "the fragments before the depth test should take many chunks"
    np.testing.assert_array_equal(chunked.pixel, whole.pixel)
    np.testing.assert_array_equal(chunked.triangle, whole.triangle)
    np.testing.assert_array_equal(chunked.barycentric, whole.barycentric)
    checked, _ = compare(clip, attributes, triangles, 48, 36, "perspective")
    assert checked > 300


@pytest.mark.parametrize("band", [1, 100, 10**9])
def test_bands_of_any_height_draw_the_same(monkeypatch, band):
    # rasterize works through the image BAND pixels (whole rows) at a time: one row per band,
    # a few rows, or the whole image in one band must draw the same, bit for bit, and so must
    # fragments(). Overlapping triangles and triangles behind the eye, both modes.
    clip, attributes, triangles = random_scene(np.random.default_rng(5), 30, behind=True)
    whole = {mode: interp.rasterize(clip, attributes, triangles, 48, 36, mode) for mode in MODES}
    frags = interp.fragments(clip, attributes, triangles, 48, 36)
    monkeypatch.setattr(raster, "BAND", band)
    for mode in MODES:
        values, covered = interp.rasterize(clip, attributes, triangles, 48, 36, mode)
        np.testing.assert_array_equal(values, whole[mode][0])
        np.testing.assert_array_equal(covered, whole[mode][1])
    banded = interp.fragments(clip, attributes, triangles, 48, 36)
    np.testing.assert_array_equal(banded.pixel, frags.pixel)
    np.testing.assert_array_equal(banded.row_item, frags.row_item)
    np.testing.assert_array_equal(banded.barycentric, frags.barycentric)


@pytest.mark.parametrize("mode", MODES)
def test_rasterize_is_fragments_then_interpolate(mode):
    # rasterize interpolates along rows (a line per triangle and row), interpolate per fragment
    # from its barycentrics: the same numbers, to rounding, and the same pixels.
    camera = interp.Camera(height=1.0, pitch=20, yaw=30, distance=3.0)
    scene = interp.ground_plane(camera, quads=4)
    values, covered = interp.rasterize(scene.clip, scene.uv, scene.triangles, 200, 150, mode)
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 200, 150)
    np.testing.assert_array_equal(covered, frags.covered)
    np.testing.assert_allclose(values, interp.interpolate(frags, mode), rtol=0, atol=1e-13)
    assert covered.mean() > 0.5


def test_depth_test_nearest_wins_and_first_wins_ties():
    full = [[-1, -1], [3, -1], [-1, 3]]  # covers the whole view
    clip = np.array([[x, y, z, 1.0] for z in (0.5, -0.5, -0.5) for x, y in full])
    attributes = np.repeat([[1.0], [2.0], [3.0]], 3, axis=0)
    triangles = np.arange(9).reshape(3, 3)
    values, _ = interp.rasterize(clip, attributes, triangles, 4, 4)
    assert np.all(values == 2.0)  # nearer than the first; ties with the third and was first
    values, _ = interp.rasterize(clip, attributes, triangles[::-1], 4, 4)
    assert np.all(values == 3.0)


def test_far_plane_and_side_clipping_match_reference(rng):
    # Long triangles reaching past the far plane and the sides of the view.
    P = interp.perspective(60, 1.0, 1.0, 10.0)
    view = rng.uniform([-20, -20, -30], [20, 20, -2], (30, 3))
    clip = np.column_stack([view, np.ones(30)]) @ P.T
    triangles = np.arange(30).reshape(-1, 3)
    attributes = rng.uniform(0, 1, (30, 1))
    assert np.any(clip[:, 2] > clip[:, 3])
    compare(clip, attributes, triangles, 32, 32, "perspective")


def test_subdivided_is_exact_at_anchors_and_between_affine_and_correct():
    scene = interp.ground_plane(interp.Camera(height=1, pitch=25), quads=1)
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 64, 64)
    correct = interp.interpolate(frags, "perspective")
    affine = interp.interpolate(frags, "affine")
    np.testing.assert_allclose(interp.interpolate(frags, "subdivided", span=1), correct, atol=1e-12)
    sub = interp.interpolate(frags, "subdivided", span=16)
    first = frags.image(frags.span[:, 0], -1)
    columns = np.arange(64)[None, :]
    anchor = frags.covered & ((columns - first) % 16 == 0)
    np.testing.assert_allclose(sub[anchor], correct[anchor], atol=1e-12)
    error = lambda image: np.abs(image - correct)[frags.covered].mean()  # noqa: E731
    assert 0 < error(sub) < error(affine)


def test_values_per_span_are_the_ray_cast_values_at_anchors_and_affine_between():
    """Several span lengths at once (what the approximation lab draws), against the ray cast
    (tests/reference.py): each pixel's value is the exact value at its span's anchors, every N
    pixels from the row's first and its last, and the straight line between them."""
    P = interp.perspective(70, 4 / 3, 0.5, 20)
    view = np.array([[-2.0, -1.0, -2.5], [3.0, -1.2, -14.0], [-1.0, 2.0, -5.0]])
    clip = np.column_stack([view, np.ones(3)]) @ P.T
    uv = np.array([[0.0, 0.0], [6.0, 1.0], [1.0, 5.0]])
    width, height, spans = 48, 36, (1, 3, 8, 64)
    frags = interp.fragments(clip, uv, [[0, 1, 2]], width, height)
    seen = render(clip, np.array([[0, 1, 2]]), width, height)
    exact = seen.values(uv, np.array([[0, 1, 2]]), "perspective")  # (H, W, 2)
    row, x = frags.pixel // width, frags.pixel % width
    first, last = frags.row_spans[frags.row_item].T
    assert not seen.ambiguous[row, first].any() and not seen.ambiguous[row, last].any()
    got = raster.fragment_values_per_span(frags, spans)
    for n, values in zip(spans, got, strict=True):
        left = first + (x - first) // n * n
        right = np.minimum(left + n, last)
        t = np.where(right > left, (x - left) / np.maximum(right - left, 1), 0.0)[:, None]
        expected = exact[row, left] + t * (exact[row, right] - exact[row, left])
        np.testing.assert_allclose(values.T, expected, atol=1e-9, err_msg=f"span {n}")
        np.testing.assert_array_equal(values, raster.fragment_values(frags, "subdivided", n))
    assert not np.allclose(got[2], got[0])  # spans of 8 are not exact


@pytest.mark.parametrize(
    ("spans", "error", "words"),
    [
        (8, TypeError, "spans must be a sequence"),
        ((), ValueError, "spans must hold at least one"),
        ((4, 0), ValueError, "span"),
    ],
)
def test_values_per_span_refuse_bad_spans(spans, error, words):
    frags = interp.fragments(
        [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]], [[0.0]] * 3, [[0, 1, 2]], 4, 4
    )
    with pytest.raises(error, match=words):
        raster.fragment_values_per_span(frags, spans)


def test_empty_and_off_screen_scenes():
    values, covered = interp.rasterize(
        np.zeros((0, 4)), np.zeros((0, 2)), np.zeros((0, 3), int), 5, 4
    )
    assert values.shape == (4, 5, 2) and not covered.any()
    behind = [[0, 0, 2, -1], [1, 0, 2, -1], [0, 1, 2, -1]]  # all behind the eye
    values, covered = interp.rasterize(behind, [[1.0]] * 3, [[0, 1, 2]], 5, 4)
    assert not covered.any() and np.all(values == 0)


def test_fragments_barycentrics_sum_to_one_and_reproduce_positions(rng):
    clip, attributes, triangles = random_scene(rng, 6)
    frags = interp.fragments(clip, attributes, triangles, 40, 30)
    np.testing.assert_allclose(frags.barycentric.sum(axis=0), 1.0, atol=1e-12)
    window = interp.viewport(frags.clipped.clip, 40, 30)[frags.piece]  # (P, 3, 3)
    x = np.einsum("ip,pi->p", frags.barycentric, window[..., 0])
    np.testing.assert_allclose(x, frags.column + 0.5, atol=1e-9)


def test_perspective_weights_give_what_rasterize_draws():
    # OpenGL's λ_i = (b_i/w_i) / Σ b_j/w_j, applied to the fragments' screen-space barycentrics,
    # must give rasterize's perspective-correct values exactly (the same formula, one home).
    clip, attributes, triangles = random_scene(np.random.default_rng(11), 30, behind=True)
    frags = interp.fragments(clip, attributes, triangles, 64, 48)
    w = frags.clipped.clip[frags.piece, :, 3].T  # (3, P): each fragment's vertex w
    weights = interp.perspective_weights(frags.barycentric, w)
    np.testing.assert_allclose(weights.sum(axis=0), 1.0, atol=1e-12)
    a = frags.clipped.smooth[frags.piece]  # (P, 3, K)
    expected = np.einsum("ip,pik->kp", weights, a)
    from interp.raster import fragment_values

    np.testing.assert_allclose(fragment_values(frags), expected, atol=1e-12)
