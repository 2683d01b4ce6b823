"""Figures of lesson 4: depth across the screen, and the depth buffer's precision."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from interp import depth, lerp
from interp.plots._base import Plot
from interp.plots._style import CORRECT, OTHERS, markevery


def _normalized(y: np.ndarray) -> np.ndarray:
    span = y[-1] - y[0]
    return (y - y[0]) / span if span != 0 else np.zeros_like(y)


class DepthAcross(Plot):
    """Along the image of a segment from depth ``w1`` to ``w2``: view depth w, ``1/w`` and NDC z,
    each rescaled to run from 0 to 1. ``1/w`` and NDC z are straight lines (linear on the
    screen); w is not.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = DepthAcross(plt.subplots()[1], w1=1.0, w2=3.0, near=0.5, far=10.0)
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
        super().__init__(w1=w1, w2=w2, near=near, far=far)

    def redraw(self) -> None:
        """Draw for the current ``w1``, ``w2``, ``near`` and ``far``."""
        p = self.params
        inverse_w = lerp.lerp_inverse_w(p["w1"], p["w2"], self.s)
        w = 1 / inverse_w
        self.curves["w (view depth)"].set_data(self.s, _normalized(w))
        self.curves["1/w"].set_data(self.s, _normalized(-inverse_w))
        z = depth.ndc_depth(np.clip(w, p["near"], p["far"]), p["near"], p["far"])
        self.curves["NDC z"].set_data(self.s, _normalized(z))

    @property
    def dynamic(self) -> list:
        return list(self.curves.values())


class DepthPrecision(Plot):
    """The smallest depth difference a depth buffer notices, against depth, for three near
    planes: each tenfold smaller near plane makes every depth tenfold coarser.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = DepthPrecision(plt.subplots()[1], near=0.1, far=100.0)
    >>> len(plot.lines)
    3
    """

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
        styles = [CORRECT, *OTHERS[:2]]
        self.lines = [
            ax.plot(
                [],
                [],
                color=st["color"],
                linestyle=st["linestyle"],
                marker=st["marker"],
                markevery=markevery(points),
            )[0]
            for st in styles
        ]
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("view depth w")
        ax.set_ylabel("smallest depth step the buffer resolves")
        super().__init__(near=near, far=far, buffer=buffer)

    def redraw(self) -> None:
        """Draw for the current ``near``, ``far`` and ``buffer`` ("float32" or "fixed24")."""
        near, far = float(self.params["near"]), float(self.params["far"])
        steps = []
        for line, factor in zip(self.lines, (1.0, 10.0, 0.1), strict=True):
            n = near * factor
            if n >= far:
                line.set_data([], [])
                line.set_label("_")
                continue
            w = np.geomspace(1.1 * n, far, self.points)  # float32 is absurdly fine at z = 0
            step = depth.depth_resolution(w, n, far, str(self.params["buffer"]))
            line.set_data(w, step)
            line.set_label(f"near = {n:g}")
            steps.append(step)
        every = np.concatenate(steps)
        self.ax.set_xlim(near * 0.1, far)
        self.ax.set_ylim(every.min() / 2, every.max() * 2)
        self.ax.set_title(f"{self.params['buffer']} depth buffer, far = {far:g}")
        self.ax.legend(loc="upper left", fontsize="small")

    @property
    def dynamic(self) -> list:
        return [*self.lines, self.ax.title]
