"""The camera seen from outside: its frustum, image plane and pixel rays in world space, and what
clipping did to the scene, for the outside view (:class:`interp.plots.outside.OutsideView`).

The camera sees what lies inside its *frustum*: the pyramid from the eye through the edges of
the image, cut by the near plane (view depth ``near``) and the far plane (depth ``far``). Each
pixel shows what its *ray*, from the eye through the pixel's centre on the image plane, meets
first. Clipping (:func:`interp.clip_triangles`) cuts every triangle down to the frustum in clip
space; here its pieces are carried back to world space, with the vertices clipping made, and
the parts the near plane cut off (those nearer than it, and those behind the eye).

Glossary
--------
view depth     : distance in front of the eye along its line of sight (clip-space w).
image plane    : the plane at view depth ``image_distance`` (1 unless given) where the image
                 forms; its rectangle spans the field of view.
reach          : how far the drawn frustum goes: the far plane, or less where it would
                 leave the picture (the far plane is usually much further than the scene).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp import _checks
from interp.camera import Camera
from interp.clipping import PLANES, _clip_against, _Soup, clip_triangles
from interp.raster import drawn
from interp.scenes import Scene

#: The image's corners in NDC (x, y), counter-clockwise from the bottom left.
CORNERS = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])


def to_world(camera: Camera, view_points: np.ndarray) -> np.ndarray:
    """View-space points (..., 3) in world space.

    Examples
    --------
    >>> cam = Camera(height=2.0, pitch=90.0, distance=0.0)
    >>> to_world(cam, np.array([0.0, 0.0, -2.0])).round(12)     # 2 ahead of an eye looking down
    array([ 0.,  0., -0.])
    """
    rotation = camera.view[:3, :3]
    return view_points @ rotation + camera.eye  # rotation.T @ p, for each p


def section(camera: Camera, depth: float | np.ndarray) -> np.ndarray:
    """The frustum's cross-section at view depth ``depth``: its four corners in world space,
    counter-clockwise as the image shows them, from the bottom left.

    Parameters
    ----------
    camera : Camera
    depth : float or (D,) array
        One depth, or several.

    Returns
    -------
    (4, 3) array, or (D, 4, 3) for several depths

    Examples
    --------
    >>> cam = Camera(height=2.0, pitch=90.0, distance=0.0, fovy=90.0)
    >>> section(cam, 2.0)[:, [0, 2]].round(12)      # on the ground, 2 below: a 4 x 4 square
    array([[-2.,  2.],
           [ 2.,  2.],
           [ 2., -2.],
           [-2., -2.]])
    >>> section(cam, np.array([1.0, 2.0])).shape
    (2, 4, 3)
    """
    depth = np.asarray(depth, dtype=float)
    half_height = depth[..., None] * np.tan(np.radians(camera.fovy) / 2)  # (..., 1)
    x = CORNERS[:, 0] * half_height * camera.aspect
    y = CORNERS[:, 1] * half_height
    z = np.broadcast_to(-depth[..., None], x.shape)
    return to_world(camera, np.stack([x, y, z], axis=-1))


def clip_to_world(camera: Camera, clip: np.ndarray) -> np.ndarray:
    """Clip-space points (..., 4) back in world space (..., 3), through ``(P V)^-1``.

    Clipping makes points as convex combinations of clip-space points; ``(P V)^-1`` is linear,
    so they land on the same combinations of the world points (homogeneous w stays 1), also
    for points behind the eye (clip w < 0).

    Examples
    --------
    >>> cam = Camera()
    >>> world = np.array([1.0, 0.0, -1.0, 1.0])
    >>> clip_to_world(cam, cam.projection @ cam.view @ world).round(12)
    array([ 1.,  0., -1.])
    """
    homogeneous = clip @ np.linalg.inv(camera.projection @ camera.view).T
    return homogeneous[..., :3] / homogeneous[..., 3:4]


def pixel_centres(width: int, height: int, per_side: int) -> np.ndarray:
    """Window positions ``(x, y)`` of ``per_side x per_side`` pixel centres spread evenly over the
    image (y up, as OpenGL's window coordinates).

    Examples
    --------
    >>> pixel_centres(320, 240, 2)
    array([[ 80.5,  60.5],
           [240.5,  60.5],
           [ 80.5, 180.5],
           [240.5, 180.5]])
    """
    spread = (np.arange(per_side) + 0.5) / per_side
    columns = np.floor(spread * width) + 0.5
    rows = np.floor(spread * height) + 0.5
    x, y = np.meshgrid(columns, rows)
    return np.stack([x.ravel(), y.ravel()], axis=1)


@dataclass(frozen=True)
class Rays:
    """Rays from the eye through pixel centres, and where they meet the ground plane.

    Attributes
    ----------
    pixel : (R, 2) array
        Window positions of the pixel centres.
    on_image_plane : (R, 3) array
        Where each ray crosses the image plane, in world space.
    end : (R, 3) array
        Where the ray meets the ground (y = 0), or, if it never does in front of the eye, its
        point at the frustum's reach.
    hits : (R,) bool array
        The ray meets the ground quad inside the view volume there: the pixel shows the quad.
    depth : (R,) array
        View depth of ``end``.
    """

    pixel: np.ndarray
    on_image_plane: np.ndarray
    end: np.ndarray
    hits: np.ndarray
    depth: np.ndarray


def pixel_rays(
    camera: Camera,
    width: int,
    height: int,
    per_side: int = 3,
    quad_size: float = 4.0,
    reach: float | None = None,
    image_distance: float = 1.0,
) -> Rays:
    """Rays through ``per_side x per_side`` pixels of a ``width x height`` image of ``camera``.

    Parameters
    ----------
    camera : Camera
        Its aspect should be ``width / height`` (:meth:`Camera.fitted`).
    width, height : int
        The image's size in pixels.
    per_side : int
        Rays per side of the image.
    quad_size : float
        Side of the ground quad ``|x|, |z| <= quad_size / 2`` on the plane y = 0.
    reach : float, optional
        View depth where a ray that misses the ground ends; the far plane if None.
    image_distance : float
        View depth of the image plane.

    Examples
    --------
    One ray, through the centre of the image of a camera 2 above the ground looking down:

    >>> rays = pixel_rays(Camera(height=2.0, pitch=90.0, distance=0.0), 1, 1, per_side=1)
    >>> rays.end.round(12), rays.hits, rays.depth
    (array([[ 0.,  0., -0.]]), array([ True]), array([2.]))
    """
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    per_side = _checks.positive_int(per_side, "per_side", 64)
    reach = camera.far if reach is None else _checks.real_in(reach, "reach", 0, None)
    pixel = pixel_centres(width, height, per_side)
    ndc = 2 * pixel / [width, height] - 1
    tangent = np.tan(np.radians(camera.fovy) / 2)
    direction = np.stack(  # in view space, one unit of depth per unit of length along -z
        [ndc[:, 0] * tangent * camera.aspect, ndc[:, 1] * tangent, -np.ones(len(ndc))], axis=1
    )
    world_direction = direction @ camera.view[:3, :3]
    eye = camera.eye
    with np.errstate(divide="ignore", invalid="ignore"):
        depth = -eye[1] / world_direction[:, 1]  # where y = 0, in view depth
    meets = np.isfinite(depth) & (depth > 0)
    depth = np.where(meets, depth, reach)
    end = eye + depth[:, None] * world_direction
    inside = np.all(np.abs(end[:, [0, 2]]) <= quad_size / 2, axis=1)
    hits = meets & inside & (depth >= camera.near) & (depth <= camera.far)
    return Rays(
        pixel=pixel,
        on_image_plane=eye + image_distance * world_direction,
        end=end,
        hits=hits,
        depth=depth,
    )


@dataclass(frozen=True)
class ClippedScene:
    """What clipping did to a scene, in world space.

    Attributes
    ----------
    visible : (T, 3, 3) array
        The pieces inside the view volume (the rasterizer draws these).
    cut_off : (C, 3, 3) array
        The pieces the near plane removed: nearer to the eye than the near plane, or behind it.
    new_vertices : (N, 3) array
        The vertices clipping made (on the planes of the view volume), each once.
    in_view : int
        How many input triangles have a visible piece.
    """

    visible: np.ndarray
    cut_off: np.ndarray
    new_vertices: np.ndarray
    in_view: int


def clipped_in_world(scene: Scene, width: int, height: int) -> ClippedScene:
    """Clip ``scene``'s triangles as the rasterizer does at ``width`` x ``height`` pixels and
    carry the pieces it draws to world space.

    Pieces the rasterizer leaves out, having no area on screen, are left out: a plane through
    a corner makes some, and a camera in the ground's plane sees every piece edge-on.

    Examples
    --------
    A camera just above the middle of the plane, looking ahead: the part of the plane behind it
    is cut off by the near plane, and clipping makes new vertices where the planes cross it.

    >>> from interp.scenes import ground_plane
    >>> scene = ground_plane(Camera(height=0.3, pitch=15.0, distance=1.0), size=4.0, quads=2)
    >>> clipped = clipped_in_world(scene, 320, 240)
    >>> len(clipped.visible) > clipped.in_view, len(clipped.cut_off) > 0
    (True, True)
    >>> bool(np.allclose(clipped.new_vertices[:, 1], 0.0))    # all on the ground
    True
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be an interp.Scene, got {type(scene).__name__}")
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    camera = scene.camera
    pieces = clip_triangles(scene.clip, scene.uv, scene.triangles)
    # The other side of the near plane (z < -w), with clipping's own one-plane pass: positions
    # only, no attributes.
    whole = _Soup(scene.clip[scene.triangles], np.arange(len(scene.triangles)))
    before_near = _clip_against(whole, -PLANES[0]).vertices[:, :, :4]
    counts = np.cumsum([0, 3 * len(pieces.clip), 3 * len(before_near)])
    world = clip_to_world(  # one inverse for both
        camera, np.concatenate([pieces.clip.reshape(-1, 4), before_near.reshape(-1, 4)])
    )
    visible = world[: counts[1]].reshape(-1, 3, 3)
    cut_off = world[counts[1] :].reshape(-1, 3, 3)

    # Clipping keeps an input vertex bit for bit, but for a power of two (it scales each
    # triangle so); any other vertex is new.
    original = _unit(scene.clip[scene.triangles[pieces.source]])  # (T, 3, 4) the input triangles
    same = np.all(_unit(pieces.clip)[:, :, None, :] == original[:, None, :, :], axis=3)
    is_new = ~np.any(same, axis=2)
    kept = drawn(pieces.clip, width, height)
    scale = max(float(np.abs(visible).max()), 1.0) if len(visible) else 1.0
    new = visible[is_new & kept[:, None]]
    if len(new):  # each point once, though neighbouring pieces share it (to rounding)
        new = new[np.unique(np.round(new / scale, 9), axis=0, return_index=True)[1]]
    return ClippedScene(
        visible=visible[kept],
        cut_off=cut_off,
        new_vertices=new,
        in_view=len(np.unique(pieces.source[kept])),
    )


def _unit(points: np.ndarray) -> np.ndarray:
    """Homogeneous points (..., 4) each scaled by a power of two to a largest coordinate in
    [1/2, 1): exact, so two points equal up to such a scale become equal bit for bit."""
    _, exponent = np.frexp(np.abs(points).max(axis=-1, keepdims=True))
    return np.ldexp(points, -exponent)


def reach_of(camera: Camera, points: np.ndarray, default: float) -> float:
    """How far to draw the frustum: to the farthest of ``points`` (N, 3) in front of the eye, but
    within ``[near, far]``; ``default`` (clamped likewise) if none is in front.

    Examples
    --------
    >>> cam = Camera(height=2.0, pitch=90.0, distance=0.0)
    >>> reach_of(cam, np.array([[0.0, 0.0, 0.0], [0.0, 5.0, 0.0]]), 10.0)   # 2 ahead, 3 behind
    2.0
    """
    depth = -(np.c_[points, np.ones(len(points))] @ camera.view.T)[:, 2]
    ahead = depth[depth > 0]
    farthest = float(ahead.max()) if ahead.size else default
    return float(np.clip(farthest, camera.near, camera.far))
