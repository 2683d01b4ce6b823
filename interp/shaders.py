"""The shader's view: GLSL's interpolation qualifiers, and the mistake students make in shaders.

A vertex shader writes ``gl_Position``, a clip-space position ``(x, y, z, w)``, and its outputs.
How each output reaches the fragment shader is chosen by its *interpolation qualifier*
(GLSL 4.60, section 4.5; OpenGL 4.6, section 14.6.1):

- ``smooth`` (the default): perspective-correct, OpenGL's eq. 14.9; ``mode="perspective"`` of
  :func:`interp.rasterize`.
- ``noperspective``: linear in screen space (the screen-space barycentrics);
  ``mode="affine"``.
- ``flat``: not interpolated at all. Every fragment of a triangle gets the value of one vertex,
  the *provoking vertex*: the last of the three by default (``GL_LAST_VERTEX_CONVENTION``), the
  first after ``glProvokingVertex(GL_FIRST_VERTEX_CONVENTION)``. Clipping does not change
  which vertex provokes: it is the input triangle's.

The mistake: a vertex shader that does the perspective divide itself, ``gl_Position =
vec4(p.xyz / p.w, 1.0)``. The picture lands in the same place (OpenGL divides by ``w = 1``
again), but every vertex now reports ``w = 1``, so ``smooth`` has nothing to correct with and
becomes ``noperspective``. And a vertex behind the camera (``w < 0``) is divided *before*
clipping could cut it away, so it is mirrored into view. :func:`divide_in_vertex_shader` makes
exactly the clip coordinates such a shader writes; ``tests/test_shaders.py`` draws them on
llvmpipe with a real vertex shader that divides.
"""

from __future__ import annotations

import numpy as np

from interp import _checks
from interp.clipping import MAX_COORDINATE
from interp.raster import _check_scene, fragments, interpolate

#: GLSL's interpolation qualifiers and the :func:`interp.rasterize` mode each one is.
QUALIFIERS = {"smooth": "perspective", "noperspective": "affine", "flat": "flat"}

#: OpenGL's default provoking vertex: the last vertex of each triangle.
PROVOKING_VERTEX = 2


def divide_in_vertex_shader(clip: object) -> np.ndarray:
    """The clip coordinates a vertex shader writes when it divides by w itself:
    ``(x/w, y/w, z/w, 1)``.

    Parameters
    ----------
    clip : (N, 4) array_like
        The clip coordinates it should have written, every ``w != 0``.

    Returns
    -------
    (N, 4) float array

    Examples
    --------
    >>> divide_in_vertex_shader([[1.0, 2.0, 0.5, 2.0], [1.0, 1.0, 1.0, -1.0]])
    array([[ 0.5 ,  1.  ,  0.25,  1.  ],
           [-1.  , -1.  , -1.  ,  1.  ]])
    """
    clip = _checks.float_array(clip, "clip", (None, 4))
    if np.any(clip[:, 3] == 0):
        raise ValueError("clip must have w != 0 at every vertex: dividing by 0 has no answer")
    divided = np.ones_like(clip)
    divided[:, :3] = clip[:, :3] / clip[:, 3:4]
    return divided


def drawable(clip: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Which triangles a divided scene can still be drawn from: those whose vertices all have
    ``w != 0`` and land within :data:`interp.clipping.MAX_COORDINATE` after the division (a vertex
    very near the camera's plane lands near infinity).

    Examples
    --------
    >>> clip = np.array([[0, 0, 0, 1.0], [1, 0, 0, 1], [0, 1, 0, 0], [0, 1, 0, 1]])
    >>> drawable(clip, np.array([[0, 1, 2], [0, 1, 3]]))
    array([False,  True])
    """
    w = clip[:, 3]
    with np.errstate(divide="ignore", invalid="ignore"):
        far = np.abs(clip[:, :3]).max(axis=1) > MAX_COORDINATE * np.abs(w)
    bad = (w == 0) | far
    return ~bad[triangles].any(axis=1)


def shade(
    clip: object,
    attributes: object,
    triangles: object,
    width: int,
    height: int,
    qualifier: str = "smooth",
    divided: bool = False,
) -> tuple[np.ndarray, np.ndarray]:
    """Draw triangles as OpenGL does with a vertex shader output of the given qualifier.

    Parameters
    ----------
    clip, attributes, triangles, width, height
        As for :func:`interp.rasterize`.
    qualifier : {"smooth", "noperspective", "flat"}
        The output's interpolation qualifier (see :data:`QUALIFIERS`). ``flat`` takes each
        triangle's last vertex (:data:`PROVOKING_VERTEX`).
    divided : bool
        The vertex shader divided by w itself (:func:`divide_in_vertex_shader`); triangles with
        a vertex it sends to infinity are left out (see :func:`drawable`).

    Returns
    -------
    values : (height, width, K) float array
        0 where nothing is drawn.
    covered : (height, width) bool array

    Examples
    --------
    A quad whose top edge is three times as far as its bottom: dividing in the vertex shader
    makes ``smooth`` the same as ``noperspective``.

    >>> clip = [[-1, -1, 0, 1], [1, -1, 0, 1], [3, 3, 0, 3], [-3, 3, 0, 3]]
    >>> uv, quad = [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1, 2], [0, 2, 3]]
    >>> mistake, _ = shade(clip, uv, quad, 8, 8, "smooth", divided=True)
    >>> affine, _ = shade(clip, uv, quad, 8, 8, "noperspective")
    >>> bool(np.allclose(mistake, affine))
    True
    >>> flat, _ = shade(clip, uv, quad, 8, 8, "flat")
    >>> sorted({tuple(v) for v in flat.reshape(-1, 2).tolist()})   # vertices 2 and 3
    [(0.0, 1.0), (1.0, 1.0)]
    """
    clip, attributes, triangles = _check_scene(clip, attributes, triangles)
    qualifier = _checks.choice(qualifier, "qualifier", tuple(QUALIFIERS))
    if not isinstance(divided, (bool, np.bool_)):
        raise TypeError("divided must be True or False")
    if divided:
        triangles = triangles[drawable(clip, triangles)]
        used = np.zeros(len(clip), dtype=bool)
        used[triangles] = True
        clip = divide_in_vertex_shader(np.where(used[:, None], clip, [0.0, 0.0, 0.0, 1.0]))
    frags = fragments(clip, attributes, triangles, width, height)
    if qualifier == "flat":
        provoking = triangles[frags.triangle, PROVOKING_VERTEX]
        return frags.image(attributes[provoking], 0.0), frags.covered
    return interpolate(frags, QUALIFIERS[qualifier]), frags.covered
