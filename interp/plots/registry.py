"""Every figure of the lessons, composed once: the live apps and ``interp-figures`` draw these.

Each class below is one figure: which lesson shows it, its title and caption, its size on screen
and in print, its parameters (:class:`~interp.plots.params.Param`: default, range, label) and
how it arranges the plots of :mod:`interp.plots` on a matplotlib figure. An app
(:mod:`interp.apps`) makes one control per parameter and calls :meth:`LessonFigure.update`;
``interp-figures`` checks ``--set`` values against the same parameters, draws the same class at
its print size and puts the caption under it in ``handout.pdf``.

:data:`FIGURES` lists them all, by name, in lesson order.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

import numpy as np
from matplotlib.artist import Artist
from matplotlib.figure import Figure, SubFigure

from interp import approximation, depth, lerp, mipmap, mistakes
from interp.plots._base import Plot
from interp.plots.attributes import ClipVertexMistake, ColourTriangle, MistakesAlongALine
from interp.plots.checker import CheckerPanels, UVImages
from interp.plots.depth import DepthAcross, DepthPrecision
from interp.plots.filtering import FILTERS, FilteringPanels, MipmapPyramid
from interp.plots.gpu import (
    LAB_CAMERA,
    SHADER_OUTPUTS,
    ApproximationLab,
    ClippingView,
    ShaderView,
)
from interp.plots.line import GapPlot, ImageStrip, LineView, STCurve, STFamily
from interp.plots.outside import SHOWS, VIEWS, OutsideView
from interp.plots.params import Param, camera_from, camera_params, table
from interp.plots.planes import PANEL_QUANTITIES, PlanePanels, verdict
from interp.scenes import LESSON_SIZE, ground_plane

#: Print widths that fit a column of an A4 or Letter page (6.3 in of text between 1 in margins).
NARROW, WIDE = 3.3, 6.3


class LessonFigure(Plot):
    """One figure of a lesson: plots arranged on a figure, driven by named parameters.

    Subclasses set the class attributes and implement :meth:`build` (make the plots, once) and
    :meth:`redraw` (update them from ``self.params``).

    Parameters
    ----------
    figure : Figure or SubFigure
        Where to draw.
    **params
        Values for some of :attr:`PARAMS`; the rest take their defaults. Each is checked
        against its range: a wrong name raises ``TypeError``, a value out of range
        ``ValueError``, both naming the parameter.
    """

    name: ClassVar[str]  #: file name and ``--only`` name
    lesson: ClassVar[int]
    title: ClassVar[str]
    description: ClassVar[str]  #: one line, for ``interp-figures --list``
    caption: ClassVar[str]  #: what to look at, true at the default parameters
    size: ClassVar[tuple[float, float]]  #: on screen, inches at 100 dpi
    print_size: ClassVar[tuple[float, float]]  #: in print, inches
    PARAMS: ClassVar[Mapping[str, Param]]

    def __init__(self, figure: Figure | SubFigure, **params: object) -> None:
        self.figure = figure
        values = self.checked({**self.defaults(), **params})
        self.build(figure)
        super().__init__(**values)

    @classmethod
    def defaults(cls) -> dict[str, object]:
        """Every parameter's default value, by name."""
        return {name: param.default for name, param in cls.PARAMS.items()}

    @classmethod
    def checked(cls, params: dict[str, object]) -> dict[str, object]:
        """``params`` checked against :attr:`PARAMS`, converted to their types."""
        for name in params:
            if name not in cls.PARAMS:
                raise TypeError(
                    f"{cls.name} has no parameter {name!r}; it has: {', '.join(cls.PARAMS)}"
                )
        return {name: cls.PARAMS[name].check(name, value) for name, value in params.items()}

    def update(self, **params: object) -> None:
        """Change some parameters (checked, as for the constructor) and redraw."""
        super().update(**self.checked(params))

    def build(self, figure: Figure | SubFigure) -> None:  # pragma: no cover - overridden
        """Make the plots on ``figure``."""
        raise NotImplementedError

    def readout(self) -> str:
        """The figure's key result in one or two plain sentences, true for the current
        parameters (e.g. "M, the middle of AB, shows at s = 0.800 of the image."): shown as
        live text beside the app, for screen readers and for copying. Empty if there is none."""
        return ""

    def inactive(self) -> dict[str, str]:
        """The parameters that change nothing at the others' current values, each with a
        sentence saying why (an app disables their controls and shows the sentence); empty
        where every parameter counts."""
        return {}

    @property
    def dynamic(self) -> list[Artist] | None:
        """Every artist the figure's plots change (see :attr:`Plot.dynamic`); None if one of
        them cannot say."""
        artists: list[Artist] = []
        for value in vars(self).values():
            for plot in value if isinstance(value, list) else [value]:
                if isinstance(plot, Plot):
                    if plot.dynamic is None:
                        return None
                    artists += plot.dynamic
        return artists


# ---------------------------------------------------------------------------- lessons 1-3


def _endpoints() -> dict[str, Param]:
    """A and B in the top view of lessons 1-2, and the image plane's distance d."""
    return {
        "A_x": Param(-1.5, -4.5, 4.5, 0.05, "A: x"),
        "A_w": Param(2.0, 0.5, 9.5, 0.05, "A: depth w"),
        "B_x": Param(2.5, -4.5, 4.5, 0.05, "B: x"),
        "B_w": Param(8.0, 0.5, 9.5, 0.05, "B: depth w"),
        "d": Param(1.0, 0.2, 4.0, 0.05, "image plane d"),
    }


def _points(p: dict) -> dict[str, object]:
    """LineView's ``A``, ``B`` (view-space ``(x, z)``) and ``d`` from the endpoint parameters."""
    return {"A": (p["A_x"], -p["A_w"]), "B": (p["B_x"], -p["B_w"]), "d": p["d"]}


def _in_line(view: LineView) -> bool:
    """Whether A, B and the eye are in line, so that the image of AB is one point (c = 0 in
    Lengyel's ``a x + b z = c``)."""
    return bool(view.points["a"][0] == view.points["b"][0])


def midpoint_title(view: LineView) -> str:
    """Where the middle M of AB shows on the image, in words true in every state.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> view = LineView(plt.subplots()[1], A=(-1.0, -2.0), B=(1.0, -2.0))
    >>> print(midpoint_title(view))
    M, the middle of AB, shows at s = 0.500:
    the middle of the image (A and B equally deep)
    """
    w1, w2 = -view.points["A"][1], -view.points["B"][1]
    if _in_line(view):
        return "A, B and the eye are in line:\nthe image is one point, and s means nothing"
    s_m = lerp.s_from_t(0.5, w1, w2)
    where = f"M, the middle of AB, shows at s = {s_m:.3f}:"
    if w1 == w2:
        return f"{where}\nthe middle of the image (A and B equally deep)"
    if round(s_m, 3) == 0.5:
        return f"{where}\nnearly the middle (A and B nearly equally deep)"
    return f"{where}\nnot the middle of the image (s = 0.5)"


def midpoint_readout(view: LineView) -> str:
    """:func:`midpoint_title` as one or two plain sentences."""
    w1, w2 = -view.points["A"][1], -view.points["B"][1]
    if _in_line(view):
        return (
            "A, B and the eye are in line (the line through A and B passes through the eye: "
            "c = 0 in Lengyel's a x + b z = c), so the image of AB is a single point and the "
            "screen parameter s is undefined."
        )
    s_m = lerp.s_from_t(0.5, w1, w2)
    where = f"M, the middle of AB, shows at s = {s_m:.3f} of the image"
    if w1 == w2:
        return f"{where}, its middle: A and B are equally deep."
    if round(s_m, 3) == 0.5:
        return f"{where}, nearly its middle: A and B are nearly equally deep."
    return f"{where}, not at its middle (s = 0.5)."


class TheProblem(LessonFigure):
    name = "the-problem"
    lesson = 1
    title = "The midpoint mismatch"
    description = "a segment seen by a 1D camera: the image's middle is not the middle's image"
    caption = (
        "The eye (left) sees segment AB on the image plane (grey). M, the middle of AB, shows "
        "at m; the middle of the image, c, shows C. They coincide only when A and B are equally "
        "deep. The faint dashed line is the whole line through A and B: when it passes through "
        "the eye, the image is a single point. (Lesson 1)"
    )
    size = (6.5, 4.5)
    print_size = (NARROW, 3.0)
    PARAMS = table(**_endpoints())

    def build(self, figure: Figure | SubFigure) -> None:
        self.view = LineView(figure.add_subplot())

    def redraw(self) -> None:
        self.view.update(**_points(self.params))
        self.view.ax.set_title(midpoint_title(self.view))

    def readout(self) -> str:
        return midpoint_readout(self.view)


class ProjectingALine(LessonFigure):
    name = "projecting-a-line"
    lesson = 2
    title = "Equally spaced pixels fan out"
    description = "rays through equally spaced pixels, the attribute along the image, and t(s)"
    caption = (
        "Left: rays through 8 equally spaced pixels meet AB at points that crowd towards its "
        "near end A. Middle: an attribute going from 0 at A to 1 at B, interpolated on the "
        "screen (dashed) and as it really is (solid): it lags, then catches up near B. Right: "
        "the object parameter t seen at each screen parameter s. (Lesson 2)"
    )
    size = (9.5, 3.4)
    print_size = (WIDE, 2.4)
    PARAMS = table(**_endpoints(), samples=Param(8, 1, 32, 1, "samples"))

    def build(self, figure: Figure | SubFigure) -> None:
        axes = figure.subplots(1, 3, gridspec_kw={"width_ratios": [1.3, 1, 1]})
        self.view = LineView(axes[0], samples=8)
        self.strip = ImageStrip(axes[1])
        self.curve = STCurve(axes[2], samples=8)

    def redraw(self) -> None:
        p = self.params
        self.view.update(**_points(p), samples=p["samples"])
        self.strip.update(w1=p["A_w"], w2=p["B_w"])
        self.curve.update(w1=p["A_w"], w2=p["B_w"], samples=p["samples"])
        if _in_line(self.view):
            self.view.ax.set_title("A, B and the eye in line: no s")
        else:
            s_m = lerp.s_from_t(0.5, p["A_w"], p["B_w"])
            self.view.ax.set_title(f"the midpoint of AB shows at s = {s_m:.3f}")

    def near_half(self) -> int:
        """How many of the equally spaced pixels show the half of AB nearer A (t < 1/2)."""
        n = int(self.params["samples"])
        s = (np.arange(n) + 0.5) / n
        return int(np.sum(lerp.t_from_s(s, self.params["A_w"], self.params["B_w"]) < 0.5))

    def readout(self) -> str:
        n = int(self.params["samples"])
        pixels = f"{self.near_half()} of the {n} equally spaced pixel{'s' * (n != 1)}"
        if _in_line(self.view):
            return (
                "A, B and the eye are in line: every pixel ray that meets AB meets it end-on, "
                "and the image is one point."
            )
        s_m = lerp.s_from_t(0.5, self.params["A_w"], self.params["B_w"])
        return (
            f"The middle of AB shows at s = {s_m:.3f} of the image: {pixels} show the half "
            "of AB nearer A."
        )


class STMapping(LessonFigure):
    name = "st-mapping"
    lesson = 3
    title = "The s-t curves, and where |t - s| peaks"
    description = "t against s for several depth ratios; the gap |t - s| and its derived peak"
    caption = (
        "Left: the object parameter t against the screen parameter s for depth ratios w2/w1 "
        "from 1/16 to 16; ratio 1 is the diagonal, and the bold curve is the chosen ratio, 4. "
        "Right: the gap |t - s|; the circle marks the derived peak s* = sqrt(w2)/(sqrt(w1) + "
        "sqrt(w2)) and the cross the largest of 2001 samples. They agree. (Lesson 3)"
    )
    size = (9.0, 4.2)
    print_size = (WIDE, 3.0)
    PARAMS = table(
        w1=Param(1.0, 0.1, 10.0, 0.01, "w1"),
        w2=Param(4.0, 0.1, 10.0, 0.01, "w2"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        axes = figure.subplots(1, 2)
        self.family = STFamily(axes[0])
        self.gap = GapPlot(axes[1])

    def redraw(self) -> None:
        w1, w2 = self.params["w1"], self.params["w2"]
        self.family.update(ratio=w2 / w1)
        self.gap.update(w1=w1, w2=w2)

    def readout(self) -> str:
        w1, w2 = self.params["w1"], self.params["w2"]
        if w1 == w2:
            return "With w1 = w2 the curve is the diagonal t = s: the gap |t - s| is 0 everywhere."
        (s_star, gap), (s_sample, gap_sample) = self.gap.derived, self.gap.measured
        return (
            f"For w2/w1 = {w2 / w1:.3g} the gap |t - s| peaks at s* = {s_star:.3f}, where it is "
            f"{gap:.3f}; the largest of 2001 samples is {gap_sample:.3f}, at s = {s_sample:.3f}."
        )


# ---------------------------------------------------------------------------- lessons 4-5


class Depth(LessonFigure):
    name = "depth"
    lesson = 4
    title = "Depth across the screen, and the depth buffer's precision"
    description = "w, 1/w and NDC z along the image; the smallest depth step a buffer resolves"
    caption = (
        "Left: along the image of a segment from depth 1 to depth 8, each rescaled to [0, 1], "
        "the view depth w bends while 1/w and NDC z are straight (a part beyond the near or far "
        "plane is shaded: clipping removes it). Right: the smallest change of depth a depth "
        "buffer notices, against depth, for near planes 0.01, 0.1 and 1 with far = 100, on log "
        "scales: a float32 buffer storing window z, a 24-bit fixed-point one, or either storing "
        "reversed depth (reversed Z). (Lesson 4)"
    )
    size = (9.5, 4.0)
    print_size = (WIDE, 2.8)
    PARAMS = table(
        w1=Param(1.0, 0.2, 50.0, 0.1, "w1"),
        w2=Param(8.0, 0.2, 50.0, 0.1, "w2"),
        near=Param(0.1, 0.001, 1.0, 0.05, "near plane", log=True, fmt=".3f"),
        far=Param(100.0, 2.0, 1000.0, 1.0, "far plane"),
        buffer=Param("float32", options=depth.DEPTH_BUFFERS, label="depth buffer"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        axes = figure.subplots(1, 2)
        self.across = DepthAcross(axes[0])
        self.precision = DepthPrecision(axes[1])

    def redraw(self) -> None:
        p = self.params
        self.across.update(w1=p["w1"], w2=p["w2"], near=p["near"], far=p["far"])
        self.precision.update(near=p["near"], far=p["far"], buffer=p["buffer"])

    def readout(self) -> str:
        p = self.params
        near, far, buffer = p["near"], p["far"], str(p["buffer"])
        clipped = ""
        for low, high in self.across.clipped:
            if (low, high) == (0.0, 1.0):
                clipped = " All of the segment lies beyond the near or far plane: it is clipped."
            else:
                clipped += f" The part from s = {low:.2f} to {high:.2f} is clipped away."
        steps = depth.depth_step([1.0, 0.9 * far], near, far, buffer)
        return (
            "Along the image, 1/w and NDC z are straight and w is not."
            f"{clipped} A {buffer} depth buffer with near = {near:.3g} and far = {far:g} "
            f"resolves depth steps of {steps[0]:.3g} at w = 1 and {steps[1]:.3g} at w = "
            f"{0.9 * far:g}."
        )


class Attributes(LessonFigure):
    name = "attributes"
    lesson = 5
    title = "Classic mistakes, and the clip vertex"
    description = "the right attribute beside affine and two classic mistakes; a clipped segment"
    caption = (
        "Left: an attribute from 0 at A (depth 1) to 1 at B (depth 6) along the image: the "
        "right answer (solid) beside affine interpolation, dividing by the depth buffer's window "
        "z instead of w, and dividing too early. Right: a segment from A to a point B behind the "
        "near plane (w <= 0), clipped at the near plane at C: with C's own attribute, a1 + "
        "t_C (a2 - a1) where t_C = (w1 - near) / (w1 - w_B), the visible part is right (solid); "
        "keeping B's attribute (dotted) makes all of it wrong. (Lesson 5)"
    )
    size = (9.5, 4.0)
    print_size = (WIDE, 2.8)
    PARAMS = table(
        a1=Param(0.0, -1.0, 1.0, 0.01, "a at A"),
        a2=Param(1.0, -1.0, 1.0, 0.01, "a at B"),
        w1=Param(1.0, 1.0, 20.0, 0.1, "w1"),
        w2=Param(6.0, 1.0, 20.0, 0.1, "w2"),
        behind=Param(-2.0, -10.0, 0.0, 0.1, "B's w when clipped"),
        near=Param(0.5, 0.1, 0.95, 0.01, "near plane"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        axes = figure.subplots(1, 2)
        self.line = MistakesAlongALine(axes[0])
        self.clip = ClipVertexMistake(axes[1])

    def redraw(self) -> None:
        p = self.params
        a, w = {"a1": p["a1"], "a2": p["a2"]}, {"w1": p["w1"], "near": p["near"]}
        self.line.update(**a, **w, w2=p["w2"])
        self.clip.update(**a, **w, w2=p["behind"])

    def readout(self) -> str:
        p = self.params
        at_half = {name: line.get_ydata()[50] for name, line in self.line.lines.items()}
        a_c = mistakes.clip_vertex_attribute(p["a1"], p["a2"], p["w1"], p["behind"], p["near"])
        return (
            f"At the middle of the image (s = 0.5) the right attribute is "
            f"{at_half['perspective-correct']:.3f}; affine interpolation gives "
            f"{at_half['affine']:.3f}, dividing by window z {at_half['divided by window z']:.3f} "
            f"and dividing too early {at_half['divided too early']:.3f}. Clipped at the near "
            f"plane, C must get {a_c:.3f}, not B's {p['a2']:.3f}."
        )


def _image_difference(images: list[ColourTriangle]) -> tuple[float, int] | None:
    """The largest colour difference between two drawings of the same quad, and the image row
    where it is; None if nothing is drawn."""
    first, second = (np.asarray(image.image.get_array()) for image in images)
    # Channel by channel: numpy reduces an axis of three slowly (4.5 ms against 1.0 ms here).
    drawn = np.zeros(first.shape[:2], dtype=bool)
    difference = np.zeros(first.shape[:2])
    for channel in range(first.shape[2]):
        drawn |= (first[..., channel] != 1.0) | (second[..., channel] != 1.0)
        np.maximum(difference, np.abs(first[..., channel] - second[..., channel]), out=difference)
    if not drawn.any():
        return None
    difference[~drawn] = -1.0
    row = int(np.unravel_index(np.argmax(difference), difference.shape)[0])
    return float(difference.max()), row


class ColourQuad(LessonFigure):
    name = "colour-quad"
    lesson = 5
    title = "Colour across a quad"
    description = "a colour gradient across a ground quad, affine and perspective-correct"
    caption = (
        "The same four corner colours across a ground quad, interpolated affinely (left) and "
        "perspective-correctly (right). The affine colours slide along the diagonal where the "
        "quad's two triangles meet. (Lesson 5)"
    )
    size = (9.0, 3.6)
    print_size = (WIDE, 2.4)
    PARAMS = table(**camera_params())
    whole_quad = True

    def build(self, figure: Figure | SubFigure) -> None:
        self.images = [
            ColourTriangle(ax, mode=mode, whole_quad=self.whole_quad)
            for ax, mode in zip(figure.subplots(1, 2), ("affine", "perspective"), strict=True)
        ]

    def redraw(self) -> None:
        camera = camera_from(self.params)
        for image in self.images:
            image.update(camera=camera)

    def readout(self) -> str:
        found = _image_difference(self.images)
        if found is None:
            return "Nothing is drawn: the quad is out of view."
        largest, row = found
        if largest < 0.005:
            return "Affine and perspective-correct colours agree (they differ by less than 0.005)."
        return (
            f"Affine and perspective-correct colours differ by up to {largest:.2f} (on a scale "
            f"of 0 to 1 per channel), at image row {row}."
        )


# ---------------------------------------------------------------------------- lessons 6-8

#: Image sizes the resolution control offers, (width, height).
RESOLUTIONS = {
    "160 x 120": (160, 120),
    "320 x 240": (320, 240),
    "480 x 360": (480, 360),
    "640 x 480": (640, 480),
}


class Checkerboards(LessonFigure):
    name = "checkerboards"
    lesson = 6
    title = "Checkerboards"
    description = "affine beside perspective-correct texture mapping, and the error in texels"
    caption = (
        "A checkerboard quad drawn affinely (left) and perspective-correctly (middle); right, "
        "how far apart their texture coordinates are, in texels (one texel is one check), on a "
        "colour scale that ends just above the largest error; blank where nothing is drawn. "
        "The affine lines bend, and bend differently in the quad's two triangles. (Lesson 6)"
    )
    size = (9.5, 2.9)
    print_size = (WIDE, 1.9)
    PARAMS = table(
        **camera_params(roll=True),
        frequency=Param(8.0, 1.0, 64.0, 1.0, "checks per side", fmt=".0f"),
        resolution=Param("320 x 240", options=tuple(RESOLUTIONS), label="resolution"),
        mode=Param("affine", options=("affine", "subdivided"), label="left panel"),
        span=Param(16, 2, 64, 1, "span (subdivided)"),
        quads=Param(1, 1, 32, 1, "quads per side"),
        filtered=Param("filtered", options=("filtered", "nearest"), label="texture"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        self.panels = CheckerPanels(figure.subplots(1, 3))

    def redraw(self) -> None:
        p = self.params
        width, height = RESOLUTIONS[str(p["resolution"])]
        self.panels.update(
            camera=camera_from(p),
            frequency=p["frequency"],
            width=width,
            height=height,
            mode=p["mode"],
            span=p["span"],
            quads=p["quads"],
            filtered=p["filtered"] == "filtered",
        )

    def inactive(self) -> dict[str, str]:
        if self.params["mode"] == "subdivided":
            return {}
        mode = self.PARAMS["mode"].label
        return {"span": f"The span is used only when {mode} is 'subdivided'."}

    def readout(self) -> str:
        views = self.panels.views
        if not views.covered.any():
            return "Nothing is drawn: the quad is out of view."
        error = np.where(views.covered, views.error, -1.0)
        row = int(np.unravel_index(np.argmax(error), error.shape)[0])
        how = "affine" if views.mode == "affine" else f"exact every {self.params['span']} px"
        if error.max() < 0.005:
            return f"Largest error {error.max():.1g} texels ({how}): nothing to see, rounding."
        return f"Largest error {error.max():.2f} texels ({how}), at image row {row}."


class UVImagesFigure(LessonFigure):
    name = "uv-images"
    lesson = 6
    title = "u and v as images"
    description = "the texture coordinates u and v across the ground quad, as images"
    caption = (
        "The texture coordinates u (left) and v (right) across the ground quad, from 0 (dark) "
        "to 1 (light), with a contour line every 0.1; where nothing is drawn is blank. "
        "Perspective-correct, the contour lines crowd towards the horizon; affine, they are "
        "evenly spaced and parallel within each triangle and bend at the diagonal. (Lesson 6)"
    )
    size = (9.0, 3.4)
    print_size = (WIDE, 2.4)
    PARAMS = table(
        **camera_params(),
        mode=Param("perspective", options=("perspective", "affine"), label="mode"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        self.uv = UVImages(figure.subplots(1, 2))

    def redraw(self) -> None:
        self.uv.update(camera=camera_from(self.params), mode=self.params["mode"])

    def readout(self) -> str:
        if not self.uv.views.covered.any():
            return "Nothing is drawn: the quad is out of view."
        du, dv = self.uv.largest_difference()
        return (
            f"Shown: {self.params['mode']} u and v. Affine interpolation is off from the "
            f"perspective-correct values by up to {du:.3f} in u and {dv:.3f} in v here."
        )


# The scene from outside (issue 11): beside the camera's image in lessons 6 and 8. Each figure
# adds its 3D axes before its other axes: a 3D box's tick labels may reach past its axes, and
# drawn first they lie under the neighbouring panels in a full draw as in a blitted one (drawn
# last, a full draw would put them over a neighbour's image, a blit under it).


def _view_param(default: str = "three-quarter") -> Param:
    return Param(default, options=tuple(VIEWS), label="seen from")


def outside_eye(view: OutsideView) -> str:
    """Where the eye is and how many of the outside view's pixel rays meet the quad.

    Examples
    --------
    >>> from interp.camera import Camera
    >>> ax = Figure().add_subplot(projection="3d")
    >>> print(outside_eye(OutsideView(ax, Camera(height=1.0, pitch=90.0))))
    The eye is 1.00 above the ground, 3.00 from the quad's centre horizontally; 0 of 9 pixel \
rays meet the quad.
    """
    camera = view.params["camera"]
    c = view.counts
    side = "above" if camera.height >= 0 else "below"
    return (
        f"The eye is {abs(camera.height):.2f} {side} the ground, {camera.distance:.2f} from the "
        f"quad's centre horizontally; {c['hits']} of {c['rays']} pixel rays meet the quad."
    )


def outside_clipping(view: OutsideView) -> str:
    """What clipping does, as the outside view shows it.

    Examples
    --------
    >>> from interp.camera import Camera
    >>> ax = Figure().add_subplot(projection="3d")
    >>> print(outside_clipping(OutsideView(ax, Camera(height=0.3, distance=1.0), quads=2)))
    Clipping keeps 7 of 8 triangles as 15 pieces, with 12 new vertices; the near plane cuts \
part of the quad off.
    """
    c = view.counts
    total = 2 * int(view.params["quads"]) ** 2
    near = "part of the quad off" if c["cut off"] else "nothing off"
    return (
        f"Clipping keeps {c['visible triangles']} of {total} triangles as {c['pieces']} pieces, "
        f"with {c['new vertices']} new vertices; the near plane cuts {near}."
    )


class OutsideViewFigure(LessonFigure):
    name = "outside-view"
    lesson = 6
    title = "The camera seen from outside"
    description = "camera, frustum, image plane, pixel rays and ground quad in world space"
    caption = (
        "The lesson's camera seen from outside: the eye, its frustum (near plane bold, cut-off "
        "dashed where the far plane lies far beyond), the image plane one unit ahead, and rays "
        "through nine pixels of a 320 x 240 image: solid with a dot where they meet the "
        "checkerboard quad, dotted where they pass above its far edge. (Lesson 6)"
    )
    size = (7.5, 4.6)
    print_size = (WIDE, 3.4)
    PARAMS = table(
        **camera_params(),
        quads=Param(1, 1, 16, 1, "quads per side"),
        frequency=Param(8, 1, 64, 1, "checks per side"),
        ground=Param("checkerboard", options=SHOWS, label="ground shows"),
        view=_view_param(),
        rays=Param(3, 1, 8, 1, "rays per side"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        grid = figure.add_gridspec(1, 2, width_ratios=[2.4, 1])
        self.outside = OutsideView(
            figure.add_subplot(grid[0, 0], projection="3d"),
            legend_ax=figure.add_subplot(grid[0, 1]),
        )

    def redraw(self) -> None:
        p = self.params
        self.outside.update(
            camera=camera_from(p),
            quads=p["quads"],
            frequency=p["frequency"],
            show=p["ground"],
            view=p["view"],
            rays=p["rays"],
        )

    def readout(self) -> str:
        return f"{outside_eye(self.outside)} {outside_clipping(self.outside)}"


class CheckerboardsOutside(Checkerboards):
    name = "checkerboards-outside"
    lesson = 6
    title = "Checkerboards, and the scene from outside"
    description = "the checkerboard app beside a 3D view of camera, frustum, rays and quad"
    caption = (
        "Left: the scene from outside the camera: the checkerboard quad, the eye and its "
        "frustum (near plane bold, far plane or cut-off dashed), the image plane, and rays "
        "through nine pixels, solid where they meet the quad. Right: the quad drawn affinely and "
        "perspective-correctly by that camera, and how far apart their texture coordinates "
        "are, in texels. The same sliders move both. (Lesson 6)"
    )
    size = (9.0, 5.2)
    print_size = (WIDE, 3.8)
    PARAMS = table(
        **{
            **Checkerboards.PARAMS,  # the affine image is not on the left here, but first
            "mode": Param("affine", options=("affine", "subdivided"), label="first image"),
        },
        ground=Param("checkerboard", options=SHOWS, label="outside: ground shows"),
        view=_view_param(),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        grid = figure.add_gridspec(2, 3, width_ratios=[1.6, 1, 1])
        self.outside = OutsideView(  # the 3D axes first: see the notes above
            figure.add_subplot(grid[:, 0], projection="3d"),
            legend_ax=figure.add_subplot(grid[1, 2]),
        )
        self.panels = CheckerPanels(
            [figure.add_subplot(grid[0, 1]), figure.add_subplot(grid[0, 2]),
             figure.add_subplot(grid[1, 1])]
        )  # fmt: skip

    def redraw(self) -> None:
        super().redraw()
        for ax in self.panels.axes:  # the panels are narrower than in Checkerboards
            ax.title.set_fontsize("small")
        p = self.params
        width, height = RESOLUTIONS[str(p["resolution"])]
        self.outside.update(
            camera=camera_from(p),
            width=width,
            height=height,
            quads=p["quads"],
            frequency=round(p["frequency"]),
            show=p["ground"],
            view=p["view"],
        )

    def readout(self) -> str:
        return f"{super().readout()} {outside_eye(self.outside)}"


class LinearOnScreen(LessonFigure):
    name = "linear-on-screen"
    lesson = 7
    title = "What is a plane over the screen"
    description = "w, 1/w, u, u/w and NDC z over the ground quad, ray cast, with contour lines"
    caption = (
        "Two quantities over the ground quad, ray cast through every pixel centre (not "
        "interpolated), with ten contour lines evenly spaced in value. 1/w, u/w and NDC z are "
        "planes over the screen (straight, parallel, evenly spaced contours); w and u are not. "
        "The title gives the largest distance from the best-fitting plane on either triangle. "
        "(Lesson 7)"
    )
    size = (9.0, 3.6)
    print_size = (WIDE, 2.4)
    PARAMS = table(
        **camera_params(),
        left=Param("w", options=PANEL_QUANTITIES, label="left panel"),
        right=Param("1/w", options=PANEL_QUANTITIES, label="right panel"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        self.panels = PlanePanels(figure.subplots(1, 2))

    def redraw(self) -> None:
        p = self.params
        self.panels.update(camera=camera_from(p), left=p["left"], right=p["right"])

    def readout(self) -> str:
        if not self.panels.truth.covered.any():
            return "Nothing is drawn: the quad is out of view."
        names = (self.params["left"], self.params["right"])
        fits = self.panels.fits
        said = [f"{name} {verdict(fit)}" for name, fit in zip(names, fits, strict=True)]
        return "Over the screen, " + "; ".join(said) + "."


#: A camera that frames the whole first triangle of the lesson quad, its corners at depths of
#: about 0.4, 2.6 and 3.1 (a ratio of 7.5), so that screen-space and clip-space weights differ
#: clearly.
BARYCENTRIC_CAMERA = {"height": 0.5, "pitch": 30.0, "yaw": 40.0, "distance": 3.0, "fovy": 90.0}


class Barycentrics(ColourQuad):
    name = "barycentrics"
    lesson = 7
    title = "Barycentrics, screen and clip space"
    description = "one triangle coloured by its barycentric coordinates: noperspective and smooth"
    caption = (
        "One triangle with red, green and blue corners, so its colour is its barycentric "
        "coordinates: screen-space (noperspective, left) and clip-space (smooth, OpenGL 4.6 eq. "
        "14.9, right). Its corners are at very different depths, so the two differ clearly. "
        "(Lesson 7)"
    )
    PARAMS = table(**camera_params(**BARYCENTRIC_CAMERA))
    whole_quad = False

    def readout(self) -> str:
        found = _image_difference(self.images)
        camera = camera_from(self.params).fitted(self.images[0].width, self.images[0].height)
        scene = ground_plane(camera, LESSON_SIZE, quads=1)
        w = scene.clip[scene.triangles[0], 3]
        depths = ", ".join(f"{x:.2f}" for x in w)
        if found is None:
            return f"Nothing is drawn: the triangle is out of view (corner depths w = {depths})."
        largest, row = found
        if largest < 0.005:
            return (
                "The colour is the weights: clip-space (smooth) and screen-space "
                "(noperspective) weights agree to within 0.005, because the corners' depths "
                f"are w = {depths}."
            )
        return (
            f"The colour is the weights: clip-space (smooth) and screen-space (noperspective) "
            f"weights differ by up to {largest:.2f}, at image row {row}; the corners' depths "
            f"are w = {depths}."
        )


class Shader(LessonFigure):
    name = "shader"
    lesson = 8
    title = "The shader's view"
    description = "smooth beside noperspective, flat, or smooth after dividing in the vertex shader"
    caption = (
        "A colour per corner across the ground quad, as the fragment shader receives it: smooth "
        "(left) beside, on the right, a vertex shader that divided by w itself and wrote w = 1: "
        "smooth then has nothing to correct with and gives noperspective's colours (while every "
        "corner is in front of the camera; behind it, the divided positions are wrong). The right "
        "panel can also show noperspective, or flat (each triangle the colour of its provoking "
        "vertex, the last). (Lesson 8)"
    )
    size = (9.0, 3.6)
    print_size = (WIDE, 2.4)
    PARAMS = table(
        **camera_params(),
        output=Param(
            "smooth, divided by w in the vertex shader",
            options=tuple(SHADER_OUTPUTS),
            label="right panel",
        ),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        self.view = ShaderView(figure.subplots(1, 2))

    def redraw(self) -> None:
        self.view.update(camera=camera_from(self.params), output=self.params["output"])

    def readout(self) -> str:
        output = str(self.params["output"])
        covered = self.view.values[output][1]
        if not covered.any():
            return "Nothing is drawn: the quad is out of view."
        if output.startswith("smooth") and self.view.behind:
            corners = "corner is" if self.view.behind == 1 else "corners are"
            return (
                f"{self.view.behind} {corners} behind the camera (w < 0): divided before "
                "clipping could cut them off, they are mirrored through the eye, and the picture "
                f"covers {int(covered.sum())} pixels where smooth covers "
                f"{int(self.view.values['smooth'][1].sum())}."
            )
        try:
            from_smooth = self.view.difference_from("smooth")
        except ValueError:  # a sliver at the edge of the view, drawn by one side only
            return "The two panels draw no pixel in common to compare."
        if output == "flat":
            return (
                "Flat: every pixel of a triangle takes the colour of its provoking vertex (the "
                f"last); it differs from smooth by up to {from_smooth:.2f}."
            )
        if output == "noperspective":
            text = f"Noperspective differs from smooth by up to {from_smooth:.2f} here."
            beyond = self.view.beyond()
            if beyond >= 0.005:
                text += (
                    f" Corners behind the camera: linear on the screen across triangles that "
                    f"reach behind the eye, its colours run up to {beyond:.2f} past the corners' "
                    "range [0, 1] (drawn clipped)."
                )
            return text
        return (
            "Dividing by w in the vertex shader leaves every w = 1, so smooth has nothing to "
            "correct with: the picture is noperspective's, up to "
            f"{from_smooth:.2f} away from smooth."
        )


class Clipping(LessonFigure):
    name = "clipping"
    lesson = 8
    title = "Near-plane clipping"
    description = "the ground plane from just above it, with the outline of every clipped triangle"
    caption = (
        "With the camera just above the ground and over it, some triangles reach behind it; "
        "clipping in clip space cuts them against the planes of the view volume (at this "
        "camera the left, right and bottom planes) into the outlined pieces, and the image "
        "stays correct. (Lesson 8)"
    )
    size = (6.5, 5.0)
    print_size = (NARROW, 2.6)
    PARAMS = table(**camera_params(height=0.3, distance=1.0), quads=Param(2, 1, 8, 1, "quads"))

    def build(self, figure: Figure | SubFigure) -> None:
        self.view = ClippingView(figure.add_subplot())

    def redraw(self) -> None:
        self.view.update(camera=camera_from(self.params), quads=self.params["quads"])

    def readout(self) -> str:
        p = self.view.params
        camera = p["camera"].fitted(int(p["width"]), int(p["height"]))
        scene = ground_plane(camera, LESSON_SIZE, quads=int(p["quads"]))
        behind = int(np.sum(scene.clip[:, 3] <= 0))
        counts = self.view.counts
        return (
            f"{counts['visible triangles']} triangles in view became {counts['pieces']} after "
            f"clipping; {behind} of the ground's {len(scene.clip)} vertices are behind the camera "
            "(w <= 0)."
        )


class ClippingOutside(Clipping):
    name = "clipping-outside"
    lesson = 8
    title = "Near-plane clipping, seen from outside"
    description = "the clipping app beside a 3D view of what the near plane cuts off"
    caption = (
        "Left: the camera's image, with the outline of every piece clipping made. Right: the "
        "same from outside: the quad's triangles, the pieces the camera draws (outlined), the "
        "vertices clipping made (diamonds) and the part of the quad the near plane cuts off "
        "(hatched: nearer than the near plane, or behind the eye). (Lesson 8)"
    )
    size = (9.0, 4.6)
    print_size = (WIDE, 3.4)
    PARAMS = table(**Clipping.PARAMS, view=_view_param())

    def build(self, figure: Figure | SubFigure) -> None:
        grid = figure.add_gridspec(2, 2, width_ratios=[1, 1.2], height_ratios=[1.1, 1])
        outside = figure.add_subplot(grid[:, 1], projection="3d")  # first: see the notes above
        self.view = ClippingView(figure.add_subplot(grid[0, 0]))
        self.outside = OutsideView(
            outside, legend_ax=figure.add_subplot(grid[1, 0]), show="triangles"
        )

    def redraw(self) -> None:
        super().redraw()
        self.view.ax.title.set_fontsize("small")  # the panel is narrower than in Clipping
        p = self.params
        image = self.view.params
        self.outside.update(
            camera=camera_from(p),
            width=image["width"],
            height=image["height"],
            quads=p["quads"],
            frequency=image["frequency"],
            view=p["view"],
        )

    def readout(self) -> str:
        c = self.outside.counts
        near = "part of the quad off" if c["cut off"] else "nothing off"
        return (
            f"{super().readout()} Clipping made {c['new vertices']} new vertices; the near "
            f"plane cuts {near}."
        )


class Approximations(LessonFigure):
    name = "approximations"
    lesson = 8
    title = "The approximation lab"
    description = "mean texture error against divides per pixel: Quake's spans and tessellation"
    caption = (
        "Mean texture error against divides per pixel, on log scales: exact every N pixels "
        "along a row (Quake's spans) against cutting the quad into n x n affine quads "
        "(PlayStation era). The camera starts rolled: with no roll, depth is constant along "
        "each row, spans are exact, and only tessellation is left to plot. (Lesson 8)"
    )
    size = (6.5, 4.6)
    print_size = (NARROW, 3.0)
    PARAMS = table(**camera_params(LAB_CAMERA, roll=True))

    def build(self, figure: Figure | SubFigure) -> None:
        self.lab = ApproximationLab(figure.add_subplot())

    def redraw(self) -> None:
        self.lab.update(camera=camera_from(self.params, LAB_CAMERA))

    def readout(self) -> str:
        spans, tess = self.lab.costs["spans"], self.lab.costs["tessellation"]
        span16 = int(np.flatnonzero(spans.setting == 16)[0])
        quads8 = int(np.flatnonzero(tess.setting == 8)[0])
        if spans.divides_per_pixel[span16] == 0:
            return "Nothing is drawn: the plane is out of view."

        def texels(error: float) -> str:
            return "0 (to rounding)" if error < approximation.EXACT else f"{error:.3g}"

        return (
            f"Spans of 16 pixels: mean error {texels(spans.mean_error[span16])} texels at "
            f"{spans.divides_per_pixel[span16]:.3f} divides per pixel; 8 x 8 affine quads: "
            f"{texels(tess.mean_error[quads8])} texels at {tess.divides_per_pixel[quads8]:.3f}."
        )


# ---------------------------------------------------------------------------- lesson 9

#: Checks per side the filtering figures offer: powers of two, so the mipmap halves evenly.
FREQUENCIES = tuple(str(2**k) for k in range(1, 8))
#: The filtering lesson's camera: low, looking far, so the far checks are smaller than pixels.
FILTERING_CAMERA = {"height": 0.6, "pitch": 10.0}


class TextureFiltering(LessonFigure):
    name = "texture-filtering"
    lesson = 9
    title = "Texture filtering: footprints, mip levels, trilinear"
    description = "pixel footprints in the texture, OpenGL's level of detail, the filtered image"
    caption = (
        "Left: the footprints of a grid of pixels in a 256 x 256-texel checkerboard texture "
        "(parallelograms, drawn enlarged): about a texel long near the camera, several texels "
        "long far away. Middle: OpenGL's level of detail λ = log2 of the longer footprint edge in "
        "texels, per pixel, one colour per mipmap level. Right: the image filtered as chosen; by "
        "default trilinear, from the mipmap (GL_LINEAR_MIPMAP_LINEAR). (Lesson 9)"
    )
    size = (9.0, 3.3)
    print_size = (WIDE, 2.3)
    PARAMS = table(
        **camera_params(**FILTERING_CAMERA),
        frequency=Param("64", options=FREQUENCIES, label="checks per side"),
        filter=Param("trilinear", options=tuple(FILTERS), label="right panel"),
        mode=Param("perspective", options=("perspective", "affine"), label="interpolation"),
        quads=Param(1, 1, 16, 1, "quads per side"),
        scale=Param(8.0, 1.0, 32.0, 1.0, "footprints drawn x", fmt=".0f"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        self.panels = FilteringPanels(figure.subplots(1, 3))

    def redraw(self) -> None:
        p = self.params
        self.panels.update(
            camera=camera_from(p),
            frequency=int(p["frequency"]),
            filter=p["filter"],
            mode=p["mode"],
            quads=p["quads"],
            scale=p["scale"],
        )

    def readout(self) -> str:
        views = self.panels.views
        drawn = views.lod[views.lod > -float("inf")]
        if not drawn.size:
            return "Nothing is drawn: the quad is out of view."
        low, high = float(drawn.min()), float(drawn.max())
        magnified = float((drawn <= 0).mean())
        last = len(mipmap.mipmap(np.zeros((views.size, views.size)))) - 1
        deepest = 0 if high <= 0 else min(int(np.floor(high)) + 1, last)
        return (
            f"λ runs from {low:.2f} to {high:.2f}: {magnified:.0%} of the drawn pixels are "
            f"magnified (λ <= 0: level 0 alone); trilinear filtering reaches down to mipmap "
            f"level {deepest}."
        )


class MipmapPyramidFigure(LessonFigure):
    name = "mipmap-pyramid"
    lesson = 9
    title = "A mipmap"
    description = "the checkerboard texture and its first halvings, each texel the mean of four"
    caption = (
        "Levels 0 to 5 of the mipmap of a 16 x 16 checkerboard in a 256 x 256 texture, each "
        "drawn at the same size: every texel of a level is the mean of 2 x 2 texels of the one "
        "before. Once a check is smaller than a texel (level 5 here) the board is uniform grey: "
        "what a pixel far away should show. (Lesson 9)"
    )
    size = (9.0, 2.2)
    print_size = (WIDE, 1.5)
    PARAMS = table(frequency=Param("16", options=FREQUENCIES, label="checks per side"))

    def build(self, figure: Figure | SubFigure) -> None:
        self.pyramid = MipmapPyramid(figure.subplots(1, 6))

    def redraw(self) -> None:
        self.pyramid.update(frequency=int(self.params["frequency"]))

    def readout(self) -> str:
        frequency = int(self.params["frequency"])
        levels = mipmap.mipmap(mipmap.checker_texture(frequency))
        grey = next(k for k, level in enumerate(levels) if np.all(level == 0.5))
        shown = len(self.pyramid.axes)
        beyond = "" if grey < shown else f", beyond the levels shown (0 to {shown - 1})"
        return (
            f"{frequency} x {frequency} checks of {len(levels[0]) // frequency} texels each: "
            f"level {grey - 1} still has one texel a check, and from level {grey} on every "
            f"texel is 0.5, uniform grey{beyond}."
        )


#: Every lesson figure, by name, in lesson order.
FIGURES: dict[str, type[LessonFigure]] = {
    figure.name: figure
    for figure in (
        TheProblem,
        ProjectingALine,
        STMapping,
        Depth,
        Attributes,
        ColourQuad,
        Checkerboards,
        UVImagesFigure,
        CheckerboardsOutside,
        OutsideViewFigure,
        LinearOnScreen,
        Barycentrics,
        Shader,
        Clipping,
        ClippingOutside,
        Approximations,
        TextureFiltering,
        MipmapPyramidFigure,
    )
}
