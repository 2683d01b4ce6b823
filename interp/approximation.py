"""How renderers before per-pixel division approximated it, and what it cost them.

Two remedies for affine texture mapping, measured on the same ground plane:

- spans (Quake): exact every N pixels along a row, affine between: about one divide per N
  pixels;
- tessellation (PlayStation-era): cut the plane into more, smaller triangles and draw them
  affinely: one divide per vertex, no divides per pixel.

Error is the mean distance, in texels, between the approximate and the exact ``(u, v)``.
Both are measured on the pixels the plane covers, drawn as one quad.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from interp import _checks
from interp.barycentric import _screen_weights, lerp
from interp.camera import Camera
from interp.raster import Fragments, fragment_values, fragment_values_per_span, fragments
from interp.scenes import LESSON_SIZE, Scene, ground_plane
from interp.texture import _texel_error

#: The settings the lesson compares.
SPANS = (1, 2, 4, 8, 16, 32, 64)
QUADS = (1, 2, 4, 8, 16, 32)
#: A mean error below this many texels is rounding: the method is exact there (spans of an
#: unrolled camera, along rows of constant depth, err by about 1e-16).
EXACT = 1e-9


@dataclass(frozen=True)
class Costs:
    """For each setting: divides per drawn pixel and mean error in texels."""

    setting: np.ndarray
    divides_per_pixel: np.ndarray
    mean_error: np.ndarray


def _distinct(ids: np.ndarray, size: int) -> np.ndarray:
    """The distinct values among ``ids`` (integers in [0, size)), sorted: ``np.unique``, but
    counted rather than hashed (25 times faster for a frame's fragments, ~1.7 ms each).

    Examples
    --------
    >>> _distinct(np.array([3, 1, 3, 0]), 5).tolist()
    [0, 1, 3]
    """
    return np.flatnonzero(np.bincount(ids, minlength=size))


@functools.lru_cache(maxsize=4)
def _drawn(
    camera: Camera, width: int, height: int, quads: int
) -> tuple[Scene, Fragments, np.ndarray]:
    """The ground plane cut into ``quads`` x ``quads`` quads, its fragments and their exact
    ``(u, v)``: ``(scene, fragments, exact)``. Kept for the last few, as :func:`span_costs`
    and :func:`tessellation_costs` both draw the plane of one quad for a camera (shared:
    not to be changed).

    Examples
    --------
    >>> camera = Camera(height=1, pitch=25).fitted(8, 6)
    >>> _drawn(camera, 8, 6, 1) is _drawn(camera, 8, 6, 1)
    True
    """
    scene = ground_plane(camera, LESSON_SIZE, quads)
    frags = fragments(scene.clip, scene.uv, scene.triangles, width, height)
    return scene, frags, fragment_values(frags, "perspective")


def _mean_texel_error(approximate: np.ndarray, exact: np.ndarray, frequency: float) -> float:
    return float(np.mean(_texel_error(approximate, exact, frequency))) if exact.size else 0.0


def span_costs(
    camera: Camera,
    width: int = 256,
    height: int = 192,
    frequency: float = 8,
    spans: tuple[int, ...] = SPANS,
    quads: int = 1,
) -> Costs:
    """Quake-style spans: error and divides per pixel for each span length.

    Each span starts with one exact (divided) pixel, so a row of n pixels of a triangle costs
    ``ceil(n / N) + 1`` divides (the +1 closes the last span).

    Examples
    --------
    >>> costs = span_costs(Camera(height=1, pitch=25), 64, 48, spans=(1, 16))
    >>> float(costs.mean_error[0])       # exact at every pixel
    0.0
    >>> bool(costs.divides_per_pixel[1] < 0.25)
    True
    """
    camera = camera.fitted(width, height)
    _, frags, exact = _drawn(camera, width, height, _checks.positive_int(quads, "quads", 256))
    pixels = max(len(frags.pixel), 1)
    rows = frags.row_spans[_distinct(frags.row_item, len(frags.row_spans))]
    lengths = rows[:, 1] - rows[:, 0] + 1
    spans = tuple(_checks.positive_int(n, "spans") for n in spans)
    divides, errors = [], []
    for n, values in zip(spans, fragment_values_per_span(frags, spans), strict=True):
        errors.append(_mean_texel_error(values, exact, frequency))
        divides.append(float(np.sum(np.minimum(-(-lengths // n) + 1, lengths))) / pixels)
    return Costs(np.array(spans), np.array(divides), np.array(errors))


def tessellation_costs(
    camera: Camera,
    width: int = 256,
    height: int = 192,
    frequency: float = 8,
    quads: tuple[int, ...] = QUADS,
) -> Costs:
    """PlayStation-style tessellation: error and divides per pixel for each grid.

    Affine interpolation needs no divide per pixel, only the perspective divide of each visible
    vertex, so divides per pixel is (vertices drawn) / (pixels drawn). What each pixel shows
    is worked out from the one drawing of the plane (``_affine_on_quads``), not drawn again
    for every grid.

    Examples
    --------
    >>> costs = tessellation_costs(Camera(height=1, pitch=25), 64, 48, quads=(1, 8))
    >>> bool(costs.mean_error[1] < costs.mean_error[0])
    True
    """
    camera = camera.fitted(width, height)
    plane, frags, exact = _drawn(camera, width, height, 1)
    divides, errors = [], []
    for n in quads:
        scene = ground_plane(camera, LESSON_SIZE, _checks.positive_int(n, "quads", 256))
        affine, triangle = _affine_on_quads(exact, plane.clip[:3, 3], n)
        errors.append(_mean_texel_error(affine, exact, frequency))
        drawn = _distinct(triangle, len(scene.triangles))
        visible = _distinct(scene.triangles[drawn].ravel(), len(scene.clip))
        divides.append(len(visible) / max(len(frags.pixel), 1))
    return Costs(np.array(quads), np.array(divides), np.array(errors))


def _affine_on_quads(exact: np.ndarray, w: np.ndarray, quads: int) -> tuple[np.ndarray, np.ndarray]:
    """What the ground plane cut into ``quads`` x ``quads`` quads, drawn affinely, shows at
    pixels whose exact ``(u, v)`` is ``exact``: ``(affine, triangle)``, the affine ``(u, v)``
    and which of :func:`~interp.scenes.ground_plane`'s triangles covers each pixel.

    No quad is drawn. A pixel's exact ``(u, v)`` is the point of the plane it shows, so it
    names the small triangle the pixel falls in (a projection keeps which side of a line a
    point is on), and that point's weights λ for the triangle's corners: the plane is linear
    in ``(u, v)``, so λ are the barycentrics of ``(u, v)`` among the corners' ``(u, v)``, the
    perspective-correct weights. Affine interpolation weights the corners by the screen-space
    barycentrics b instead, ``b_i = λ_i w_i / Σ_j λ_j w_j``. The smaller the triangle, the
    less w varies across it, and the nearer b is to λ. The rasterizer drawing the quads gives
    the same values (to its snapping of corners to 1/256 of a pixel, which can give a pixel
    on an edge to the triangle beside it).

    Parameters
    ----------
    exact : (2, P) array
        The exact ``(u, v)`` of P pixels of the plane (in [0, 1], to rounding).
    w : (3,) array
        The plane's clip-space w at ``(u, v)`` = (0, 0), (1, 0) and (0, 1); it is linear in
        ``(u, v)``.
    quads : int
        Quads per side.

    Returns
    -------
    affine : (2, P) array
    triangle : (P,) int array

    Examples
    --------
    Where w grows along u (the plane's far side is at u = 1), affine interpolation runs ahead
    of the exact u, the less so the smaller the triangles:

    >>> exact = np.array([[0.3], [0.5]])
    >>> w = np.array([1.0, 3.0, 1.0])
    >>> [float(_affine_on_quads(exact, w, n)[0][0, 0]) for n in (1, 4)]
    [0.5625, 0.3125]
    """
    u, v = exact * quads  # in quads: quad (j, i) holds [j, j + 1) x [i, i + 1)
    j = np.clip(np.floor(u), 0, quads - 1)
    i = np.clip(np.floor(v), 0, quads - 1)
    f, g = u - j, v - i  # where in its quad, each in [0, 1]
    # ground_plane cuts quad (j, i) along its diagonal a-d into triangles (a, b, d) below it
    # (f >= g) and (a, d, c) above, with corners a (0, 0), b (1, 0), c (0, 1), d (1, 1).
    above = g > f
    corner_u = j + np.array([0.0, 1.0, 1.0])[:, None] - above * np.array([0, 0, 1])[:, None]
    corner_v = i + np.array([0.0, 0.0, 1.0])[:, None] + above * np.array([0, 1, 0])[:, None]
    # In (a, b, d): f = λ_b + λ_d and g = λ_d; in (a, d, c): f = λ_d and g = λ_d + λ_c.
    weights = np.where(above, [1 - g, f, g - f], [1 - f, f - g, g])
    w00, w10, w01 = w
    w_corners = w00 + (w10 - w00) * corner_u / quads + (w01 - w00) * corner_v / quads
    b = _screen_weights(weights, w_corners)
    affine = np.stack([lerp(b, corner_u), lerp(b, corner_v)]) / quads
    triangle = 2 * (i * quads + j).astype(np.int64) + above
    return affine, triangle
