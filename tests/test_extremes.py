"""Every public function, fed extreme but finite floats: subnormals, 1e-300, 1e308, -0.0.

Each call must either refuse with a ValueError or TypeError that names one of its arguments, or
return finite numbers without a warning (warnings are errors in this suite). Nothing in between:
no NaN, no inf, no overflow warning reaching a student.
"""

from __future__ import annotations

import inspect
import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import interp

#: Any finite double: subnormals, the largest ones, both zeros.
EXTREME = st.floats(allow_nan=False, allow_infinity=False)
#: Mostly ordinary, sometimes extreme: so that some calls get past the argument checks.
MIXED = st.one_of(st.floats(-10, 10), EXTREME, st.sampled_from([1e-310, 5e-324, 1.7e308, 1e-12]))
POSITIVE = st.one_of(st.floats(0.01, 100), st.sampled_from([1e-310, 5e-324, 1e-12, 1e12, 1e308]))


def arrays(shape, elements=MIXED):
    return hnp.arrays(np.float64, shape, elements=elements)


def finite_leaves(result):
    """Every number inside a result: arrays, floats, tuples and the fields of dataclasses."""
    if isinstance(result, (tuple, list)):
        for item in result:
            yield from finite_leaves(item)
    elif isinstance(result, (np.ndarray, float, int, np.floating)):
        yield np.asarray(result)
    elif hasattr(result, "__dataclass_fields__"):
        for name in result.__dataclass_fields__:
            yield from finite_leaves(getattr(result, name))


def check(function, *args, **kwargs):
    """Call ``function``: a ValueError/TypeError naming one of its parameters, or finite
    results. Returns the result, or None if refused."""
    names = list(inspect.signature(function).parameters)
    try:
        result = function(*args, **kwargs)
    except (ValueError, TypeError) as error:
        message = str(error)
        assert any(re.search(rf"\b{name}\b", message) for name in names), (
            f"{function.__name__}: {message!r} names none of {names}"
        )
        return None
    for leaf in finite_leaves(result):
        if leaf.dtype.kind == "f":
            assert np.isfinite(leaf).all(), f"{function.__name__}: non-finite result {leaf}"
    return result


def finite(result):
    """Assert a computed result is finite (no arguments to name)."""
    for leaf in finite_leaves(result):
        if leaf.dtype.kind == "f":
            assert np.isfinite(leaf).all(), f"non-finite result {leaf}"


@given(MIXED, POSITIVE, POSITIVE)
def test_the_1d_story(x, w1, w2):
    check(interp.s_from_t, x, w1, w2)
    check(interp.t_from_s, x, w1, w2)
    check(interp.lerp_affine, x, w1, w2)
    check(interp.lerp_inverse_w, w1, w2, x)
    check(interp.lerp_perspective, x, -x, w1, w2, 0.5)
    check(interp.lerp_perspective, 0.0, 1.0, w1, w2, x)
    check(interp.gap_peak, w1, w2)
    check(interp.project_to_image_plane, [x, -w1], w2)


@given(MIXED, POSITIVE, POSITIVE, st.floats(0, 1))
def test_depth(w, near, far, fraction):
    check(interp.ndc_depth, w, near, far)
    check(interp.window_depth, w, near, far)
    check(interp.depth_resolution, w, near, far, "float32")
    check(interp.depth_resolution, w, near, far, "fixed24")
    # Between the planes, what the depth buffer stores lies in [0, 1]; on them, exactly 0, 1.
    if 1e-12 <= near < far <= 1e12:
        assert interp.window_depth(near, near, far) == 0.0
        assert interp.window_depth(far, near, far) == 1.0
        z = interp.window_depth(min(near + fraction * (far - near), far), near, far)
        assert 0 <= z <= 1


@given(MIXED, POSITIVE, POSITIVE, POSITIVE, arrays((3, 3)))
def test_cameras(fovy, aspect, near, far, points):
    check(interp.perspective, fovy, aspect, near, far)
    check(interp.look_at, *points)


@given(st.lists(MIXED, min_size=9, max_size=9), MIXED)
def test_camera_and_ground_plane(values, size):
    camera = check(interp.Camera, *values)
    if camera is not None:
        finite((camera.eye, camera.view, camera.projection))
        check(interp.ground_plane, camera, size=size)


@given(arrays((3,)), arrays((3,)))
def test_perspective_weights(b, w):
    weights = check(interp.perspective_weights, b, w)
    if weights is not None:
        assert abs(weights.sum() - 1) < 1e-9


@given(arrays((6, 4)), arrays((6, 2)), st.sampled_from(interp.MODES))
def test_triangles(clip, attributes, mode):
    triangles = [[0, 1, 2], [3, 4, 5]]
    check(interp.rasterize, clip, attributes, triangles, 8, 6, mode)
    frags = check(interp.fragments, clip, attributes, triangles, 8, 6)
    if frags is not None:
        finite((interp.interpolate(frags, mode), frags.depth, frags.barycentric))
    check(interp.clip_triangles, clip, attributes, triangles)
    check(interp.viewport, clip, 8, 6)


#: Anything the rasterizer accepts: every double within 1e12, subnormals and -0.0 included.
IN_RANGE = st.one_of(
    st.floats(-1e12, 1e12),
    st.floats(-1e-12, 1e-12),
    st.sampled_from([0.0, -0.0, 5e-324, -1e-310, 1e-17, 1.0, -1.0, 1e12]),
)


@given(
    hnp.arrays(np.float64, (9, 4), elements=IN_RANGE),
    hnp.arrays(np.float64, (9, 2), elements=IN_RANGE),
    st.sampled_from(interp.MODES),
    st.sampled_from([24, 40]),
)
def test_any_scene_within_range_draws_a_finite_image(clip, attributes, mode, depth_bits):
    triangles = np.arange(9).reshape(3, 3)
    values, covered = interp.rasterize(clip, attributes, triangles, 12, 8, mode, 4, depth_bits)
    assert np.isfinite(values).all() and np.all(values[~covered] == 0)
    if mode == "perspective":  # a convex combination of its triangle's vertex values
        low, high = attributes.min(axis=0), attributes.max(axis=0)
        slack = 1e-9 * np.abs(attributes).max(axis=0) + 1e-300  # subnormal values underflow
        assert np.all(values[covered] >= low - slack) and np.all(values[covered] <= high + slack)


@given(arrays((3, 4)), arrays((3, 4)), MIXED, st.booleans(), MIXED)
def test_textures(u, v, frequency, filtered, background):
    check(interp.checkerboard, u, v, frequency, filtered, background=background)
    uv, reference = np.stack([u, v], axis=2), np.stack([v, u], axis=2)
    check(interp.texel_error, uv, reference, frequency)


@settings(max_examples=10)
@given(st.sampled_from([1e-310, 1e-200, 1e-17, 1.0, 1e11]))
def test_a_vertex_at_any_tiny_w_draws_a_finite_image(w):
    # Issue 13: a subnormal w made an all-NaN image.
    clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [0, 0, 0, w]]
    for mode in interp.MODES:
        values, covered = interp.rasterize(clip, [[0.0], [1.0], [2.0]], [[0, 1, 2]], 8, 8, mode)
        assert covered.any() and np.isfinite(values).all()
