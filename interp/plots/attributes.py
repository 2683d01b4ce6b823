"""Figures of lesson 5: attributes along a line, mistakes, and colour across a triangle."""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes

from interp import lerp, mistakes
from interp.camera import Camera
from interp.plots._base import Plot
from interp.plots._style import AFFINE, CORRECT, OTHERS, fit_y, markevery
from interp.raster import rasterize
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane


class MistakesAlongALine(Plot):
    """An attribute along the image of a segment: right, affine, and two classic mistakes.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = MistakesAlongALine(plt.subplots()[1], w1=1.0, w2=3.0)
    >>> float(plot.lines["perspective-correct"].get_ydata()[50])
    0.25
    """

    def __init__(
        self,
        ax: Axes,
        a1: float = 0.0,
        a2: float = 1.0,
        w1: float = 1.0,
        w2: float = 6.0,
        near: float = 0.5,
        far: float = 20.0,
        points: int = 101,
    ) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        every = markevery(points)
        styles = {
            "perspective-correct": CORRECT,
            "affine": AFFINE,
            "divided by window z": OTHERS[0],
            "divided too early": OTHERS[1],
        }
        self.lines = {
            name: ax.plot([], [], markevery=every, **{**style, "label": name})[0]
            for name, style in styles.items()
        }
        ax.set_xlim(0, 1)
        ax.set_xlabel("screen parameter s")
        ax.set_ylabel("attribute")
        ax.legend(loc="upper left")
        super().__init__(a1=a1, a2=a2, w1=w1, w2=w2, near=near, far=far)

    def redraw(self) -> None:
        """Draw for the current ``a1``, ``a2``, ``w1``, ``w2``, ``near`` and ``far``."""
        p, s = self.params, self.s
        curves = {
            "perspective-correct": lerp.lerp_perspective(p["a1"], p["a2"], p["w1"], p["w2"], s),
            "affine": lerp.lerp_affine(p["a1"], p["a2"], s),
            "divided by window z": mistakes.lerp_with_window_z(
                p["a1"],
                p["a2"],
                np.clip(p["w1"], p["near"], p["far"]),
                np.clip(p["w2"], p["near"], p["far"]),
                s,
                p["near"],
                p["far"],
            ),
            "divided too early": mistakes.lerp_divided_too_early(
                p["a1"], p["a2"], p["w1"], p["w2"], s
            ),
        }
        for name, y in curves.items():
            self.lines[name].set_data(s, y)
        fit_y(self.ax, *curves.values())

    @property
    def dynamic(self) -> list:
        return list(self.lines.values())


class ClipVertexMistake(Plot):
    """A segment from A (in front) to B (behind the near plane), clipped to A-C at the near
    plane: the attribute along the image of A-C when C gets its own attribute, and when it
    wrongly keeps B's.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> plot = ClipVertexMistake(plt.subplots()[1], w1=3.0, w2=-1.0, near=1.0)
    >>> float(plot.right.get_ydata()[-1]), float(plot.wrong.get_ydata()[-1])
    (0.5, 1.0)
    """

    def __init__(
        self,
        ax: Axes,
        a1: float = 0.0,
        a2: float = 1.0,
        w1: float = 4.0,
        w2: float = -2.0,
        near: float = 0.5,
        points: int = 101,
    ) -> None:
        self.ax = ax
        self.s = np.linspace(0, 1, points)
        every = markevery(points)
        (self.right,) = ax.plot(
            [], [], markevery=every, **{**CORRECT, "label": "C gets its own attribute"}
        )
        (self.wrong,) = ax.plot(
            [], [], markevery=every, **{**OTHERS[1], "label": "C keeps B's attribute"}
        )
        ax.set_xlim(0, 1)
        ax.set_xlabel("s from A to C (C on the near plane)")
        ax.set_ylabel("attribute")
        ax.legend(loc="upper left")
        super().__init__(a1=a1, a2=a2, w1=w1, w2=w2, near=near)

    def redraw(self) -> None:
        """Draw for the current ``a1``, ``a2``, ``w1`` (> near), ``w2`` (< near) and ``near``."""
        p, s = self.params, self.s
        a_c = mistakes.clip_vertex_attribute(p["a1"], p["a2"], p["w1"], p["w2"], p["near"])
        self.right.set_data(s, lerp.lerp_perspective(p["a1"], a_c, p["w1"], p["near"], s))
        self.wrong.set_data(
            s,
            mistakes.lerp_forgetting_the_clip_vertex(
                p["a1"], p["a2"], p["w1"], p["w2"], s, p["near"]
            ),
        )
        fit_y(self.ax, p["a1"], p["a2"])

    @property
    def dynamic(self) -> list:
        return [self.right, self.wrong]


#: Colours of the ground quad's corners (u, v) = (0, 0), (1, 0), (0, 1), (1, 1): red, green,
#: yellow and blue, so that its first triangle, corners 0, 1 and 3, is red, green and blue and its
#: colour is its barycentric coordinates.
CORNER_COLOURS = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 1.0]])


class ColourTriangle(Plot):
    """A colour gradient across a ground-plane quad, drawn with one interpolation mode.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> image = ColourTriangle(plt.subplots()[1], Camera(height=1, pitch=30), "affine", 32, 24)
    >>> image.image.get_array().shape
    (24, 32, 3)
    """

    def __init__(
        self,
        ax: Axes,
        camera: Camera | None = None,
        mode: str = "perspective",
        width: int = 240,
        height: int = 180,
        whole_quad: bool = True,
    ) -> None:
        self.ax = ax
        self.width, self.height = width, height
        self.whole_quad = whole_quad  # False: one triangle, its colours its barycentrics
        self.image = ax.imshow(np.zeros((height, width, 3)), interpolation="nearest")
        ax.set_axis_off()
        super().__init__(camera=camera or LESSON_CAMERA, mode=mode)

    def redraw(self) -> None:
        """Draw for the current ``camera`` and ``mode``."""
        camera, mode = self.params["camera"], str(self.params["mode"])
        scene = ground_plane(camera.fitted(self.width, self.height), LESSON_SIZE, quads=1)
        triangles = scene.triangles if self.whole_quad else scene.triangles[:1]
        colours, covered = rasterize(
            scene.clip, CORNER_COLOURS, triangles, self.width, self.height, mode
        )
        self.image.set_data(np.where(covered[..., None], np.clip(colours, 0, 1), 1.0))
        # One triangle: its colours are its weights, named as a shader and lesson 7 name them.
        weights = {"affine": "noperspective (b)", "perspective": "smooth (λ)"}
        self.ax.set_title(mode if self.whole_quad else weights.get(mode, mode))

    @property
    def dynamic(self) -> list:
        return [self.image, self.ax.title]
