"""Figures of the 1D story (lessons 1-3): a segment seen by a camera with a 1D image plane.

The top view draws view depth ``w = -z`` to the right and x upwards: the eye at the origin, the
image plane at ``w = d``. Points are given as in :mod:`interp.lerp`, view-space ``(x, z)``
with ``z < 0``.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from interp import lerp
from interp.plots._base import Plot, label
from interp.plots._style import (
    AFFINE,
    CORRECT,
    OTHERS,
    fit_y,
    markevery,
    nice_ceiling,
    set_limits,
)

Point = tuple[float, float]


def _wx(point: np.ndarray) -> tuple[float, float]:
    """Plot coordinates (w, x) of a view-space point (x, z)."""
    return float(-point[1]), float(point[0])


class LineView(Plot):
    """Top view: the eye, the image plane, segment AB, and the rays that image it.

    Shows the midpoint M of AB and its image m, and the midpoint c of the image ab with the
    point C of AB that it shows: c and m differ unless A and B are equally deep. With
    ``samples`` > 0, also equally spaced image points and their rays fanning out onto AB.

    The whole line through A and B is drawn faintly: Lengyel's ``a x + b z = c``. When it passes
    through the eye (``c = 0``) the segment is seen edge-on and its image is a single point.

    Parameters
    ----------
    ax : Axes
    A, B : (x, z) view-space points, z < 0.
    d : float
        Distance of the image plane.
    samples : int
        Equally spaced image samples to cast rays through (0 for none).
    extent : (w_max, x_max)
        The view shows ``0 <= w <= w_max`` and ``|x| <= x_max``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> view = LineView(ax, A=(-1.0, -2.0), B=(2.0, -6.0), d=1.0)
    >>> view.update(B=(2.0, -2.0))       # equally deep: the two midpoints agree
    >>> bool(np.allclose(view.points["C"], view.points["M"]))
    True
    """

    def __init__(
        self,
        ax: Axes,
        A: Point = (-1.5, -2.0),
        B: Point = (2.5, -8.0),
        d: float = 2.0,
        samples: int = 0,
        extent: tuple[float, float] = (10.0, 5.0),
    ) -> None:
        self.ax = ax
        w_max, x_max = extent
        ax.set_xlim(-0.3, w_max)
        ax.set_ylim(-x_max, x_max)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("depth w = -z")
        ax.set_ylabel("x")
        ax.plot([0], [0], marker=">", color="black", markersize=9, linestyle="none")
        ax.annotate("eye", (0, 0), xytext=(-4, -12), textcoords="offset points", fontsize="small")
        (self.plane,) = ax.plot([], [], color="0.4", linewidth=2.5, solid_capstyle="butt")
        (self.carrier,) = ax.plot([], [], color="0.7", linewidth=0.8, linestyle=(0, (6, 3)))
        (self.segment,) = ax.plot([], [], color="black", linewidth=2)
        self.rays = [ax.plot([], [], color="0.6", linewidth=0.8)[0] for _ in range(2)]
        self.fan = LineCollection([], colors=OTHERS[0]["color"], linewidths=0.6, alpha=0.8)
        ax.add_collection(self.fan)
        (self.hits,) = ax.plot(
            [], [], linestyle="none", marker="o", markersize=3, color=OTHERS[0]["color"]
        )
        (self.m_ray,) = ax.plot([], [], color=AFFINE["color"], linestyle=":", linewidth=1)
        (self.c_ray,) = ax.plot([], [], color=CORRECT["color"], linestyle=":", linewidth=1)
        self.markers = {
            "A": ax.plot([], [], "o", color="black", markersize=8, picker=True)[0],
            "B": ax.plot([], [], "o", color="black", markersize=8, picker=True)[0],
            "M": ax.plot([], [], marker=AFFINE["marker"], color=AFFINE["color"], linestyle="none")[
                0
            ],
            "C": ax.plot(
                [], [], marker=CORRECT["marker"], color=CORRECT["color"], linestyle="none"
            )[0],
        }
        self.labels = {
            name: label(
                ax,
                name,
                (0, 0),
                (6, 4) if name.isupper() else (-10, -3),
                fontsize="medium" if name.isupper() else "small",
            )
            for name in ("A", "B", "M", "C", "a", "b", "m", "c")
        }
        (self.image_points,) = ax.plot(
            [], [], linestyle="none", marker="|", markersize=10, color="black"
        )
        self.points: dict[str, np.ndarray] = {}
        super().__init__(A=A, B=B, d=d, samples=samples)

    def redraw(self) -> None:
        """Draw for the current ``A``, ``B``, ``d`` and ``samples``."""
        A = np.asarray(self.params["A"], float)
        B = np.asarray(self.params["B"], float)
        d = float(self.params["d"])
        w1, w2 = -A[1], -B[1]
        a, b = lerp.project_to_image_plane(A, d), lerp.project_to_image_plane(B, d)
        M = (A + B) / 2
        m = lerp.project_to_image_plane(M, d)
        c = (a + b) / 2
        C = A + lerp.t_from_s(0.5, w1, w2) * (B - A)  # the point of AB that c shows
        self.points = {
            "A": A,
            "B": B,
            "M": M,
            "C": C,
            "a": np.array([a, -d]),
            "b": np.array([b, -d]),
            "m": np.array([m, -d]),
            "c": np.array([c, -d]),
        }

        # Lengyel's line a x + b z = c through A and B: (a, b) = (z2 - z1, x1 - x2).
        self.c = float(A[0] * B[1] - B[0] * A[1])
        if np.array_equal(A, B):
            self.carrier.set_data([], [])
        else:
            k = np.array([-100.0, 100.0])
            line = A + k[:, None] * (B - A) / np.hypot(*(B - A))
            self.carrier.set_data(-line[:, 1], line[:, 0])

        x_max = self.ax.get_ylim()[1]
        self.plane.set_data([d, d], [-x_max, x_max])
        self.segment.set_data([w1, w2], [A[0], B[0]])
        for ray, P in zip(self.rays, (A, B), strict=True):
            ray.set_data([0, -P[1]], [0, P[0]])
        self.m_ray.set_data([0, -M[1]], [0, M[0]])
        self.c_ray.set_data([0, -C[1]], [0, C[0]])
        for name in ("A", "B", "M", "C"):
            self.markers[name].set_data(*([v] for v in _wx(self.points[name])))
        for name, point in self.points.items():
            self.labels[name].xy = _wx(point)
        self.image_points.set_data([d] * 4, [a, b, m, c])

        n = int(self.params["samples"])
        if n > 0:
            s = (np.arange(n) + 0.5) / n
            t = lerp.t_from_s(s, w1, w2)
            hits = A + t[:, None] * (B - A)
            self.fan.set_segments([[(0.0, 0.0), _wx(hit)] for hit in hits])
            self.hits.set_data(-hits[:, 1], hits[:, 0])
        else:
            self.fan.set_segments([])
            self.hits.set_data([], [])

    @property
    def dynamic(self) -> list:
        return [
            self.plane,
            self.carrier,
            self.segment,
            *self.rays,
            self.fan,
            self.hits,
            self.m_ray,
            self.c_ray,
            *self.markers.values(),
            *self.labels.values(),
            self.image_points,
            self.ax.title,
        ]

    def nearest_endpoint(self, w: float, x: float, radius: float) -> str | None:
        """``"A"`` or ``"B"`` if the plot point (w, x) is within ``radius`` of it, else None."""
        best, best_distance = None, radius
        for name in ("A", "B"):
            pw, px = _wx(self.points[name])
            distance = float(np.hypot(pw - w, px - x))
            if distance <= best_distance:
                best, best_distance = name, distance
        return best


class ImageStrip(Plot):
    """An attribute along the image of AB: affine and perspective-correct, against s.

    ``a1`` at A and ``a2`` at B (an intensity, say). The affine one is a straight line; the
    correct one is ``lerp_perspective``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> strip = ImageStrip(plt.subplots()[1], w1=1.0, w2=3.0)
    >>> float(strip.correct.get_ydata()[50])        # s = 1/2: a quarter of the way
    0.25
    """

    def __init__(
        self,
        ax: Axes,
        w1: float = 2.0,
        w2: float = 8.0,
        a1: float = 0.0,
        a2: float = 1.0,
        points: int = 101,
    ) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        every = markevery(points)
        (self.correct,) = ax.plot([], [], markevery=every, **CORRECT)
        (self.affine,) = ax.plot([], [], markevery=every, **AFFINE)
        ax.set_xlim(0, 1)
        ax.set_xlabel("screen parameter s along the image ab")
        ax.set_ylabel("attribute (intensity)")
        ax.legend(loc="upper left")
        super().__init__(w1=w1, w2=w2, a1=a1, a2=a2)

    def redraw(self) -> None:
        """Draw for the current ``w1``, ``w2``, ``a1`` and ``a2``."""
        p = self.params
        self.correct.set_data(
            self.s, lerp.lerp_perspective(p["a1"], p["a2"], p["w1"], p["w2"], self.s)
        )
        self.affine.set_data(self.s, lerp.lerp_affine(p["a1"], p["a2"], self.s))
        fit_y(self.ax, p["a1"], p["a2"])

    @property
    def dynamic(self) -> list:
        return [self.correct, self.affine]


class STCurve(Plot):
    """The mapping from screen parameter s to object parameter t, with samples marked.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> curve = STCurve(plt.subplots()[1], w1=1.0, w2=3.0, samples=2)
    >>> curve.samples.get_ydata().round(4).tolist()     # t at s = 1/4 and 3/4
    [0.1, 0.5]
    """

    def __init__(
        self, ax: Axes, w1: float = 2.0, w2: float = 8.0, samples: int = 0, points: int = 201
    ) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        ax.plot(
            [0, 1],
            [0, 1],
            color=AFFINE["color"],
            linestyle=AFFINE["linestyle"],
            linewidth=1,
            label="t = s (affine)",
        )
        (self.curve,) = ax.plot(
            [], [], color=CORRECT["color"], linestyle="-", label="t = t_from_s(s, w1, w2)"
        )
        (self.samples,) = ax.plot(
            [], [], linestyle="none", marker="o", markersize=4, color=OTHERS[0]["color"]
        )
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("s (screen)")
        ax.set_ylabel("t (object)")
        ax.legend(loc="upper left")
        super().__init__(w1=w1, w2=w2, samples=samples)

    def redraw(self) -> None:
        """Draw for the current ``w1``, ``w2`` and ``samples``."""
        w1, w2 = float(self.params["w1"]), float(self.params["w2"])
        self.curve.set_data(self.s, lerp.t_from_s(self.s, w1, w2))
        n = int(self.params["samples"])
        s = (np.arange(n) + 0.5) / n if n else np.array([])
        self.samples.set_data(s, lerp.t_from_s(s, w1, w2) if n else [])

    @property
    def dynamic(self) -> list:
        return [self.curve, self.samples]


class STFamily(Plot):
    """The family of s-t curves for depth ratios ``w2/w1``, the current one in bold.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> family = STFamily(plt.subplots()[1], ratio=4.0)
    >>> float(family.current.get_ydata()[100])    # s = 1/2 with w2 = 4 w1
    0.2
    """

    RATIOS = (1 / 16, 1 / 4, 1.0, 4.0, 16.0)

    def __init__(self, ax: Axes, ratio: float = 4.0, points: int = 201) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        styles = iter(OTHERS)
        for r in self.RATIOS:
            style = next(styles) if r != 1 else {"color": "0.3", "linestyle": "--"}
            ax.plot(
                self.s,
                lerp.t_from_s(self.s, 1.0, r),
                color=style["color"],
                linestyle=style["linestyle"],
                linewidth=1,
                label=f"w2/w1 = {r:g}" if r >= 1 else f"w2/w1 = 1/{1 / r:g}",
            )
        (self.current,) = ax.plot([], [], color="black", linewidth=2.6, label="current")
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("s (screen)")
        ax.set_ylabel("t (object)")
        ax.legend(loc="upper left", fontsize="x-small")
        super().__init__(ratio=ratio)

    def redraw(self) -> None:
        """Draw the bold curve for the current ``ratio`` = w2 / w1."""
        self.current.set_data(self.s, lerp.t_from_s(self.s, 1.0, float(self.params["ratio"])))

    @property
    def dynamic(self) -> list:
        return [self.current]


class GapPlot(Plot):
    """``|t - s|`` against s, with the derived peak and the sampled maximum marked.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = GapPlot(plt.subplots()[1], w1=1.0, w2=9.0)
    >>> plot.derived, round(plot.measured[0], 3)
    ((0.75, 0.5), 0.75)
    """

    def __init__(self, ax: Axes, w1: float = 2.0, w2: float = 8.0, points: int = 2001) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        (self.curve,) = ax.plot([], [], color=CORRECT["color"], label="|t - s|")
        (self.peak,) = ax.plot(
            [],
            [],
            linestyle="none",
            marker="o",
            markersize=8,
            markerfacecolor="none",
            color=AFFINE["color"],
            label="derived peak",
        )
        (self.measured_peak,) = ax.plot(
            [],
            [],
            linestyle="none",
            marker="+",
            markersize=10,
            color="black",
            label="largest sample",
        )
        ax.set_xlim(0, 1)
        ax.set_xlabel("s (screen)")
        ax.set_ylabel("|t - s|")
        ax.legend(loc="lower center")
        super().__init__(w1=w1, w2=w2)

    def redraw(self) -> None:
        """Draw for the current ``w1`` and ``w2``."""
        w1, w2 = float(self.params["w1"]), float(self.params["w2"])
        gap = np.abs(lerp.t_from_s(self.s, w1, w2) - self.s)
        self.curve.set_data(self.s, gap)
        self.derived = lerp.gap_peak(w1, w2)
        k = int(np.argmax(gap))
        self.measured = (float(self.s[k]), float(gap[k]))
        self.peak.set_data([self.derived[0]], [self.derived[1]])
        self.measured_peak.set_data([self.measured[0]], [self.measured[1]])
        set_limits(self.ax, y=(0, nice_ceiling(max(0.05, 1.1 * self.derived[1]))))
        self.ax.set_title(
            f"derived peak: s* = {self.derived[0]:.3f}, gap {self.derived[1]:.3f}\n"
            f"largest sample: s = {self.measured[0]:.3f}, gap {self.measured[1]:.3f}",
            fontsize="small",
        )

    @property
    def dynamic(self) -> list:
        return [self.curve, self.peak, self.measured_peak, self.ax.title]
