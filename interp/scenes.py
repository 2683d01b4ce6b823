"""The standard setups the lessons draw.

Glossary
--------
ground plane : the square ``|x|, |z| <= size/2`` of the plane ``y = 0``, cut into
               ``quads x quads`` squares of two triangles each.
(u, v)       : texture coordinates, 0 to 1 across the plane (u along +x, v along -z).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp import _checks
from interp.camera import Camera
from interp.raster import MODES, Fragments, fragment_footprints, fragment_values, fragments
from interp.texture import MAX_FREQUENCY, _texel_error, checker


@dataclass(frozen=True)
class Scene:
    """Everything :func:`interp.rasterize` needs, plus the camera that made it.

    Attributes
    ----------
    clip : (N, 4) array
        Clip-space vertex positions.
    uv : (N, 2) array
        Texture coordinates per vertex.
    triangles : (M, 3) int array
        Vertex indices.
    camera : Camera
    """

    clip: np.ndarray
    uv: np.ndarray
    triangles: np.ndarray
    camera: Camera

    def __post_init__(self) -> None:
        clip = _checks.float_array(self.clip, "clip", (None, 4))
        uv = _checks.float_array(self.uv, "uv", (len(clip), 2))
        triangles = _checks.index_array(self.triangles, "triangles", len(clip), (None, 3))
        if not isinstance(self.camera, Camera):
            raise TypeError(f"camera must be an interp.Camera, got {type(self.camera).__name__}")
        for name, value in (("clip", clip), ("uv", uv), ("triangles", triangles)):
            object.__setattr__(self, name, value)


#: Most quads per side of the ground plane (4 * 256**2 vertices would already be silly).
MAX_QUADS = 256

#: The lessons' standard view: a 4 x 4 quad wholly in front of a camera looking down at it.
LESSON_SIZE = 4.0
LESSON_CAMERA = Camera(height=1.0, pitch=15.0, yaw=0.0, distance=3.0)


def ground_plane(
    camera: Camera | None = None, size: float = 8.0, quads: int = 16, **camera_parameters: float
) -> Scene:
    """A textured square on the ground, seen by ``camera``.

    Parameters
    ----------
    camera : Camera, optional
        The camera; if None, ``Camera(**camera_parameters)``.
    **camera_parameters : float
        Slider values instead of a camera: height, pitch, yaw, distance, fovy, near, far,
        aspect (see :class:`~interp.camera.Camera`).
    size : float
        Side of the square, in [1e-12, 1e12].
    quads : int
        Squares per side, in [1, 256]; each is two triangles (16 gives 512 triangles).
        Smaller triangles make affine interpolation less wrong: the PlayStation's remedy.

    Returns
    -------
    Scene

    Examples
    --------
    >>> scene = ground_plane(Camera(height=2.0, pitch=90.0, distance=0.0), size=2.0, quads=1)
    >>> scene.triangles
    array([[0, 1, 3],
           [0, 3, 2]])
    >>> scene.clip[:, 3]          # looking straight down: every vertex at depth 2
    array([2., 2., 2., 2.])
    >>> len(ground_plane(height=1.0, pitch=20.0).triangles)   # slider values work too
    512
    """
    if camera is None:
        camera = Camera(**camera_parameters)
    elif camera_parameters:
        raise TypeError("give either camera or camera parameters, not both")
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be an interp.Camera, got {type(camera).__name__}")
    size = _checks.scale(size, "size")
    quads = _checks.positive_int(quads, "quads", MAX_QUADS)

    steps = np.linspace(0.0, 1.0, quads + 1)
    u, v = np.meshgrid(steps, steps)  # vertex (row i, column j) has u = steps[j], v = steps[i]
    u, v = u.ravel(), v.ravel()
    world = np.stack([(u - 0.5) * size, np.zeros_like(u), (0.5 - v) * size, np.ones_like(u)], 1)
    clip = world @ (camera.projection @ camera.view).T

    corner = (np.arange(quads)[:, None] * (quads + 1) + np.arange(quads)).ravel()
    a, b, c, d = corner, corner + 1, corner + quads + 1, corner + quads + 2  # c d above a b
    triangles = np.stack([np.stack([a, b, d], 1), np.stack([a, d, c], 1)], 1).reshape(-1, 3)
    return Scene(clip, np.stack([u, v], 1), triangles, camera)


@dataclass(frozen=True)
class CheckerViews:
    """One frame of the checkerboard lesson: the same ground plane drawn two ways.

    Attributes
    ----------
    correct : (H, W) float array
        The checkerboard, perspective-correct (1 white, 0 black, ``background`` where nothing
        is drawn).
    approximate : (H, W) float array
        The same in ``mode`` (affine, or Quake's subdivided spans).
    error : (H, W) float array
        ``|Δ(u, v)|`` between the two, in texels; 0 where nothing is drawn.
    mode : str
        The approximate image's interpolation mode.
    fragments : Fragments
        What the rasterizer drew (coverage, depth, barycentrics).
    uv : dict
        Per-fragment texture coordinates, ``{"perspective": (2, P), mode: (2, P)}``; see
        :meth:`uv_image` for them as images.
    """

    correct: np.ndarray
    approximate: np.ndarray
    error: np.ndarray
    mode: str
    fragments: Fragments
    uv: dict[str, np.ndarray]

    @property
    def covered(self) -> np.ndarray:
        """(H, W) bool array: where the plane was drawn."""
        return self.fragments.covered

    def uv_image(self, mode: str = "perspective") -> np.ndarray:
        """(H, W, 2) float array: texture coordinates per pixel, 0 where nothing is drawn."""
        return self.fragments.image(self.uv[mode].T, 0.0)


def checker_views(
    scene: Scene,
    width: int = 512,
    height: int = 512,
    frequency: float = 8,
    filtered: bool = True,
    background: float = 0.5,
    mode: str = "affine",
    span: int = 16,
) -> CheckerViews:
    """Draw ``scene`` with a checkerboard, perspective-correct and approximately, and their
    difference.

    One slider step of the checkerboard lesson: the triangles are scan-converted once and
    interpolated both ways; everything is computed per drawn pixel and spread into images last.

    Parameters
    ----------
    scene : Scene
        E.g. from :func:`ground_plane`.
    width, height : int
        Image size, each in [1, 4096].
    frequency : float
        Checks per unit of (u, v), in (0, 1024].
    filtered : bool
        Average the checkerboard over each pixel's footprint (anti-aliased, using the exact
        screen derivatives of (u, v)) or sample it at the pixel centre.
    background : float
        Image value where nothing is drawn.
    mode : {"affine", "subdivided", "perspective"}
        How to draw the approximate image.
    span : int
        For ``"subdivided"``: pixels between exact values.

    Returns
    -------
    CheckerViews

    Examples
    --------
    Looking straight down, every vertex has the same w, so both ways agree exactly:

    >>> scene = ground_plane(Camera(height=2.0, pitch=90.0, distance=0.0), quads=1)
    >>> views = checker_views(scene, 32, 32)
    >>> float(views.error.max())
    0.0
    """
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be an interp.Scene, got {type(scene).__name__}")
    frequency = _checks.real_in(frequency, "frequency", 0, MAX_FREQUENCY, low_open=True)
    if not isinstance(filtered, (bool, np.bool_)):
        raise TypeError("filtered must be True or False")
    background = _checks.real(background, "background")
    mode = _checks.choice(mode, "mode", MODES)
    span = _checks.positive_int(span, "span")

    frags = fragments(scene.clip, scene.uv, scene.triangles, width, height)
    uv = {"perspective": fragment_values(frags, "perspective")}
    uv[mode] = fragment_values(frags, mode, span)

    def texture(mode: str) -> np.ndarray:
        p, q = uv[mode] * frequency  # texel coordinates
        if not filtered:
            return frags.image(checker(p, q), background)
        footprint_p, footprint_q = fragment_footprints(frags, mode, uv[mode]) * frequency
        return frags.image(checker(p, q, footprint_p, footprint_q), background)

    error = _texel_error(uv[mode], uv["perspective"], frequency)
    return CheckerViews(
        correct=texture("perspective"),
        approximate=texture(mode),
        error=frags.image(error, 0.0),
        mode=mode,
        fragments=frags,
        uv=uv,
    )
