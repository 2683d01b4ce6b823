"""interp.textbook.draw draws exactly the pixels interp.rasterize draws.

Same coverage, bit for bit; the same visible triangle on every pixel; the same values to 1e-12;
in both modes, on random scenes (clipped ones too), overlapping triangles, both windings,
vertices on the half-pixel grid (many pixel centres exactly on edges, and exact depth ties),
slivers, and the ground plane the lessons draw. rasterize is held to the ray-cast reference and
to OpenGL elsewhere (test_raster.py, test_opengl.py), so this makes the textbook version right
too, and shows a student that the fast version is the same algorithm.
"""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp.raster import DEPTH_BITS
from interp.textbook import draw, edge_function, owns_edge

from helpers import random_scene

MODES = ("perspective", "affine")


def assert_same_pixels(clip, attributes, triangles, width, height, mode, atol=1e-12):
    """Draw with both; assert identical coverage, visible triangle and values (to ``atol``).
    Return the number of pixels drawn."""
    clip, attributes, triangles = (np.asarray(a) for a in (clip, attributes, triangles))
    frags = interp.fragments(clip, attributes, triangles, width, height)
    fast = interp.interpolate(frags, mode)
    values, covered = draw(clip, attributes, triangles, width, height, mode)

    assert values.shape == fast.shape and covered.shape == (height, width)
    np.testing.assert_array_equal(covered, frags.covered)
    np.testing.assert_allclose(values, fast, rtol=0, atol=atol)
    assert np.all(values[~covered] == 0)
    np.testing.assert_array_equal(
        visible_triangle(clip, triangles, width, height, mode), frags.image(frags.triangle, -1)
    )
    return int(covered.sum())


def visible_triangle(clip, triangles, width, height, mode):
    """Which triangle draw shows at each pixel (-1: none): draw the same triangles, each with
    its own three vertices and its own number as a constant attribute."""
    soup = clip[triangles].reshape(-1, 4)
    number = np.repeat(np.arange(len(triangles), dtype=float), 3)[:, None]
    values, covered = draw(soup, number, np.arange(len(soup)).reshape(-1, 3), width, height, mode)
    return np.where(covered, np.rint(values[..., 0]).astype(int), -1)


def overlaps(clip, triangles, width, height):
    """Pixels covered by more than one triangle."""
    count = sum(
        interp.fragments(clip, np.zeros((len(clip), 1)), [t], width, height).covered.astype(int)
        for t in triangles
    )
    return int((count > 1).sum())


def half_pixel_grid_scene(rng, n, width, height, flat):
    """Triangles with corners on the half-pixel grid, so many pixel centres lie exactly on
    edges. ``flat``: each triangle at one of three depths, so overlaps tie exactly."""
    window = rng.integers(0, 2 * np.array([width, height]) + 1, (3 * n, 2)) / 2
    ndc = window / [width, height] * 2 - 1
    if flat:
        z = rng.choice([-0.5, 0.0, 0.5], (n, 1)).repeat(3, axis=0)
    else:
        z = rng.uniform(-0.9, 0.9, (3 * n, 1))
    w = rng.choice([0.5, 1.0, 3.0], (3 * n, 1))  # a sloped w keeps perspective non-trivial
    clip = np.hstack([ndc * w, z * w, w])
    return clip, rng.uniform(0, 1, (3 * n, 2)), np.arange(3 * n).reshape(-1, 3)


def centres_on_edges(clip, triangles, width, height):
    """How many (pixel centre, edge) pairs meet exactly: a centre on an edge's segment."""
    window = interp.viewport(clip, width, height)[:, :2] * 2  # doubled: integers on the grid
    cx, cy = np.meshgrid(2 * np.arange(width) + 1, 2 * np.arange(height) + 1)
    hits = 0
    for t in triangles:
        for j, k in ((0, 1), (1, 2), (2, 0)):
            (x0, y0), (x1, y1) = window[t[j]], window[t[k]]
            on_line = edge_function(x0, y0, x1, y1, cx, cy) == 0
            between = (np.minimum(x0, x1) <= cx) & (cx <= np.maximum(x0, x1))
            between &= (np.minimum(y0, y1) <= cy) & (cy <= np.maximum(y0, y1))
            hits += int((on_line & between).sum())
    return hits


def windings(clip, triangles, width, height):
    """How many triangles are counter-clockwise and clockwise on the screen."""
    window = interp.viewport(clip, width, height)[triangles]
    x, y = window[..., 0], window[..., 1]
    area2 = edge_function(x[:, 1], y[:, 1], x[:, 2], y[:, 2], x[:, 0], y[:, 0])
    return int((area2 > 0).sum()), int((area2 < 0).sum())


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("behind", [False, True], ids=["in-front", "clipped"])
@pytest.mark.parametrize("seed", range(8))
def test_random_scenes(seed, behind, mode):
    rng = np.random.default_rng(300 + seed)
    clip, attributes, triangles = random_scene(rng, 30, behind=behind)
    if behind:
        assert np.any(clip[:, 2] < -clip[:, 3]), "the scene should need near-plane clipping"
    else:  # all in front, so the windings on the screen are the ones drawn
        assert min(windings(clip, triangles, 80, 60)) >= 5, "both windings should occur"
    assert overlaps(clip, triangles, 80, 60) > 50, "triangles should overlap"
    drawn = assert_same_pixels(clip, attributes, triangles, 80, 60, mode)
    assert drawn > 300


@pytest.mark.parametrize("mode", MODES)
def test_reversed_windings(mode):
    clip, attributes, triangles = random_scene(np.random.default_rng(7), 20, behind=True)
    assert_same_pixels(clip, attributes, triangles[:, ::-1], 64, 48, mode)
    triangles[::2] = triangles[::2, ::-1]
    assert_same_pixels(clip, attributes, triangles, 64, 48, mode)


@pytest.mark.parametrize("flat", [True, False], ids=["ties", "sloped"])
@pytest.mark.parametrize("mode", MODES)
def test_half_pixel_grid_edges_and_ties(mode, flat):
    rng = np.random.default_rng(11 if flat else 12)
    on_edges = 0
    for _ in range(40):
        clip, attributes, triangles = half_pixel_grid_scene(rng, 4, 13, 11, flat)
        on_edges += centres_on_edges(clip, triangles, 13, 11)
        assert_same_pixels(clip, attributes, triangles, 13, 11, mode)
    assert on_edges > 100, "the scenes should put many pixel centres exactly on edges"


def test_slivers_whose_snapped_corners_are_not_collinear():
    # Corners exactly collinear on the screen, which snapping to 1/256 pixel pulls apart: the
    # snapped triangle covers a centre now and then, and there the barycentrics must come from
    # the snapped corners, as in rasterize (the exact ones have no area to divide by). Here the
    # textbook's edge functions are exact (dyadic corners, half-integer centres), while
    # rasterize's planes (A x + B y + C) / area lose a few digits: about 2e-12 on 0.01 px².
    rng = np.random.default_rng(3)
    width, height, n = 32, 24, 1000
    start, end = rng.uniform(0, [width, height], (2, n, 2))
    middle = start + rng.uniform(0.2, 0.8, (n, 1)) * (end - start)
    window = np.stack([start, middle, end], axis=1).reshape(-1, 2)
    clip = np.hstack([window / [width, height] * 2 - 1, np.zeros((3 * n, 1)), np.ones((3 * n, 1))])
    attributes = rng.uniform(0, 1, (3 * n, 2))
    triangles = np.arange(3 * n).reshape(-1, 3)
    for mode in MODES:
        drawn = assert_same_pixels(clip, attributes, triangles, width, height, mode, atol=1e-11)
        assert drawn >= 5


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize(
    "camera",
    [
        interp.Camera(height=1.0, pitch=20, yaw=30, distance=3.0),  # the benchmark's view
        interp.Camera(height=0.005, pitch=30, distance=0.0, near=0.002),  # inside the plane
    ],
    ids=["bench", "inside"],
)
def test_ground_plane(camera, mode):
    scene = interp.ground_plane(camera, quads=8)
    drawn = assert_same_pixels(scene.clip, scene.uv, scene.triangles, 160, 120, mode)
    assert drawn > 5000


def test_ground_plane_at_512():
    scene = interp.ground_plane(interp.Camera(height=1.0, pitch=20, yaw=30, distance=3.0))
    assert assert_same_pixels(scene.clip, scene.uv, scene.triangles, 512, 512, "perspective")


def test_depth_ties_go_to_the_first_drawn():
    # Three triangles over the whole view at depths 0.5, -0.5, -0.5 (NDC): the second is
    # nearer than the first and ties with the third, so it stays (GL_LESS).
    full = [[-1, -1], [3, -1], [-1, 3]]
    clip = np.array([[x, y, z, 1.0] for z in (0.5, -0.5, -0.5) for x, y in full])
    attributes = np.repeat([[1.0], [2.0], [3.0]], 3, axis=0)
    triangles = np.arange(9).reshape(3, 3)
    assert np.all(draw(clip, attributes, triangles, 4, 4)[0] == 2.0)
    assert np.all(draw(clip, attributes, triangles[::-1], 4, 4)[0] == 3.0)
    # Depths closer than a 40-bit step tie too, as in rasterize's fixed-point keys.
    clip[6:, 2] = -0.5 - 2.0**-DEPTH_BITS  # half a 40-bit step nearer in window z
    assert np.all(draw(clip, attributes, triangles, 4, 4)[0] == 2.0)
    assert_same_pixels(clip, attributes, triangles, 4, 4, "perspective")


def test_fill_rule_owns_left_and_bottom_edges():
    # Hand-derived: y up, a counter-clockwise triangle with corners (0.5, 0.5), (3.5, 0.5),
    # (0.5, 3.5) in window pixels. Its bottom edge (going right) and left edge (going down) are
    # its own, its diagonal is not: it draws the centres on x = 0.5 and y = 0.5 but not those
    # on x + y = 4.
    assert owns_edge(0, 0, 4, 0) and owns_edge(0, 4, 0, 0)  # bottom, left
    assert not owns_edge(4, 0, 0, 0) and not owns_edge(0, 0, 0, 4)  # top, right
    window = np.array([[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]])
    clip = np.hstack([window / 4 * 2 - 1, np.zeros((3, 1)), np.ones((3, 1))])
    _, covered = draw(clip, np.zeros((3, 1)), [[0, 1, 2]], 4, 4)
    expected = [[0, 0, 0, 0], [1, 0, 0, 0], [1, 1, 0, 0], [1, 1, 1, 0]]  # row 0 is the top
    np.testing.assert_array_equal(covered, np.array(expected, dtype=bool))


def test_rejects_what_rasterize_rejects():
    clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]
    with pytest.raises(ValueError, match="mode"):
        draw(clip, np.zeros((3, 1)), [[0, 1, 2]], 4, 4, mode="subdivided")
    with pytest.raises(ValueError, match="width"):
        draw(clip, np.zeros((3, 1)), [[0, 1, 2]], 0, 4)
    with pytest.raises(ValueError, match="triangles"):
        draw(clip, np.zeros((3, 1)), [[0, 1, 3]], 4, 4)
