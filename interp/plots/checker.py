"""Figures of lesson 6: checkerboards, affine beside perspective-correct, and the error."""

from __future__ import annotations

from collections.abc import Sequence

import contourpy
import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from interp.camera import Camera
from interp.plots._base import Plot, place_pixels
from interp.plots._style import bare, nice_ceiling
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, CheckerViews, checker_views, ground_plane


class CheckerPanels(Plot):
    """Affine | perspective-correct | ``|Δ(u, v)|`` in texels, for one camera.

    Parameters
    ----------
    axes : three Axes
    camera : Camera
    frequency : float
        Checks per side of the plane.
    width, height : int
        Pixels per panel.
    quads : int
        Squares per side of the ground plane (1: one quad, two triangles: the seam shows).
    filtered : bool
        Anti-alias the checkerboard.
    max_error : float or None
        Top of the error colour scale, in texels; None (the default) sets it to a round number
        just above the largest error shown, so the scale never saturates. Where nothing is
        drawn the error map is blank, not the colour of zero error.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> panels = CheckerPanels(plt.subplots(1, 3)[1], Camera(pitch=90, height=2, distance=0),
    ...                        width=32, height=24)
    >>> float(panels.views.error.max())        # looking straight down: nothing to correct
    0.0
    """

    def __init__(
        self,
        axes: Sequence[Axes],
        camera: Camera | None = None,
        frequency: float = 8,
        width: int = 320,
        height: int = 240,
        quads: int = 1,
        filtered: bool = True,
        max_error: float | None = None,
        mode: str = "affine",
        span: int = 16,
    ) -> None:
        self.axes = list(axes)
        blank = np.zeros((height, width))
        grey = {"cmap": "gray", "vmin": 0, "vmax": 1}
        self.approximate = self.axes[0].imshow(blank, **grey)
        self.correct = self.axes[1].imshow(blank, **grey)
        self.max_error = max_error
        blank_error = np.ma.masked_array(blank, mask=np.ones_like(blank, dtype=bool))
        self.error = self.axes[2].imshow(
            blank_error,
            cmap=matplotlib.colormaps["viridis"].with_extremes(bad="white"),
            vmin=0,
            vmax=max_error or 1.0,
        )
        for ax, title in zip(
            self.axes, ("affine", "perspective-correct", "|Δ(u, v)| in texels"), strict=True
        ):
            ax.set_title(title)
            bare(ax)
        figure = self.axes[2].get_figure(root=False)  # the subfigure, if drawn in one
        self.colorbar = figure.colorbar(self.error, ax=self.axes[2], shrink=0.8)
        super().__init__(
            camera=camera or LESSON_CAMERA,
            frequency=frequency,
            width=width,
            height=height,
            quads=quads,
            filtered=filtered,
            mode=mode,
            span=span,
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``frequency``, ``width``, ``height``, ``quads``,
        ``filtered``, ``mode`` (of the left panel) and ``span``."""
        p = self.params
        camera = p["camera"].fitted(int(p["width"]), int(p["height"]))
        scene = ground_plane(camera, size=LESSON_SIZE, quads=int(p["quads"]))
        self.views: CheckerViews = checker_views(
            scene,
            int(p["width"]),
            int(p["height"]),
            float(p["frequency"]),
            bool(p["filtered"]),
            mode=str(p["mode"]),
            span=int(p["span"]),
        )
        error = np.ma.masked_array(self.views.error, mask=~self.views.covered)
        for image, data in (
            (self.approximate, self.views.approximate),
            (self.correct, self.views.correct),
            (self.error, error),
        ):
            image.set_data(data)
            place_pixels(image, int(p["width"]), int(p["height"]))
        mode = str(p["mode"])
        self.axes[0].set_title(mode if mode != "subdivided" else f"exact every {p['span']} px")
        worst = float(self.views.error.max())
        self.error.set_clim(0, self.max_error or nice_ceiling(max(worst, 0.01)))
        self.axes[2].set_title(f"|Δ(u, v)| in texels (max {worst:.2f})")

    @property
    def dynamic(self) -> list:
        images = [self.approximate, self.correct, self.error]
        # The colour bar is drawn whole each frame: its scale follows the largest error, and
        # a change of scale would otherwise redraw the whole figure.
        return [*images, *(ax.title for ax in self.axes), self.colorbar.ax]


#: The values of u and v the contour lines of :class:`UVImages` follow.
CONTOURS = np.round(np.arange(0.1, 1.0, 0.1), 10)


def contour_segments(image: np.ndarray, levels: Sequence[float]) -> list[np.ndarray]:
    """The contour lines of an image (masked or NaN where there is nothing) at ``levels``, as
    (N, 2) arrays of (column, row) points, for a LineCollection over ``imshow``.

    Examples
    --------
    >>> ramp = np.tile(np.linspace(0, 1, 11), (3, 1))       # u growing to the right
    >>> [line[:, 0].tolist() for line in contour_segments(ramp, [0.5])]
    [[5.0, 5.0, 5.0]]
    """
    data = np.ma.filled(np.ma.asarray(image, dtype=float), np.nan)  # contourpy skips NaN, inf
    if data.shape[0] < 2 or data.shape[1] < 2:
        return []
    generator = contourpy.contour_generator(z=data, line_type=contourpy.LineType.Separate)
    return [line for level in levels for line in generator.lines(level) if len(line) > 1]


class UVImages(Plot):
    """The interpolated u and v as images, for one mode, with contour lines every 0.1.

    Perspective-correct u and v are evenly spaced *on the ground*, so on the screen their
    contour lines crowd together towards the horizon (and those of u meet at a vanishing
    point); affine u and v are linear *on the screen* within each triangle, so their contour
    lines are evenly spaced and parallel there, and bend where the triangles meet.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> uv = UVImages(plt.subplots(1, 2)[1], width=16, height=12)
    >>> uv.images[0].get_array().shape
    (12, 16)
    """

    def __init__(
        self,
        axes: Sequence[Axes],
        camera: Camera | None = None,
        mode: str = "perspective",
        width: int = 240,
        height: int = 180,
        quads: int = 1,
    ) -> None:
        self.axes = list(axes)
        self.images = [
            ax.imshow(np.zeros((height, width)), cmap="cividis", vmin=0, vmax=1) for ax in self.axes
        ]
        self.contours = [LineCollection([], colors="white", linewidths=0.7) for _ in self.axes]
        for ax, lines in zip(self.axes, self.contours, strict=True):
            ax.add_collection(lines)
            bare(ax)
        super().__init__(
            camera=camera or LESSON_CAMERA, mode=mode, width=width, height=height, quads=quads
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``mode``, ``width``, ``height`` and ``quads``."""
        p = self.params
        camera = p["camera"].fitted(int(p["width"]), int(p["height"]))
        scene = ground_plane(camera, size=LESSON_SIZE, quads=int(p["quads"]))
        mode = str(p["mode"])
        width, height = int(p["width"]), int(p["height"])
        views = checker_views(scene, width, height, filtered=False, mode="affine")
        self.views = views
        uv = views.uv_image(mode)
        for k, (image, ax) in enumerate(zip(self.images, self.axes, strict=True)):
            shown = np.ma.masked_array(uv[..., k], mask=~views.covered)
            image.set_data(shown)
            place_pixels(image, width, height)
            self.contours[k].set_segments(contour_segments(shown, CONTOURS))
            ax.set_title(f"{'uv'[k]} ({mode}), contours every 0.1")

    def largest_difference(self) -> tuple[float, float]:
        """How far affine u and v are from perspective-correct ones, at most, over the picture."""
        difference = np.abs(self.views.uv["affine"] - self.views.uv["perspective"])
        if difference.size == 0:
            return 0.0, 0.0
        return float(difference[0].max()), float(difference[1].max())

    @property
    def dynamic(self) -> list:
        return [*self.images, *self.contours, *(ax.title for ax in self.axes)]
