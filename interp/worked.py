"""Lesson 7's worked example: one triangle and one pixel, every step a student can do by hand.

The camera is OpenGL's eye: at the origin, looking down -z, y up, so world space *is* view
space and the view matrix is the identity. Its projection is ``interp.perspective(90, 1, 0.5,
4.5)``: with a 90 degree field of view and a square image, clip x and y are just view x and y,
and the third row is ``(0, 0, -1.25, -1.125)``. The image is 8 x 8 pixels.

The triangle's corners sit at depths 1, 2 and 4, chosen so that every number in the table is a
short decimal, and the pixel is chosen so that its screen-space barycentrics are (1/4, 1/4, 1/2).

==========  ====================  ==========================================
step        corner 0, 1, 2        how
==========  ====================  ==========================================
world       (-0.75, -0.75, -1),   given (= view space)
            (1.5, -1.5, -2),
            (-1, 0, -4)
clip        (x, y, z, w)          ``P @ (x, y, z, 1)``: w = -z
NDC         (x, y, z) / w         the perspective divide
window      ((x+1) 4, (y+1) 4,    the viewport: 8 x 8 pixels, depth range [0, 1]
            (z+1)/2)
b           at the pixel          screen-space barycentrics of its centre (3.5, 2.5)
lambda      at the pixel          ``(b_i / w_i) / sum_j (b_j / w_j)``
u           at the pixel          ``sum_i lambda_i u_i``; affine: ``sum_i b_i u_i``
==========  ====================  ==========================================

Examples
--------
>>> row = table()
>>> row["lambda"], row["u"], row["u affine"]
((0.5, 0.25, 0.25), 0.375, 0.625)
>>> values, covered = drawn()
>>> round(float(values[IMAGE_ROW, COLUMN, 0]), 12)     # interp.rasterize, at that very pixel
0.375
"""

from __future__ import annotations

import numpy as np

from interp.barycentric import perspective_weights
from interp.camera import perspective
from interp.raster import rasterize, viewport

#: The projection: 90 degrees, square, near 0.5, far 4.5.
FOVY, ASPECT, NEAR, FAR = 90.0, 1.0, 0.5, 4.5
#: The image size in pixels.
WIDTH = HEIGHT = 8
#: The triangle's corners in world (= view) space, one row each.
CORNERS = np.array([[-0.75, -0.75, -1.0], [1.5, -1.5, -2.0], [-1.0, 0.0, -4.0]])
#: The attribute at each corner (a texture coordinate u).
U = np.array([0.0, 0.5, 1.0])
#: The pixel: column 3 and row 2 counted from the bottom (OpenGL's window y), whose centre is
#: (3.5, 2.5); in an image array, whose row 0 is the top, that is row 8 - 1 - 2 = 5.
COLUMN, WINDOW_ROW = 3, 2
IMAGE_ROW = HEIGHT - 1 - WINDOW_ROW


def _tuple(values: np.ndarray) -> tuple:
    """Numbers as a hand computation writes them: tan(45 degrees) is 1 only to 1e-16 in floats,
    so each is rounded to 12 decimals."""
    return tuple(_number(x) for x in np.asarray(values).ravel())


def _number(x: float) -> float:
    return round(float(x), 12) + 0.0  # + 0.0: no -0.0


def table() -> dict[str, object]:
    """Every entry of the lesson's table, computed with the library one step at a time.

    Keys: ``"clip"`` (three (x, y, z, w) tuples), ``"w"``, ``"ndc x"``, ``"ndc y"``, ``"ndc z"``,
    ``"window x"``, ``"window y"``, ``"window z"`` (three numbers each, one per corner), then at
    the pixel ``"b"`` and ``"lambda"`` (three each), ``"1/w"``, ``"u"`` and ``"u affine"``.
    """
    P = perspective(FOVY, ASPECT, NEAR, FAR)
    clip = np.column_stack([CORNERS, np.ones(3)]) @ P.T
    w = clip[:, 3]
    ndc = clip[:, :3] / w[:, None]
    window = viewport(clip, WIDTH, HEIGHT)
    centre = np.array([COLUMN + 0.5, WINDOW_ROW + 0.5])
    # Screen-space barycentrics: centre = b0 p0 + b1 p1 + b2 p2 with b0 + b1 + b2 = 1.
    system = np.vstack([window[:, :2].T, np.ones(3)])
    b = np.linalg.solve(system, np.append(centre, 1.0))
    lam = perspective_weights(b, w)
    return {
        "clip": tuple(_tuple(row) for row in clip),
        "w": _tuple(w),
        "ndc x": _tuple(ndc[:, 0]),
        "ndc y": _tuple(ndc[:, 1]),
        "ndc z": _tuple(ndc[:, 2]),
        "window x": _tuple(window[:, 0]),
        "window y": _tuple(window[:, 1]),
        "window z": _tuple(window[:, 2]),
        "b": _tuple(b),
        "lambda": _tuple(lam),
        "1/w": _number(np.sum(b / w)),
        "u": _number(lam @ U),
        "u affine": _number(b @ U),
    }


def drawn(mode: str = "perspective") -> tuple[np.ndarray, np.ndarray]:
    """The triangle drawn by :func:`interp.rasterize` with u as its attribute: (8, 8, 1) values
    and (8, 8) coverage."""
    P = perspective(FOVY, ASPECT, NEAR, FAR)
    clip = np.column_stack([CORNERS, np.ones(3)]) @ P.T
    return rasterize(clip, U[:, None], [[0, 1, 2]], WIDTH, HEIGHT, mode)
