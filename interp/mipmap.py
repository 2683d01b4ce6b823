"""Texture filtering: one pixel's footprint in the texture, mipmaps, and OpenGL's level of detail.

A pixel is a small square of the screen. Through the perspective mapping it covers a patch of
the texture, its *footprint*. Across one pixel the mapping is nearly linear, so the footprint is
nearly the parallelogram spanned by the two derivative vectors, in texels::

    (du/dx, dv/dx) * size     the step in the texture for one pixel to the right
    (du/dy, dv/dy) * size     the step in the texture for one pixel up

A texture sampled only at each pixel centre (``GL_NEAREST``) ignores the rest of the footprint:
where a footprint spans several checks, neighbouring pixels land on unrelated ones, and the image
aliases into moiré that shimmers as the camera moves. The cure is to average the texture over
each footprint. A *mipmap* prepares such averages once: level k is the texture shrunk ``2**k``
times, each of its texels the mean of 2 x 2 texels of level k - 1. OpenGL then picks, per pixel,
the level whose texels are about as large as the footprint (OpenGL 4.6, section 8.14.1)::

    ρ = max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|) * size     the longer footprint edge, in texels
    λ = log2 ρ                                              the level of detail

λ <= 0 means a texel covers a pixel or more (magnified): ``GL_LINEAR`` on level 0. Otherwise
``GL_LINEAR_MIPMAP_LINEAR`` (trilinear filtering, section 8.14.3) samples the levels ⌊λ⌋ and
⌊λ⌋ + 1 bilinearly and blends them by the fraction of λ.

Affine (``noperspective``) interpolation makes (u, v) linear on the screen, so its derivatives
are constant across each triangle: one level of detail for the whole triangle, too sharp where
it is far and too blurred where it is near.

Glossary
--------
size        : texels per side of level 0 (a power of two).
(p, q)      : texel coordinates, ``(u, v) * size``.
derivatives : a (2, 2, P) array ``[[du/dx, dv/dx], [du/dy, dv/dy]]``: first index the screen
              direction (x right, y up as OpenGL's window y), second the texture coordinate.
ρ (rho)     : the scale factor, the longer footprint edge in texels.
λ (lambda)  : the level of detail, ``log2 ρ``.
quad        : 2 x 2 pixels that a GPU shades together; its derivatives are differences between
              them (GLSL ``dFdx``, ``dFdy``), see :func:`quad_derivatives`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from interp import _checks, barycentric
from interp.raster import Fragments, fragment_values, fragments
from interp.scenes import Scene
from interp.texture import MAX_FREQUENCY, checker

#: Texels per side of level 0 of the lessons' checkerboard texture.
TEXTURE_SIZE = 256
#: Largest texture this module makes (a power of two).
MAX_TEXTURE_SIZE = 4096
#: Derivative modes: GLSL ``smooth`` and ``noperspective``.
DERIVATIVE_MODES = ("perspective", "affine")


def _power_of_two(value: object, name: str, cap: int = MAX_TEXTURE_SIZE) -> int:
    value = _checks.positive_int(value, name, cap)
    if value & (value - 1):
        raise ValueError(f"{name} must be a power of two, got {value}")
    return value


# ------------------------------------------------------------------- the texture and its pyramid


def checker_texture(frequency: int, size: int = TEXTURE_SIZE) -> np.ndarray:
    """Level 0 of the checkerboard texture: ``frequency x frequency`` checks of
    ``size / frequency`` texels each.

    Parameters
    ----------
    frequency : int
        Checks per side, a power of two at most ``size``.
    size : int
        Texels per side, a power of two.

    Returns
    -------
    (size, size) float array
        Row j holds v in ``[j, j + 1) / size``, column i holds u in ``[i, i + 1) / size`` (the
        order OpenGL reads an uploaded image in); 0 on black checks, 1 on white, the check at the
        origin black, as :func:`interp.texture.checker`.

    Examples
    --------
    >>> checker_texture(2, 4)
    array([[0., 0., 1., 1.],
           [0., 0., 1., 1.],
           [1., 1., 0., 0.],
           [1., 1., 0., 0.]])
    """
    size = _power_of_two(size, "size")
    frequency = _power_of_two(frequency, "frequency", size)
    centre = (np.arange(size) + 0.5) * frequency / size  # texel centres, in checks
    return checker(centre[None, :], centre[:, None])


def mipmap(level0: object) -> list[np.ndarray]:
    """The mipmap pyramid: level 0, then each level the 2 x 2 average of the one before, down to
    one texel (what ``glGenerateMipmap`` makes of a power-of-two texture).

    Parameters
    ----------
    level0 : (size, size) array_like
        A square texture whose side is a power of two.

    Returns
    -------
    list of arrays
        ``log2(size) + 1`` levels; level k is ``size / 2**k`` texels square.

    Examples
    --------
    >>> levels = mipmap(checker_texture(2, 4))
    >>> [level.shape for level in levels]
    [(4, 4), (2, 2), (1, 1)]
    >>> levels[1]
    array([[0., 1.],
           [1., 0.]])
    >>> levels[2]                  # every check averaged in: grey
    array([[0.5]])
    """
    level = _checks.float_array(level0, "level0")
    if level.ndim != 2 or level.shape[0] != level.shape[1]:
        raise ValueError(f"level0 must be a square image, got shape {level.shape}")
    _power_of_two(level.shape[0], "level0's side")
    levels = [level]
    while level.shape[0] > 1:
        n = level.shape[0] // 2
        level = level.reshape(n, 2, n, 2).mean(axis=(1, 3))
        levels.append(level)
    return levels


@lru_cache(maxsize=16)
def _checker_pyramid(frequency: int, size: int = TEXTURE_SIZE) -> tuple[np.ndarray, ...]:
    """:func:`mipmap` of :func:`checker_texture`, made once per ``(frequency, size)``: a slider
    that moves the camera leaves the texture as it was. The levels are read-only, as they are
    shared.

    Examples
    --------
    >>> [level.shape for level in _checker_pyramid(2, 4)]
    [(4, 4), (2, 2), (1, 1)]
    >>> _checker_pyramid(2, 4) is _checker_pyramid(2, 4)
    True
    """
    levels = tuple(mipmap(checker_texture(frequency, size)))
    for level in levels:
        level.setflags(write=False)
    return levels


# ----------------------------------------------------------------------- derivatives and footprints


def _planes(frags: Fragments, mode: str) -> tuple[np.ndarray, np.ndarray | None]:
    """Per piece, what is linear on the screen: ``a`` (affine) or ``a/w`` and ``1/w``."""
    pieces = frags.clipped
    if mode == "affine":
        return pieces.noperspective, None
    one_over_w = 1.0 / pieces.clip[:, :, 3]  # (T, 3)
    return pieces.smooth * one_over_w[..., None], one_over_w


def uv_derivatives(
    frags: Fragments, mode: str = "perspective", values: np.ndarray | None = None
) -> np.ndarray:
    """The exact screen derivatives of the interpolated attributes at every fragment.

    Perspective-correct: ``a = N / D`` with ``N = lerp(b, a/w)`` and ``D = lerp(b, 1/w)`` linear
    on the screen, so ``da = (dN - a dD) / D`` (:func:`interp.barycentric.smooth_derivative`),
    per axis. Affine: ``a`` itself is linear, so its steps are constant on each triangle.

    Parameters
    ----------
    frags : Fragments
        From :func:`interp.fragments`, e.g. with the (u, v) of a ground plane as attributes.
    mode : {"perspective", "affine"}
    values : (K, P) array, optional
        ``fragment_values(frags, mode)``, if already at hand.

    Returns
    -------
    (2, K, P) float array
        ``[da/dx, da/dy]`` per attribute and fragment: x one pixel to the right, y one pixel
        *up* (OpenGL's window y, as GLSL ``dFdy``).

    Examples
    --------
    A triangle covering the view whose attribute goes from 0 to 4 across its 4-pixel-wide base:

    >>> f = fragments([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]], [[0.0], [4.0], [0.0]],
    ...               [[0, 1, 2]], 2, 1)
    >>> uv_derivatives(f, "affine")     # 1 per pixel along x, nothing along y
    array([[[1., 1.]],
    <BLANKLINE>
           [[0., 0.]]])
    """
    mode = _checks.choice(mode, "mode", DERIVATIVE_MODES)
    piece = frags.piece
    # Per pixel step right, and up (the rasterizer's dy steps down the image).
    steps = np.stack([frags.barycentric_dx, -frags.barycentric_dy], axis=1)  # (3, 2, T)
    numerator, one_over_w = _planes(frags, mode)
    dN = np.einsum("idt,tik->dkt", steps, numerator)  # (2, K, T)
    if mode == "affine":
        return np.take(dN, piece, axis=2)
    if values is None:
        values = fragment_values(frags, "perspective")
    dD = np.einsum("idt,ti->dt", steps, one_over_w)  # (2, T)
    D = barycentric.lerp(frags.barycentric, np.take(one_over_w.T, piece, axis=1))
    return np.stack(
        [
            barycentric.smooth_derivative(
                values, D, np.take(dN[d], piece, axis=1), np.take(dD[d], piece)
            )
            for d in range(2)
        ]
    )


def footprint(derivatives: object, size: float) -> np.ndarray:
    """The two edges of each pixel's footprint in texel space.

    Parameters
    ----------
    derivatives : (2, 2, ...) array_like
        ``[[du/dx, dv/dx], [du/dy, dv/dy]]``, e.g. from :func:`uv_derivatives`.
    size : float
        Texels per unit of u and v.

    Returns
    -------
    (2, 2, ...) float array
        ``[(dp/dx, dq/dx), (dp/dy, dq/dy)]``: the parallelogram that one pixel covers, spanned
        by one step right and one step up, in texels.

    Examples
    --------
    >>> footprint([[0.01, 0.0], [0.0, -0.02]], 256)
    array([[ 2.56,  0.  ],
           [ 0.  , -5.12]])
    """
    derivatives = _checks.float_array(derivatives, "derivatives")
    if derivatives.ndim < 2 or derivatives.shape[:2] != (2, 2):
        raise ValueError(f"derivatives must have shape (2, 2, ...), got {derivatives.shape}")
    size = _checks.real_in(size, "size", 0, None, low_open=True)
    return derivatives * size


def scale_factor(dudx: object, dvdx: object, dudy: object, dvdy: object, size: float) -> np.ndarray:
    """OpenGL's ρ: the longer of the two footprint edges, in texels (OpenGL 4.6, section 8.14.1).

    ``ρ = max(sqrt(dudx² + dvdx²), sqrt(dudy² + dvdy²)) * size``

    Examples
    --------
    >>> float(scale_factor(3 / 256, 4 / 256, 0.0, 1 / 256, 256))   # edges of 5 and 1 texels
    5.0
    """
    size = _checks.real_in(size, "size", 0, None, low_open=True)
    along_x = np.hypot(np.asarray(dudx, float), np.asarray(dvdx, float))
    along_y = np.hypot(np.asarray(dudy, float), np.asarray(dvdy, float))
    return np.maximum(along_x, along_y) * size


def level_of_detail(
    dudx: object, dvdx: object, dudy: object, dvdy: object, size: float
) -> np.ndarray:
    """OpenGL's level of detail ``λ = log2 ρ`` (no bias, no clamps; section 8.14.1).

    Parameters
    ----------
    dudx, dvdx, dudy, dvdy : float or arrays
        How u and v change for one pixel step along x and along y.
    size : float
        Texels per unit of u and v (the texture's side).

    Returns
    -------
    float array
        0 where a footprint edge is one texel long, 1 where two, -1 where half: the mipmap
        level whose texels match the footprint. ``-inf`` where the texture does not move at all.

    Examples
    --------
    >>> float(level_of_detail(4 / 256, 0.0, 0.0, 1 / 256, 256))     # 4 texels per pixel step
    2.0
    >>> float(level_of_detail(1 / 512, 0.0, 0.0, 1 / 512, 256))     # magnified: half a texel
    -1.0
    """
    rho = scale_factor(dudx, dvdx, dudy, dvdy, size)
    with np.errstate(divide="ignore"):
        return np.log2(rho)


# ----------------------------------------------------------------------- sampling, as OpenGL does


def sample_nearest(level: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``GL_NEAREST`` with ``GL_REPEAT``: the texel that contains (u, v).

    Examples
    --------
    >>> sample_nearest(checker_texture(2, 4), np.array([0.1, 0.6]), np.array([0.1, 0.1]))
    array([0., 1.])
    """
    n = level.shape[0]
    i = np.floor(u * n).astype(np.int64) % n
    j = np.floor(v * n).astype(np.int64) % n
    return level[j, i]


def sample_linear(level: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``GL_LINEAR`` with ``GL_REPEAT`` (OpenGL 4.6, section 8.14.2): the four texels whose centres
    surround (u, v), weighted bilinearly.

    Examples
    --------
    Half-way between the centres of a black and a white texel:

    >>> sample_linear(checker_texture(2, 4), np.array([0.5]), np.array([0.125]))
    array([0.5])
    """
    n = level.shape[0]
    x, y = u * n - 0.5, v * n - 0.5  # texel centres sit at half-integers
    i0, j0 = np.floor(x), np.floor(y)
    alpha, beta = x - i0, y - j0
    i0, j0 = i0.astype(np.int64) % n, j0.astype(np.int64) % n
    i1, j1 = (i0 + 1) % n, (j0 + 1) % n
    return (
        (1 - alpha) * (1 - beta) * level[j0, i0]
        + alpha * (1 - beta) * level[j0, i1]
        + (1 - alpha) * beta * level[j1, i0]
        + alpha * beta * level[j1, i1]
    )


def sample_trilinear(
    levels: list[np.ndarray], u: np.ndarray, v: np.ndarray, lod: np.ndarray
) -> np.ndarray:
    """``GL_LINEAR_MIPMAP_LINEAR`` (magnification ``GL_LINEAR``), at level of detail ``lod``.

    λ <= 0: bilinear on level 0. Otherwise bilinear on levels ``d1 = ⌊λ⌋`` and ``d2 = d1 + 1``
    (both the last level where λ reaches it), blended ``(1 - frac λ) τ1 + frac(λ) τ2``
    (OpenGL 4.6, section 8.14.3).

    Parameters
    ----------
    levels : list of arrays
        From :func:`mipmap`.
    u, v, lod : arrays of one shape
        Texture coordinates and λ per sample.

    Examples
    --------
    >>> levels = mipmap(checker_texture(2, 4))
    >>> u = v = np.array([0.25, 0.25, 0.25])     # the centre of a black texel of level 1
    >>> sample_trilinear(levels, u, v, np.array([-1.0, 1.5, 5.0]))   # level 0; 1 and 2; last
    array([0.  , 0.25, 0.5 ])
    """
    lod = np.asarray(lod, dtype=float)
    last = len(levels) - 1
    whole = np.floor(np.where(lod > 0, np.minimum(lod, last), 0.0))
    fraction = np.where((lod > 0) & (lod < last), lod - whole, 0.0)
    near = whole.astype(np.int64)  # d1
    far = np.minimum(near + 1, last)  # d2
    out = np.zeros(np.broadcast(u, v, lod).shape)
    for k, level in enumerate(levels):
        first, second = near == k, (far == k) & (fraction > 0)
        if first.any():
            out[first] += (1 - fraction[first]) * sample_linear(level, u[first], v[first])
        if second.any():
            out[second] += fraction[second] * sample_linear(level, u[second], v[second])
    return out


# ----------------------------------------------------------------------- what llvmpipe computes


def quad_derivatives(frags: Fragments, mode: str = "perspective") -> np.ndarray:
    """The derivatives a GPU uses for ``texture()``: differences within each 2 x 2 pixel quad.

    A GPU shades pixels in quads of 2 x 2, aligned to even window coordinates, running every
    pixel of a quad even where the triangle misses it (the attributes are evaluated there from
    the triangle's planes anyway). The derivatives are then differences between the quad's
    pixels, the same for all four: Mesa's llvmpipe takes right minus left along the quad's
    lower row (window y even) and upper minus lower along its left column. This function
    computes exactly that, per fragment, from its own triangle's planes.

    Parameters
    ----------
    frags : Fragments
        The image height must be even (quads then align the same way from either end).
    mode : {"perspective", "affine"}

    Returns
    -------
    (2, K, P) float array
        As :func:`uv_derivatives`; equal to it where the attribute is linear on the screen.

    Examples
    --------
    >>> f = fragments([[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]], [[0.0], [4.0], [0.0]],
    ...               [[0, 1, 2]], 2, 2)
    >>> quad_derivatives(f, "affine")[0]    # linear: the differences are the derivatives
    array([[1., 1., 1., 1.]])
    """
    mode = _checks.choice(mode, "mode", DERIVATIVE_MODES)
    if frags.height % 2:
        raise ValueError(f"the image height must be even for 2 x 2 quads, got {frags.height}")
    piece = frags.piece
    x = frags.column
    row = frags.pixel // frags.width
    window_y = frags.height - 1 - row
    corner_x, corner_row = x & ~1, frags.height - 1 - (window_y & ~1)  # the quad's lower left

    numerator, one_over_w = _planes(frags, mode)
    per_fragment = np.take(np.moveaxis(numerator, 0, 2), piece, axis=2)  # (3, K, P)
    if one_over_w is not None:
        w_per_fragment = np.take(one_over_w.T, piece, axis=1)  # (3, P)
    b_dx = np.take(frags.barycentric_dx, piece, axis=1)
    b_dy = np.take(frags.barycentric_dy, piece, axis=1)  # per image row, downwards

    def value_at(column: np.ndarray, image_row: np.ndarray) -> np.ndarray:
        b = frags.barycentric + (column - x) * b_dx + (image_row - row) * b_dy
        if one_over_w is None:
            return barycentric.noperspective(b, per_fragment)
        return barycentric.smooth(b, per_fragment, w_per_fragment)

    lower_left = value_at(corner_x, corner_row)
    return np.stack(
        [
            value_at(corner_x + 1, corner_row) - lower_left,
            value_at(corner_x, corner_row - 1) - lower_left,
        ]
    )


def fast_log2(x: np.ndarray) -> np.ndarray:
    """llvmpipe's ``lp_build_fast_log2``: exact at powers of two, straight in between.

    With ``x = m 2**e``, ``1 <= m < 2``, it returns ``e + (m - 1)`` instead of ``e + log2 m``:
    at most 0.086 low (near ``m = 1.44``).

    Examples
    --------
    >>> fast_log2(np.array([1.0, 1.5, 2.0, 12.0]))
    array([0. , 0.5, 1. , 3.5])
    """
    mantissa, exponent = np.frexp(np.asarray(x, dtype=float))  # x = mantissa 2**exponent, [0.5, 1)
    return (exponent - 1) + (2 * mantissa - 1)


def llvmpipe_level_of_detail(derivatives: np.ndarray, size: float) -> np.ndarray:
    """The λ Mesa's llvmpipe computes for ``texture()`` with ``GL_LINEAR_MIPMAP_LINEAR``, from
    the quad derivatives of :func:`quad_derivatives`.

    It squares: ``ρ² = max(|d/dx|², |d/dy|²)`` in texels (the exact ρ of the specification, not
    its allowed max-of-components shortcut), then ``λ = fast_log2(ρ²) / 2`` (:func:`fast_log2`:
    up to 0.043 below ``log2 ρ``). One λ per quad, since the quad derivatives are.

    Examples
    --------
    >>> d = np.array([[[3 / 256], [0.0]], [[0.0], [1 / 256]]])   # 3 texels along x
    >>> llvmpipe_level_of_detail(d, 256), np.log2(3)              # 9 = 1.125 * 2**3
    (array([1.5625]), np.float64(1.584962500721156))
    """
    squared = np.maximum(np.sum(derivatives[0] ** 2, axis=0), np.sum(derivatives[1] ** 2, axis=0))
    with np.errstate(divide="ignore"):
        return fast_log2(squared * size**2) / 2


# ----------------------------------------------------------------------- one frame of the lesson


@dataclass(frozen=True)
class FilteringViews:
    """One frame of the texture-filtering lesson: a checkerboard plane filtered three ways.

    Attributes
    ----------
    fragments : Fragments
    uv : (2, P) float array
        Texture coordinates per fragment, in ``mode``.
    derivatives : (2, 2, P) float array
        ``[[du/dx, dv/dx], [du/dy, dv/dy]]`` per fragment, exact, in ``mode``.
    lod : (P,) float array
        OpenGL's λ per fragment, from ``derivatives``.
    levels : list of arrays
        The checkerboard's mipmap (:func:`mipmap`).
    size, frequency : int
        Texels per side of level 0, and checks per side.
    mode : str
    background : float
        Image value where nothing is drawn.

    Notes
    -----
    The three images, :attr:`nearest`, :attr:`box` and :attr:`trilinear`, are computed when
    first asked for: a figure that shows one pays for one.
    """

    fragments: Fragments
    uv: np.ndarray
    derivatives: np.ndarray
    lod: np.ndarray
    levels: list[np.ndarray]
    size: int
    frequency: int
    mode: str
    background: float = 0.5

    @cached_property
    def nearest(self) -> np.ndarray:
        """(H, W) float array: the texture point-sampled at each pixel centre (``GL_NEAREST``)."""
        return self.fragments.image(sample_nearest(self.levels[0], *self.uv), self.background)

    @cached_property
    def box(self) -> np.ndarray:
        """(H, W) float array: the exact average of the checkerboard over the box that holds
        each pixel's footprint (:func:`interp.texture.checker`)."""
        u, v = self.uv * self.frequency  # in checks
        widths = (np.abs(self.derivatives[0]) + np.abs(self.derivatives[1])) * self.frequency
        return self.fragments.image(checker(u, v, *widths), self.background)

    @cached_property
    def trilinear(self) -> np.ndarray:
        """(H, W) float array: trilinear filtering from the mipmap at OpenGL's λ
        (``GL_LINEAR_MIPMAP_LINEAR``)."""
        filtered = sample_trilinear(self.levels, *self.uv, self.lod)
        return self.fragments.image(filtered, self.background)

    @property
    def lod_image(self) -> np.ndarray:
        """(H, W) float array: λ per pixel, NaN where nothing is drawn."""
        return self.fragments.image(self.lod, np.nan)

    @property
    def footprints(self) -> np.ndarray:
        """(2, 2, P) float array: each fragment's footprint edges in texels (:func:`footprint`)."""
        return self.derivatives * self.size


def filtering_views(
    scene: Scene,
    width: int = 320,
    height: int = 240,
    frequency: int = 8,
    size: int = TEXTURE_SIZE,
    mode: str = "perspective",
    background: float = 0.5,
) -> FilteringViews:
    """Draw ``scene``'s checkerboard point-sampled, box-filtered and trilinear, with every
    pixel's derivatives and level of detail.

    Parameters
    ----------
    scene : Scene
        E.g. from :func:`interp.ground_plane`; its (u, v) run from 0 to 1 across the plane.
    width, height : int
        Image size, each in [1, 4096].
    frequency : int
        Checks per side of the plane, a power of two at most ``size``.
    size : int
        Texels per side of level 0, a power of two.
    mode : {"perspective", "affine"}
        How (u, v) and their derivatives are interpolated.
    background : float
        Image value where nothing is drawn.

    Returns
    -------
    FilteringViews

    Examples
    --------
    Looking straight down from height 2 with a field of view of 90 degrees, the 64 pixels of a
    row span the 4 units of the plane: one pixel covers 1/64 of u, 4 texels of 256, so λ = 2
    everywhere.

    >>> from interp.camera import Camera
    >>> from interp.scenes import ground_plane
    >>> scene = ground_plane(Camera(height=2.0, pitch=90.0, distance=0.0, fovy=90.0), size=4.0)
    >>> views = filtering_views(scene, 64, 64)
    >>> round(float(views.lod.min()), 9), round(float(views.lod.max()), 9)
    (2.0, 2.0)
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be an interp.Scene, got {type(scene).__name__}")
    size = _power_of_two(size, "size")
    frequency = _power_of_two(frequency, "frequency", min(size, MAX_FREQUENCY))
    mode = _checks.choice(mode, "mode", DERIVATIVE_MODES)
    background = _checks.real(background, "background")

    frags = fragments(scene.clip, scene.uv, scene.triangles, width, height)
    uv = fragment_values(frags, mode)
    derivatives = uv_derivatives(frags, mode, uv)
    (dudx, dvdx), (dudy, dvdy) = derivatives
    lod = level_of_detail(dudx, dvdx, dudy, dvdy, size)
    return FilteringViews(
        fragments=frags,
        uv=uv,
        derivatives=derivatives,
        lod=lod,
        levels=list(_checker_pyramid(frequency, size)),
        size=size,
        frequency=frequency,
        mode=mode,
        background=background,
    )
