"""Projection and view matrices against glFrustum / gluLookAt written out independently."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

import interp


def gl_frustum(left, right, bottom, top, near, far):
    """glFrustum's matrix, as printed in the OpenGL 2.1 reference pages."""
    return np.array(
        [
            [2 * near / (right - left), 0, (right + left) / (right - left), 0],
            [0, 2 * near / (top - bottom), (top + bottom) / (top - bottom), 0],
            [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)],
            [0, 0, -1, 0],
        ]
    )


@given(st.floats(1, 179), st.floats(0.1, 10), st.floats(0.01, 10), st.floats(1.01, 1000))
def test_perspective_is_a_symmetric_frustum(fovy, aspect, near, far_over_near):
    far = near * far_over_near
    top = near * np.tan(np.radians(fovy) / 2)
    right = top * aspect
    expected = gl_frustum(-right, right, -top, top, near, far)
    np.testing.assert_allclose(interp.perspective(fovy, aspect, near, far), expected, rtol=1e-12)


def test_perspective_maps_the_frustum_onto_the_ndc_cube():
    P = interp.perspective(90, 2.0, 1.0, 10.0)
    for z, ndc_z in ((-1.0, -1.0), (-10.0, 1.0)):
        half_height = -z  # tan(45 deg) = 1
        corner = P @ [2 * half_height, half_height, z, 1]
        np.testing.assert_allclose(corner[:3] / corner[3], [1, 1, ndc_z], atol=1e-12)
    assert (P @ [0, 0, -5, 1])[3] == 5  # clip w is the view depth


@given(
    st.lists(st.floats(-10, 10), min_size=3, max_size=3),
    st.lists(st.floats(-10, 10), min_size=3, max_size=3),
)
def test_look_at_is_a_rigid_motion_onto_minus_z(eye, target):
    eye, target = np.array(eye), np.array(target)
    distance = np.linalg.norm(target - eye)
    forward = (target - eye) / max(distance, 1e-300)
    assume(distance >= 1e-3 and abs(forward[1]) <= 0.99)  # look_at needs a direction, not up
    V = interp.look_at(eye, target, [0, 1, 0])
    R = V[:3, :3]
    np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(R) == pytest.approx(1.0)
    np.testing.assert_allclose(V @ [*eye, 1], [0, 0, 0, 1], atol=1e-9)
    np.testing.assert_allclose(V @ [*target, 1], [0, 0, -distance, 1], atol=1e-9)
    up_in_view = R @ [0, 1, 0]
    assert up_in_view[1] > 0 and abs(up_in_view[0]) < 1e-9  # world up stays up, not sideways


def test_camera_view_matches_look_at_and_handles_straight_down():
    camera = interp.Camera(height=2, pitch=35, yaw=-60, distance=4)
    forward = -camera.view[2, :3]
    np.testing.assert_allclose(
        camera.view, interp.look_at(camera.eye, camera.eye + forward, [0, 1, 0]), atol=1e-12
    )
    assert forward[1] == pytest.approx(-np.sin(np.radians(35)))
    horizontal = forward[[0, 2]] / np.linalg.norm(forward[[0, 2]])
    np.testing.assert_allclose(horizontal, -camera.eye[[0, 2]] / 4, atol=1e-12)  # faces origin
    down = interp.Camera(height=3, pitch=90, distance=0)
    np.testing.assert_allclose(down.view @ [0, 0, 0, 1], [0, 0, -3, 1], atol=1e-12)
    np.testing.assert_allclose(down.projection, interp.perspective(60, 1, 0.1, 100))
