"""Lesson 7's 2D theory, checked without the rasterizer: what each pixel really sees.

The claim: across a triangle (which lies in a plane), ``1/w`` and ``a/w`` are *affine*
functions of the screen position, ``alpha x + beta y + gamma``; ``w`` and ``a`` themselves are
not. :func:`interp.rasterize` builds that claim in (it interpolates ``1/w`` and ``a/w`` with
screen-space barycentrics), so it cannot be used to test it. Here every pixel centre is
instead *ray cast*: the ray from the eye through the pixel centre is intersected with the
ground plane, and the point it hits gives the true view depth ``w`` and texture coordinates
``(u, v)``. :func:`plane_fit` then measures how far each quantity is from a plane in pixel
coordinates.

Glossary
--------
truth     : :class:`GroundTruth`, per pixel: the hit point's w, u, v, NDC z, and which of the
            quad's two triangles it lies in.
quantity  : one of :data:`QUANTITIES`, an image computed from the truth.
misfit    : the largest distance between a quantity and its best-fitting plane (least
            squares) over one triangle's pixels, as a fraction of the quantity's range there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from interp import _checks, depth
from interp.camera import Camera
from interp.scenes import LESSON_SIZE

#: What :func:`quantity` can show. The first three are affine on the screen, the rest are not.
QUANTITIES = ("1/w", "u/w", "NDC z", "w", "u")


@dataclass(frozen=True)
class GroundTruth:
    """What each pixel centre of a camera's image sees of the ground square, by ray casting.

    Attributes
    ----------
    w, u, v, ndc_z : (H, W) float arrays
        View depth, texture coordinates and NDC z of the point hit; NaN where nothing is hit.
    triangle : (H, W) int array
        0 for the quad's first triangle (corners (u, v) = (0, 0), (1, 0), (1, 1): v <= u), 1 for
        the second (v > u), -1 where nothing is hit.
    """

    w: np.ndarray
    u: np.ndarray
    v: np.ndarray
    ndc_z: np.ndarray
    triangle: np.ndarray

    @property
    def covered(self) -> np.ndarray:
        """(H, W) bool array: where the ground square is seen."""
        return self.triangle >= 0


def ground_truth(camera: Camera, width: int, height: int, size: float = LESSON_SIZE) -> GroundTruth:
    """Ray cast every pixel centre of ``camera`` (fitted to the image) onto the ground square
    ``|x|, |z| <= size/2`` of the plane ``y = 0``, as :func:`interp.ground_plane` lays it out.

    A pixel sees the square when its ray meets it between the near and far planes. The ray of
    the centre of pixel (column i, row j, row 0 at the top) runs through NDC
    ``x = 2 (i + 1/2) / width - 1`` and ``y = 1 - 2 (j + 1/2) / height``; unprojecting that
    point at NDC z = -1 and z = +1 gives the ray's stretch from the near plane to the far one.

    Examples
    --------
    Looking straight down from height 2 the whole image shows ground at depth 2:

    >>> truth = ground_truth(Camera(height=2.0, pitch=90.0, distance=0.0), 4, 4)
    >>> np.unique(truth.w.round(12)).tolist(), bool(truth.covered.all())
    ([2.0], True)
    """
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be an interp.Camera, got {type(camera).__name__}")
    width = _checks.positive_int(width, "width")
    height = _checks.positive_int(height, "height")
    size = _checks.real_in(size, "size", 0, None, low_open=True)
    camera = camera.fitted(width, height)
    to_world = np.linalg.inv(camera.projection @ camera.view)

    x = 2 * (np.arange(width) + 0.5) / width - 1
    y = 1 - 2 * (np.arange(height) + 0.5) / height
    ndc = np.ones((height, width, 4))  # each pixel centre's (x, y, z, 1), z set below
    ndc[..., 0], ndc[..., 1] = np.meshgrid(x, y)
    ends = []
    for z in (-1.0, 1.0):  # the near and far ends of each pixel's ray, in world space
        ndc[..., 2] = z
        world = ndc @ to_world.T
        ends.append(world[..., :3] / world[..., 3:])
    start, stop = ends
    rise = stop[..., 1] - start[..., 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.where(rise != 0, -start[..., 1] / rise, np.nan)  # where y = 0 along the ray
    hit = start + k[..., None] * (stop - start)
    half = size / 2
    seen = (k >= 0) & (k <= 1) & (np.abs(hit[..., 0]) <= half) & (np.abs(hit[..., 2]) <= half)
    view_z = hit @ camera.view[2, :3] + camera.view[2, 3]  # the hit point's z in view space
    w = np.where(seen, -view_z, np.nan)
    u = np.where(seen, hit[..., 0] / size + 0.5, np.nan)
    v = np.where(seen, 0.5 - hit[..., 2] / size, np.nan)
    ndc_z = np.full_like(w, np.nan)
    ndc_z[seen] = depth.ndc_depth(w[seen], camera.near, camera.far) if seen.any() else []
    triangle = np.where(seen, np.where(v <= u, 0, 1), -1)
    return GroundTruth(w, u, v, ndc_z, triangle)


def quantity(truth: GroundTruth, name: str) -> np.ndarray:
    """One of :data:`QUANTITIES` as an (H, W) image (NaN where nothing is seen).

    Examples
    --------
    >>> truth = ground_truth(Camera(height=2.0, pitch=90.0, distance=0.0), 2, 2)
    >>> quantity(truth, "1/w").round(12).tolist()
    [[0.5, 0.5], [0.5, 0.5]]
    """
    name = _checks.choice(name, "name", QUANTITIES)
    return {
        "1/w": lambda: 1 / truth.w,
        "u/w": lambda: truth.u / truth.w,
        "NDC z": lambda: truth.ndc_z,
        "w": lambda: truth.w,
        "u": lambda: truth.u,
    }[name]()


@dataclass(frozen=True)
class PlaneFit:
    """The best plane ``alpha x + beta y + gamma`` through an image's values (pixel column x,
    row y), and how far the values are from it.

    Attributes
    ----------
    coefficients : (3,) float array
        ``alpha, beta, gamma``.
    misfit : float
        Largest ``|value - plane|``, as a fraction of the values' range (0 for a plane).
    pixels : int
        How many pixels were fitted.
    on_a_line : bool
        The pixels all lie on one line (one row, say): any function along a line is fitted by
        some plane there, so the fit tells nothing about the values being a plane.
    """

    coefficients: np.ndarray
    misfit: float
    pixels: int
    on_a_line: bool = False


def plane_fit(values: np.ndarray, where: np.ndarray) -> PlaneFit:
    """Fit a plane to ``values`` over the pixels ``where`` is True (least squares).

    Examples
    --------
    >>> rows, cols = np.mgrid[0:4, 0:5]
    >>> fit = plane_fit(2.0 * cols - rows + 1, np.ones((4, 5), bool))
    >>> fit.coefficients.round(12).tolist(), fit.misfit < 1e-12
    ([2.0, -1.0, 1.0], True)
    >>> plane_fit(1.0 / (1 + cols + rows), np.ones((4, 5), bool)).misfit > 0.05
    True
    >>> plane_fit(1.0 / (1 + cols + rows), rows == 2).on_a_line   # one row: anything fits
    True
    """
    values = np.asarray(values, dtype=float)
    where = np.asarray(where, dtype=bool) & np.isfinite(values)
    rows, cols = np.nonzero(where)
    if len(rows) < 3:
        return PlaneFit(np.zeros(3), 0.0, len(rows))
    z = values[where]
    design = np.column_stack([cols, rows, np.ones(len(rows))]).astype(float)
    scale = max(float(np.abs(z).max()), 1e-300)
    # lstsq's rank is matrix_rank's: singular values above eps * max(N, 3) times the largest.
    coefficients, _, rank, _ = np.linalg.lstsq(design, z / scale, rcond=None)
    if rank < 3:
        return PlaneFit(np.zeros(3), 0.0, len(rows), on_a_line=True)
    coefficients = coefficients * scale
    spread = float(z.max() - z.min())
    residual = float(np.abs(design @ coefficients - z).max())
    # A constant (to rounding) is a plane: its spread is rounding, and so is its residual.
    constant = spread <= 1e-12 * float(np.abs(z).max())
    misfit = 0.0 if constant else residual / spread
    return PlaneFit(coefficients, misfit, len(rows))


def misfits(truth: GroundTruth, name: str) -> list[PlaneFit]:
    """:func:`plane_fit` of a quantity over each of the quad's two triangles.

    Examples
    --------
    >>> truth = ground_truth(Camera(height=1.0, pitch=20.0), 64, 48)
    >>> [round(f.misfit, 9) for f in misfits(truth, "1/w")]
    [0.0, 0.0]
    >>> min(f.misfit for f in misfits(truth, "u")) > 0.01
    True
    """
    values = quantity(truth, name)
    return [plane_fit(values, truth.triangle == k) for k in (0, 1)]
