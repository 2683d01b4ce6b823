"""Figures of lesson 6: checkerboards, affine beside perspective-correct, and the error."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.axes import Axes

from interp.camera import Camera
from interp.plots._base import Plot
from interp.plots._style import bare
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
    max_error : float
        Top of the error colour scale, in texels.

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
        max_error: float = 2.0,
        mode: str = "affine",
        span: int = 16,
    ) -> None:
        self.axes = list(axes)
        blank = np.zeros((height, width))
        grey = {"cmap": "gray", "vmin": 0, "vmax": 1}
        self.approximate = self.axes[0].imshow(blank, **grey)
        self.correct = self.axes[1].imshow(blank, **grey)
        self.error = self.axes[2].imshow(blank, cmap="viridis", vmin=0, vmax=max_error)
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
        extent = (-0.5, int(p["width"]) - 0.5, int(p["height"]) - 0.5, -0.5)
        for image, data in (
            (self.approximate, self.views.approximate),
            (self.correct, self.views.correct),
            (self.error, self.views.error),
        ):
            image.set_data(data)
            image.set_extent(extent)
        mode = str(p["mode"])
        self.axes[0].set_title(mode if mode != "subdivided" else f"exact every {p['span']} px")
        worst = float(self.views.error.max())
        self.axes[2].set_title(f"|Δ(u, v)| in texels (max {worst:.2f})")

    @property
    def dynamic(self) -> list:
        images = [self.approximate, self.correct, self.error]
        return [*images, *(ax.title for ax in self.axes)]


class UVImages(Plot):
    """The interpolated u and v as images, for one mode.

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
        for ax in self.axes:
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
        views = checker_views(scene, int(p["width"]), int(p["height"]), filtered=False, mode=mode)
        uv = views.uv_image(mode)
        for k, (image, ax) in enumerate(zip(self.images, self.axes, strict=True)):
            image.set_data(np.ma.masked_array(uv[..., k], mask=~views.covered))
            image.set_extent((-0.5, int(p["width"]) - 0.5, int(p["height"]) - 0.5, -0.5))
            ax.set_title(f"{'uv'[k]} ({mode})")

    @property
    def dynamic(self) -> list:
        return [*self.images, *(ax.title for ax in self.axes)]
