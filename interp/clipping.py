"""Clipping triangles against the view volume ``-w <= x, y, z <= w`` in clip space.

Clipping happens before the perspective divide, where everything is still linear: a point on an
edge at clip-space parameter t has clip position and ``smooth`` attributes ``lerp(t)``. That
is why clipped triangles stay perspective-correct (OpenGL 4.6, section 13.7.1). A
``noperspective`` attribute must instead vary linearly on the screen: a new vertex takes it at
the screen parameter ``s = s_from_t(t, w_in, w_out)`` of the same point. Equivalently, and
better for a computer: an attribute ``a`` linear on the screen, times ``w``, is linear in clip
space (``w (alpha x/w + beta y/w + gamma) = alpha x + beta y + gamma w``). So ``a w`` is clipped
like a ``smooth`` attribute and divided by w at the end; that stays right even where an edge
passes through the eye's plane ``w = 0`` on its way to being cut away, where s has no value.

The near and far planes (``-w <= z <= w``) come first; together they keep every vertex at
``w >= 0``, in front of the eye. The side planes then keep the window coordinates small.
Everything is vectorized over triangles: one pass per plane.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp import _checks
from interp.lerp import _lerp

#: Clip coordinates and attributes larger than this in magnitude are surely a mistake.
MAX_COORDINATE = _checks.MAX_MAGNITUDE
#: Most triangles one call takes (the largest ground plane has 131072). Clipping needs up to
#: about 1.6 kB + 0.7 kB per attribute column for each: 1.6 GB at 16 columns.
MAX_TRIANGLES = 1 << 17
#: Most attribute columns (RGBA and texture coordinates need 6).
MAX_ATTRIBUTES = 16

#: The six planes of the view volume as rows ``n``: a clip-space point P is inside when
#: ``n @ P >= 0``. Near and far first.
PLANES = np.array(
    [
        [0, 0, 1, 1],  # near:   z >= -w
        [0, 0, -1, 1],  # far:    z <= w
        [1, 0, 0, 1],  # left:   x >= -w
        [-1, 0, 0, 1],  # right:  x <= w
        [0, 1, 0, 1],  # bottom: y >= -w
        [0, -1, 0, 1],  # top:    y <= w
    ],
    dtype=np.float64,
)


@dataclass(frozen=True)
class ClippedTriangles:
    """A triangle soup: every triangle has its own three vertices.

    Attributes
    ----------
    clip : (T, 3, 4) array
        Clip-space positions, each triangle scaled by a power of two so that its largest
        coordinate lies in [1/2, 1): the same points (clip coordinates are homogeneous), kept
        far from underflow.
    smooth : (T, 3, K) array
        Attributes for perspective-correct (``smooth``) interpolation.
    noperspective : (T, 3, K) array
        Attributes for screen-linear (``noperspective``) interpolation. Equal to ``smooth``
        at the input vertices (to rounding); they differ at vertices made by clipping.
    source : (T,) int array
        Which input triangle each came from, in draw order.
    """

    clip: np.ndarray
    smooth: np.ndarray
    noperspective: np.ndarray
    source: np.ndarray

    def __post_init__(self) -> None:  # kinds and shapes only, and quickly: made often
        source, clip, smooth, noperspective = (
            self.source,
            self.clip,
            self.smooth,
            self.noperspective,
        )
        if not (isinstance(source, np.ndarray) and source.dtype.kind in "iu" and source.ndim == 1):
            raise TypeError("source must be a (T,) int array: which input triangle each came from")
        if not (isinstance(clip, np.ndarray) and clip.dtype.kind == "f"):
            raise TypeError("clip must be a (T, 3, 4) float array")
        if clip.shape != (len(source), 3, 4):
            raise TypeError(f"clip must be a (T, 3, 4) float array, T = {len(source)}")
        for name, array in (("smooth", smooth), ("noperspective", noperspective)):
            if not (
                isinstance(array, np.ndarray)
                and array.dtype.kind == "f"
                and array.shape[:2] == (len(source), 3)
                and array.shape == smooth.shape
            ):
                raise TypeError(f"{name} must be a (T, 3, K) float array, T = {len(source)}")

    def __len__(self) -> int:
        return len(self.source)

    def take(self, index: np.ndarray) -> ClippedTriangles:
        """The triangles at ``index`` (an integer or boolean array)."""
        return ClippedTriangles(
            self.clip[index], self.smooth[index], self.noperspective[index], self.source[index]
        )


def clip_triangles(clip: object, attributes: object, triangles: object) -> ClippedTriangles:
    """Clip indexed triangles against the view volume.

    Parameters
    ----------
    clip : (N, 4) array_like
        Clip-space vertex positions, coordinates in [-1e12, 1e12] (any finite value there,
        however small).
    attributes : (N, K) array_like
        Vertex attributes, values in [-1e12, 1e12], at most 16 columns.
    triangles : (M, 3) array_like of int
        Vertex indices, at most 131072 triangles.

    Returns
    -------
    ClippedTriangles
        The visible pieces, in the input's draw order. A triangle inside the view volume comes out
        unchanged (up to a power-of-two scale); one outside is dropped; one crossing a plane comes
        out as one or more pieces.

    Examples
    --------
    >>> clip = np.array([[0., 0, 0, 1], [0, 0, -3, 1], [1, 0, 0, 1]])   # vertex 1 beyond near
    >>> pieces = clip_triangles(clip, np.array([[0.], [1], [0]]), np.array([[0, 1, 2]]))
    >>> ndc_z = pieces.clip[..., 2] / pieces.clip[..., 3]
    >>> len(pieces), float(ndc_z.min())   # a quad: two triangles, cut at z = -w
    (2, -1.0)
    """
    return _clip_triangles(*_check_scene(clip, attributes, triangles))


def _check_scene(
    clip: object, attributes: object, triangles: object
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The checks :func:`clip_triangles`, :func:`interp.rasterize` and friends share."""
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
    if attributes.shape[1] > MAX_ATTRIBUTES:
        raise ValueError(
            f"attributes must have at most {MAX_ATTRIBUTES} columns, got {attributes.shape[1]}"
        )
    if attributes.size and np.abs(attributes).max() > MAX_COORDINATE:
        raise ValueError(f"attributes must hold values of magnitude at most {MAX_COORDINATE:g}")
    triangles = _checks.index_array(triangles, "triangles", len(clip), (None, 3))
    if len(triangles) > MAX_TRIANGLES:
        raise ValueError(
            f"triangles must hold at most {MAX_TRIANGLES:,} triangles, got {len(triangles):,}"
        )
    return clip, attributes, triangles


def _clip_triangles(
    clip: np.ndarray, attributes: np.ndarray, triangles: np.ndarray
) -> ClippedTriangles:
    """:func:`clip_triangles` without the checks."""
    positions = _normalized(clip[triangles])
    a = attributes[triangles]
    soup = _Soup(np.concatenate([positions, a * positions[:, :, 3:], a], axis=2), np.arange(len(a)))
    # Trivial accept and reject, like Cohen and Sutherland's outcodes: a triangle inside every
    # plane comes through every pass unchanged, and one with all three vertices outside the
    # same plane is cut away whole. Only the rest go through the passes.
    inside = positions @ PLANES.T >= 0  # (T, 3, 6): the passes' own test, plane by plane
    accept = inside.all(axis=(1, 2))
    reject = (~inside.any(axis=1)).any(axis=1)
    cut = soup.take(~accept & ~reject)
    for plane in PLANES:
        cut = _clip_against(cut, plane)
    soup = _in_draw_order(soup.take(accept), cut)
    in_front = np.all(soup.vertices[:, :, 3] > 0, axis=1)  # drops degenerate pieces at the eye
    vertices, source = soup.vertices[in_front], soup.source[in_front]
    # Every vertex is now inside, up to rounding: make that exact, so that no rounding (nor a
    # piece far below the precision of its triangle, 1e-300 times smaller) can put a vertex
    # outside, where dividing by its w could overflow.
    k = attributes.shape[1]
    w = vertices[:, :, 3:4]
    position = np.concatenate([np.clip(vertices[:, :, :3], -w, w), w], axis=2)
    a_w = vertices[:, :, 4 : 4 + k]
    return ClippedTriangles(
        _normalized(position),
        vertices[:, :, 4 + k :],
        a_w / np.maximum(w, np.abs(a_w) / _HUGE),  # a w / w = a, and never beyond _HUGE
        source,
    )


@dataclass(frozen=True)
class _Soup:
    """Triangles while they are clipped. Per vertex, everything clipping interpolates is in one
    (T, 3, 4 + 2K) array: the clip position, then ``a w`` for each noperspective attribute
    (linear in clip space), then each smooth attribute ``a``."""

    vertices: np.ndarray
    source: np.ndarray  # (T,) the input triangle each came from

    def take(self, index: np.ndarray) -> _Soup:
        return _Soup(self.vertices[index], self.source[index])


def _in_draw_order(a: _Soup, b: _Soup) -> _Soup:
    """The triangles of both, in the order of the input triangles they came from (each of
    ``a`` and ``b`` is in that order already)."""
    if len(b.source) == 0 or len(a.source) == 0:
        return b if len(a.source) == 0 else a
    source = np.concatenate([a.source, b.source])
    order = np.argsort(source, kind="stable")  # a triangle's pieces stay in their order
    return _Soup(np.concatenate([a.vertices, b.vertices])[order], source[order])


def _normalized(clip: np.ndarray) -> np.ndarray:
    """Each triangle (T, 3, 4) scaled by a power of two to a largest coordinate in [1/2, 1).

    Clip coordinates are homogeneous: scaling a triangle's three vertices by one positive number
    changes neither its image nor its interpolation, and scaling by a power of two is exact. It
    keeps the arithmetic as precise for a triangle of size 1e-300 (or a piece cut off right at
    the eye) as for one of size 1.
    """
    _, exponent = np.frexp(np.abs(clip).max(axis=(1, 2), initial=0.0))
    return np.ldexp(clip, -exponent[:, None, None])


def _clip_against(soup: _Soup, plane: np.ndarray) -> _Soup:
    """One Sutherland-Hodgman pass against one plane, for all triangles at once."""
    distance = soup.vertices[:, :, :4] @ plane  # (T, 3), >= 0 inside
    inside = distance >= 0
    n_inside = inside.sum(axis=1)
    if np.all(n_inside == 3):
        return soup

    # Each kind of triangle is cut only where there is one: on a handful of triangles (a ground
    # plane of two) the numpy calls, not the arithmetic, are the cost.
    whole = n_inside == 3
    pieces, parents = [soup.take(whole)], [np.flatnonzero(whole)]
    # One vertex inside: roll it to position 0; the piece is (v0, cut(v0, v1), cut(v0, v2)).
    one = n_inside == 1
    if one.any():
        v0, v1, v2 = _rolled(soup.take(one), np.argmax(inside[one], axis=1), distance[one])
        pieces.append(_assemble(v0, _cut(v0, v1), _cut(v0, v2)))
        parents.append(np.flatnonzero(one))
    # Two inside: roll the outside one to position 0; the quad (v1, v2, cut(v2, v0), cut(v1, v0))
    # becomes two triangles. Rolling keeps each triangle's winding.
    two = n_inside == 2
    if two.any():
        u0, u1, u2 = _rolled(soup.take(two), np.argmin(inside[two], axis=1), distance[two])
        cut20, cut10 = _cut(u2, u0), _cut(u1, u0)
        pieces += [_assemble(u1, u2, cut20), _assemble(u1, cut20, cut10)]
        parents += [np.flatnonzero(two)] * 2
    order = np.argsort(np.concatenate(parents), kind="stable")  # back into draw order
    return _Soup(
        np.concatenate([p.vertices for p in pieces])[order],
        np.concatenate([p.source for p in pieces])[order],
    )


_EPSILON = np.finfo(np.float64).eps
#: A bound no noperspective attribute reaches unless its vertex's w is lost below float64's
#: precision (a piece 1e300 times smaller than its triangle): there it stops, finite.
_HUGE = 1e200


@dataclass(frozen=True)
class _Vertex:
    """One vertex of each of T triangles: what clipping interpolates, and the plane distance."""

    data: np.ndarray  # (T, 4 + 2K): clip position, a w, a
    source: np.ndarray  # (T,)
    distance: np.ndarray  # (T,)


def _rolled(soup: _Soup, first: np.ndarray, distance: np.ndarray) -> list[_Vertex]:
    """The three vertices of each triangle, cyclically rolled so vertex ``first`` comes first."""
    rows = np.arange(len(soup.source))
    vertices = []
    for k in range(3):
        i = (first + k) % 3
        vertices.append(_Vertex(soup.vertices[rows, i], soup.source, distance[rows, i]))
    return vertices


def _cut(inner: _Vertex, outer: _Vertex) -> _Vertex:
    """The point where edge inner -> outer meets the plane.

    It lies at ``t = d_in / (d_in - d_out)`` from the inside vertex (``d`` the plane distances,
    ``d_in >= 0 > d_out``). Close to 1, a float t cannot say how close: for an outer vertex a
    hair outside the plane, ``1 - 1e-17`` rounds to 1 and the cut would land on the outer vertex
    itself. So the point is interpolated from whichever end is nearer, by that end's own
    parameter computed directly: t from the inner vertex, or ``1 - t = -d_out / (d_in - d_out)``
    from the outer one. Both are in [0, 1/2] and exact to rounding, however small.

    The same (inner, outer) pair always gives the same bits, so two triangles sharing the edge
    make identical vertices and no crack can open between them.
    """
    span = inner.distance - outer.distance  # > 0, and no cancellation: d_in >= 0 > d_out
    from_inner = inner.distance <= -outer.distance  # t <= 1/2
    f = np.where(from_inner, inner.distance, -outer.distance) / span  # t or 1 - t: in [0, 1/2]
    column = from_inner[:, None]
    near = np.where(column, inner.data, outer.data)
    far = np.where(column, outer.data, inner.data)
    point = _lerp(near, far, f[:, None])
    # Where the point's w is lost in rounding (the edge crosses the eye's plane w = 0 right
    # there), make it exactly 0: such a point has no place on the screen, and a later plane cuts
    # it away, or drops the piece as degenerate.
    rounding = 4 * _EPSILON * (np.abs(near[:, 3]) + f * np.abs(far[:, 3]))
    point[:, 3] = np.where(np.abs(point[:, 3]) > rounding, point[:, 3], 0.0)
    return _Vertex(point, inner.source, np.zeros_like(f))


def _assemble(a: _Vertex, b: _Vertex, c: _Vertex) -> _Soup:
    return _Soup(np.stack([a.data, b.data, c.data], axis=1), a.source)
