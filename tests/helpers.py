"""Scenes the tests share."""

from __future__ import annotations

import numpy as np

import interp


def random_scene(rng: np.random.Generator, n_triangles: int, behind: bool = False):
    """Random triangles in view space, projected with a real perspective matrix.

    With ``behind``, some vertices lie behind the camera or before the near plane, so the
    rasterizer must clip. Returns (clip, attributes, triangles).
    """
    P = interp.perspective(70, 4 / 3, 0.5, 20)
    centres = np.column_stack(
        [
            rng.uniform(-3, 3, n_triangles),
            rng.uniform(-2, 2, n_triangles),
            rng.uniform(-12, -2, n_triangles),
        ]
    )
    spread = 4.0 if behind else 1.5
    view = centres.repeat(3, axis=0) + rng.uniform(-spread, spread, (3 * n_triangles, 3))
    if behind:
        view[::5, 2] = rng.uniform(-1.0, 2.0, len(view[::5]))  # near plane at -0.5
    clip = np.column_stack([view, np.ones(len(view))]) @ P.T
    attributes = rng.uniform(0, 1, (len(view), 3))
    triangles = np.arange(3 * n_triangles).reshape(-1, 3)
    return clip, attributes, triangles
