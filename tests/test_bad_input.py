"""Every public function rejects bad input with a clear error naming the argument."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import interp
from interp.scenes import checker_views

TRI = np.array([[-1, -1, 0, 1], [1, -1, 0, 1], [0, 1, 0, 1.0]])
ATTR = np.zeros((3, 2))
IDX = np.array([[0, 1, 2]])
UV = np.zeros((4, 4))

CASES = [
    # (call, exception, words the message must contain)
    (lambda: interp.perspective(0, 1, 1, 2), ValueError, "fovy_degrees"),
    (lambda: interp.perspective(180, 1, 1, 2), ValueError, "fovy_degrees"),
    (lambda: interp.perspective("60", 1, 1, 2), TypeError, "fovy_degrees"),
    (lambda: interp.perspective(True, 1, 1, 2), TypeError, "fovy_degrees"),
    (lambda: interp.perspective(60, 0, 1, 2), ValueError, "aspect"),
    (lambda: interp.perspective(60, 1, 0, 2), ValueError, "near"),
    (lambda: interp.perspective(60, 1, -1, 2), ValueError, "near"),
    (lambda: interp.perspective(60, 1, 2, 2), ValueError, "far"),
    (lambda: interp.perspective(60, 1, 1, np.inf), ValueError, "far"),
    (lambda: interp.perspective(np.nan, 1, 1, 2), ValueError, "fovy_degrees"),
    (lambda: interp.look_at([1, 2, 3], [1, 2, 3], [0, 1, 0]), ValueError, "eye and target"),
    (lambda: interp.look_at([0, 0, 0], [0, 5, 0], [0, 1, 0]), ValueError, "up"),
    (lambda: interp.look_at([0, 0, 0], [0, 0, -1], [0, 0, 0]), ValueError, "up"),
    (lambda: interp.look_at([0, 0], [0, 0, -1], [0, 1, 0]), ValueError, "eye"),
    (lambda: interp.look_at([0, 0, np.nan], [0, 0, -1], [0, 1, 0]), ValueError, "eye"),
    (lambda: interp.look_at("abc", [0, 0, -1], [0, 1, 0]), TypeError, "eye"),
    (lambda: interp.perspective_weights([0.5, 0.5], [1, 2, 3]), ValueError, "b"),
    (lambda: interp.perspective_weights([0.5, 0.5, 0], [1, 0, 3]), ValueError, "w"),
    (lambda: interp.perspective_weights([0.5, 0.5, 0], [[1, 2]]), ValueError, "w"),
    (lambda: interp.perspective_weights([1, -1, 0], [1, 1, 3]), ValueError, "zero"),
    (lambda: interp.perspective_weights("abc", [1, 2, 3]), TypeError, "b"),
    (lambda: interp.gap_peak(0, 1), ValueError, "w1"),
    (lambda: interp.Camera(pitch=91), ValueError, "pitch"),
    (lambda: interp.Camera(distance=-1), ValueError, "distance"),
    (lambda: interp.Camera(height=np.nan), ValueError, "height"),
    (lambda: interp.Camera(fovy=200), ValueError, "fovy"),
    (lambda: interp.Camera(near=0), ValueError, "near"),
    (lambda: interp.s_from_t(0.5, 0, 1), ValueError, "w1"),
    (lambda: interp.s_from_t(0.5, 1, -2), ValueError, "w2"),
    (lambda: interp.s_from_t(np.nan, 1, 2), ValueError, "t"),
    (lambda: interp.s_from_t("half", 1, 2), TypeError, "t"),
    (lambda: interp.s_from_t(-10, 1, 3), ValueError, "t"),
    (lambda: interp.t_from_s(0.5, [1, 2], -1), ValueError, "w2"),
    (lambda: interp.t_from_s(None, 1, 2), TypeError, "s"),
    (lambda: interp.t_from_s(5, 1, 3), ValueError, "s"),
    (lambda: interp.project_to_image_plane([1, 2, 3]), ValueError, "points"),
    (lambda: interp.project_to_image_plane([1, 2]), ValueError, "points"),
    (lambda: interp.project_to_image_plane([1, -2], d=0), ValueError, "d"),
    (lambda: interp.lerp_perspective(0, 1, 0, 1, 0.5), ValueError, "w1"),
    (lambda: interp.lerp_inverse_w(1, -1, 0.5), ValueError, "w2"),
    (lambda: interp.lerp_affine(0, [1, np.inf], 0.5), ValueError, "a2"),
    (lambda: interp.rasterize(TRI[:, :3], ATTR, IDX, 8, 8), ValueError, "clip"),
    (lambda: interp.rasterize(TRI, np.zeros((4, 2)), IDX, 8, 8), ValueError, "attributes"),
    (lambda: interp.rasterize(TRI, ATTR, [[0, 1, 3]], 8, 8), ValueError, "triangles"),
    (lambda: interp.rasterize(TRI, ATTR, [[0, -1, 2]], 8, 8), ValueError, "triangles"),
    (lambda: interp.rasterize(TRI, ATTR, [[0.0, 1.0, 2.0]], 8, 8), TypeError, "triangles"),
    (lambda: interp.rasterize(TRI, ATTR, [0, 1, 2], 8, 8), ValueError, "triangles"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 0, 8), ValueError, "width"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8.5, 8), TypeError, "width"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 10**6), ValueError, "height"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, True), TypeError, "height"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 8, mode="smooth"), ValueError, "mode"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 8, mode=None), TypeError, "mode"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 8, span=0), ValueError, "span"),
    (lambda: interp.rasterize(TRI * np.nan, ATTR, IDX, 8, 8), ValueError, "clip"),
    (lambda: interp.rasterize(TRI * 1e20, ATTR, IDX, 8, 8), ValueError, "clip"),
    (lambda: interp.rasterize(TRI, ATTR + np.inf, IDX, 8, 8), ValueError, "attributes"),
    (lambda: interp.rasterize(TRI.astype(str), ATTR, IDX, 8, 8), TypeError, "clip"),
    (lambda: interp.fragments(TRI, ATTR, IDX, -3, 8), ValueError, "width"),
    (
        lambda: interp.interpolate(interp.fragments(TRI, ATTR, IDX, 4, 4), "nope"),
        ValueError,
        "mode",
    ),
    (lambda: interp.ground_plane("camera"), TypeError, "camera"),
    (lambda: interp.ground_plane(size=0), ValueError, "size"),
    (lambda: interp.ground_plane(pitch=100), ValueError, "pitch"),
    (lambda: interp.ground_plane(interp.Camera(), pitch=10), TypeError, "not both"),
    (lambda: interp.ground_plane(tilt=10), TypeError, "tilt"),
    (lambda: interp.ground_plane(quads=0), ValueError, "quads"),
    (lambda: interp.ground_plane(quads=10**4), ValueError, "quads"),
    (lambda: interp.checkerboard(UV, np.zeros((4, 3))), ValueError, "u and v"),
    (lambda: interp.checkerboard(UV, UV, frequency=0), ValueError, "frequency"),
    (lambda: interp.checkerboard(UV, UV, filtered="yes"), TypeError, "filtered"),
    (lambda: interp.checkerboard(UV, UV, covered=np.ones((4, 4))), ValueError, "covered"),
    (lambda: interp.texel_error(np.zeros((4, 4, 2)), np.zeros((4, 4))), ValueError, "uv"),
    (lambda: checker_views("scene"), TypeError, "scene"),
    (lambda: checker_views(interp.ground_plane(), 8, 8, frequency=-1), ValueError, "frequency"),
]


@pytest.mark.parametrize("call, exception, words", CASES)
def test_bad_input_is_named(call, exception, words):
    with pytest.raises(exception, match=words):
        call()


finite = st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False)


@given(
    hnp.arrays(np.float64, (9, 4), elements=finite),
    hnp.arrays(np.float64, (9, 2), elements=st.floats(0, 1)),
    st.sampled_from(["perspective", "affine", "subdivided"]),
)
def test_any_scene_gives_a_clean_image(clip, attributes, mode):
    """No warnings (they are errors in this suite), no NaN, and perspective-correct values are
    convex combinations of their triangle's vertex values."""
    triangles = np.arange(9).reshape(3, 3)
    values, covered = interp.rasterize(clip, attributes, triangles, 16, 12, mode=mode)
    assert np.isfinite(values).all()
    assert np.all(values[~covered] == 0)
    if mode == "perspective":
        assert values.min() >= -1e-6 and values.max() <= 1 + 1e-6


@given(
    st.floats(-1, 5),
    st.floats(-89, 90),
    st.floats(-720, 720),
    st.floats(0, 10),
    st.floats(1, 170),
    st.floats(1e-4, 1),
)
def test_any_camera_gives_a_clean_checkerboard(height, pitch, yaw, distance, fovy, near):
    camera = interp.Camera(height, pitch, yaw, distance, fovy, near)
    views = checker_views(interp.ground_plane(camera, quads=4), 24, 16)
    for image in (views.correct, views.approximate, views.error):
        assert np.isfinite(image).all()
    assert views.correct.min() >= 0 and views.correct.max() <= 1
