"""A textbook rasterizer: triangles to pixels, one triangle at a time. Students: read this first.

:func:`interp.rasterize` draws exactly the same pixels (``tests/test_textbook.py`` proves it),
but it is written to be fast, and speed hides the idea. This module is written to be read in
one sitting, the way tinyrenderer and Scratchapixel draw a triangle. After clipping against the
view volume (:func:`~interp.clipping.clip_triangles`) and mapping to the window
(:func:`~interp.raster.viewport`), the same code ``rasterize`` runs, each triangle in draw order:

1. snap its corners to the subpixel grid and take the bounding box of pixel centres;
2. at each pixel centre in the box, the three *edge functions*: the centre is inside when all
   three are positive, or zero on an edge the triangle owns (the *fill rule*);
3. the *depth test* ``z < depth[y, x]``: a fragment survives only if it is nearer than whatever
   was drawn there before (``GL_LESS``; on a tie the first triangle drawn stays);
4. the attribute from the barycentrics: ``a/w`` and ``1/w`` interpolated and divided
   (``"perspective"``, GLSL ``smooth``), or ``a`` interpolated as it is (``"affine"``, GLSL
   ``noperspective``; clipping gives new vertices their ``noperspective`` values).

Glossary
--------
window (x, y, z) : window coordinates: x, y in pixels with y *up* (OpenGL's), z in [0, 1].
X, Y             : window x, y snapped to 1/SUBPIXELS pixel, as integers (subpixel units).
pixel (x, y)     : column x, row y counted from the *bottom*; its centre is (x + 1/2, y + 1/2).
corners 0, 1, 2  : a (clipped) triangle's vertices, counter-clockwise once it is drawn.
edge function    : ``e(p) = (x1 - x0)(py - y0) - (y1 - y0)(px - x0)`` for the edge from corner
                   0 to corner 1: > 0 left of it, 0 on it. ``e_i`` is for edge i, the one
                   opposite corner i; in a counter-clockwise triangle all three are > 0 inside.
area2            : twice the signed area, positive when counter-clockwise: ``e_i`` at corner i.
fill rule        : who draws a centre exactly on an edge. Mesa's: a counter-clockwise triangle
                   owns its left edges (going down) and horizontal bottom edges (going right).
b                : screen-space barycentrics ``b_i = e_i / area2``, from the exact positions.
depth            : the depth buffer, cleared to 1 (the far plane): window z of the nearest
                   fragment so far, rounded to DEPTH_BITS bits like a GPU's fixed-point buffer.
w                : each corner's clip-space w, its view depth.

Exactness. Coverage is decided in integers on the snapped grid, so no rounding can make two
triangles sharing an edge both draw a centre on it, or both skip it, and it is bit-identical
to ``rasterize``'s. The depth test is what needs care. Compared as plain floats, two triangles
at the same depth get values of ``b @ z`` a unit in the last place apart, and a later one can
win a tie that ``GL_LESS`` gives to the first (about 1 pixel in 100 of random flat-tie scenes
on the half-pixel grid). So, as ``rasterize`` does, ``z`` is rounded to DEPTH_BITS (40) bits
before the test: equal depths then compare equal, and the last-place differences between this
module's ``b @ z`` and ``rasterize``'s row-by-row depth vanish too. What remains: triangles in
the same sloped plane but with different corners (z-fighting) can round to neighbouring 40-bit
steps, about 2 pixels in 10**4 of such overlaps; and ``rasterize`` gives up depth bits when
more than 2**22 (triangle, row) pairs share one draw (see its ``_depth_test``).

What :func:`interp.rasterize` does differently, and why
-------------------------------------------------------
- *Spans, not per-pixel tests.* On each pixel row the inside of a triangle is one run of
  columns; ``rasterize`` solves ``e_i >= 0`` for the first and last column of each row by
  integer ceiling division instead of testing every centre of a bounding box (about half of
  which a triangle misses).
- *One depth test for all triangles at once.* Instead of a Python loop over triangles, each
  fragment's rounded depth and draw order are packed into one integer key; ``np.minimum.at``
  keeps the smallest key per pixel, which is the nearest fragment and, on a tie, the first drawn.
- *Bands and chunks.* Like llvmpipe with its tiles, it works through the image in bands of
  whole rows (``BAND`` pixels), each depth-tested only against the triangles' rows that lie
  on it, and those keys are made ``CHUNK`` fragments at a time: memory stays bounded however
  much the triangles overlap, and the temporaries stay small enough to be reused.
- *Lines along rows.* ``a/w`` and ``1/w`` (affinely, ``a``) are planes over the screen, so on
  each row a triangle's span lies on they are a line: a value at the span's first column plus
  a step per column. Each pixel evaluates the line of the triangle that won it, and only those.
- *No clipping where none is needed.* Triangles wholly inside the view volume skip the six
  clipping passes, and triangles wholly outside one plane are dropped before them.
"""

from __future__ import annotations

import numpy as np

from interp import _checks
from interp.clipping import clip_triangles
from interp.raster import DEPTH_BITS, SUBPIXELS, _check_scene, viewport

#: Edge i, opposite corner i, runs from corner j to corner k (counter-clockwise order).
EDGES = ((1, 2), (2, 0), (0, 1))
#: A coordinate: a Python or numpy number, or an array of them.
Number = int | float | np.integer | np.floating | np.ndarray

#: What this rasterizer draws (``rasterize`` also has Quake's ``"subdivided"``).
MODES = ("perspective", "affine")


def draw(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    mode: str = "perspective",
) -> tuple[np.ndarray, np.ndarray]:
    """Draw triangles one at a time, the textbook way; the same pixels as :func:`~interp.rasterize`.

    Parameters
    ----------
    clip, attributes, triangles, width, height
        The scene and the image size, exactly as for :func:`~interp.rasterize`: clip-space
        ``(x, y, z, w)`` per vertex, K attributes per vertex, vertex indices in draw order.
    mode : {"perspective", "affine"}
        GLSL ``smooth`` (divide by the interpolated ``1/w``) or ``noperspective``.

    Returns
    -------
    values, covered : ndarray
        As :func:`~interp.rasterize` returns them: a ``(height, width, K)`` float array of the
        attributes at each pixel centre (0 where nothing is drawn; row 0 is the top), and a
        ``(height, width)`` bool array of where a triangle was drawn.

    Examples
    --------
    The lower-left half of the view, 4 x 4 pixels; centres on the diagonal belong to the
    triangle on the other side of it:

    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]
    >>> values, covered = draw(clip, [[0.0], [1.0], [0.0]], [[0, 1, 2]], 4, 4)
    >>> covered.astype(int)
    array([[0, 0, 0, 0],
           [1, 0, 0, 0],
           [1, 1, 0, 0],
           [1, 1, 1, 0]])
    >>> values[3, :, 0]                      # the bottom row: x = 1/8, 3/8, 5/8, not drawn
    array([0.125, 0.375, 0.625, 0.   ])

    A quad whose top is three times as far away as its bottom, as ``rasterize`` draws it:

    >>> import interp
    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [3, 3, 0, 3], [-3, 3, 0, 3]]
    >>> uv, quad = [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1, 2], [0, 2, 3]]
    >>> values, covered = draw(clip, uv, quad, 8, 8)
    >>> fast, fast_covered = interp.rasterize(clip, uv, quad, 8, 8)
    >>> bool(np.array_equal(covered, fast_covered) and np.allclose(values, fast, atol=1e-12))
    True
    """
    clip, attributes, triangles = _check_scene(clip, attributes, triangles)
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    mode = _checks.choice(mode, "mode", MODES)

    # The buffers, indexed [y, x] with y going up as in the window; flipped into images at the end.
    depth = np.ones((height, width))  # cleared to the far plane: nothing drawn yet
    values = np.zeros((height, width, attributes.shape[1]))

    pieces = clip_triangles(clip, attributes, triangles)  # still in draw order
    for position, smooth, noperspective in zip(
        pieces.clip, pieces.smooth, pieces.noperspective, strict=True
    ):
        window = viewport(position, width, height)  # (3, 3): x, y in pixels, z in [0, 1]
        a = smooth if mode == "perspective" else noperspective
        draw_triangle(window, position[:, 3], a, mode, depth, values)

    covered = depth < 1.0  # whatever passed a depth test against the cleared buffer
    return values[::-1].copy(), covered[::-1].copy()  # image row 0 is the top


def draw_triangle(
    window: np.ndarray,
    w: np.ndarray,
    a: np.ndarray,
    mode: str,
    depth: np.ndarray,
    values: np.ndarray,
) -> None:
    """Draw one triangle into ``depth`` (H, W) and ``values`` (H, W, K), both indexed [y, x].

    ``window`` (3, 3) holds the corners' window coordinates, ``w`` (3,) their clip-space w and
    ``a`` (3, K) their attributes.
    """
    height, width = depth.shape

    # 1. Snap the corners to the subpixel grid. Drop lines and points; turn clockwise triangles
    #    counter-clockwise by swapping two corners (the same triangle, the same pixels). Then
    #    the bounding box: every pixel whose centre might be inside (a few more do no harm).
    X, Y = (np.rint(window[:, i] * SUBPIXELS).astype(np.int64) for i in (0, 1))
    area2 = edge_function(X[1], Y[1], X[2], Y[2], X[0], Y[0])
    if area2 == 0:
        return
    if area2 < 0:
        window, w, a, X, Y = (v[[0, 2, 1]] for v in (window, w, a, X, Y))

    x, y = np.meshgrid(
        np.arange(max(X.min() // SUBPIXELS, 0), min(X.max() // SUBPIXELS + 1, width)),
        np.arange(max(Y.min() // SUBPIXELS, 0), min(Y.max() // SUBPIXELS + 1, height)),
    )
    x, y = x.ravel(), y.ravel()
    centre_X, centre_Y = SUBPIXELS * x + SUBPIXELS // 2, SUBPIXELS * y + SUBPIXELS // 2

    # 2. Inside all three edges, exactly, in integers; on an edge only if the triangle owns it.
    inside = np.ones(x.shape, dtype=bool)
    for j, k in EDGES:
        e = edge_function(X[j], Y[j], X[k], Y[k], centre_X, centre_Y)
        inside &= (e > 0) | ((e == 0) & owns_edge(X[j], Y[j], X[k], Y[k]))
    x, y = x[inside], y[inside]

    # 3. The depth test. Window z is linear on the screen: z = b_0 z_0 + b_1 z_1 + b_2 z_2, with
    #    the barycentrics from the exact corners (the snapped ones decided only coverage; a
    #    sliver whose exact area is next to nothing takes the snapped ones). Then round z to
    #    DEPTH_BITS bits, as a fixed-point depth buffer does, so equal depths compare equal.
    x_w, y_w, z_w = window.T
    area2 = edge_function(x_w[1], y_w[1], x_w[2], y_w[2], x_w[0], y_w[0])
    if abs(area2) <= 1e-9 * (1.0 + np.abs(x_w).max() * np.abs(y_w).max()):
        x_w, y_w = X / SUBPIXELS, Y / SUBPIXELS
        area2 = edge_function(x_w[1], y_w[1], x_w[2], y_w[2], x_w[0], y_w[0])
    e = np.array(
        [edge_function(x_w[j], y_w[j], x_w[k], y_w[k], x + 0.5, y + 0.5) for j, k in EDGES]
    )
    b = e / area2  # (3, P): b_i = e_i / area2, and b_0 + b_1 + b_2 = 1
    z = np.rint(np.clip(b.T @ z_w, 0.0, 1.0) * 2.0**DEPTH_BITS) / 2.0**DEPTH_BITS
    closer = z < depth[y, x]
    x, y, b, z = x[closer], y[closer], b[:, closer], z[closer]
    depth[y, x] = z

    # 4. The attribute: a/w and 1/w are linear on the screen, a itself is not (unless affine).
    if mode == "perspective":
        values[y, x] = (b.T @ (a / w[:, None])) / (b.T @ (1.0 / w))[:, None]
    else:
        values[y, x] = b.T @ a


def edge_function(x0: Number, y0: Number, x1: Number, y1: Number, px: Number, py: Number) -> Number:
    """Twice the signed area of the triangle (corner 0, corner 1, p): > 0 when p is left of the
    edge from corner 0 to corner 1 (y up), 0 on its line. Exact for integers.

    Examples
    --------
    >>> edge_function(0, 0, 4, 0, 1, 2), edge_function(0, 0, 4, 0, 1, -2)   # above, below
    (8, -8)
    """
    return (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)


def owns_edge(x0: int, y0: int, x1: int, y1: int) -> bool:
    """Mesa's fill rule, for an edge of a counter-clockwise triangle from corner 0 to corner 1.

    Walking along the edges of a counter-clockwise triangle (y up), the inside is on your left.
    Walking down, your left is the screen's +x: the triangle lies right of the edge, which is
    one of its *left* edges. Walking right along a horizontal edge, your left is +y: the
    triangle lies above, and the edge is its *bottom* edge. The triangle owns the centres on
    those; its neighbour across them does not.

    Examples
    --------
    >>> owns_edge(0, 4, 0, 0), owns_edge(0, 0, 4, 0), owns_edge(4, 0, 0, 4)   # left, bottom, other
    (True, True, False)
    """
    return bool(y1 < y0 or (y1 == y0 and x1 > x0))
