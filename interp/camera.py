"""Cameras: the projection matrix, the view matrix, and a ground-plane camera for the lessons.

Conventions are OpenGL's: right-handed view space, the camera at the origin looking down -z,
clip coordinates ``(x, y, z, w)`` with ``w = -z_view`` (the view depth), NDC in ``[-1, 1]^3``.

Glossary
--------
fovy   : vertical field of view, in degrees.
aspect : width / height of the image.
near   : distance to the near clipping plane (> 0).
far    : distance to the far clipping plane (> near).
eye    : where the camera is; target: a point it looks at; up: which way is up.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from interp import _checks

#: The narrowest field of view, in degrees (a telescope's is about 0.01).
MIN_FOVY = 1e-6


def perspective(fovy_degrees: float, aspect: float, near: float, far: float) -> np.ndarray:
    """The perspective projection matrix of ``gluPerspective``.

    Parameters
    ----------
    fovy_degrees : float
        Vertical field of view in degrees, in [1e-6, 180).
    aspect : float
        Width / height, in [1e-12, 1e12].
    near, far : float
        Distances to the near and far planes, ``1e-12 <= near < far <= 1e12``.

    Returns
    -------
    (4, 4) array
        Maps view space to clip space. Its last row is ``(0, 0, -1, 0)``, so the clip-space
        ``w`` of a point is its view depth ``-z``: the number perspective-correct
        interpolation divides by.

    Examples
    --------
    >>> P = perspective(90, 1.0, 1.0, 3.0)
    >>> P @ [0, 0, -1, 1]            # a point on the near plane lands at NDC z = -1
    array([ 0.,  0., -1.,  1.])
    >>> clip = P @ [0, 0, -3, 1]     # on the far plane: z / w = +1
    >>> float(clip[2] / clip[3])
    1.0
    """
    fovy = _fovy(fovy_degrees, "fovy_degrees")
    aspect = _checks.scale(aspect, "aspect")
    near, far = _planes(near, far)
    f = 1.0 / np.tan(np.radians(fovy) / 2)
    return np.array(
        [
            [f / aspect, 0.0, 0.0, 0.0],
            [0.0, f, 0.0, 0.0],
            [0.0, 0.0, (far + near) / (near - far), 2 * far * near / (near - far)],
            [0.0, 0.0, -1.0, 0.0],
        ]
    )


def _fovy(value: object, name: str) -> float:
    return _checks.real_in(value, name, MIN_FOVY, 180, high_open=True)


def _planes(near: object, far: object) -> tuple[float, float]:
    near = _checks.scale(near, "near")
    far = _checks.scale(far, "far")
    if far <= near:
        raise ValueError(f"far must be greater than near ({near:g}), got {far:g}")
    return near, far


def look_at(eye: object, target: object, up: object) -> np.ndarray:
    """The view matrix of ``gluLookAt``: world space to view space.

    Parameters
    ----------
    eye, target : (3,) array_like
        Where the camera is and a point it looks at; they must differ. Coordinates in
        [-1e12, 1e12].
    up : (3,) array_like
        Which way is up; must not be zero or parallel to ``target - eye``.

    Returns
    -------
    (4, 4) array
        A rigid motion taking ``eye`` to the origin and ``target`` onto the -z axis.

    Examples
    --------
    >>> V = look_at(eye=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0])
    >>> V @ [0, 0, 0, 1]             # the target is 5 units in front: z = -5
    array([ 0.,  0., -5.,  1.])
    """
    eye, target, up = (
        _point(p, name) for p, name in ((eye, "eye"), (target, "target"), (up, "up"))
    )
    forward = target - eye
    if not forward.any():
        raise ValueError("eye and target must differ")
    forward = _unit(forward)
    side = np.cross(forward, _unit(up) if up.any() else up)
    if np.linalg.norm(side) <= 1e-12:
        raise ValueError("up must not be zero or parallel to the view direction target - eye")
    side = side / np.linalg.norm(side)
    true_up = np.cross(side, forward)
    view = np.eye(4)
    view[0, :3], view[1, :3], view[2, :3] = side, true_up, -forward
    view[:3, 3] = -view[:3, :3] @ eye
    return view


def _point(value: object, name: str) -> np.ndarray:
    point = _checks.float_array(value, name, (3,))
    return _checks.in_range(point, name, -_checks.MAX_MAGNITUDE, _checks.MAX_MAGNITUDE)


def _unit(v: np.ndarray) -> np.ndarray:
    """``v / |v|``, scaled first so that a tiny v (1e-300) does not underflow on the way."""
    v = v / np.abs(v).max()
    return v / np.linalg.norm(v)


@dataclass(frozen=True)
class Camera:
    """A camera above the ground plane ``y = 0``, described by the lessons' slider values.

    The camera stands ``distance`` away from the world origin horizontally, at ``height``
    above the ground, on the side given by ``yaw``; it faces the origin's direction horizontally,
    tilts down by ``pitch`` degrees (90 looks straight down, 0 at the horizon) and turns the
    picture by ``roll`` degrees about its line of sight. (Without roll, every image row of the
    ground lies at one depth, so affine interpolation is exact along rows: Doom's floors.)

    Parameters
    ----------
    height : float
        Height of the eye above the ground (may be 0 or negative: the camera is then in or
        below the plane), in [-1e12, 1e12].
    pitch : float
        Degrees below the horizon, in [-89, 90].
    yaw : float
        Degrees of rotation about the vertical axis, in [-1e12, 1e12].
    distance : float
        Horizontal distance from the origin, in [0, 1e12].
    fovy : float
        Vertical field of view in degrees, in [1e-6, 180).
    near, far : float
        Clipping distances, ``1e-12 <= near < far <= 1e12``.
    aspect : float
        Width / height of the image, in [1e-12, 1e12].
    roll : float
        Degrees of rotation about the line of sight, in [-1e12, 1e12].

    Examples
    --------
    >>> cam = Camera(height=2.0, pitch=90.0, distance=0.0)
    >>> cam.eye
    array([0., 2., 0.])
    >>> cam.view @ [0, 0, 0, 1]      # looking straight down: the origin is 2 units ahead
    array([ 0.,  0., -2.,  1.])
    >>> Camera(height=np.array(2), pitch=90).height   # any real number, kept as a float
    2.0
    """

    height: float = 1.0
    pitch: float = 20.0
    yaw: float = 0.0
    distance: float = 3.0
    fovy: float = 60.0
    near: float = 0.1
    far: float = 100.0
    aspect: float = 1.0
    roll: float = 0.0

    def __post_init__(self) -> None:
        _checks.number(self.height, "height")
        _checks.real_in(self.pitch, "pitch", -89, 90)
        _checks.number(self.yaw, "yaw")
        _checks.real_in(self.distance, "distance", 0, _checks.MAX_MAGNITUDE)
        _checks.number(self.roll, "roll")
        _fovy(self.fovy, "fovy")
        _checks.scale(self.aspect, "aspect")
        _planes(self.near, self.far)
        for name in (f.name for f in fields(self)):  # held as Python floats: hashable, exact
            object.__setattr__(self, name, float(getattr(self, name)))

    @property
    def eye(self) -> np.ndarray:
        """(3,) array: the camera's position in world space."""
        yaw = np.radians(self.yaw)
        return np.array(
            [self.distance * np.sin(yaw), float(self.height), self.distance * np.cos(yaw)]
        )

    @property
    def view(self) -> np.ndarray:
        """(4, 4) array: world to view space, built from rotations so pitch = 90 is fine."""
        yaw, pitch = np.radians(self.yaw), np.radians(self.pitch)
        rotate_yaw = np.array(  # undo the yaw: turn about +y by -yaw
            [[np.cos(yaw), 0, -np.sin(yaw)], [0, 1, 0], [np.sin(yaw), 0, np.cos(yaw)]]
        )
        rotate_pitch = np.array(  # tilt the view down by pitch: turn about +x by +pitch
            [[1, 0, 0], [0, np.cos(pitch), -np.sin(pitch)], [0, np.sin(pitch), np.cos(pitch)]]
        )
        roll = np.radians(self.roll)
        rotate_roll = np.array(  # turn the picture: about the view axis -z
            [[np.cos(roll), np.sin(roll), 0], [-np.sin(roll), np.cos(roll), 0], [0, 0, 1]]
        )
        view = np.eye(4)
        view[:3, :3] = rotate_roll @ rotate_pitch @ rotate_yaw
        view[:3, 3] = -view[:3, :3] @ self.eye
        return view

    def fitted(self, width: int, height: int) -> Camera:
        """The same camera with ``aspect = width / height``, for an image of that size.

        Examples
        --------
        >>> Camera().fitted(640, 480).aspect
        1.3333333333333333
        """
        return replace(
            self,
            aspect=_checks.positive_int(width, "width") / _checks.positive_int(height, "height"),
        )

    @property
    def projection(self) -> np.ndarray:
        """(4, 4) array: ``perspective(fovy, aspect, near, far)``."""
        return perspective(self.fovy, self.aspect, self.near, self.far)
