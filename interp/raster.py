"""Triangles to pixels, the way OpenGL does it.

The pipeline, one function each:

1. :func:`~interp.clipping.clip_triangles`: clip against ``-w <= x, y, z <= w`` in clip space.
2. :func:`viewport`: divide by w (NDC), then map onto window coordinates ``[0, width] x [0,
   height]``, y up, depth ``(z/w + 1) / 2``.
3. Scan conversion (:func:`fragments`): on every pixel row a triangle covers a *span* of pixel
   centres between its edges; the nearest fragment per pixel wins (``GL_LESS``).
4. Interpolation (:func:`interpolate`): the attribute at each visible pixel from its screen-space
   barycentrics, affinely or perspective-correctly (see :mod:`interp.interpolate`).

Window coordinates are snapped to 1/256 pixel, as GPUs do, and the edge functions are evaluated
in exact integer arithmetic there. A fill rule decides pixel centres exactly on an edge, so two
triangles sharing an edge never both draw a pixel, and never both skip one. OpenGL leaves the
rule to the implementation; this is Mesa's: in window coordinates (y up) a triangle owns the
centres on its left edges and on its horizontal bottom edges (Direct3D's top-left rule, with y
flipped).

Images are arrays: row 0 is the *top* of the image (window y = height - 1/2).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp import _checks
from interp import interpolate as formulas
from interp.clipping import ClippedTriangles, clip_triangles

#: Window coordinates are snapped to 1/SUBPIXELS of a pixel (8 bits, like llvmpipe).
SUBPIXELS = 256
#: Interpolation modes: GLSL ``smooth``, GLSL ``noperspective``, and Quake-style spans.
MODES = ("perspective", "affine", "subdivided")
#: Most fragments handled at once; bounds memory when triangles overlap a lot.
CHUNK = 1 << 22
#: Clip coordinates larger than this are surely a mistake (and would overflow).
MAX_COORDINATE = 1e12


@dataclass(frozen=True)
class Fragments:
    """What the rasterizer decided for every pixel, before interpolating any attribute.

    All per-pixel arrays are images: shape (height, width, ...), row 0 at the top.

    Attributes
    ----------
    covered : (H, W) bool array
        Whether any triangle covers the pixel centre.
    depth : (H, W) float array
        Window-space depth ``(z/w + 1) / 2`` of the visible fragment; 1 (the cleared depth
        buffer) where nothing is drawn.
    triangle : (H, W) int array
        Index of the input triangle seen at each pixel, -1 where nothing is drawn.
    barycentric : (H, W, 3) float array
        Screen-space barycentric coordinates of the pixel centre in the visible (clipped)
        triangle; 0 where nothing is drawn.
    piece : (H, W) int array
        Index into ``clipped`` of the visible triangle, -1 where nothing is drawn.
    span : (H, W, 2) int array
        First and last pixel column the visible triangle covers on this row.
    clipped : ClippedTriangles
        The triangles after clipping.
    barycentric_dx : (T, 3) float array
        How each clipped triangle's barycentrics change from one pixel to the next in a row.
    """

    covered: np.ndarray
    depth: np.ndarray
    triangle: np.ndarray
    barycentric: np.ndarray
    piece: np.ndarray
    span: np.ndarray
    clipped: ClippedTriangles
    barycentric_dx: np.ndarray


def viewport(clip: np.ndarray, width: int, height: int) -> np.ndarray:
    """Window coordinates ``(x_w, y_w, z_w)`` of clip-space points with ``w > 0``.

    Parameters
    ----------
    clip : (..., 4) array
        Clip-space positions.
    width, height : int
        The viewport's size in pixels.

    Returns
    -------
    (..., 3) array
        ``x_w = (x/w + 1) width/2``, ``y_w = (y/w + 1) height/2`` (y up, as in OpenGL) and
        ``z_w = (z/w + 1)/2``.

    Examples
    --------
    >>> viewport(np.array([[0.0, 0.0, 0.0, 2.0], [-2.0, 2.0, 2.0, 2.0]]), 100, 50)
    array([[50. , 25. ,  0.5],
           [ 0. , 50. ,  1. ]])
    """
    ndc = clip[..., :3] / clip[..., 3:4]  # the perspective divide
    return (ndc + 1) / 2 * np.array([width, height, 1.0])


def _check_scene(
    clip: object, attributes: object, triangles: object
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    clip = _checks.float_array(clip, "clip", (None, 4))
    if clip.size and np.abs(clip).max() > MAX_COORDINATE:
        raise ValueError(f"clip must hold coordinates of magnitude at most {MAX_COORDINATE:g}")
    attributes = _checks.float_array(attributes, "attributes")
    if attributes.ndim == 1:
        attributes = attributes[:, None]
    if attributes.ndim != 2 or len(attributes) != len(clip):
        raise ValueError(
            f"attributes must have shape (N, K) with N = {len(clip)} (one row per vertex), "
            f"got {attributes.shape}"
        )
    triangles = _checks.index_array(triangles, "triangles", len(clip), (None, 3))
    return clip, attributes, triangles


def fragments(
    clip: object, attributes: object, triangles: object, width: int, height: int
) -> Fragments:
    """Clip, scan-convert and depth-test triangles; interpolate nothing yet.

    Parameters
    ----------
    clip : (N, 4) array_like
        Clip-space vertex positions ``(x, y, z, w)``.
    attributes : (N, K) array_like
        Vertex attributes (carried through clipping).
    triangles : (M, 3) array_like of int
        Vertex indices, in draw order. Both windings are drawn.
    width, height : int
        Image size in pixels, each in [1, 4096].

    Returns
    -------
    Fragments
        Coverage, depth, visible triangle and barycentrics per pixel.

    Examples
    --------
    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]   # lower-left half of the view
    >>> f = fragments(clip, np.zeros((3, 1)), [[0, 1, 2]], 4, 4)
    >>> f.covered.astype(int)    # row 0 is the top; centres on the diagonal go to the other half
    array([[0, 0, 0, 0],
           [1, 0, 0, 0],
           [1, 1, 0, 0],
           [1, 1, 1, 0]])
    """
    clip, attributes, triangles = _check_scene(clip, attributes, triangles)
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    return _fragments(clip_triangles(clip, attributes, triangles), width, height)


def _fragments(pieces: ClippedTriangles, width: int, height: int) -> Fragments:
    window = viewport(pieces.clip, width, height)
    X = np.rint(window[..., 0] * SUBPIXELS).astype(np.int64)  # snap to the subpixel grid
    Y = np.rint(window[..., 1] * SUBPIXELS).astype(np.int64)
    area2 = (X[:, 1] - X[:, 0]) * (Y[:, 2] - Y[:, 0]) - (X[:, 2] - X[:, 0]) * (Y[:, 1] - Y[:, 0])

    # Both windings are drawn: turn clockwise triangles counter-clockwise, drop degenerate ones.
    pieces, X, Y, window = (
        _take(a, area2 != 0) for a in (pieces, X, Y, window)
    )
    area2 = area2[area2 != 0]
    clockwise = area2 < 0
    swap = np.where(clockwise[:, None], [0, 2, 1], [0, 1, 2])
    pieces = _reorder(pieces, swap)
    X, Y, window = (np.take_along_axis(a, swap if a.ndim == 2 else swap[..., None], axis=1)
                    for a in (X, Y, window))
    area2 = np.abs(area2)

    edges = _Edges.of(X, Y)
    rows = _rows(pieces, Y, edges, width, height)
    depth_per_x, depth_at_row = _depth_plane(window[..., 2], edges, rows, area2)
    winner, depth = _nearest(rows, depth_per_x, depth_at_row, width, height)

    # Per visible pixel: screen-space barycentrics b_i = E_i / (2 area), exact E_i.
    covered = winner >= 0
    item = winner[covered]
    piece = rows.piece[item]
    px = np.flatnonzero(covered) % width
    E = SUBPIXELS * edges.A[piece] * px[:, None] + rows.K[item]
    b = E / area2[piece, None]

    def image(values: np.ndarray, fill: float | int) -> np.ndarray:
        out = np.full((height * width, *values.shape[1:]), fill, dtype=values.dtype)
        out[covered] = values
        return np.ascontiguousarray(out.reshape(height, width, *values.shape[1:])[::-1])

    return Fragments(
        covered=np.ascontiguousarray(covered.reshape(height, width)[::-1]),
        depth=np.ascontiguousarray(depth.reshape(height, width)[::-1]),
        triangle=image(pieces.source[piece], -1),
        barycentric=image(b, 0.0),
        piece=image(piece, -1),
        span=image(np.stack([rows.x_first[item], rows.x_last[item]], axis=1), 0),
        clipped=pieces,
        barycentric_dx=SUBPIXELS * edges.A / area2[:, None],
    )


def _take(a: np.ndarray | ClippedTriangles, keep: np.ndarray) -> np.ndarray | ClippedTriangles:
    return a.take(keep) if isinstance(a, ClippedTriangles) else a[keep]


def _reorder(pieces: ClippedTriangles, order: np.ndarray) -> ClippedTriangles:
    def per_vertex(a: np.ndarray) -> np.ndarray:
        return np.take_along_axis(a, order.reshape(*order.shape, *([1] * (a.ndim - 2))), axis=1)

    return ClippedTriangles(
        per_vertex(pieces.clip),
        per_vertex(pieces.smooth),
        per_vertex(pieces.noperspective),
        pieces.source,
    )


@dataclass(frozen=True)
class _Edges:
    """Edge functions of counter-clockwise triangles in subpixel units.

    ``E_i(X, Y) = A_i X + B_i Y + C_i`` for the edge opposite vertex i: positive inside, zero on
    the edge, and ``E_0 + E_1 + E_2 = 2 * area``. A pixel centre is inside when every
    ``E_i >= threshold_i``: 0 on left and bottom edges (they own the pixels on them), else 1.
    """

    A: np.ndarray  # (T, 3) int64
    B: np.ndarray
    C: np.ndarray
    threshold: np.ndarray

    @classmethod
    def of(cls, X: np.ndarray, Y: np.ndarray) -> _Edges:
        Xj, Yj = np.roll(X, -1, axis=1), np.roll(Y, -1, axis=1)  # edge i runs j -> k
        Xk, Yk = np.roll(X, -2, axis=1), np.roll(Y, -2, axis=1)
        A, B = Yj - Yk, Xk - Xj
        C = -(A * Xj + B * Yj)
        dx, dy = Xk - Xj, Yk - Yj  # counter-clockwise, y up: the interior is on the left
        left = dy < 0  # going down, interior to the right (+x)
        bottom = (dy == 0) & (dx > 0)  # going right, interior above
        return cls(A, B, C, np.where(left | bottom, 0, 1))


@dataclass(frozen=True)
class _Rows:
    """One item per (triangle, pixel row): the span of pixel columns it covers there."""

    piece: np.ndarray  # (R,) which triangle
    y: np.ndarray  # (R,) which row (window y, 0 at the bottom)
    x_first: np.ndarray  # (R,) first covered column
    x_last: np.ndarray  # (R,) last covered column (x_last < x_first: none)
    K: np.ndarray  # (R, 3) E_i at column 0 of the row: E_i(x) = SUBPIXELS A_i x + K_i


def _rows(pieces: ClippedTriangles, Y: np.ndarray, e: _Edges, width: int, height: int) -> _Rows:
    # Rows whose centres (y + 1/2) lie within the triangle's vertical extent.
    half = SUBPIXELS // 2
    y_low = np.maximum(-((half - Y.min(axis=1)) // SUBPIXELS), 0)  # ceil
    y_high = np.minimum((Y.max(axis=1) - half) // SUBPIXELS, height - 1)
    count = np.maximum(y_high - y_low + 1, 0)
    piece = np.repeat(np.arange(len(count)), count)
    y = y_low[piece] + _ranks(count)

    # E_i at the centre of pixel (x, y) is SUBPIXELS A_i x + K_i; solve E_i >= threshold_i for x.
    A, threshold = e.A[piece], e.threshold[piece]
    K = e.B[piece] * (SUBPIXELS * y + half)[:, None] + e.C[piece] + A * half
    step = SUBPIXELS * np.where(A != 0, np.abs(A), 1)
    from_left = np.where(A > 0, -((K - threshold) // step), 0)  # ceil((threshold - K) / step)
    to_right = np.where(A < 0, (K - threshold) // step, width - 1)
    never = np.any((A == 0) & (K < threshold), axis=1)
    x_first = np.maximum(from_left.max(axis=1), 0)
    x_last = np.where(never, -1, np.minimum(to_right.min(axis=1), width - 1))
    return _Rows(piece, y, x_first, x_last, K)


def _ranks(count: np.ndarray) -> np.ndarray:
    """``[0, 1, .., count[0]-1, 0, 1, .., count[1]-1, ...]`` without a Python loop."""
    total = int(count.sum())
    starts = np.repeat(np.cumsum(count) - count, count)
    return np.arange(total) - starts


def _depth_plane(
    z: np.ndarray, e: _Edges, rows: _Rows, area2: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Window depth is linear on the screen: ``z_w(x) = depth_at_row + depth_per_x * x``."""
    depth_per_x = SUBPIXELS * np.sum(z * e.A, axis=1) / area2  # per triangle
    depth_at_row = np.sum(z[rows.piece] * rows.K, axis=1) / area2[rows.piece]  # per row item
    return depth_per_x, depth_at_row


def _nearest(
    rows: _Rows, depth_per_x: np.ndarray, depth_at_row: np.ndarray, width: int, height: int
) -> tuple[np.ndarray, np.ndarray]:
    """Depth test ``GL_LESS`` against a buffer cleared to 1: per pixel, the row item that wins.

    Items are in draw order, so among equally near fragments the earliest one wins, as in
    OpenGL where a later fragment must be strictly nearer to replace it.
    """
    depth = np.ones(width * height)
    winner = np.full(width * height, -1, dtype=np.int64)
    length = np.maximum(rows.x_last - rows.x_first + 1, 0)
    end = np.cumsum(length)
    start = 0
    while start < len(length):
        stop = max(int(np.searchsorted(end, end[start] - length[start] + CHUNK, "right")),
                   start + 1)
        item = np.arange(start, stop).repeat(length[start:stop])
        x = rows.x_first[item] + _ranks(length[start:stop])
        pixel = rows.y[item] * width + x
        z = depth_at_row[item] + depth_per_x[rows.piece[item]] * x
        nearest = depth.copy()
        np.minimum.at(nearest, pixel, z)
        wins = (z == nearest[pixel]) & (z < depth[pixel])
        first = np.full(width * height, np.iinfo(np.int64).max)
        np.minimum.at(first, pixel[wins], item[wins])
        hit = first != np.iinfo(np.int64).max
        depth[hit], winner[hit] = nearest[hit], first[hit]
        start = stop
    return winner, depth


def interpolate(frags: Fragments, mode: str = "perspective", span: int = 16) -> np.ndarray:
    """Interpolate the clipped triangles' attributes at every visible pixel.

    Parameters
    ----------
    frags : Fragments
        From :func:`fragments`.
    mode : {"perspective", "affine", "subdivided"}
        ``"perspective"`` is GLSL ``smooth`` (OpenGL 4.6 eq. 14.9), ``"affine"`` GLSL
        ``noperspective``, ``"subdivided"`` exact every ``span`` pixels along a row and affine
        in between (Quake's span drawer used 16).
    span : int
        Pixels between exact values, for ``"subdivided"``.

    Returns
    -------
    (H, W, K) float array
        The interpolated attributes; 0 where nothing is drawn.

    Examples
    --------
    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]
    >>> f = fragments(clip, [[0.0], [1.0], [0.0]], [[0, 1, 2]], 4, 4)
    >>> interpolate(f)[3, :, 0]               # the bottom row: x = 1/8, 3/8, 5/8, not drawn
    array([0.125, 0.375, 0.625, 0.   ])
    """
    mode = _checks.choice(mode, "mode", MODES)
    span = _checks.positive_int(span, "span")
    covered = frags.covered
    piece = frags.piece[covered]
    b = frags.barycentric[covered]
    w = frags.clipped.clip[piece, :, 3]
    if mode == "affine":
        values = formulas.noperspective(b, frags.clipped.noperspective[piece])
    elif mode == "perspective":
        values = formulas.smooth(b, frags.clipped.smooth[piece], w)
    else:
        x = np.nonzero(covered)[1]
        first, last = frags.span[covered].T
        left = first + (x - first) // span * span
        right = np.minimum(left + span, last)
        db = frags.barycentric_dx[piece]
        fraction = np.where(right > left, (x - left) / np.maximum(right - left, 1), 0.0)
        values = formulas.subdivided(
            b + (left - x)[:, None] * db,
            b + (right - x)[:, None] * db,
            fraction,
            frags.clipped.smooth[piece],
            w,
        )
    out = np.zeros((*covered.shape, frags.clipped.smooth.shape[2]))
    out[covered] = values
    return out


def rasterize(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    mode: str = "perspective",
    span: int = 16,
) -> tuple[np.ndarray, np.ndarray]:
    """Draw triangles into an image of interpolated attributes, exactly as OpenGL would.

    Parameters
    ----------
    clip : (N, 4) array_like
        Clip-space vertex positions ``(x, y, z, w)``, e.g. ``(P @ V @ [x, y, z, 1])``.
    attributes : (N, K) array_like
        Vertex attributes to interpolate (colours, texture coordinates ``(u, v)``...).
    triangles : (M, 3) array_like of int
        Vertex indices, in draw order. Both windings are drawn.
    width, height : int
        Image size in pixels, each in [1, 4096].
    mode : {"perspective", "affine", "subdivided"}
        ``"perspective"``: GLSL ``smooth``, interpolate ``a/w`` and ``1/w`` and divide per pixel.
        ``"affine"``: GLSL ``noperspective``, screen-space barycentrics.
        ``"subdivided"``: exact every ``span`` pixels along a row, affine in between.
    span : int
        For ``"subdivided"``: pixels between exact values (Quake used 16).

    Returns
    -------
    values : (height, width, K) float array
        Attributes at each pixel centre; 0 where nothing is drawn. Row 0 is the top.
    covered : (height, width) bool array
        Where a triangle was drawn.

    Notes
    -----
    Triangles are clipped against the view volume in clip space, so vertices behind the camera
    are fine; pixels are sampled at their centres; where triangles overlap the nearest wins
    (depth test ``GL_LESS`` on ``z/w``); Mesa's fill rule decides centres on an edge.

    Examples
    --------
    A quad whose top edge is three times as far away as its bottom edge, filling the screen:
    the far half of the quad gets less of the screen, so the perspective-correct ``v`` climbs
    slowly at the bottom of the image and fast near the top, while the affine one climbs evenly.

    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [3, 3, 0, 3], [-3, 3, 0, 3]]
    >>> uv = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> quad = [[0, 1, 2], [0, 2, 3]]
    >>> correct, covered = rasterize(clip, uv, quad, 8, 8)
    >>> affine, _ = rasterize(clip, uv, quad, 8, 8, mode="affine")
    >>> bool(covered.all())
    True
    >>> correct[:, 0, 1].round(3)            # v in the left column, top row first
    array([0.833, 0.591, 0.423, 0.3  , 0.206, 0.132, 0.071, 0.022])
    >>> affine[:, 0, 1].round(3)
    array([0.938, 0.812, 0.688, 0.562, 0.438, 0.312, 0.188, 0.062])

    The correct column is the 1D mapping ``t_from_s`` with ``w1 = 1`` and ``w2 = 3``:

    >>> from interp.lerp import t_from_s
    >>> bool(np.allclose(correct[:, 0, 1], t_from_s(affine[:, 0, 1], 1.0, 3.0)))
    True
    """
    clip, attributes, triangles = _check_scene(clip, attributes, triangles)
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    mode = _checks.choice(mode, "mode", MODES)
    span = _checks.positive_int(span, "span")
    frags = _fragments(clip_triangles(clip, attributes, triangles), width, height)
    return interpolate(frags, mode, span), frags.covered
