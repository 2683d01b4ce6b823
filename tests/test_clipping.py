"""Clipping held to an exact rational ray cast, where floats are at their weakest: near the eye.

A vertex whose clip coordinates are all tiny sits next to the eye; the cut of an edge towards it
is at a parameter t within 1e-17 of 1, which a float cannot tell from 1. Issue 13 found whole
triangles vanishing or flooding the image there. ``tests/exact.py`` answers in integers, so it
is right for any input; pixels whose answer changes within 1/64 pixel are skipped, since
coverage is decided on positions snapped to 1/256 pixel.
"""

from __future__ import annotations

import numpy as np
import pytest
from exact import render

import interp

ONE = [[0, 1, 2]]


def compare(clip, attributes, triangles, width, height, atol=1e-9):
    """Assert coverage, visible triangle and both modes' values agree with the exact ray cast
    on every unambiguous pixel; return how many pixels the triangles cover."""
    clip, attributes = np.asarray(clip, float), np.asarray(attributes, float)
    exact = render(clip, triangles, width, height)
    frags = interp.fragments(clip, attributes, triangles, width, height)
    seen = frags.image(frags.triangle, -1)
    clear = ~exact.ambiguous
    wrong = int((seen[clear] != exact.triangle[clear]).sum())
    assert wrong == 0, f"{wrong} pixels show another triangle than the exact ray cast"
    both = clear & (seen >= 0)
    for mode in ("perspective", "affine"):
        values = interp.interpolate(frags, mode)
        assert np.isfinite(values).all()
        expected = exact.values(attributes, triangles, mode)
        np.testing.assert_allclose(values[both], expected[both], rtol=0, atol=atol, err_msg=mode)
    return int((exact.triangle >= 0).sum())


@pytest.mark.parametrize(
    "clip, width, covers",
    [
        ([[0, 0, 0, -1e-17], [0.8, -0.8, 0, 1], [0, 0.8, 0, 1]], 32, 301),  # drew nothing
        ([[-2e-16, -3e-16, 1e-16, -4e-16], [1, 1, 0.7, 1], [-0.5, 0.4, -0.25, 1]], 24, 20),  # flood
    ],
)
def test_issue_examples_match_the_exact_ray_cast(clip, width, covers):
    assert compare(clip, np.eye(3), ONE, width, width) == covers


def near_eye_triangle(rng, smallest=-17, largest=-13):
    """One vertex with every clip coordinate tiny, two ordinary ones (sometimes behind the eye)."""
    tiny = 10.0 ** rng.uniform(smallest, largest) * rng.normal(size=4)
    others = np.column_stack([rng.uniform(-1.5, 1.5, (2, 3)), rng.uniform(-0.5, 2, (2, 1))])
    return np.vstack([tiny, others])[rng.permutation(3)]


@pytest.mark.parametrize("seed", range(4))
def test_near_eye_triangles_match_the_exact_ray_cast(seed):
    rng = np.random.default_rng(seed)
    covered = 0
    for _ in range(15):
        covered += compare(near_eye_triangle(rng), rng.uniform(0, 1, (3, 2)), ONE, 16, 16)
    assert covered > 100  # the triangles are not all off screen


@pytest.mark.parametrize("seed", range(3))
def test_triangles_of_any_size_match_the_exact_ray_cast(seed):
    # The same kind of triangle at any overall size, from 1e-290 to 1e11, with the near vertex
    # up to 1e-250 times smaller still: only ratios matter.
    rng = np.random.default_rng(100 + seed)
    for _ in range(15):
        clip = near_eye_triangle(rng, -250, -1) * 10.0 ** rng.uniform(-290, 11)
        compare(clip, rng.uniform(0, 1, (3, 2)), ONE, 16, 16)


def test_scaling_a_triangle_by_a_power_of_two_changes_no_bit():
    # Clip coordinates are homogeneous; scaled by 2**k a triangle must draw the same image,
    # bit for bit, down into subnormal numbers (few mantissa bits keep the scaling exact).
    rng = np.random.default_rng(7)
    for _ in range(10):
        clip = np.round(near_eye_triangle(rng, -3, -1) * 64) / 64
        clip[rng.integers(3), 3] = 2.0**-9  # a vertex close to the eye
        uv = rng.uniform(0, 1, (3, 2))
        expected = interp.rasterize(clip, uv, ONE, 16, 16)
        for k in (-1060, -600, -40, 30):
            values, covered = interp.rasterize(np.ldexp(clip, k), uv, ONE, 16, 16)
            np.testing.assert_array_equal(values, expected[0])
            np.testing.assert_array_equal(covered, expected[1])


def test_triangles_sharing_a_cut_edge_leave_no_crack():
    # A fan around a vertex next to the eye (in front of it or behind), whose image lies inside
    # the ring: every edge through it is cut where floats are weakest. Neighbours must cut their
    # shared edge identically: no pixel drawn twice, none skipped (against the exact ray cast
    # of the whole fan, which tiles the inside of the ring, or the outside for a centre behind).
    rng = np.random.default_rng(3)
    for case in range(12):
        side = 1.0 if case % 2 else -1.0
        ndc = rng.uniform(-0.2, 0.2, 2)
        centre = 10.0 ** rng.uniform(-17, -13) * side * np.array([*ndc, rng.uniform(-1, 1), 1.0])
        angles = np.arange(5) * 2 * np.pi / 5 + rng.uniform(-0.3, 0.3, 5)
        radii, w = rng.uniform(0.5, 2, 5), rng.uniform(0.5, 1.5, 5)
        ring = np.column_stack(
            [radii * np.cos(angles) * w, radii * np.sin(angles) * w, rng.uniform(-1, 1, 5) * w, w]
        )
        clip = np.vstack([centre, ring])
        fan = [[0, 1 + i, 1 + (i + 1) % 5] for i in range(5)]
        counts = sum(
            interp.rasterize(clip, np.zeros((6, 1)), [t], 20, 20)[1].astype(int) for t in fan
        )
        assert counts.max() <= 1, "a pixel on a shared edge was drawn twice"
        exact = render(clip, fan, 20, 20)
        clear = ~exact.ambiguous
        np.testing.assert_array_equal((counts == 1)[clear], (exact.triangle >= 0)[clear])
        assert (exact.triangle >= 0).sum() > 20


@pytest.mark.parametrize("seed", range(2))
def test_scenes_needing_every_plane_match_in_both_modes(seed):
    # Ordinary perspective scenes with vertices behind the camera and beyond the sides.
    from helpers import random_scene

    clip, attributes, triangles = random_scene(np.random.default_rng(seed), 5, behind=True)
    assert compare(clip, attributes, triangles, 24, 18) > 100
