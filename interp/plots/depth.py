"""Figures of lesson 4: depth across the screen, and the depth buffer's precision."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import Rectangle

from interp import depth, lerp
from interp.plots._base import Plot
from interp.plots._style import AFFINE, CORRECT, OTHERS, decades, markevery, set_limits


def _normalized(y: np.ndarray) -> np.ndarray:
    span = y[-1] - y[0]
    return (y - y[0]) / span if span != 0 else np.zeros_like(y)


def clipped_ranges(w1: float, w2: float, near: float, far: float) -> list[tuple[float, float]]:
    """The ranges of the screen parameter s (0 at the end of depth ``w1``, 1 at ``w2``) whose
    points lie in front of the near plane or beyond the far plane: clipping removes them.

    ``1/w`` is linear in s, so each range is found by solving ``1/w(s) = 1/near`` or ``1/far``.

    Examples
    --------
    >>> [(round(a, 4), b) for a, b in clipped_ranges(1.0, 8.0, near=0.5, far=4.0)]  # s = 6/7
    [(0.8571, 1.0)]
    >>> clipped_ranges(2.0, 3.0, near=0.5, far=100.0)
    []
    """
    ranges = []
    inverse = (1 / w1, 1 / w2)
    for plane, outside in ((near, lambda x: x > 1 / near), (far, lambda x: x < 1 / far)):
        ends = [outside(x) for x in inverse]
        if not any(ends):
            continue
        if all(ends):
            ranges.append((0.0, 1.0))
            continue
        s = (inverse[0] - 1 / plane) / (inverse[0] - inverse[1])  # where 1/w(s) = 1/plane
        ranges.append((0.0, float(s)) if ends[0] else (float(s), 1.0))
    return ranges


class DepthAcross(Plot):
    """Along the image of a segment from depth ``w1`` to ``w2``: view depth w, ``1/w`` and NDC z,
    each rescaled to run from 0 to 1. ``1/w`` and NDC z are straight lines (linear on the
    screen); w is not. Where the segment lies in front of the near plane or beyond the far
    plane, the screen is shaded: clipping removes that part (its NDC z is outside [-1, 1]),
    but the formulas, and so the straight lines, go on through it.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = DepthAcross(plt.subplots()[1], w1=1.0, w2=3.0, near=0.5, far=10.0)
    >>> bool(np.allclose(plot.curves["NDC z"].get_ydata(), plot.curves["1/w"].get_ydata()))
    True
    >>> plot.update(far=2.0)                 # the far plane inside the segment: still straight
    >>> bool(np.allclose(plot.curves["NDC z"].get_ydata(), plot.curves["1/w"].get_ydata()))
    True
    """

    def __init__(
        self,
        ax: Axes,
        w1: float = 1.0,
        w2: float = 8.0,
        near: float = 0.5,
        far: float = 20.0,
        points: int = 101,
    ) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        every = markevery(points)
        self.shades = [
            ax.add_patch(
                Rectangle(
                    (0, -0.02), 0, 1.04, facecolor="0.88", edgecolor="0.6", hatch="//", zorder=0
                )
            )
            for _ in range(2)
        ]
        self.shade_labels = [
            ax.text(0, 0.5, "", ha="center", va="center", rotation=90, fontsize="small")
            for _ in range(2)
        ]
        self.curves = {
            "w (view depth)": ax.plot(
                [],
                [],
                markevery=every,
                label="w (view depth)",
                **OTHERS[0],
            )[0],
            "1/w": ax.plot(
                [],
                [],
                markevery=every,
                label="1/w",
                color=CORRECT["color"],
                linestyle="-",
                marker="o",
            )[0],
            "NDC z": ax.plot(
                [],
                [],
                markevery=(every // 2, every),
                label="NDC z (depth buffer)",
                color="black",
                linestyle=":",
                marker="x",
            )[0],
        }
        ax.set_xlim(0, 1)
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel("screen parameter s")
        ax.set_ylabel("rescaled to [0, 1]")
        ax.legend(loc="upper left")
        self.clipped: list[tuple[float, float]] = []
        super().__init__(w1=w1, w2=w2, near=near, far=far)

    def redraw(self) -> None:
        """Draw for the current ``w1``, ``w2``, ``near`` and ``far``."""
        p = self.params
        inverse_w = lerp.lerp_inverse_w(p["w1"], p["w2"], self.s)
        w = 1 / inverse_w
        self.curves["w (view depth)"].set_data(self.s, _normalized(w))
        self.curves["1/w"].set_data(self.s, _normalized(-inverse_w))
        # NDC z = A + B/w for every w > 0; outside [-1, 1] the point is clipped, not moved.
        z = depth.ndc_depth(w, p["near"], p["far"])
        self.curves["NDC z"].set_data(self.s, _normalized(z))
        self.clipped = clipped_ranges(p["w1"], p["w2"], p["near"], p["far"])
        for k, (shade, label) in enumerate(zip(self.shades, self.shade_labels, strict=True)):
            low, high = self.clipped[k] if k < len(self.clipped) else (0.0, 0.0)
            shade.set_x(low)
            shade.set_width(high - low)
            label.set_position(((low + high) / 2, 0.5))
            label.set_text("clipped" if high - low > 0.06 else "")

    @property
    def dynamic(self) -> list:
        return [*self.shades, *self.shade_labels, *self.curves.values()]


#: Line styles of the precision plot's three near planes.
_NEAR_STYLES = (CORRECT, OTHERS[0], AFFINE)

#: The precision plot's near planes, as multiples of the chosen one, and their legend labels.
_NEAR_FACTORS = ((1.0, "near = n"), (10.0, "near = 10 n"), (0.1, "near = n / 10"))


class DepthPrecision(Plot):
    """The smallest depth difference a depth buffer notices, against depth, for three near
    planes (the chosen one, ten times larger, ten times smaller) and one of the buffers of
    :data:`interp.depth.DEPTH_BUFFERS`.

    For a 24-bit fixed-point buffer each tenfold smaller near plane makes every depth tenfold
    coarser; a float32 buffer storing window z is the same beyond about twice the near plane;
    a reversed-Z float32 buffer hardly depends on the near plane at all.

    The axes stay as they are (:attr:`DEPTHS`, :attr:`STEPS`) for every near plane, far plane
    and buffer lesson 4's sliders reach: a change moves the curves, which is what the lesson
    asks a student to watch (a tenfold smaller near plane lifts a fixed-point curve by a
    decade), and a live figure redraws only the curves and the title. Curves beyond those
    ranges (other arguments) widen the axes to the decades that hold them.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = DepthPrecision(plt.subplots()[1], near=0.1, far=100.0)
    >>> len(plot.lines), plot.ax.get_xlim() == DepthPrecision.DEPTHS
    (3, True)
    >>> [text.get_text() for text in plot.ax.get_legend().get_texts()]
    ['near = n', 'near = 10 n', 'near = n / 10']
    >>> plot.update(near=0.01)               # tenfold smaller: the same axes
    >>> plot.ax.get_ylim() == DepthPrecision.STEPS, plot.ax.get_title()
    (True, 'float32 depth buffer: n = 0.01, far = 100')
    """

    #: The depths on the x axis: from a tenth of the smallest near plane of lesson 4's slider
    #: (0.001 / 10) to its largest far plane (1000).
    DEPTHS = (1e-4, 1e3)
    #: The depth steps on the y axis: the decades holding every curve those sliders and any
    #: buffer draw (from 9e-13, float32 at a near plane of 0.0001, to 970, float32 at a far
    #: plane of 1000 with a near plane of 0.0001).
    STEPS = (1e-13, 1e3)

    def __init__(
        self,
        ax: Axes,
        near: float = 0.1,
        far: float = 100.0,
        buffer: str = "float32",
        points: int = 200,
    ) -> None:
        self.ax = ax
        self.points = points
        self.lines = [
            ax.plot(
                [],
                [],
                color=st["color"],
                linestyle=st["linestyle"],
                marker=st["marker"],
                markevery=markevery(points),
                label=label,
            )[0]
            for st, (_, label) in zip(_NEAR_STYLES, _NEAR_FACTORS, strict=True)
        ]
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("view depth w")
        ax.set_ylabel("smallest depth step the buffer resolves")
        super().__init__(near=near, far=far, buffer=buffer)

    def redraw(self) -> None:
        """Draw for the current ``near``, ``far`` and ``buffer``."""
        near, far = float(self.params["near"]), float(self.params["far"])
        buffer = str(self.params["buffer"])
        steps, shown = [], []
        for line, (factor, label) in zip(self.lines, _NEAR_FACTORS, strict=True):
            n = near * factor
            if 1.1 * n >= 0.9 * far:  # no depths between this near plane and the far one
                line.set_data([], [])
                continue
            # From just beyond the near plane to just before the far one: right at the near
            # plane float32 window z is absurdly fine, and right at the far plane reversed
            # depth is 0, where float32 is finer still.
            w = np.geomspace(1.1 * n, 0.9 * far, self.points)
            step = depth.depth_step(w, n, far, buffer)
            line.set_data(w, step)
            steps.append(step)
            shown.append(label)
        every = np.concatenate(steps)
        low, high = decades(every.min(), every.max())
        set_limits(
            self.ax,
            x=(min(self.DEPTHS[0], near * 0.1), max(self.DEPTHS[1], far)),
            y=(min(self.STEPS[0], low), max(self.STEPS[1], high)),
        )
        self.ax.set_title(f"{buffer} depth buffer: n = {near:.3g}, far = {far:g}")
        legend = self.ax.get_legend()
        if legend is None or [t.get_text() for t in legend.get_texts()] != shown:
            # Only when a curve comes or goes: a new legend is a full redraw of a live figure.
            handles = [line for line in self.lines if line.get_label() in shown]
            self.ax.legend(handles=handles, loc="upper left", fontsize="small")

    @property
    def dynamic(self) -> list:
        return [*self.lines, self.ax.title]
