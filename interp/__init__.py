"""interp: perspective-correct interpolation, from a line on a 1D screen to a GPU's rasterizer.

The public names, by the lesson that introduces them:

- 1D story (:mod:`interp.lerp`): :func:`s_from_t`, :func:`t_from_s`,
  :func:`project_to_image_plane`, :func:`lerp_affine`, :func:`lerp_perspective`,
  :func:`lerp_inverse_w`, :func:`gap_peak`.
- Cameras (:mod:`interp.camera`): :func:`perspective`, :func:`look_at`, :class:`Camera`.
- Triangles (:mod:`interp.raster`, :mod:`interp.clipping`, :mod:`interp.barycentric`):
  :func:`rasterize`, :func:`fragments`, :func:`interpolate`, :func:`clip_triangles`,
  :func:`viewport`, :func:`perspective_weights`.
- Depth (:mod:`interp.depth`): :func:`ndc_depth`, :func:`window_depth`, :func:`depth_resolution`.
- Textures and scenes: :func:`checkerboard`, :func:`texel_error`, :func:`ground_plane`.
- For the lessons: :mod:`interp.plots` (figures), :mod:`interp.apps` (live sliders),
  :mod:`interp.check` (exercise checkers), :mod:`interp.mistakes`, :mod:`interp.approximation`.
"""

from interp.barycentric import perspective_weights
from interp.camera import Camera, look_at, perspective
from interp.clipping import ClippedTriangles, clip_triangles
from interp.depth import depth_resolution, ndc_depth, window_depth
from interp.lerp import (
    gap_peak,
    lerp_affine,
    lerp_inverse_w,
    lerp_perspective,
    project_to_image_plane,
    s_from_t,
    t_from_s,
)
from interp.raster import MODES, Fragments, fragments, interpolate, rasterize, viewport
from interp.scenes import Scene, ground_plane
from interp.texture import checkerboard, texel_error

__all__ = [
    "MODES",
    "Camera",
    "ClippedTriangles",
    "Fragments",
    "Scene",
    "checkerboard",
    "clip_triangles",
    "depth_resolution",
    "fragments",
    "gap_peak",
    "ground_plane",
    "interpolate",
    "lerp_affine",
    "lerp_inverse_w",
    "lerp_perspective",
    "look_at",
    "ndc_depth",
    "perspective",
    "perspective_weights",
    "project_to_image_plane",
    "rasterize",
    "s_from_t",
    "t_from_s",
    "texel_error",
    "viewport",
    "window_depth",
]
