"""The shader's view (interp.shaders), against the library and against real OpenGL: `flat` with
the provoking vertex, and the vertex shader that divides by w itself, drawn on Mesa's llvmpipe
with a real shader that does (interp.opengl's ``vertex_divide``)."""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp import shaders
from interp.scenes import LESSON_SIZE

from helpers import random_scene

#: llvmpipe interpolates in float32.
FLOAT32 = 5e-5


def scenes():
    """Random triangles in front of the camera, and the lesson's ground plane from three
    cameras, all of its vertices in front of the eye."""
    yield random_scene(np.random.default_rng(41), 25)
    for camera in (
        interp.Camera(height=1.0, pitch=15.0),
        interp.Camera(height=0.5, pitch=30.0, yaw=40.0, distance=3.0, fovy=90.0),
        interp.Camera(height=2.0, pitch=60.0, yaw=-20.0, roll=25.0),
    ):
        scene = interp.ground_plane(camera.fitted(96, 72), LESSON_SIZE, quads=2)
        yield scene.clip, np.c_[scene.uv, scene.uv[:, 0] * scene.uv[:, 1]], scene.triangles


@pytest.mark.parametrize("k", range(4))
def test_dividing_in_the_vertex_shader_is_noperspective(k):
    clip, attributes, triangles = list(scenes())[k]
    assert np.all(clip[:, 3] > 0)
    mistake, covered = shaders.shade(clip, attributes, triangles, 96, 72, "smooth", divided=True)
    affine, drawn = interp.rasterize(clip, attributes, triangles, 96, 72, mode="affine")
    right, _ = interp.rasterize(clip, attributes, triangles, 96, 72)
    np.testing.assert_array_equal(covered, drawn)
    np.testing.assert_allclose(mistake[covered], affine[covered], atol=1e-9)
    assert np.abs(mistake - right)[covered].max() > 0.01  # and it is not smooth


def test_flat_takes_the_last_vertex_of_each_input_triangle():
    # clipped pieces keep their triangle's provoking vertex
    camera = interp.Camera(height=0.3, pitch=15.0, distance=1.0).fitted(64, 48)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=2)
    values, covered = shaders.shade(scene.clip, scene.uv, scene.triangles, 64, 48, "flat")
    frags = interp.fragments(scene.clip, scene.uv, scene.triangles, 64, 48)
    assert len(frags.clipped) > len(np.unique(frags.clipped.source)), "some triangles clipped"
    last = scene.uv[scene.triangles[frags.triangle, shaders.PROVOKING_VERTEX]]
    np.testing.assert_array_equal(values[covered], last)


def test_divide_in_vertex_shader_and_drawable():
    clip = np.array([[2.0, -2.0, 1.0, 2.0], [1.0, 1.0, 1.0, -0.5], [0.0, 0.0, 0.0, 1.0]])
    np.testing.assert_array_equal(
        shaders.divide_in_vertex_shader(clip), [[1, -1, 0.5, 1], [-2, -2, -2, 1], [0, 0, 0, 1]]
    )
    with pytest.raises(ValueError, match="w != 0"):
        shaders.divide_in_vertex_shader([[1.0, 0.0, 0.0, 0.0]])
    clip[2, 3] = 0.0
    assert shaders.drawable(clip, np.array([[0, 1, 2], [0, 1, 1]])).tolist() == [False, True]
    with pytest.raises(ValueError, match="qualifier"):
        shaders.shade(clip, np.zeros((3, 1)), [[0, 1, 1]], 8, 8, "centroid")


@pytest.mark.opengl
@pytest.mark.parametrize("qualifier", ["smooth", "noperspective", "flat"])
@pytest.mark.parametrize("divided", [False, True], ids=["as written", "divided in the shader"])
def test_llvmpipe_agrees_pixel_for_pixel(gl, qualifier, divided):
    mode = shaders.QUALIFIERS[qualifier]
    for clip, attributes, triangles in scenes():
        ours, covered = shaders.shade(clip, attributes, triangles, 96, 72, qualifier, divided)
        image = gl.render(clip, attributes, triangles, 96, 72, mode, vertex_divide=divided)
        np.testing.assert_array_equal(image.covered, covered)
        np.testing.assert_allclose(image.values[covered], ours[covered], atol=FLOAT32)


@pytest.mark.opengl
def test_llvmpipe_mirrors_vertices_behind_the_camera_too(gl):
    """With corners behind the eye, the dividing shader draws the same (wrong) pixels on
    llvmpipe. The mirrored triangles overlap in one plane, so which one a pixel shows is a
    depth tie: values are compared where both show the same triangle."""
    camera = interp.Camera(height=0.3, pitch=15.0, distance=1.0).fitted(96, 72)
    scene = interp.ground_plane(camera, LESSON_SIZE, quads=2)
    assert np.any(scene.clip[:, 3] < 0)
    ours, covered = shaders.shade(scene.clip, scene.uv, scene.triangles, 96, 72, "smooth", True)
    image = gl.render(scene.clip, scene.uv, scene.triangles, 96, 72, vertex_divide=True)
    np.testing.assert_array_equal(image.covered, covered)
    frags = interp.fragments(
        shaders.divide_in_vertex_shader(scene.clip), scene.uv, scene.triangles, 96, 72
    )
    same = frags.image(frags.triangle, -1) == image.triangle
    assert (same & covered).sum() > 0.5 * covered.sum()
    np.testing.assert_allclose(image.values[same & covered], ours[same & covered], atol=FLOAT32)
