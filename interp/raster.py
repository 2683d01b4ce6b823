"""Triangles to pixels, the way OpenGL does it.

The pipeline, one function each:

1. :func:`~interp.clipping.clip_triangles`: clip against ``-w <= x, y, z <= w`` in clip space.
2. :func:`viewport`: divide by w (NDC), then map onto window coordinates ``[0, width] x [0,
   height]``, y up, depth ``(z/w + 1) / 2``.
3. Scan conversion (:func:`fragments`): on every pixel row a triangle covers a *span* of pixel
   centres between its edges; the nearest fragment per pixel wins (``GL_LESS``).
4. Interpolation (:func:`interpolate`): the attribute at each visible pixel from its screen-space
   barycentrics, affinely or perspective-correctly (see :mod:`interp.barycentric`).

:func:`rasterize` does all four, the last two on the image in bands of rows (see its Notes).

Window coordinates are snapped to 1/256 pixel, as GPUs do, and the edge functions are evaluated
in exact integer arithmetic there. A fill rule decides pixel centres exactly on an edge, so two
triangles sharing an edge never both draw a pixel, and never both skip one. OpenGL leaves the
rule to the implementation; this is Mesa's: in window coordinates (y up) a triangle owns the
centres on its left edges and on its horizontal bottom edges (Direct3D's top-left rule, with y
flipped).

Images are arrays: row 0 is the *top* of the image (window y = height - 1/2).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field

import numpy as np

from interp import _checks, barycentric
from interp.clipping import ClippedTriangles, _check_scene, _clip_triangles

#: Window coordinates are snapped to 1/SUBPIXELS of a pixel (8 bits, like llvmpipe).
SUBPIXELS = 256
#: Interpolation modes: GLSL ``smooth``, GLSL ``noperspective``, and Quake-style spans.
MODES = ("perspective", "affine", "subdivided")
#: Bits of the fixed-point depth the depth test compares by default (GL's buffers have 24).
DEPTH_BITS = 40
#: Pixels depth-tested and interpolated together: a band of whole image rows (at least one).
#: Small enough that every temporary fits in the CPU's cache and is recycled by the allocator.
BAND = 1 << 14
#: Most fragments depth-tested at once: bounds memory however much the triangles overlap.
CHUNK = 1 << 22
#: Most attribute values interpolated at once: bounds memory however large the image.
VALUES_CHUNK = 1 << 20
#: Most (triangle, pixel row) pairs one image may hold: about 300 bytes each while drawing.
MAX_ROWS = 1 << 22
#: Most attribute values one image may hold (width x height x columns): 8 bytes each in the
#: result (interpolated VALUES_CHUNK at a time), beside about 100 bytes per pixel drawing it.
MAX_VALUES = 1 << 25


def rasterize(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    mode: str = "perspective",
    span: int = 16,
    depth_bits: int = DEPTH_BITS,
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
    depth_bits : int
        Bits of the fixed-point depth the depth test compares, in [16, 40]. Depths that round
        to the same number tie, and the first drawn wins. The default, 40, resolves depths
        closer than a GL depth buffer can. 24 (or less) behaves like a GL depth buffer of that
        many bits: depth rounded to fixed point from float32, as llvmpipe does, so nearly
        coplanar triangles tie where OpenGL's do (where they are not parallel to the screen,
        OpenGL's own float32 rounding can still tip a few pixels either way).

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

    To see how, read :mod:`interp.textbook` first: the same drawing the way a textbook does it,
    one triangle at a time: its bounding box, the three edge functions at every pixel centre,
    ``if z < depth[y, x]``, then ``a/w`` and ``1/w`` interpolated and divided. It is proven to
    draw exactly the same pixels as this function. This one is the same algorithm arranged for
    numpy, to run at the speed of a slider, and differs in four ways. It never tests a pixel
    that is outside: on each pixel row a triangle covers one span of columns, and the span's
    ends are solved from the edge functions by integer ceiling division. It depth-tests all
    triangles at once: each fragment's depth, in fixed point, and its draw order are packed
    into one integer key, and ``np.minimum.at`` keeps the smallest key per pixel, which is the
    nearest fragment, the first drawn among equals (``GL_LESS``). It interpolates along rows:
    ``a/w`` and ``1/w`` (or, affinely, ``a``) are planes over the screen, so on the row a
    triangle's span lies on each is a line, a value at the span's first column plus a step per
    column, and each pixel evaluates the line of the triangle that won it. And, like llvmpipe
    with its tiles, it works through the image in bands of rows, ``BAND`` pixels at a time, so
    that its temporaries stay small (within a band the fragments are depth-tested ``CHUNK`` at
    a time): memory stays bounded however much the triangles overlap and however large the
    image, and the temporaries stay in the CPU's cache and are recycled by the allocator
    instead of being handed back to the operating system and faulted in again.

    Limits: images up to 4096 x 4096, at most 16 attribute columns and width x height x
    columns at most 2**25; at most 131072 triangles, covering at most 2**22 (triangle, pixel
    row) pairs after clipping; coordinates and attributes within 1e12 in magnitude. Beyond, a
    ValueError names the argument. Peak memory is about 100 bytes per pixel (1.6 GB at 4096 x
    4096) plus 300 per (triangle, row) pair.

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
    mode = _checks.choice(mode, "mode", MODES)  # a bad mode fails before any work
    span = _checks.positive_int(span, "span")
    if mode == "subdivided":  # its exact anchors depend on each fragment's span: per fragment
        frags = fragments(clip, attributes, triangles, width, height, depth_bits)
        return interpolate(frags, mode, span), frags.covered
    scan = _checked_scan(clip, attributes, triangles, width, height, depth_bits)
    lines = _RowLines(scan, mode)
    values = np.zeros((height, width, scan.pieces.smooth.shape[2]))
    covered = np.zeros((height, width), dtype=bool)
    for rows, drawn, item in _depth_test(scan):
        covered[rows] = drawn
        lines.evaluate(item, out=values[rows])
    return values, covered


def fragments(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    depth_bits: int = DEPTH_BITS,
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
    depth_bits : int
        Bits of fixed-point depth the depth test compares, in [16, 40]; see
        :func:`rasterize`.

    Returns
    -------
    Fragments
        Coverage, depth, visible triangle and barycentrics per pixel.

    Examples
    --------
    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]   # lower-left half of the view
    >>> f = fragments(clip, np.zeros((3, 1)), [[0, 1, 2]], 4, 4)
    >>> f.covered.astype(int)   # row 0 is the top; centres on the diagonal go to the other half
    array([[0, 0, 0, 0],
           [1, 0, 0, 0],
           [1, 1, 0, 0],
           [1, 1, 1, 0]])
    """
    return _fragments(_checked_scan(clip, attributes, triangles, width, height, depth_bits))


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
    _check_fragments(frags)
    mode = _checks.choice(mode, "mode", MODES)
    span = _checks.positive_int(span, "span")
    image = np.zeros((frags.height * frags.width, frags.clipped.smooth.shape[2]))
    for chunk, (values,) in _values_in_chunks(frags, mode, (span,)):
        _scatter(image, frags.pixel[chunk], values.T)
    return image.reshape(frags.height, frags.width, -1)


def viewport(clip: object, width: int, height: int) -> np.ndarray:
    """Window coordinates ``(x_w, y_w, z_w)`` of clip-space points with ``w > 0``.

    Parameters
    ----------
    clip : (..., 4) array_like
        Clip-space positions, coordinates in [-1e12, 1e12], in front of the eye (``w > 0``)
        and with ``|x|, |y|, |z| <= 1e12 w`` (NDC within 1e12: the divide must not overflow).
    width, height : int
        The viewport's size in pixels, each in [1, 4096].

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
    clip = _checks.float_array(clip, "clip")
    if clip.ndim == 0 or clip.shape[-1] != 4:
        raise ValueError(f"clip must have shape (..., 4): (x, y, z, w) per point, got {clip.shape}")
    _checks.in_range(clip, "clip", -_checks.MAX_MAGNITUDE, _checks.MAX_MAGNITUDE)
    w = clip[..., 3:]
    if np.any(w <= 0):
        raise ValueError("clip must have w > 0 everywhere, points in front of the eye: clip first")
    if np.any(np.abs(clip[..., :3]) > _checks.MAX_MAGNITUDE * w):
        raise ValueError("clip must have |x|, |y|, |z| <= 1e12 w: beyond, the divide overflows")
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    return _viewport(clip, width, height)


def _viewport(clip: np.ndarray, width: int, height: int) -> np.ndarray:
    """``((x/w + 1) width/2, (y/w + 1) height/2, (z/w + 1)/2)``, for (..., 4) clip positions."""
    ndc = clip[..., :3] / clip[..., 3:4]  # the perspective divide
    return (ndc + 1) / 2 * np.array([width, height, 1.0])


@dataclass(frozen=True)
class Fragments:
    """What the rasterizer decided, before interpolating any attribute: one fragment per drawn
    pixel, the nearest one there.

    Per-fragment arrays have one row per drawn pixel, in image order (row 0 at the top); use
    :meth:`image` to spread one over the image.

    Attributes
    ----------
    width, height : int
        The image size.
    pixel : (P,) int array
        Flat image index ``row * width + column`` of each fragment's pixel.
    piece : (P,) int array
        Index into ``clipped`` of the triangle the fragment belongs to.
    barycentric : (3, P) float array
        Screen-space barycentric coordinates ``b0, b1, b2`` of each pixel centre in its
        triangle (vertex first: ``b0, b1, b2 = frags.barycentric``).
    clipped : ClippedTriangles
        The triangles after clipping.
    barycentric_dx, barycentric_dy : (3, T) float arrays
        How each clipped triangle's barycentrics change from one pixel to the next along a row
        (x) and down a column (y, the image's row index).
    row_item : (P,) int array
        Which row item drew each fragment. A *row item* is one (clipped triangle, pixel row)
        pair that the triangle covers: scan conversion works on these, not on single pixels.
    row_spans : (R, 2) int array
        Per row item, the first and last column the triangle covers on that row (the span;
        last < first when it covers none). ``span`` is this per fragment.
    row_depths : (R, 2) float array
        Per row item, window depth at column 0 and its step per column: depth is linear along
        a row. ``depth`` is this evaluated per fragment.
    """

    width: int
    height: int
    pixel: np.ndarray
    piece: np.ndarray
    barycentric: np.ndarray
    clipped: ClippedTriangles
    barycentric_dx: np.ndarray
    barycentric_dy: np.ndarray
    row_item: np.ndarray = field(repr=False)
    row_spans: np.ndarray = field(repr=False)
    row_depths: np.ndarray = field(repr=False)

    def __post_init__(self) -> None:  # kinds and shapes only: fragments() makes these
        _checks.positive_int(self.width, "width")
        _checks.positive_int(self.height, "height")
        if not isinstance(self.clipped, ClippedTriangles):
            raise TypeError("clipped must be the ClippedTriangles the fragments came from")

        def length(array: object) -> tuple[int]:
            return array.shape[:1] if isinstance(array, np.ndarray) and array.ndim else (-1,)

        P, T, R = length(self.pixel), len(self.clipped), length(self.row_spans)
        expected = {
            "pixel": ("iu", (*P,)),
            "piece": ("iu", (*P,)),
            "row_item": ("iu", (*P,)),
            "barycentric": ("f", (3, *P)),
            "barycentric_dx": ("f", (3, T)),
            "barycentric_dy": ("f", (3, T)),
            "row_spans": ("iu", (*R, 2)),
            "row_depths": ("f", (*R, 2)),
        }
        for name, (kinds, shape) in expected.items():
            array = getattr(self, name)
            if not (
                isinstance(array, np.ndarray) and array.dtype.kind in kinds and array.shape == shape
            ):
                raise TypeError(f"{name} must be an array of shape {shape}, as fragments() makes")

    @property
    def depth(self) -> np.ndarray:
        """(P,) float array: window-space depth ``(z/w + 1) / 2``, linear along each row."""
        at_0, step = self.row_depths[self.row_item].T
        return at_0 + step * self.column

    @property
    def span(self) -> np.ndarray:
        """(P, 2) int array: first and last column its triangle covers on the fragment's row."""
        return self.row_spans[self.row_item]

    @property
    def covered(self) -> np.ndarray:
        """(H, W) bool array: where a triangle was drawn."""
        return self.image(np.ones(len(self.pixel), dtype=bool), False)

    @property
    def column(self) -> np.ndarray:
        """(P,) int array: each fragment's pixel column."""
        return self.pixel % self.width

    @property
    def triangle(self) -> np.ndarray:
        """(P,) int array: the input triangle each fragment comes from."""
        return self.clipped.source[self.piece]

    def image(self, values: np.ndarray, fill: float | int | bool = 0) -> np.ndarray:
        """Spread per-fragment ``values`` (P, ...) over an image (H, W, ...), ``fill`` elsewhere.

        Examples
        --------
        >>> clip = [[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]]   # covers the whole view
        >>> f = fragments(clip, [[0]] * 3, [[0, 1, 2]], 2, 1)
        >>> f.image(f.depth, fill=1.0)
        array([[0.5, 0.5]])
        """
        values = np.asarray(values)
        out = np.full((self.height * self.width, *values.shape[1:]), fill, dtype=values.dtype)
        _scatter(out, self.pixel, values)
        return out.reshape(self.height, self.width, *values.shape[1:])


def fragment_values(frags: Fragments, mode: str = "perspective", span: int = 16) -> np.ndarray:
    """Like :func:`interpolate`, but per fragment: a (K, P) array, column j at ``frags.pixel[j]``.

    Examples
    --------
    >>> f = fragments([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]], [[0.0], [4.0], [0.0]],
    ...               [[0, 1, 2]], 2, 1)
    >>> fragment_values(f)
    array([[0.5, 1.5]])
    """
    return fragment_values_per_span(frags, (span,), mode)[0]


def fragment_values_per_span(
    frags: Fragments, spans: tuple[int, ...], mode: str = "subdivided"
) -> list[np.ndarray]:
    """:func:`fragment_values` for several span lengths at once: one (K, P) array per span.

    The same values as calling it for each span; what does not depend on the span (gathering
    each fragment's vertices, where its row's span starts) is done once. With a mode other
    than ``"subdivided"`` the spans do not matter: one array per span, all the same.

    Examples
    --------
    One row of three pixels: spans of 1 pixel are exact everywhere; a span of 5 is exact at the
    row's ends and affine in between:

    >>> f = fragments([[-1, -1, 0, 1], [3, -3, 0, 3], [-1, 1, 0, 1]], [[0.0], [4.0], [0.0]],
    ...               [[0, 1, 2]], 6, 1)
    >>> [v.round(2).tolist() for v in fragment_values_per_span(f, (1, 5))]
    [[[0.12, 0.4, 0.77]], [[0.12, 0.44, 0.77]]]
    """
    _check_fragments(frags)
    mode = _checks.choice(mode, "mode", MODES)
    if isinstance(spans, (str, bytes)) or not isinstance(spans, Iterable):
        raise TypeError(
            f"spans must be a sequence of span lengths (positive integers), got "
            f"{type(spans).__name__}"
        )
    spans = tuple(_checks.positive_int(span, "span") for span in spans)
    if not spans:
        raise ValueError("spans must hold at least one span length, got none")
    shape = (frags.clipped.smooth.shape[2], len(frags.pixel))
    if mode != "subdivided":
        values = np.empty(shape)
        for chunk, (block,) in _values_in_chunks(frags, mode):
            values[:, chunk] = block
        return [values] * len(spans)
    per_span = [np.empty(shape) for _ in spans]
    for chunk, blocks in _values_in_chunks(frags, mode, spans):
        for values, block in zip(per_span, blocks, strict=True):
            values[:, chunk] = block
    return per_span


def fragment_footprints(
    frags: Fragments, mode: str = "perspective", values: np.ndarray | None = None
) -> np.ndarray:
    """How much each attribute changes across each fragment's pixel: ``|da/dx| + |da/dy|``.

    The exact screen-space derivatives of the interpolated attribute (what GLSL's ``fwidth``
    estimates from neighbouring pixels), used to filter textures. ``"subdivided"`` is treated
    as ``"perspective"``.

    Parameters
    ----------
    frags : Fragments
    mode : {"perspective", "affine", "subdivided"}
    values : (K, P) array, optional
        ``fragment_values(frags, mode)``, if already at hand.

    Returns
    -------
    (K, P) float array

    Examples
    --------
    >>> f = fragments([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]], [[0.0], [4.0], [0.0]],
    ...               [[0, 1, 2]], 2, 1)
    >>> fragment_footprints(f, "affine")     # 4 units over 4 pixels along x
    array([[1., 1.]])
    """
    _check_fragments(frags)
    mode = _checks.choice(mode, "mode", MODES)
    pieces, piece = frags.clipped, frags.piece
    db = np.stack([frags.barycentric_dx, frags.barycentric_dy], axis=1)  # (3, 2, T)
    if mode == "affine":  # a is linear on the screen: constant steps on each triangle
        da = np.einsum("idt,tik->dkt", db, pieces.noperspective)  # (2, K, T)
        return np.take(np.abs(da).sum(axis=0), piece, axis=1)

    one_over_w = _one_over_w(pieces)  # (T, 3)
    a_over_w = pieces.smooth * one_over_w[..., None]
    dN = np.einsum("idt,tik->dkt", db, a_over_w)  # steps of N = lerp(a/w), (2, K, T)
    dD = np.einsum("idt,ti->dt", db, one_over_w)  # steps of D = lerp(1/w), (2, T)
    if values is None:
        values = fragment_values(frags, "perspective")
    D = barycentric.lerp(frags.barycentric, np.take(one_over_w.T, piece, axis=1))
    footprint = np.zeros_like(values)
    for d in range(2):  # x, then y
        da = barycentric.smooth_derivative(
            values, D, np.take(dN[d], piece, axis=1), np.take(dD[d], piece)
        )
        footprint += np.abs(da)
    return footprint


def _scatter(out: np.ndarray, index: np.ndarray, values: np.ndarray) -> None:
    """``out[index] = values``, for (N, ...) ``out`` and (P, ...) ``values``, one column at a
    time: numpy scatters a column several times faster than rows of a few values each."""
    columns = int(np.prod(out.shape[1:]))
    out, values = out.reshape(len(out), columns), values.reshape(len(values), columns)
    for k in range(columns):
        out[:, k][index] = values[:, k]


def _check_fragments(frags: object) -> None:
    if not isinstance(frags, Fragments):
        raise TypeError(
            f"frags must be the Fragments that interp.fragments returns, got {type(frags).__name__}"
        )


# Scan conversion: triangles to fragments, one span of pixels per (triangle, row)
# -------------------------------------------------------------------------------


def _checked_scan(
    clip: object, attributes: object, triangles: object, width: int, height: int, depth_bits: int
) -> _Scan:
    """Check :func:`fragments`' (and :func:`rasterize`'s) arguments, clip and scan-convert."""
    clip, attributes, triangles = _check_scene(clip, attributes, triangles)
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    depth_bits = _checks.integer_in(depth_bits, "depth_bits", 16, DEPTH_BITS)
    pixels_times_columns = width * height * attributes.shape[1]
    if pixels_times_columns > MAX_VALUES:
        raise ValueError(
            f"attributes has {attributes.shape[1]} columns: at {width} x {height} pixels at most "
            f"{MAX_VALUES // (width * height)} fit (width x height x columns <= {MAX_VALUES:,})"
        )
    return _scan(_clip_triangles(clip, attributes, triangles), width, height, depth_bits)


@dataclass(frozen=True)
class _Scan:
    """Everything before the depth test: the spans each clipped triangle covers, row by row, and
    its barycentrics and depth as planes over the screen."""

    pieces: ClippedTriangles  # (T) counter-clockwise, none degenerate
    width: int
    height: int
    depth_bits: int
    rows: _Rows  # (R) one item per (triangle, pixel row): the span it covers there
    b_at_0: np.ndarray  # (3, R) barycentrics at column 0 of each row item
    b_dx: np.ndarray  # (3, T) their step per column
    b_dy: np.ndarray  # (3, T) their step per image row (downwards)
    z_at_0: np.ndarray  # (R,) window depth at column 0 of each row item
    z_dx: np.ndarray  # (R,) its step per column


def _scan(pieces: ClippedTriangles, width: int, height: int, depth_bits: int) -> _Scan:
    """Snap, orient and scan-convert the clipped triangles: their row items and planes."""
    window = _viewport(pieces.clip, width, height)
    X, Y = _snap(window)
    area2 = _twice_area(X, Y)

    # Both windings are drawn: turn clockwise triangles counter-clockwise, drop degenerate ones.
    pieces, X, Y, window = (_take(a, area2 != 0) for a in (pieces, X, Y, window))
    area2 = area2[area2 != 0]
    clockwise = area2 < 0
    if clockwise.any():  # (a mesh's triangles often all wind one way: then nothing to swap)
        swap = np.where(clockwise[:, None], [0, 2, 1], [0, 1, 2])
        pieces = _reorder(pieces, swap)
        X, Y, window = (
            np.take_along_axis(a, swap if a.ndim == 2 else swap[..., None], axis=1)
            for a in (X, Y, window)
        )
        area2 = np.abs(area2)

    edges = _Edges.of(X, Y)
    rows = _rows(Y, edges, width, height)

    # Coverage used the snapped positions; interpolation uses the exact ones, like llvmpipe.
    # Along a row everything is linear in the column x: per row item, a value at x = 0 and a
    # step per pixel. Barycentrics b_i = e_i / (2 area); window depth z_w = sum(b_i z_i).
    b_at_0, b_dx, b_dy = _barycentric_planes(window, rows, X, Y, area2)
    z = window[..., 2].T if depth_bits > 24 else _float32_window_depth(pieces.clip).T  # (3, T)
    z_at_0 = np.sum(b_at_0 * z[:, rows.piece], axis=0)
    z_dx = np.sum(b_dx * z, axis=0)[rows.piece]
    return _Scan(pieces, width, height, depth_bits, rows, b_at_0, b_dx, b_dy, z_at_0, z_dx)


def _fragments(scan: _Scan) -> Fragments:
    """The fragments that pass the depth test, in image order: what :func:`fragments` returns."""
    width, rows = scan.width, scan.rows
    pixels, items = [np.zeros(0, dtype=np.int64)], [np.zeros(0, dtype=np.int64)]
    for band, drawn, item in _depth_test(scan):
        in_band = np.flatnonzero(drawn)
        pixels.append(band.start * width + in_band)
        items.append(item.ravel()[in_band])
    pixel, item = np.concatenate(pixels), np.concatenate(items)
    x = pixel % width
    line = np.take(np.concatenate([scan.b_at_0, scan.b_dx[:, rows.piece]]), item, axis=1)
    return Fragments(
        width=width,
        height=scan.height,
        pixel=pixel,
        piece=rows.piece[item],
        barycentric=line[0:3] + line[3:6] * x,  # one gather, then b = b_at_0 + b_dx x
        clipped=scan.pieces,
        barycentric_dx=scan.b_dx,
        barycentric_dy=scan.b_dy,
        row_item=item,
        row_spans=np.stack([rows.x_first, rows.x_last], axis=1),
        row_depths=np.stack([scan.z_at_0, scan.z_dx], axis=1),
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
        A, B, C = _edge_functions(X, Y)
        dx, dy = B, -A  # the direction of edge i, from vertex j to k
        # Counter-clockwise with y up, the interior lies to the left of every edge.
        left = dy < 0  # going down, interior to the right (+x)
        bottom = (dy == 0) & (dx > 0)  # going right, interior above
        return cls(A, B, C, np.where(left | bottom, 0, 1))


def _edge_functions(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(A, B, C)``, each (T, 3): ``e_i(x, y) = A_i x + B_i y + C_i`` is zero on the edge
    opposite vertex i (from vertex j = i + 1 to k = i + 2) and equals twice the area at vertex i.
    """
    xj, yj = np.roll(x, -1, axis=1), np.roll(y, -1, axis=1)
    xk, yk = np.roll(x, -2, axis=1), np.roll(y, -2, axis=1)
    A, B = yj - yk, xk - xj
    return A, B, -(A * xj + B * yj)


def _snap(window: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Window positions (..., >= 2) snapped to the subpixel grid: integer X and Y."""
    X = np.rint(window[..., 0] * SUBPIXELS).astype(np.int64)
    Y = np.rint(window[..., 1] * SUBPIXELS).astype(np.int64)
    return X, Y


def drawn(clip: np.ndarray, width: int, height: int) -> np.ndarray:
    """Which clipped triangles the rasterizer draws at all: those whose corners, snapped to
    the subpixel grid, are not in one line (a triangle seen edge-on has no area to cover).

    Parameters
    ----------
    clip : (T, 3, 4) array
        Clip-space corners of triangles already clipped (every ``w > 0``).
    width, height : int
        The image size in pixels.

    Returns
    -------
    (T,) bool array

    Examples
    --------
    >>> flat = np.array([[[-1, 0, 0, 1], [1, 0, 0, 1], [0, 0, 0, 1]]], float)  # one line
    >>> drawn(np.concatenate([flat, flat + [[0, 0.5, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]]), 4, 4)
    array([False,  True])
    """
    return _twice_area(*_snap(_viewport(clip, width, height))) != 0


def _twice_area(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Twice the signed area of each triangle (T, 3): positive when counter-clockwise."""
    return (x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) - (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0])


@dataclass(frozen=True)
class _Rows:
    """One item per (triangle, pixel row): the span of pixel columns it covers there."""

    piece: np.ndarray  # (R,) which triangle
    y: np.ndarray  # (R,) which row (window y, 0 at the bottom)
    x_first: np.ndarray  # (R,) first covered column
    x_last: np.ndarray  # (R,) last covered column (x_last < x_first: none)


def _rows(Y: np.ndarray, e: _Edges, width: int, height: int) -> _Rows:
    """The span each triangle covers on each pixel row it touches, by solving its edge functions
    for the first and last inside column: no pixel is tested one by one."""
    # Rows whose centres (y + 1/2, in subpixels SUBPIXELS y + half) lie in the vertical extent.
    half = SUBPIXELS // 2
    y_low = np.maximum(_ceil_div(Y.min(axis=1) - half, SUBPIXELS), 0)
    y_high = np.minimum((Y.max(axis=1) - half) // SUBPIXELS, height - 1)
    count = np.maximum(y_high - y_low + 1, 0)
    if count.sum() > MAX_ROWS:
        raise ValueError(
            f"triangles cover {count.sum():,} (triangle, pixel row) pairs after clipping; one "
            f"image holds at most {MAX_ROWS:,} (about 1.2 GB while drawing): draw fewer or "
            "smaller triangles, or a smaller image"
        )
    piece = np.repeat(np.arange(len(count)), count)
    y = y_low[piece] + _ranks(count)

    # At the centre of pixel (x, y), E_i = SUBPIXELS A_i x + K_i: linear in x, so the inside
    # test E_i >= threshold_i holds on one side of a column. For A_i > 0 it holds from column
    # ceil((threshold_i - K_i) / (SUBPIXELS A_i)) on; for A_i < 0 up to column
    # floor((K_i - threshold_i) / (SUBPIXELS |A_i|)); for A_i = 0 on the whole row or nowhere.
    # Integers throughout, so the fill rule is exact. Each is (3, R), edge by edge: numpy
    # reduces over the three edges much faster that way round than along a (R, 3) array's rows.
    A, B, C, threshold = (_per_row_item(a, piece) for a in (e.A, e.B, e.C, e.threshold))
    K = B * (SUBPIXELS * y + half) + C + A * half
    step = SUBPIXELS * np.where(A != 0, np.abs(A), 1)
    from_left = np.where(A > 0, _ceil_div(threshold - K, step), 0)
    to_right = np.where(A < 0, (K - threshold) // step, width - 1)
    never = np.any((A == 0) & (K < threshold), axis=0)
    x_first = np.maximum(from_left.max(axis=0), 0)
    x_last = np.where(never, -1, np.minimum(to_right.min(axis=0), width - 1))
    return _Rows(piece, y, x_first, x_last)


def _per_row_item(per_triangle: np.ndarray, piece: np.ndarray) -> np.ndarray:
    """A (T, 3) array's rows for each row item's triangle, edge by edge: (3, R)."""
    return np.take(per_triangle.T, piece, axis=1)


def _ceil_div(a: np.ndarray, b: np.ndarray | int) -> np.ndarray:
    """``ceil(a / b)`` for integers, b > 0, exactly (no float): ``-(-a // b)``."""
    return -(-a // b)


def _ranks(count: np.ndarray) -> np.ndarray:
    """``[0, 1, .., count[0]-1, 0, 1, .., count[1]-1, ...]`` without a Python loop."""
    total = int(count.sum())
    starts = np.repeat(np.cumsum(count) - count, count)
    return np.arange(total) - starts


def _barycentric_planes(
    window: np.ndarray, rows: _Rows, X: np.ndarray, Y: np.ndarray, area2: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Screen-space barycentrics as planes: at column 0 of each row item, and per pixel step.

    Returns ``b_at_0`` (3, R), ``b_dx`` (3, T) and ``b_dy`` (3, T), the last per image row
    (downwards). From the exact window positions; where those are degenerate but the snapped
    ones are not, from the snapped ones.
    """
    x, y = window[..., 0], window[..., 1]
    exact_area2 = _twice_area(x, y)
    usable = np.abs(exact_area2) > 1e-9 * (1.0 + np.abs(x).max(axis=1) * np.abs(y).max(axis=1))
    x = np.where(usable[:, None], x, X / SUBPIXELS)
    y = np.where(usable[:, None], y, Y / SUBPIXELS)
    area2 = np.where(usable, exact_area2, area2 / SUBPIXELS**2)[:, None]
    a, b, c = (coefficient / area2 for coefficient in _edge_functions(x, y))  # b_i = a x + b y + c
    # At the centre of column 0 of each row item's row: (x, y) = (1/2, y + 1/2).
    at_0 = (
        _per_row_item(a, rows.piece) * 0.5
        + _per_row_item(b, rows.piece) * (rows.y + 0.5)
        + _per_row_item(c, rows.piece)
    )
    return at_0, a.T, -b.T  # image rows go down, window y goes up


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


# The depth test: the nearest fragment per pixel
# ----------------------------------------------


def _depth_test(scan: _Scan) -> Iterator[tuple[slice, np.ndarray, np.ndarray]]:
    """Depth test ``GL_LESS`` against a buffer cleared to 1: the row item that wins each pixel.

    What a textbook writes per fragment, ``if z < depth[y, x]: depth[y, x] = z; drawn[y, x] =
    item``, for all fragments at once. Each fragment's key packs its depth, rounded to
    ``depth_bits``-bit fixed point (rounding keeps equal depths equal despite float rounding),
    above its row item's index, which grows in draw order. The smallest key per pixel
    (``np.minimum.at``) is then the nearest fragment, and among equally near ones the first
    drawn: as in OpenGL, where a later fragment must be strictly nearer to replace an earlier
    one.

    The image is tested in bands of whole rows, about BAND pixels each, top to bottom: each
    band only against the row items on its rows, and their fragments CHUNK at a time. Yields,
    for every band something may be drawn on, its image rows (a slice), where something was
    drawn ((rows, width) bool), and the row item that won each pixel ((rows, width) int; R, one
    past the last row item, where nothing was).
    """
    rows, width, height = scan.rows, scan.width, scan.height
    none = len(rows.piece)  # the row item R: nothing drawn
    item_bits = max(none.bit_length(), 1)  # 0 to R fit: at most 23, see MAX_ROWS
    depth_bits = min(scan.depth_bits, 62 - item_bits)  # so 40 bits may become 39
    # The cleared buffer holds depth 1, where nothing passes, and row item R. As a key: just
    # below every fragment at depth 1 and above every nearer one, ((1 - one step) << bits) | R.
    cleared = ((int(_fixed_point(np.array(1.0), depth_bits)) - 1) << item_bits) | none

    length = np.maximum(rows.x_last - rows.x_first + 1, 0)
    image_row = height - 1 - rows.y  # row 0 at the top
    band_rows = max(BAND // width, 1)
    band = image_row // band_rows
    by_band = np.argsort(band, kind="stable")  # the row items, band by band
    band_ends = np.searchsorted(band[by_band], np.arange(1, _ceil_div(height, band_rows)))
    for top, items in zip(range(0, height, band_rows), np.split(by_band, band_ends), strict=True):
        if len(items) == 0:
            continue
        band_height = min(band_rows, height - top)
        keys = np.full(band_height * width, cleared, dtype=np.int64)
        n = length[items]
        first_fragment = np.cumsum(n) - n
        start = 0
        while start < len(n):  # in chunks of about CHUNK fragments, to bound memory
            stop = int(np.searchsorted(first_fragment, first_fragment[start] + CHUNK))
            stop = max(stop, start + 1)
            chunk, count = items[start:stop], n[start:stop]
            item = np.repeat(chunk, count)
            shift = first_fragment[start:stop] - first_fragment[start] - rows.x_first[chunk]
            x = np.arange(item.size) - np.repeat(shift, count)
            z = np.repeat(scan.z_at_0[chunk], count) + np.repeat(scan.z_dx[chunk], count) * x
            depth = _fixed_point(z, depth_bits)
            pixel = np.repeat((image_row[chunk] - top) * width, count) + x  # in the band
            np.minimum.at(keys, pixel, (depth << item_bits) | item)
            start = stop
        keys = keys.reshape(band_height, width)
        yield slice(top, top + band_height), keys < cleared, keys & ((1 << item_bits) - 1)


def _fixed_point(z: np.ndarray, bits: int) -> np.ndarray:
    """Window depth z in [0, 1] as an integer: ``round(z 2**bits)`` (interp's own depth).

    Up to 24 bits, like a GL depth buffer of that many bits, and as llvmpipe computes it:
    ``round(z (2**bits - 1))`` in float32, from z as a float32.
    """
    z = np.clip(z, 0.0, 1.0)
    if bits <= 24:
        return np.rint(z.astype(np.float32) * np.float32((1 << bits) - 1)).astype(np.int64)
    return np.rint(z * float(1 << bits)).astype(np.int64)


def _float32_window_depth(clip: np.ndarray) -> np.ndarray:
    """Window depth of each vertex (T, 3) as a GL pipeline computes it: NDC z as a float32,
    then ``z * 0.5 + 0.5`` in float32. For a GL-sized depth buffer, whose ties it decides."""
    half = np.float32(0.5)
    ndc = (clip[..., 2] / clip[..., 3]).astype(np.float32)
    return (ndc * half + half).astype(np.float64)


# Interpolation: what each vertex hands on
# ----------------------------------------


def _per_fragment(per_vertex: np.ndarray, piece: np.ndarray) -> np.ndarray:
    """Gather (T, 3, K) per-vertex values for each fragment as (3, K, P)."""
    return np.take(np.moveaxis(per_vertex, 0, 2), piece, axis=2)


def _one_over_w(pieces: ClippedTriangles) -> np.ndarray:
    """``1/w`` of each vertex (T, 3), times a number per triangle that keeps it in (0, 1].

    Perspective-correct interpolation is homogeneous in 1/w: ``lerp(a/w) / lerp(1/w)`` does not
    change when every ``1/w`` of a triangle is multiplied by the same number. Multiplying by the
    triangle's smallest w gives ``w_min / w`` in (0, 1]: no overflow, even for a vertex at w =
    1e-310. (Floored at 2**-1000, which changes nothing unless one vertex is 1e300 times
    nearer the eye than another.)
    """
    w = pieces.clip[:, :, 3]
    return np.maximum(w.min(axis=1, keepdims=True) / w, 2.0**-1000)


def _a_over_w_and_one_over_w(pieces: ClippedTriangles) -> np.ndarray:
    """What each vertex hands on for perspective-correct interpolation: a/w and 1/w (scaled),
    as one (T, 3, K + 1) array, so that each fragment gathers both at once."""
    one_over_w = _one_over_w(pieces)
    return np.concatenate([pieces.smooth * one_over_w[..., None], one_over_w[..., None]], 2)


class _RowLines:
    """What :func:`rasterize` interpolates, as a line along each row item.

    ``a/w`` and ``1/w`` (perspective) or ``a`` (affine) are planes over the screen: along the
    row of a row item, each is a line, its value at the span's first column plus a step per
    column. The value is a lerp of the vertices' values with the barycentrics there, the step
    (the same for the whole triangle) one with the barycentrics' steps. Starting from the
    span's first column rather than column 0 keeps the arithmetic as exact as the barycentrics.

    One more row item, R, on one more triangle, T, is for pixels nothing was drawn on: its
    lines are 0 (and 1/w = 1), so that those pixels come out 0 without a mask.
    """

    def __init__(self, scan: _Scan, mode: str) -> None:
        rows, pieces = scan.rows, scan.pieces
        self.divide = mode == "perspective"  # a = (a/w) / (1/w)
        # (T, 3, K'): K' = K attributes, or K a/w and then 1/w
        per_vertex = _a_over_w_and_one_over_w(pieces) if self.divide else pieces.noperspective
        columns, R = per_vertex.shape[2], len(rows.piece)
        self.piece = np.append(rows.piece, len(pieces))  # (R + 1,)
        self.first = np.append(rows.x_first, 0).astype(np.float64)  # (R + 1,)
        self.at_first = np.zeros((columns, R + 1))
        if self.divide:
            self.at_first[-1, R] = 1.0  # 1/w where nothing was drawn: 0 / 1 = 0
        step = barycentric.lerp(scan.b_dx, np.moveaxis(per_vertex, 0, 2))  # (K', T)
        self.step = np.hstack([step, np.zeros((columns, 1))])  # (K', T + 1)
        n = max(VALUES_CHUNK // max(columns, 1), 1)
        for items in (slice(i, min(i + n, R)) for i in range(0, R, n)):  # to bound memory
            piece = rows.piece[items]
            b_first = scan.b_at_0[:, items] + scan.b_dx[:, piece] * rows.x_first[items]
            self.at_first[:, items] = barycentric.lerp(b_first, _per_fragment(per_vertex, piece))

    def evaluate(self, item: np.ndarray, out: np.ndarray) -> None:
        """Into ``out`` (rows, width, K): the attributes at each pixel of a band of image rows,
        from the line of the row item that won it (``item``, (rows, width))."""
        piece = self.piece.take(item)
        x = np.arange(out.shape[1]) - self.first.take(item)  # columns from the span's first

        def along_row(k: int) -> np.ndarray:  # a/w, 1/w or a at each pixel
            return self.at_first[k].take(item) + self.step[k].take(piece) * x

        if not self.divide:
            for k in range(out.shape[2]):
                out[..., k] = along_row(k)
            return
        one_over_w = along_row(-1)
        for k in range(out.shape[2]):
            out[..., k] = along_row(k) / one_over_w  # the per-pixel divide


def _values_in_chunks(
    frags: Fragments, mode: str, spans: tuple[int, ...] = (16,)
) -> Iterator[tuple[slice, list[np.ndarray]]]:
    """The interpolated attributes, (K, n) for n fragments at a time: ``(fragments, values)``,
    ``values`` a list with one array per span length of ``spans`` ("subdivided"), else one.

    In chunks of about VALUES_CHUNK values, so that the per-fragment gathers and temporaries
    (several times the result) stay bounded however large the image. What does not depend on
    the span length (the gathers, where each row's span starts) is done once for all of them.
    """
    pieces = frags.clipped
    per_vertex = pieces.noperspective if mode == "affine" else _a_over_w_and_one_over_w(pieces)
    step = max(VALUES_CHUNK // max(per_vertex.shape[2] * len(spans), 1), 1)
    for start in range(0, len(frags.pixel), step):
        chunk = slice(start, start + step)
        piece, b = frags.piece[chunk], frags.barycentric[:, chunk]
        gathered = _per_fragment(per_vertex, piece)  # (3, K or K + 1, n): one gather
        if mode == "affine":
            yield chunk, [barycentric.noperspective(b, gathered)]
            continue
        a_over_w, one_over_w = gathered[:, :-1], gathered[:, -1]
        if mode == "perspective":
            yield chunk, [barycentric.smooth(b, a_over_w, one_over_w)]
            continue
        # Subdivided: exact at anchors every span pixels from the span's first column.
        x = frags.pixel[chunk] % frags.width
        first, last = frags.row_spans[frags.row_item[chunk]].T
        db = np.take(frags.barycentric_dx, piece, axis=1)
        blocks = []
        for span in spans:
            left = first + (x - first) // span * span
            right = np.minimum(left + span, last)
            fraction = np.where(right > left, (x - left) / np.maximum(right - left, 1), 0.0)
            blocks.append(
                barycentric.subdivided(
                    b + (left - x) * db, b + (right - x) * db, fraction, a_over_w, one_over_w
                )
            )
        yield chunk, blocks
