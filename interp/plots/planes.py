"""Figure of lesson 7: which quantities are planes over the screen.

Each panel shows one quantity of the ground quad at every pixel, from the ray cast of
:mod:`interp.theory` (not from the rasterizer, which assumes the answer), with ten contour lines
evenly spaced in value. An affine function of the screen position has straight, parallel,
evenly spaced contour lines; the title says how far the quantity is from a plane on each of the
quad's two triangles.
"""

from __future__ import annotations

from collections.abc import Sequence

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from interp import theory
from interp.camera import Camera
from interp.plots._base import Plot, place_pixels
from interp.plots._style import bare
from interp.plots.checker import contour_segments
from interp.scenes import LESSON_CAMERA

#: The quantities a panel can show (see :data:`interp.theory.QUANTITIES`).
PANEL_QUANTITIES = ("w", "1/w", "u", "u/w", "NDC z")


def verdict(fits: Sequence[theory.PlaneFit]) -> str:
    """Words for the plane fits of the two triangles: a plane, or how far from one.

    Examples
    --------
    >>> verdict([theory.PlaneFit(np.zeros(3), 1e-15, 100), theory.PlaneFit(np.zeros(3), 0, 9)])
    'is a plane on each triangle'
    >>> verdict([theory.PlaneFit(np.zeros(3), 0.21, 100), theory.PlaneFit(np.zeros(3), 0, 0)])
    'is not a plane: off by up to 21% of its range'
    >>> verdict([theory.PlaneFit(np.zeros(3), 0, 240, on_a_line=True)])
    'cannot be judged: the quad covers a single line of pixels'
    """
    seen = [f for f in fits if f.pixels >= 3]
    if not seen:
        return "is not in view"
    if all(f.on_a_line for f in seen):
        return "cannot be judged: the quad covers a single line of pixels"
    seen = [f for f in seen if not f.on_a_line]
    worst = max(f.misfit for f in seen)
    if worst < 1e-9:
        return "is a plane on each triangle"
    return f"is not a plane: off by up to {100 * worst:.0f}% of its range"


class PlanePanels(Plot):
    """Two quantities of the ground quad over the screen, with evenly spaced contour lines.

    Parameters
    ----------
    axes : two Axes
    camera : Camera
    left, right : str
        Each one of :data:`PANEL_QUANTITIES`.
    width, height : int
        Pixels per panel.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> panels = PlanePanels(Figure().subplots(1, 2), width=48, height=36)
    >>> [verdict(f) for f in panels.fits]
    ['is not a plane: off by up to 40% of its range', 'is a plane on each triangle']
    """

    def __init__(
        self,
        axes: Sequence[Axes],
        camera: Camera | None = None,
        left: str = "w",
        right: str = "1/w",
        width: int = 240,
        height: int = 180,
    ) -> None:
        self.axes = list(axes)
        cmap = matplotlib.colormaps["cividis"].with_extremes(bad="white")
        self.images = [
            ax.imshow(np.zeros((height, width)), cmap=cmap, vmin=0, vmax=1) for ax in self.axes
        ]
        self.contours = [LineCollection([], colors="white", linewidths=0.7) for _ in self.axes]
        for ax, lines in zip(self.axes, self.contours, strict=True):
            ax.add_collection(lines)
            bare(ax)
        self.fits: list[list[theory.PlaneFit]] = []
        super().__init__(
            camera=camera or LESSON_CAMERA, left=left, right=right, width=width, height=height
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``left``, ``right``, ``width`` and ``height``."""
        p = self.params
        width, height = int(p["width"]), int(p["height"])
        self.truth = theory.ground_truth(p["camera"], width, height)
        self.fits = []
        for k, name in enumerate((str(p["left"]), str(p["right"]))):
            values = theory.quantity(self.truth, name)
            shown = np.ma.masked_invalid(values)
            low, high = (float(shown.min()), float(shown.max())) if shown.count() else (0.0, 1.0)
            if high <= low:
                high = low + 1.0
            image = self.images[k]
            image.set_data(shown)
            image.set_clim(low, high)
            place_pixels(image, width, height)
            levels = np.linspace(low, high, 12)[1:-1]
            self.contours[k].set_segments(contour_segments(shown, levels))
            fits = theory.misfits(self.truth, name)
            self.fits.append(fits)
            self.axes[k].set_title(f"{name} {verdict(fits)}")

    @property
    def dynamic(self) -> list:
        return [*self.images, *self.contours, *(ax.title for ax in self.axes)]
