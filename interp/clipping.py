"""Clipping triangles against the view volume ``-w <= x, y, z <= w`` in clip space.

Clipping happens before the perspective divide, where everything is still linear: a point on an
edge at clip-space parameter t has clip position and ``smooth`` attributes ``lerp(t)``. That
is why clipped triangles stay perspective-correct (OpenGL 4.6, section 13.7.1). A
``noperspective`` attribute must instead vary linearly on the screen, so a new vertex takes it at
the screen parameter ``s = s_from_t(t, w_in, w_out)`` of the same point.

The near and far planes (``-w <= z <= w``) come first; together they keep every vertex at
``w >= 0``, in front of the eye. The side planes then keep the window coordinates small.
Everything is vectorized over triangles: one pass per plane.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp.lerp import _s_from_t

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
        Clip-space positions.
    smooth : (T, 3, K) array
        Attributes for perspective-correct (``smooth``) interpolation.
    noperspective : (T, 3, K) array
        Attributes for screen-linear (``noperspective``) interpolation. Equal to ``smooth``
        at the input vertices; they differ only at vertices made by clipping.
    source : (T,) int array
        Which input triangle each came from, in draw order.
    """

    clip: np.ndarray
    smooth: np.ndarray
    noperspective: np.ndarray
    source: np.ndarray

    def __len__(self) -> int:
        return len(self.source)

    def take(self, index: np.ndarray) -> ClippedTriangles:
        """The triangles at ``index`` (an integer or boolean array)."""
        return ClippedTriangles(
            self.clip[index], self.smooth[index], self.noperspective[index], self.source[index]
        )


def clip_triangles(
    clip: np.ndarray, attributes: np.ndarray, triangles: np.ndarray
) -> ClippedTriangles:
    """Clip indexed triangles against the view volume.

    Parameters
    ----------
    clip : (N, 4) float array
        Clip-space vertex positions.
    attributes : (N, K) float array
        Vertex attributes.
    triangles : (M, 3) int array
        Vertex indices, checked by the caller.

    Returns
    -------
    ClippedTriangles
        The visible pieces, in the input's draw order. A triangle inside the view volume comes out
        unchanged; one outside is dropped; one crossing a plane comes out as one or more pieces.

    Examples
    --------
    >>> clip = np.array([[0., 0, 0, 1], [0, 0, -3, 1], [1, 0, 0, 1]])   # vertex 1 beyond near
    >>> pieces = clip_triangles(clip, np.array([[0.], [1], [0]]), np.array([[0, 1, 2]]))
    >>> len(pieces), float(pieces.clip[0, :, 2].min())   # a quad: two triangles, z >= -w = -1
    (2, -1.0)
    """
    soup = ClippedTriangles(
        clip[triangles],
        attributes[triangles],
        attributes[triangles],
        np.arange(len(triangles)),
    )
    for plane in PLANES:
        soup = _clip_against(soup, plane)
    in_front = np.all(soup.clip[:, :, 3] > 0, axis=1)  # drops only degenerate pieces at the eye
    return soup.take(in_front)


def _clip_against(soup: ClippedTriangles, plane: np.ndarray) -> ClippedTriangles:
    """One Sutherland-Hodgman pass against one plane, for all triangles at once."""
    distance = soup.clip @ plane  # (T, 3), >= 0 inside
    inside = distance >= 0
    n_inside = inside.sum(axis=1)
    if np.all(n_inside == 3):
        return soup

    whole = soup.take(n_inside == 3)
    # One vertex inside: roll it to position 0; the piece is (v0, cut(v0, v1), cut(v0, v2)).
    one = n_inside == 1
    v0, v1, v2 = _rolled(soup.take(one), np.argmax(inside[one], axis=1), distance[one])
    cut01, cut02 = _cut(v0, v1), _cut(v0, v2)
    # Two inside: roll the outside one to position 0; the quad (v1, v2, cut(v2, v0), cut(v1, v0))
    # becomes two triangles. Rolling keeps each triangle's winding.
    two = n_inside == 2
    u0, u1, u2 = _rolled(soup.take(two), np.argmin(inside[two], axis=1), distance[two])
    cut20, cut10 = _cut(u2, u0), _cut(u1, u0)

    pieces = [
        (whole, None),
        (_assemble(v0, cut01, cut02), np.flatnonzero(one)),
        (_assemble(u1, u2, cut20), np.flatnonzero(two)),
        (_assemble(u1, cut20, cut10), np.flatnonzero(two)),
    ]
    parent = np.concatenate([np.flatnonzero(n_inside == 3)] + [index for _, index in pieces[1:]])
    order = np.argsort(parent, kind="stable")  # back into draw order
    return ClippedTriangles(
        *(np.concatenate([getattr(p, f) for p, _ in pieces])[order] for f in _FIELDS)
    )


_FIELDS = ("clip", "smooth", "noperspective", "source")


@dataclass(frozen=True)
class _Vertex:
    """One vertex of each of T triangles: clip position, attributes, plane distance."""

    clip: np.ndarray  # (T, 4)
    smooth: np.ndarray  # (T, K)
    noperspective: np.ndarray  # (T, K)
    source: np.ndarray  # (T,)
    distance: np.ndarray  # (T,)


def _rolled(soup: ClippedTriangles, first: np.ndarray, distance: np.ndarray) -> list[_Vertex]:
    """The three vertices of each triangle, cyclically rolled so vertex ``first`` comes first."""
    rows = np.arange(len(soup))
    vertices = []
    for k in range(3):
        i = (first + k) % 3
        vertices.append(
            _Vertex(
                soup.clip[rows, i],
                soup.smooth[rows, i],
                soup.noperspective[rows, i],
                soup.source,
                distance[rows, i],
            )
        )
    return vertices


def _cut(inner: _Vertex, outer: _Vertex) -> _Vertex:
    """The point where edge inner -> outer meets the plane.

    Always computed from the inside vertex towards the outside one, so two triangles sharing
    the edge make bit-identical vertices and no crack can open between them.
    """
    t = inner.distance / (inner.distance - outer.distance)  # in [0, 1): inner.distance >= 0 > outer
    point = inner.clip + t[:, None] * (outer.clip - inner.clip)
    # noperspective attributes are linear on the screen: use the screen parameter of the point,
    # s_from_t(t, w_in, w_out). The outer vertex may be behind the eye (w <= 0), where the screen
    # parameter means nothing; so may the point itself, only when the piece is degenerate (it is
    # dropped later), and then s = t stands in.
    in_front = point[:, 3] > 0  # then (1 - t) w_in + t w_out, the point's w, is > 0
    w_in, w_out = (np.where(in_front, v.clip[:, 3], 1.0) for v in (inner, outer))
    s = _s_from_t(t, w_in, w_out)  # = t where w_in = w_out = 1 stand in
    return _Vertex(
        point,
        inner.smooth + t[:, None] * (outer.smooth - inner.smooth),
        inner.noperspective + s[:, None] * (outer.noperspective - inner.noperspective),
        inner.source,
        np.zeros_like(t),
    )


def _assemble(a: _Vertex, b: _Vertex, c: _Vertex) -> ClippedTriangles:
    return ClippedTriangles(
        np.stack([a.clip, b.clip, c.clip], axis=1),
        np.stack([a.smooth, b.smooth, c.smooth], axis=1),
        np.stack([a.noperspective, b.noperspective, c.noperspective], axis=1),
        a.source,
    )
