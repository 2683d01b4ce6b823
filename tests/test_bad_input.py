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
#: 2**17 triangles covering the whole view: 2**29 (triangle, row) pairs at 4096 rows.
FULL_SCREEN_MANY = (
    np.array([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1.0]]),
    np.zeros((3, 1)),
    np.tile([0, 1, 2], (2**17, 1)),
)

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
    # Issue 13: exported names that did not check their arguments.
    (lambda: interp.interpolate(None), TypeError, "frags"),
    (lambda: interp.clip_triangles(TRI, ATTR, [[0, 1, 5]]), ValueError, "triangles"),
    (lambda: interp.clip_triangles(TRI * np.nan, ATTR, IDX), ValueError, "clip"),
    (lambda: interp.clip_triangles(TRI, ATTR, [[0.0, 1.0, 2.0]]), TypeError, "triangles"),
    (lambda: interp.viewport(TRI, 0, -3), ValueError, "width"),
    (lambda: interp.viewport(TRI, 4, -3), ValueError, "height"),
    (lambda: interp.viewport(TRI * [1, 1, 1, 0], 4, 4), ValueError, "clip must have w > 0"),
    (lambda: interp.viewport([[1, 0, 0, 1e-300]], 4, 4), ValueError, "divide overflows"),
    (lambda: interp.viewport(None, 4, 4), TypeError, "clip"),
    (lambda: interp.viewport(TRI[:, :3], 4, 4), ValueError, "clip"),
    (lambda: interp.Camera(fovy=200), ValueError, "fovy must"),
    (lambda: interp.Camera(fovy=None), TypeError, "fovy must"),
    (lambda: interp.Camera(aspect=0), ValueError, "aspect"),
    (lambda: interp.Camera(near=2, far=1), ValueError, "far"),
    # ... errors that named no argument (numpy's broadcast messages, OverflowError).
    (lambda: interp.s_from_t([0.2, 0.5], [1, 2, 3], 1), ValueError, "t, w1, w2 must broadcast"),
    (lambda: interp.t_from_s([0.2, 0.5], 1, [1, 2, 3]), ValueError, "s, w1, w2 must broadcast"),
    (lambda: interp.lerp_affine([0, 1], [1, 2, 3], 0.5), ValueError, "a1, a2, s must broadcast"),
    (lambda: interp.lerp_inverse_w([1, 2], [1, 2, 3], 0.5), ValueError, "w1, w2, s must"),
    (lambda: interp.lerp_perspective(0, 1, [1, 2], [1, 2, 3], 0.5), ValueError, "w1, w2"),
    (lambda: interp.gap_peak([1, 2], [1, 2, 3]), ValueError, "w1, w2 must broadcast"),
    (lambda: interp.perspective(60, 1, 1, 10**400), ValueError, "far"),
    (lambda: interp.Camera(height=10**400), ValueError, "height"),
    (lambda: interp.checkerboard(UV, UV, background=10**400), ValueError, "background"),
    (lambda: interp.rasterize(TRI, ATTR, [[0, 1], [2]], 8, 8), ValueError, "triangles"),
    (lambda: interp.checkerboard(UV, UV, covered=[[True], []]), ValueError, "covered"),
    (lambda: interp.Scene(None, ATTR, IDX, interp.Camera()), TypeError, "clip"),
    (lambda: interp.Scene(TRI, ATTR[:, :1], IDX, interp.Camera()), ValueError, "uv"),
    (lambda: interp.Scene(TRI, ATTR, IDX, "camera"), TypeError, "camera"),
    (lambda: interp.ClippedTriangles(TRI, ATTR, ATTR, IDX[0]), TypeError, "clip"),
    (lambda: interp.ClippedTriangles(TRI[None], ATTR[None], ATTR[None], None), TypeError, "source"),
    (
        lambda: interp.Fragments(4, 4, None, None, None, None, None, None, None, None, None),
        TypeError,
        "clipped",
    ),
    # Finite but extreme input: refused, naming the argument and its range.
    (lambda: interp.s_from_t(1e308, 1, 2), ValueError, "t must hold values in"),
    (lambda: interp.s_from_t(0.5, 1e-310, 2), ValueError, "w1 must hold values in"),
    (lambda: interp.perspective(60, 1, 1, 1.7e308), ValueError, "far"),
    (lambda: interp.perspective(1e-300, 1, 1, 2), ValueError, "fovy_degrees"),
    (lambda: interp.window_depth(1e-310, 1, 2), ValueError, "w must hold values in"),
    (lambda: interp.project_to_image_plane([1, -1e-300]), ValueError, "points"),
    (lambda: interp.perspective_weights([1, -1, 1e-20], [1, 1, 1]), ValueError, "zero"),
    (lambda: interp.checkerboard(UV + 1e308, UV), ValueError, "u must hold values in"),
    (lambda: interp.texel_error(np.full((2, 2, 2), 1e308), np.zeros((2, 2, 2))), ValueError, "uv"),
    (lambda: interp.rasterize(TRI, ATTR + 1e300, IDX, 8, 8), ValueError, "attributes"),
    (lambda: interp.ground_plane(size=1e300), ValueError, "size"),
    (lambda: interp.look_at([0, 0, 1e300], [0, 0, 0], [0, 1, 0]), ValueError, "eye"),
    # Memory bounded by what the work will cost.
    (lambda: interp.rasterize(TRI, np.zeros((3, 17)), IDX, 8, 8), ValueError, "at most 16 col"),
    (lambda: interp.rasterize(TRI, np.zeros((3, 3)), IDX, 4096, 4096), ValueError, "attributes"),
    (
        lambda: interp.fragments(TRI, ATTR, np.zeros((2**17 + 1, 3), int), 8, 8),
        ValueError,
        "triang",
    ),
    (lambda: interp.fragments(*FULL_SCREEN_MANY, 16, 4096), ValueError, "triangles cover"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 8, depth_bits=8), ValueError, "depth_bits"),
    (lambda: interp.rasterize(TRI, ATTR, IDX, 8, 8, depth_bits=24.0), TypeError, "depth_bits"),
]


@pytest.mark.parametrize("call, exception, words", CASES)
def test_bad_input_is_named(call, exception, words):
    with pytest.raises(exception, match=words):
        call()


def good_arguments():
    """A valid call of every public name: its arguments by name."""
    frags = interp.fragments(TRI, ATTR, IDX, 4, 4)
    scene = dict(clip=TRI, attributes=ATTR, triangles=IDX)
    return {
        "s_from_t": dict(t=0.5, w1=1.0, w2=2.0),
        "t_from_s": dict(s=0.5, w1=1.0, w2=2.0),
        "lerp_affine": dict(a1=0.0, a2=1.0, s=0.5),
        "lerp_inverse_w": dict(w1=1.0, w2=2.0, s=0.5),
        "lerp_perspective": dict(a1=0.0, a2=1.0, w1=1.0, w2=2.0, s=0.5),
        "gap_peak": dict(w1=1.0, w2=2.0),
        "project_to_image_plane": dict(points=[1.0, -2.0], d=1.0),
        "perspective": dict(fovy_degrees=60, aspect=1.0, near=0.1, far=10.0),
        "look_at": dict(eye=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0]),
        "Camera": dict(
            height=1.0,
            pitch=20.0,
            yaw=0.0,
            distance=3.0,
            fovy=60,
            near=0.1,
            far=9,
            aspect=1,
            roll=0,
        ),
        "ndc_depth": dict(w=2.0, near=1.0, far=10.0),
        "window_depth": dict(w=2.0, near=1.0, far=10.0),
        "depth_resolution": dict(w=2.0, near=1.0, far=10.0, buffer="float32"),
        "perspective_weights": dict(b=[0.5, 0.5, 0.0], w=[1.0, 2.0, 3.0]),
        "rasterize": dict(**scene, width=4, height=4, mode="affine", span=16, depth_bits=24),
        "fragments": dict(**scene, width=4, height=4, depth_bits=24),
        "clip_triangles": scene,
        "interpolate": dict(frags=frags, mode="perspective", span=16),
        "viewport": dict(clip=TRI, width=4, height=4),
        "checkerboard": dict(
            u=UV, v=UV, frequency=8.0, filtered=False, covered=UV > 0, background=0.5
        ),
        "texel_error": dict(uv=np.zeros((2, 2, 2)), uv_reference=np.zeros((2, 2, 2)), frequency=8),
        "ground_plane": dict(camera=interp.Camera(), size=8.0, quads=2),
        "Scene": dict(clip=TRI, uv=ATTR, triangles=IDX, camera=interp.Camera()),
        "ClippedTriangles": {name: getattr(frags.clipped, name) for name in CLIPPED_FIELDS},
        "Fragments": {name: getattr(frags, name) for name in frags.__dataclass_fields__},
    }


CLIPPED_FIELDS = ("clip", "smooth", "noperspective", "source")
#: Wrong for every argument of every public name (where None is not the default).
NONSENSE = [None, "abc", object(), 1j, np.nan, np.inf, 10**400, [[1.0, 2.0], [3.0]]]


def test_every_public_name_is_in_the_sweep():
    public = {name for name in interp.__all__ if callable(getattr(interp, name))}
    assert public == set(good_arguments())


@pytest.mark.parametrize("function", sorted(good_arguments()))
def test_every_argument_refuses_nonsense_by_name(function):
    """Each argument in turn gets each kind of nonsense: a ValueError or TypeError must come,
    and name that argument (as a word), whatever numpy would have said."""
    good = good_arguments()[function]
    for name in good:
        for bad in NONSENSE:
            if bad is None and name in ("camera", "covered"):  # None is the default there
                continue
            arguments = {**good, name: bad}
            with pytest.raises((ValueError, TypeError), match=rf"\b{name}\b"):
                getattr(interp, function)(**arguments)


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
