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

from matplotlib.artist import Artist
from matplotlib.figure import Figure, SubFigure

from interp import lerp
from interp.plots._base import Plot
from interp.plots.attributes import ClipVertexMistake, ColourTriangle, MistakesAlongALine
from interp.plots.checker import CheckerPanels, UVImages
from interp.plots.depth import DepthAcross, DepthPrecision
from interp.plots.gpu import LAB_CAMERA, ApproximationLab, ClippingView
from interp.plots.line import GapPlot, ImageStrip, LineView, STCurve, STFamily
from interp.plots.params import Param, camera_from, camera_params, table

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
    a, b = view.points["a"][0], view.points["b"][0]
    if a == b:
        return "A, B and the eye are in line:\nthe image is one point, and s means nothing"
    s_m = lerp.s_from_t(0.5, w1, w2)
    where = f"M, the middle of AB, shows at s = {s_m:.3f}:"
    if w1 == w2:
        return f"{where}\nthe middle of the image (A and B equally deep)"
    if round(s_m, 3) == 0.5:
        return f"{where}\nnearly the middle (A and B nearly equally deep)"
    return f"{where}\nnot the middle of the image (s = 0.5)"


class TheProblem(LessonFigure):
    name = "the-problem"
    lesson = 1
    title = "The midpoint mismatch"
    description = "a segment seen by a 1D camera: the image's middle is not the middle's image"
    caption = (
        "The eye (left) sees segment AB on the image plane (grey). M, the middle of AB, shows "
        "at m; the middle of the image, c, shows C. They coincide only when A and B are equally "
        "deep. (Lesson 1)"
    )
    size = (6.5, 4.5)
    print_size = (NARROW, 3.0)
    PARAMS = table(**_endpoints())

    def build(self, figure: Figure | SubFigure) -> None:
        self.view = LineView(figure.add_subplot())

    def redraw(self) -> None:
        self.view.update(**_points(self.params))
        self.view.ax.set_title(midpoint_title(self.view))


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
        s_m = lerp.s_from_t(0.5, p["A_w"], p["B_w"])
        self.view.ax.set_title(f"the midpoint of AB shows at s = {s_m:.3f}")


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


# ---------------------------------------------------------------------------- lessons 4-5


class Depth(LessonFigure):
    name = "depth"
    lesson = 4
    title = "Depth across the screen, and the depth buffer's precision"
    description = "w, 1/w and NDC z along the image; the smallest depth step a buffer resolves"
    caption = (
        "Left: along the image of a segment from depth 1 to depth 8, each rescaled to [0, 1], "
        "the view depth w bends while 1/w and NDC z are straight. Right: the smallest change of "
        "depth a float32 depth buffer notices, against depth, for near planes 0.01, 0.1 and 1 "
        "with far = 100, on log scales. (Lesson 4)"
    )
    size = (9.5, 4.0)
    print_size = (WIDE, 2.8)
    PARAMS = table(
        w1=Param(1.0, 0.2, 50.0, 0.1, "w1"),
        w2=Param(8.0, 0.2, 50.0, 0.1, "w2"),
        near=Param(0.1, 0.001, 1.0, 0.05, "near plane", log=True, fmt=".3f"),
        far=Param(100.0, 2.0, 1000.0, 1.0, "far plane"),
        buffer=Param("float32", options=("float32", "fixed24"), label="depth buffer"),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        axes = figure.subplots(1, 2)
        self.across = DepthAcross(axes[0])
        self.precision = DepthPrecision(axes[1])

    def redraw(self) -> None:
        p = self.params
        self.across.update(w1=p["w1"], w2=p["w2"], near=p["near"], far=p["far"])
        self.precision.update(near=p["near"], far=p["far"], buffer=p["buffer"])


class Attributes(LessonFigure):
    name = "attributes"
    lesson = 5
    title = "Classic mistakes, and the clip vertex"
    description = "the right attribute beside affine and two classic mistakes; a clipped segment"
    caption = (
        "Left: an attribute from 0 at A (depth 1) to 1 at B (depth 6) along the image: the "
        "right answer (solid) beside affine interpolation, dividing by the depth buffer's window "
        "z instead of w, and dividing too early. Right: a segment from A to a point B behind the "
        "camera, clipped at the near plane at C: with C's own attribute (solid) the visible part "
        "is right; keeping B's attribute (dotted) makes all of it wrong. (Lesson 5)"
    )
    size = (9.5, 4.0)
    print_size = (WIDE, 2.8)
    PARAMS = table(
        a1=Param(0.0, -1.0, 1.0, 0.01, "a at A"),
        a2=Param(1.0, -1.0, 1.0, 0.01, "a at B"),
        w1=Param(1.0, 0.5, 20.0, 0.1, "w1"),
        w2=Param(6.0, 0.5, 20.0, 0.1, "w2"),
        behind=Param(-2.0, -10.0, 0.0, 0.1, "B's w when clipped"),
        near=Param(0.5, 0.1, 0.5, 0.01, "near plane"),
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


# ---------------------------------------------------------------------------- lessons 6-7

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
        "how far apart their texture coordinates are, in texels. The affine lines bend, and "
        "bend differently in the quad's two triangles. (Lesson 6)"
    )
    size = (9.5, 2.9)
    print_size = (WIDE, 1.9)
    PARAMS = table(
        **camera_params(),
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


class UVImagesFigure(LessonFigure):
    name = "uv-images"
    lesson = 6
    title = "u and v as images"
    description = "the texture coordinates u and v across the ground quad, as images"
    caption = (
        "The perspective-correct texture coordinates u (left) and v (right) across the ground "
        "quad, from 0 (dark) to 1 (light); where nothing is drawn is blank. (Lesson 6)"
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


#: A camera that frames the whole first triangle of the lesson quad, each corner at its own depth.
BARYCENTRIC_CAMERA = {"height": 2.2, "pitch": 32.0, "yaw": 20.0, "distance": 4.2}


class Barycentrics(ColourQuad):
    name = "barycentrics"
    lesson = 7
    title = "Barycentrics, screen and clip space"
    description = "one triangle coloured by its barycentric coordinates: noperspective and smooth"
    caption = (
        "One triangle with red, green and blue corners, so its colour is its barycentric "
        "coordinates: screen-space (noperspective, left) and clip-space (smooth, OpenGL 4.6 eq. "
        "14.9, right). (Lesson 7)"
    )
    PARAMS = table(**camera_params(**BARYCENTRIC_CAMERA))
    whole_quad = False


class Clipping(LessonFigure):
    name = "clipping"
    lesson = 7
    title = "Near-plane clipping"
    description = "the ground plane from just above it, with the outline of every clipped triangle"
    caption = (
        "With the camera just above the ground and over it, some triangles reach behind it; "
        "clipping in clip space cuts them at the near plane into the outlined pieces, and the "
        "image stays correct. (Lesson 7)"
    )
    size = (6.5, 5.0)
    print_size = (NARROW, 2.6)
    PARAMS = table(**camera_params(height=0.3, distance=1.0), quads=Param(2, 1, 8, 1, "quads"))

    def build(self, figure: Figure | SubFigure) -> None:
        self.view = ClippingView(figure.add_subplot())

    def redraw(self) -> None:
        self.view.update(camera=camera_from(self.params), quads=self.params["quads"])


class Approximations(LessonFigure):
    name = "approximations"
    lesson = 7
    title = "The approximation lab"
    description = "mean texture error against divides per pixel: Quake's spans and tessellation"
    caption = (
        "Mean texture error against divides per pixel, on log scales, for a rolled camera: "
        "exact every N pixels along a row (Quake's spans) against cutting the quad into n x n "
        "affine quads (PlayStation era). (Lesson 7)"
    )
    size = (6.5, 4.6)
    print_size = (NARROW, 3.0)
    PARAMS = table(**camera_params(LAB_CAMERA, roll=True))

    def build(self, figure: Figure | SubFigure) -> None:
        self.lab = ApproximationLab(figure.add_subplot())

    def redraw(self) -> None:
        self.lab.update(camera=camera_from(self.params, LAB_CAMERA))


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
        Barycentrics,
        Clipping,
        Approximations,
    )
}
