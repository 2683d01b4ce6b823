"""Depth: what a depth buffer stores, and how finely it can tell depths apart.

Glossary
--------
w      : view depth, the distance in front of the camera (clip-space w), > 0.
near, far : the clipping distances of :func:`interp.perspective`.
NDC z  : ``z_clip / w``, from -1 at the near plane to +1 at the far plane. It equals
         ``A + B / w`` (A, B from the projection matrix), so it is an affine function of 1/w,
         and 1/w is linear on the screen: a depth buffer may interpolate it linearly
         (blog post on attribute interpolation; Lengyel).
window z : ``(NDC z + 1) / 2`` in [0, 1], what the depth buffer stores.
"""

from __future__ import annotations

import numpy as np

from interp import _checks
from interp.camera import _planes


def _view_depth(w: object) -> np.ndarray:
    return _checks.depth_array(w, "w")


def ndc_depth(w: object, near: float, far: float) -> np.ndarray | float:
    """NDC z at view depth ``w``: ``(far + near)/(far - near) - 2 far near / ((far - near) w)``.

    View depths ``w`` lie in [1e-12, 1e12], and ``1e-12 <= near < far <= 1e12``.

    Examples
    --------
    >>> ndc_depth([1.0, 10.0], near=1.0, far=10.0)
    array([-1.,  1.])
    """
    z = _ndc_depth(_view_depth(w), *_planes(near, far))
    return z.item() if z.ndim == 0 else z


def _ndc_depth(w: np.ndarray, near: float, far: float) -> np.ndarray:
    """``z_clip / w`` for the matrix of :func:`interp.perspective`: ``A + B / w``.

    ``A + B / w = (far + near)/(far - near) - 2 far near / ((far - near) w)``, written over one
    denominator, ``(far (w - near) + near (w - far)) / ((far - near) w)``, so that the near and
    far planes land on exactly -1 and +1.
    """
    return (far * (w - near) + near * (w - far)) / ((far - near) * w)


def _window_depth(w: np.ndarray, near: float, far: float) -> np.ndarray:
    """``(NDC z + 1) / 2``."""
    return (_ndc_depth(w, near, far) + 1) / 2


def window_depth(w: object, near: float, far: float) -> np.ndarray | float:
    """What the depth buffer stores for view depth ``w``: ``(NDC z + 1) / 2``, in [0, 1]
    for ``near <= w <= far`` (exactly 0 and 1 on the planes).

    Examples
    --------
    >>> window_depth(1.0, near=1.0, far=10.0), window_depth(10.0, near=1.0, far=10.0)
    (0.0, 1.0)
    >>> round(window_depth(2.0, near=1.0, far=10.0), 4)   # 1/9 of the way in w, over half in z
    0.5556
    """
    z = _window_depth(_view_depth(w), *_planes(near, far))
    return z.item() if z.ndim == 0 else z


def depth_resolution(
    w: object, near: float, far: float, buffer: str = "float32"
) -> np.ndarray | float:
    """The smallest change of view depth the depth buffer notices at depth ``w``.

    One step of the stored window z (the float32 spacing there, or ``2**-24`` for a 24-bit
    fixed-point buffer) divided by how fast window z changes with w,
    ``d z_window / d w = far near / ((far - near) w**2)``. For ``fixed24`` it grows like
    ``w**2 / near``: halve ``near`` and every depth gets about twice as coarse. ``float32`` is
    the same wherever window z >= 1/2 and finer only in front of that (:func:`depth_step`).

    Parameters
    ----------
    w : array_like
        View depths, in [1e-12, 1e12].
    near, far : float
        The clipping distances, ``1e-12 <= near < far <= 1e12``.
    buffer : {"float32", "fixed24"}
        The depth buffer's format.

    Examples
    --------
    >>> r = depth_resolution([1.0, 100.0], near=0.1, far=1000.0, buffer="fixed24")
    >>> bool(r[1] / r[0] > 9999)      # 100 times further: 10000 times coarser
    True
    """
    w = _view_depth(w)
    near, far = _planes(near, far)
    buffer = _checks.choice(buffer, "buffer", ("float32", "fixed24"))
    stored = _window_depth(w, near, far).astype(np.float32)
    step = np.abs(np.spacing(stored)).astype(np.float64) if buffer == "float32" else 2.0**-24
    result = step * (far - near) * w**2 / (far * near)
    return result.item() if np.ndim(result) == 0 else result


# --- Reversed Z and float depth (lesson 4) ---------------------------------------------------
#
# Added below the functions above, which they reuse; see Reed, "Depth Precision Visualized"
# (NVIDIA, 2015) for the same analysis with pictures.

#: The depth buffers :func:`depth_step` knows: what is stored, and in which number format.
DEPTH_BUFFERS = ("float32", "fixed24", "float32 reversed", "fixed24 reversed")


def reversed_depth(w: object, near: float, far: float) -> np.ndarray | float:
    """What a *reversed-Z* depth buffer stores at view depth ``w``: 1 at the near plane, 0 at
    the far plane, ``near (far - w) / (w (far - near))``.

    Mathematically it is ``1 - window_depth(w)``, but a GPU set up for reversed Z (OpenGL's
    ``glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)``, a projection matrix with near and far
    swapped, the depth test ``GL_GREATER`` and the buffer cleared to 0) computes it directly, so
    a float keeps its fine spacing near 0: far away, where ``1/w`` changes least.

    Examples
    --------
    >>> reversed_depth([1.0, 10.0], near=1.0, far=10.0)
    array([1., 0.])
    >>> round(reversed_depth(2.0, near=1.0, far=10.0) + window_depth(2.0, 1.0, 10.0), 12)
    1.0
    """
    w = _view_depth(w)
    near, far = _planes(near, far)
    d = near * (far - w) / (w * (far - near))
    return d.item() if d.ndim == 0 else d


def depth_step(w: object, near: float, far: float, buffer: str = "float32") -> np.ndarray | float:
    """The smallest change of view depth a depth buffer notices at depth ``w``, for the four
    buffers of :data:`DEPTH_BUFFERS`: a float32 or 24-bit fixed-point buffer, storing window z
    (the standard) or the reversed depth of :func:`reversed_depth`.

    One step of the stored number there (the float32 spacing, or ``2**-24``) divided by how
    fast the stored number changes with w, ``far near / ((far - near) w**2)`` for both.

    What follows, for ``far`` much larger than ``near``:

    - ``fixed24`` (either way round): steps grow like ``w**2 / near``; halving ``near`` doubles
      every step.
    - ``float32`` storing window z: identical to ``fixed24`` wherever window z >= 1/2, i.e. for
      every ``w >= 2 far near / (far + near)`` (about twice the near plane); finer only in front
      of that.
    - ``float32 reversed``: the stored number is about ``near / w`` and its spacing about
      ``2**-24 near / w`` or less, so steps grow only like ``w`` and hardly depend on ``near``.
    - ``fixed24 reversed``: the same evenly spaced numbers as ``fixed24``, so the same steps.

    Examples
    --------
    >>> steps = depth_step([1.0, 100.0], near=0.1, far=1000.0, buffer="float32 reversed")
    >>> bool(steps[1] / steps[0] < 200)   # 100 times further: about 100 times coarser
    True
    >>> depth_step(10.0, 0.1, 100.0, "float32") == depth_step(10.0, 0.1, 100.0, "fixed24")
    True
    """
    w = _view_depth(w)
    near, far = _planes(near, far)
    buffer = _checks.choice(buffer, "buffer", DEPTH_BUFFERS)
    if buffer.endswith("reversed"):
        stored = (near * (far - w) / (w * (far - near))).astype(np.float32)
    else:
        stored = _window_depth(w, near, far).astype(np.float32)
    if buffer.startswith("float32"):
        step = np.abs(np.spacing(stored)).astype(np.float64)
    else:
        step = np.full(np.shape(stored), 2.0**-24)
    result = step * (far - near) * w**2 / (far * near)
    return result.item() if np.ndim(result) == 0 else result


def half_depth(near: float, far: float) -> float:
    """The view depth where window z is 1/2: ``2 far near / (far + near)``. Beyond it a float32
    window z has the same spacing, ``2**-24``, as a 24-bit fixed-point one.

    Examples
    --------
    >>> half_depth(1.0, 3.0)
    1.5
    >>> window_depth(half_depth(0.1, 100.0), 0.1, 100.0)
    0.5
    """
    near, far = _planes(near, far)
    return 2 * far * near / (far + near)
