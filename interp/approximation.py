"""How renderers before per-pixel division approximated it, and what it cost them.

Two remedies for affine texture mapping, measured on the same ground plane:

- spans (Quake): exact every N pixels along a row, affine between: about one divide per N
  pixels;
- tessellation (PlayStation-era): cut the plane into more, smaller triangles and draw them
  affinely: one divide per vertex, no divides per pixel.

Error is the mean distance, in texels, between the approximate and the exact ``(u, v)``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from interp import _checks
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
    vertex, so divides per pixel is (vertices drawn) / (pixels drawn).

    Examples
    --------
    >>> costs = tessellation_costs(Camera(height=1, pitch=25), 64, 48, quads=(1, 8))
    >>> bool(costs.mean_error[1] < costs.mean_error[0])
    True
    """
    camera = camera.fitted(width, height)
    divides, errors = [], []
    for n in quads:
        scene, frags, exact = _drawn(camera, width, height, _checks.positive_int(n, "quads", 256))
        affine = fragment_values(frags, "affine")
        errors.append(_mean_texel_error(affine, exact, frequency))
        drawn = _distinct(frags.triangle, len(scene.triangles))
        visible = _distinct(scene.triangles[drawn].ravel(), len(scene.clip))
        divides.append(len(visible) / max(len(frags.pixel), 1))
    return Costs(np.array(quads), np.array(divides), np.array(errors))
