"""Lesson 7's theory, checked three ways: the ray cast of interp.theory against the rasterizer,
planes where the proof says planes, and the worked example against both rasterizers."""

from __future__ import annotations

import numpy as np
import pytest

import interp
from interp import textbook, theory, worked
from interp.scenes import LESSON_SIZE

CAMERAS = [
    interp.Camera(height=1.0, pitch=15.0),
    interp.Camera(height=0.5, pitch=30.0, yaw=40.0, distance=3.0, fovy=90.0),
    interp.Camera(height=2.0, pitch=60.0, yaw=-20.0, roll=25.0),
    interp.Camera(height=-0.5, pitch=-20.0, yaw=10.0),  # from below
    interp.Camera(height=0.3, pitch=15.0, distance=1.0),  # over the quad: clipping
]


@pytest.mark.parametrize("camera", CAMERAS, ids=range(len(CAMERAS)))
def test_the_ray_cast_sees_what_rasterize_draws(camera):
    truth = theory.ground_truth(camera, 96, 72)
    scene = interp.ground_plane(camera.fitted(96, 72), LESSON_SIZE, quads=1)
    attributes = np.c_[scene.uv, scene.clip[:, 3]]  # u, v, and w (smooth: exact)
    values, covered = interp.rasterize(scene.clip, attributes, scene.triangles, 96, 72)
    assert covered.any()
    # coverage differs at most on pixels whose centre lies on an edge (the fill rule)
    assert (covered != truth.covered).sum() <= 0.01 * covered.sum()
    both = covered & truth.covered
    np.testing.assert_allclose(values[both, 0], truth.u[both], atol=1e-9)
    np.testing.assert_allclose(values[both, 1], truth.v[both], atol=1e-9)
    np.testing.assert_allclose(values[both, 2], truth.w[both], rtol=1e-9)


@pytest.mark.parametrize("camera", CAMERAS, ids=range(len(CAMERAS)))
def test_one_over_w_is_a_plane_and_w_and_u_are_not(camera):
    truth = theory.ground_truth(camera, 96, 72)
    for name in ("1/w", "u/w", "NDC z"):
        assert max(f.misfit for f in theory.misfits(truth, name)) < 1e-9, name
    for name in ("w", "u"):
        assert max(f.misfit for f in theory.misfits(truth, name)) > 1e-3, name


def test_looking_straight_down_even_w_is_a_plane():
    truth = theory.ground_truth(interp.Camera(height=2.0, pitch=90.0, distance=0.0), 32, 24)
    assert [f.misfit for f in theory.misfits(truth, "w")] == [0.0, 0.0]


def test_the_plane_of_1_over_w_is_the_one_the_proof_gives():
    # 1/w = (n_x A/f X + n_y/f Y - n_z)/k for the plane n . P = k in view space
    camera = interp.Camera(height=1.0, pitch=15.0).fitted(96, 72)
    truth = theory.ground_truth(camera, 96, 72)
    normal = camera.view[:3, :3] @ [0.0, 1.0, 0.0]  # the ground's normal, in view space
    k = normal @ (camera.view @ [0.0, 0.0, 0.0, 1.0])[:3]  # n . P at a point of the ground
    f, A = 1 / np.tan(np.radians(camera.fovy) / 2), camera.aspect
    X = 2 * (np.arange(96) + 0.5) / 96 - 1
    Y = 1 - 2 * (np.arange(72) + 0.5) / 72
    X, Y = np.meshgrid(X, Y)
    predicted = (normal[0] * A / f * X + normal[1] / f * Y - normal[2]) / k
    seen = truth.covered
    np.testing.assert_allclose(predicted[seen], 1 / truth.w[seen], rtol=1e-9)


def test_the_worked_example_by_hand_is_what_both_rasterizers_draw():
    table = worked.table()
    assert table["lambda"] == (0.5, 0.25, 0.25) and table["u"] == 0.375
    assert table["1/w"] == 0.5 and table["window z"] == (0.5625, 0.84375, 0.984375)
    clip = np.array(table["clip"])
    for draw in (interp.rasterize, textbook.draw):
        values, covered = draw(clip, worked.U[:, None], [[0, 1, 2]], 8, 8)
        assert covered[worked.IMAGE_ROW, worked.COLUMN]
        assert values[worked.IMAGE_ROW, worked.COLUMN, 0] == pytest.approx(table["u"], abs=1e-12)
    frags = interp.fragments(clip, worked.U[:, None], [[0, 1, 2]], 8, 8)
    k = list(frags.pixel).index(worked.IMAGE_ROW * 8 + worked.COLUMN)
    np.testing.assert_allclose(frags.barycentric[:, k], table["b"], atol=1e-12)
    assert frags.depth[k] == pytest.approx(np.dot(table["b"], table["window z"]))
    affine, _ = interp.rasterize(clip, worked.U[:, None], [[0, 1, 2]], 8, 8, mode="affine")
    assert affine[worked.IMAGE_ROW, worked.COLUMN, 0] == pytest.approx(table["u affine"])


def test_the_worked_example_is_printed_in_lesson_7():
    from pathlib import Path

    import nbformat

    path = (
        Path(interp.__file__).resolve().parent.parent / "source" / "lessons" / "07_triangles.ipynb"
    )
    text = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells)
    P = interp.perspective(worked.FOVY, worked.ASPECT, worked.NEAR, worked.FAR)
    assert f"-{-P[2, 2]:g} & -{-P[2, 3]:g}" in text
    for corner, u in zip(worked.CORNERS, worked.U, strict=True):
        world = ", ".join(f"{x:g}" for x in corner)
        assert f"$({world})$ | {u:g} |" in text
    assert f"window $({worked.COLUMN + 0.5}, {worked.WINDOW_ROW + 0.5})$" in text
