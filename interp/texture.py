"""Checkerboards sampled at per-pixel texture coordinates, and texture-space error.

Glossary
--------
frequency : checks per unit of u (and of v): the texture is ``frequency x frequency`` texels,
            one texel per check.
texel     : one square of the checkerboard.
footprint : how far (u, v) moves, in texels, from one pixel to the next.
"""

from __future__ import annotations

import numpy as np

from interp import _checks

#: Most checks per unit of (u, v).
MAX_FREQUENCY = 1024


def _uv_images(u: object, v: object, covered: object) -> tuple[np.ndarray, ...]:
    u = _checks.number_array(u, "u")
    v = _checks.number_array(v, "v")
    if u.ndim != 2 or u.shape != v.shape:
        raise ValueError(f"u and v must be images of one shape (H, W), got {u.shape}, {v.shape}")
    if covered is None:
        covered = np.ones(u.shape, dtype=bool)
    else:
        covered = _checks.bool_image(covered, "covered", u.shape)
    return u, v, covered


def checkerboard(
    u: object,
    v: object,
    frequency: float = 8,
    filtered: bool = False,
    covered: object = None,
    background: float = 0.5,
) -> np.ndarray:
    """Sample a black-and-white checkerboard at per-pixel texture coordinates.

    Parameters
    ----------
    u, v : (H, W) array_like
        Texture coordinates at each pixel, e.g. the two channels from :func:`interp.rasterize`,
        in [-1e12, 1e12].
    frequency : float
        Checks per unit of u and of v, in (0, 1024].
    filtered : bool
        False: nearest sample (aliases into moiré far away). True: the exact average of the
        checkerboard over each pixel's footprint, a box filter whose size comes from how (u, v)
        change between neighbouring pixels, like a GPU's derivatives.
    covered : (H, W) bool array_like, optional
        Where the texture was drawn; elsewhere the image is ``background``, and derivatives are
        not taken across the border.
    background : float
        Value where nothing was drawn.

    Returns
    -------
    (H, W) float array
        1 for white checks, 0 for black, in between where filtered.

    Examples
    --------
    >>> u = np.array([[0.05, 0.15, 0.25]])
    >>> checkerboard(u, np.zeros_like(u), frequency=10)
    array([[0., 1., 0.]])
    """
    u, v, covered = _uv_images(u, v, covered)
    frequency = _checks.real_in(frequency, "frequency", 0, MAX_FREQUENCY, low_open=True)
    if not isinstance(filtered, (bool, np.bool_)):
        raise TypeError("filtered must be True or False")
    background = _checks.real(background, "background")
    p, q = u * frequency, v * frequency  # in texels
    if filtered:
        value = checker(p, q, _footprint(p, covered), _footprint(q, covered))
    else:
        value = checker(p, q)
    return np.where(covered, value, background)


def checker(
    p: np.ndarray,
    q: np.ndarray,
    footprint_p: np.ndarray | None = None,
    footprint_q: np.ndarray | None = None,
) -> np.ndarray:
    """The checkerboard at texel coordinates ``(p, q)``, box-filtered if footprints are given.

    The core of :func:`checkerboard`, for arrays of any shape (no argument checks).

    Parameters
    ----------
    p, q : arrays
        Texel coordinates (texture coordinates times frequency).
    footprint_p, footprint_q : arrays, optional
        Width in texels of the box to average over at each point.

    Examples
    --------
    >>> checker(np.array([0.5, 1.5]), np.array([0.5, 0.5]))
    array([0., 1.])
    >>> checker(np.array([1.0]), np.array([0.5]), np.array([1.0]), np.array([0.0]))  # half/half
    array([0.5])
    """
    if footprint_p is None or footprint_q is None:
        return (np.floor(p) + np.floor(q)) % 2
    return 0.5 - 0.5 * _box_filtered_wave(p, footprint_p) * _box_filtered_wave(q, footprint_q)


def _box_filtered_wave(x: np.ndarray, width: np.ndarray) -> np.ndarray:
    """Average over ``[x - width/2, x + width/2]`` of the square wave that is +1 on even
    texels and -1 on odd ones, exactly.

    The square wave's integral from 0 is a triangle wave, ``T(x) = 1 - 2 |frac(x/2) - 1/2|``
    (up at even texels, down at odd ones), so the average is
    ``(T(x + width/2) - T(x - width/2)) / width``.
    """

    def triangle(y: np.ndarray) -> np.ndarray:
        return 1.0 - 2.0 * np.abs(y / 2 - np.floor(y / 2) - 0.5)

    width = np.maximum(width, 1e-6)  # a point sample, as near as makes no difference
    average = (triangle(x + width / 2) - triangle(x - width / 2)) / width
    return np.clip(average, -1.0, 1.0)  # rounding of a tiny width must not leave [-1, 1]


def _footprint(p: np.ndarray, covered: np.ndarray) -> np.ndarray:
    """``|dp/dx| + |dp/dy|`` per pixel from differences with covered neighbours (GLSL fwidth)."""

    def derivative(axis: int) -> np.ndarray:
        a = np.moveaxis(p, axis, 1)
        c = np.moveaxis(covered, axis, 1)
        step = a[:, 1:] - a[:, :-1]
        both = c[:, 1:] & c[:, :-1]
        ahead = np.zeros_like(a)
        behind = np.zeros_like(a)
        has_ahead = np.zeros(a.shape, bool)
        has_behind = np.zeros(a.shape, bool)
        ahead[:, :-1], has_ahead[:, :-1] = step, both
        behind[:, 1:], has_behind[:, 1:] = step, both
        d = np.where(has_ahead, ahead, np.where(has_behind, behind, 0.0))
        return np.moveaxis(d, 1, axis)

    return np.abs(derivative(1)) + np.abs(derivative(0))


def texel_error(uv: object, uv_reference: object, frequency: float = 8) -> np.ndarray:
    """How far apart two texture-coordinate images are, in texels: ``|Δ(u, v)| * frequency``.

    Parameters
    ----------
    uv, uv_reference : (H, W, 2) array_like
        E.g. affine and perspective-correct ``(u, v)`` from :func:`interp.rasterize`, in
        [-1e12, 1e12].
    frequency : float
        Texels per unit of (u, v), in (0, 1024].

    Returns
    -------
    (H, W) float array

    Examples
    --------
    >>> texel_error([[[0.5, 0.5]]], [[[0.2, 0.1]]], frequency=10)
    array([[5.]])
    """
    uv = _checks.number_array(uv, "uv")
    uv_reference = _checks.number_array(uv_reference, "uv_reference")
    if uv.ndim != 3 or uv.shape[2] != 2 or uv.shape != uv_reference.shape:
        raise ValueError(
            f"uv and uv_reference must both have shape (H, W, 2), got {uv.shape} and "
            f"{uv_reference.shape}"
        )
    frequency = _checks.real_in(frequency, "frequency", 0, MAX_FREQUENCY, low_open=True)
    return _texel_error(np.moveaxis(uv, 2, 0), np.moveaxis(uv_reference, 2, 0), frequency)


def _texel_error(uv: np.ndarray, uv_reference: np.ndarray, frequency: float) -> np.ndarray:
    """``|Δ(u, v)| * frequency`` for (u, v) along the first axis: (2, ...) arrays in, (...) out."""
    return np.hypot(*(uv - uv_reference)) * frequency
