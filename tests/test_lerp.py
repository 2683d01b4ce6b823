"""The 1D story: s-t mappings and 1D interpolation, checked against projecting real lines."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

import interp

depth = st.floats(0.05, 100.0)
fraction = st.floats(0.0, 1.0)
coordinate = st.floats(-50.0, 50.0)


@given(fraction, depth, depth)
def test_t_from_s_inverts_s_from_t(t, w1, w2):
    s = interp.s_from_t(t, w1, w2)
    assert 0.0 <= s <= 1.0
    assert interp.t_from_s(s, w1, w2) == pytest.approx(t, abs=1e-12)


@given(fraction, depth, depth)
def test_s_from_t_inverts_t_from_s(s, w1, w2):
    assert interp.s_from_t(interp.t_from_s(s, w1, w2), w1, w2) == pytest.approx(s, abs=1e-12)


@given(depth, depth)
def test_endpoints_stay_put(w1, w2):
    assert interp.s_from_t(0.0, w1, w2) == 0.0 and interp.s_from_t(1.0, w1, w2) == 1.0
    assert interp.t_from_s(0.0, w1, w2) == 0.0 and interp.t_from_s(1.0, w1, w2) == 1.0


@given(depth, depth)
def test_monotonic(w1, w2):
    t = np.linspace(0, 1, 101)
    assert np.all(np.diff(interp.s_from_t(t, w1, w2)) > 0)
    assert np.all(np.diff(interp.t_from_s(t, w1, w2)) > 0)


@given(fraction, depth)
def test_equal_depths_give_a_straight_line(t, w):
    # An orthographic camera, or a segment parallel to the image plane: w1 = w2.
    assert interp.s_from_t(t, w, w) == pytest.approx(t, abs=1e-15)


@given(
    coordinate,
    st.floats(-100, -0.05),
    coordinate,
    st.floats(-100, -0.05),
    fraction,
    st.floats(0.1, 10.0),
)
def test_agrees_with_projecting_a_2d_line(xa, za, xb, zb, t, d):
    """Project A, B and P(t) onto the image plane and read s off the image."""
    A, B = np.array([xa, za]), np.array([xb, zb])
    a, b = interp.project_to_image_plane(A, d), interp.project_to_image_plane(B, d)
    assume(abs(b - a) > 1e-3 * d)  # the image is not a single point
    p = interp.project_to_image_plane((1 - t) * A + t * B, d)
    s_seen = (p - a) / (b - a)
    w1, w2 = -za, -zb
    assert interp.s_from_t(t, w1, w2) == pytest.approx(s_seen, abs=1e-9)
    assert interp.t_from_s(s_seen, w1, w2) == pytest.approx(t, abs=1e-6)


@given(fraction, depth, depth, st.floats(-5, 5), st.floats(-5, 5))
def test_perspective_lerp_is_lerp_at_t(s, w1, w2, a1, a2):
    t = interp.t_from_s(s, w1, w2)
    expected = (1 - t) * a1 + t * a2
    assert interp.lerp_perspective(a1, a2, w1, w2, s) == pytest.approx(expected, abs=1e-9)


@given(fraction, depth, depth)
def test_inverse_w_is_one_over_the_depth_seen(s, w1, w2):
    t = interp.t_from_s(s, w1, w2)
    depth_seen = (1 - t) * w1 + t * w2
    assert 1 / interp.lerp_inverse_w(w1, w2, s) == pytest.approx(depth_seen, rel=1e-12)


def test_exact_values():
    # The midpoint of a segment from depth 1 to depth 3 shows 3/4 of the way along the image.
    assert interp.s_from_t(0.5, 1.0, 3.0) == 0.75
    assert interp.t_from_s(0.5, 1.0, 3.0) == 0.25
    assert interp.lerp_perspective(0.0, 1.0, 1.0, 3.0, 0.5) == 0.25
    assert interp.lerp_affine(0.0, 1.0, 0.5) == 0.5
    assert interp.lerp_inverse_w(1.0, 3.0, 0.5) == pytest.approx(2 / 3)
    assert interp.project_to_image_plane([2.0, -4.0], d=1.0) == 0.5


def test_broadcasting():
    s = interp.s_from_t(np.array([[0.0], [0.5], [1.0]]), np.array([1.0, 2.0]), 3.0)
    assert s.shape == (3, 2)
    np.testing.assert_allclose(s[1], [0.75, 0.6])
    assert isinstance(interp.s_from_t(0.5, 1.0, 3.0), float)


def test_gap_peaks_where_the_derivation_says():
    # interp.gap_peak is the closed form; a dense numerical search must find the same peak.
    assert interp.gap_peak(1.0, 9.0) == (0.75, 0.5)  # exact: sqrt 9 = 3
    s = np.linspace(0, 1, 200001)
    for w1, w2 in [(1.0, 9.0), (5.0, 0.3), (2.0, 2.5), (0.1, 20.0)]:
        gap = np.abs(interp.t_from_s(s, w1, w2) - s)
        s_star, height = interp.gap_peak(w1, w2)
        assert s[gap.argmax()] == pytest.approx(s_star, abs=1e-5)
        assert gap.max() == pytest.approx(height, abs=1e-9)
    np.testing.assert_allclose(interp.gap_peak([1.0, 4.0], 4.0)[0], [2 / 3, 0.5])
