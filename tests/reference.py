"""An independent reference for ``interp.rasterize``: cast a ray through every pixel centre.

Nothing here is shared with ``interp.raster``: no clipping, no edge functions, no snapping. For
each pixel centre ``(xn, yn)`` in NDC and each triangle with clip-space vertices ``P_i``, the
point of the triangle seen there is ``P = sum(l_i P_i)`` with ``sum(l_i) = 1`` and
``P.x = xn P.w``, ``P.y = yn P.w``: a 3x3 linear system for the clip-space barycentrics
``l``. The point is on the triangle if every ``l_i >= 0``, in front of the eye if ``P.w > 0``,
and inside the depth range if ``-P.w <= P.z <= P.w``. The nearest (smallest ``P.z / P.w``) wins.
Note ``P.z / P.w = sum(b_i z_i / w_i)``: NDC depth is linear on the screen, as OpenGL has it.

Perspective-correct attributes are ``sum(l_i a_i)``: the attribute of that 3D point. Affine
(``noperspective``) attributes use the screen-space barycentrics ``b_i = l_i w_i / P.w``: they
sum to 1 and place the pixel at ``sum(b_i x_i / w_i)``, so they are linear on the screen, also
for a triangle with a vertex behind the eye (``w_i < 0``, projected through the eye). That is
what clipping must reproduce: a new vertex on an edge at clip parameter t takes the screen
parameter ``s_from_t(t, w_in, w_out)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class Reference:
    triangle: np.ndarray  # (H, W) visible triangle, -1 where none
    depth: np.ndarray  # (H, W) window depth of the visible point, 1 where none
    clip_barycentric: np.ndarray  # (H, W, 3) l of the visible point
    screen_barycentric: np.ndarray  # (H, W, 3) b of the visible point
    ambiguous: np.ndarray  # (H, W) bool: a tiny nudge of the pixel centre changes the answer

    def values(self, attributes: np.ndarray, triangles: np.ndarray, mode: str) -> np.ndarray:
        seen = self.triangle >= 0
        a = attributes[triangles[self.triangle[seen]]]  # (P, 3, K)
        weights = self.clip_barycentric if mode == "perspective" else self.screen_barycentric
        out = np.zeros((*self.triangle.shape, attributes.shape[1]))
        out[seen] = np.einsum("pi,pik->pk", weights[seen], a)
        return out


def _solve(clip: np.ndarray, tri: np.ndarray, xn: np.ndarray, yn: np.ndarray) -> tuple:
    """For one triangle and many NDC points: clip barycentrics l (P, 3) and the point P (P, 4)."""
    V = clip[tri]  # (3, 4)
    P = xn.size
    M = np.zeros((P, 3, 3))
    M[:, 0, :] = V[:, 0][None, :] - xn[:, None] * V[:, 3][None, :]
    M[:, 1, :] = V[:, 1][None, :] - yn[:, None] * V[:, 3][None, :]
    M[:, 2, :] = 1.0
    rhs = np.zeros((P, 3))
    rhs[:, 2] = 1.0
    det = np.linalg.det(M)
    ok = np.abs(det) > 1e-14
    lam = np.full((P, 3), np.nan)
    with np.errstate(all="ignore"):
        lam[ok] = np.linalg.solve(M[ok], rhs[ok][..., None])[..., 0]
    return lam, lam @ V


def _cast(clip, triangles, xn, yn, margin=0.0):
    """Nearest hit per point: triangle id, depth, l, and the gap to the runner-up depth."""
    P = xn.size
    best = np.full(P, -1)
    best_depth = np.full(P, np.inf)
    second = np.full(P, np.inf)
    best_lam = np.zeros((P, 3))
    best_point = np.zeros((P, 4))
    for k, tri in enumerate(triangles):
        lam, point = _solve(clip, tri, xn, yn)
        w, z = point[:, 3], point[:, 2]
        with np.errstate(all="ignore"):
            hit = np.all(lam >= -margin, axis=1) & (w > 0) & (z >= -w) & (z <= w)
            depth = np.where(hit, z / np.where(w > 0, w, 1.0), np.inf)
        nearer = depth < best_depth
        second = np.where(nearer, best_depth, np.minimum(second, depth))
        best = np.where(nearer, k, best)
        best_depth = np.where(nearer, depth, best_depth)
        best_lam[nearer] = lam[nearer]
        best_point[nearer] = point[nearer]
    return best, best_depth, second, best_lam, best_point


def render(clip, triangles, width, height, nudge=1 / 64, depth_gap=1e-6) -> Reference:
    """Cast rays through all pixel centres (and nudged copies, to find ambiguous pixels)."""
    clip = np.asarray(clip, float)
    triangles = np.asarray(triangles)
    cols, rows = np.meshgrid(np.arange(width), np.arange(height))
    x_w = cols + 0.5
    y_w = height - (rows + 0.5)  # row 0 is the top of the image
    xn = (2 * x_w / width - 1).ravel()
    yn = (2 * y_w / height - 1).ravel()
    tri, depth, second, lam, point = _cast(clip, triangles, xn, yn)

    with np.errstate(invalid="ignore"):  # inf - inf where nothing is hit
        ambiguous = (second - depth) < 2 * depth_gap
    for dx, dy in ((nudge, 0), (-nudge, 0), (0, nudge), (0, -nudge)):
        other, *_ = _cast(clip, triangles, xn + 2 * dx / width, yn + 2 * dy / height)
        ambiguous |= other != tri

    seen = tri >= 0
    w = np.zeros_like(lam)
    w[seen] = clip[triangles[tri[seen]], 3]
    b = np.zeros_like(lam)
    b[seen] = lam[seen] * w[seen] / point[seen, 3:4]
    shape = (height, width)
    return Reference(
        triangle=tri.reshape(shape),
        depth=np.where(seen, (depth + 1) / 2, 1.0).reshape(shape),
        clip_barycentric=lam.reshape(*shape, 3) * seen.reshape(*shape, 1),
        screen_barycentric=b.reshape(*shape, 3),
        ambiguous=ambiguous.reshape(shape),
    )
