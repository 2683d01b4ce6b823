"""Apps of lessons 4-7: depth, attributes, checkerboards, and the GPU's view."""

from __future__ import annotations

from matplotlib.figure import Figure

from interp import plots
from interp.apps._app import App, choice, int_slider, slider
from interp.apps.camera import camera_controls, camera_from
from interp.plots.gpu import LAB_CAMERA

#: Image sizes the resolution control offers, (width, height).
RESOLUTIONS = {
    "160 x 120": (160, 120),
    "320 x 240": (320, 240),
    "480 x 360": (480, 360),
    "640 x 480": (640, 480),
}


class Depth(App):
    """Lesson 4: w, 1/w and NDC z across the screen; the depth buffer's precision."""

    def __init__(self) -> None:
        controls = {
            "w1": slider(1.0, 0.2, 50.0, 0.1, "w1"),
            "w2": slider(8.0, 0.2, 50.0, 0.1, "w2"),
            "near": slider(0.1, 0.001, 1.0, 0.05, "near plane", log=True, readout_format=".3f"),
            "far": slider(100.0, 2.0, 1000.0, 1.0, "far plane"),
            "buffer": choice("float32", ["float32", "fixed24"], "depth buffer"),
        }

        def build(figure: Figure) -> None:
            axes = figure.subplots(1, 2)
            self.across = plots.DepthAcross(axes[0])
            self.precision = plots.DepthPrecision(axes[1])

        super().__init__(controls, (9.5, 4.0), build)

    def draw(self, **v: object) -> None:
        self.across.update(w1=v["w1"], w2=v["w2"], near=v["near"], far=v["far"])
        self.precision.update(near=v["near"], far=v["far"], buffer=v["buffer"])


class Attributes(App):
    """Lesson 5: an attribute along a line, right and wrong; the clip-vertex mistake."""

    def __init__(self) -> None:
        controls = {
            "a1": slider(0.0, -1.0, 1.0, 0.01, "a at A"),
            "a2": slider(1.0, -1.0, 1.0, 0.01, "a at B"),
            "w1": slider(1.0, 0.5, 20.0, 0.1, "w1"),
            "w2": slider(6.0, 0.5, 20.0, 0.1, "w2"),
            "behind": slider(-2.0, -10.0, 0.0, 0.1, "B's w when clipped"),
            "near": slider(0.5, 0.1, 0.5, 0.01, "near plane"),
        }

        def build(figure: Figure) -> None:
            axes = figure.subplots(1, 2)
            self.line = plots.MistakesAlongALine(axes[0])
            self.clip = plots.ClipVertexMistake(axes[1])

        super().__init__(controls, (9.5, 4.0), build)

    def draw(self, **v: float) -> None:
        self.line.update(a1=v["a1"], a2=v["a2"], w1=v["w1"], w2=v["w2"], near=v["near"])
        self.clip.update(a1=v["a1"], a2=v["a2"], w1=v["w1"], w2=v["behind"], near=v["near"])


class ColourQuad(App):
    """Lessons 5 and 7: a colour gradient (or one triangle's barycentrics), both modes."""

    def __init__(self, whole_quad: bool = True) -> None:
        controls = camera_controls()

        def build(figure: Figure) -> None:
            axes = figure.subplots(1, 2)
            self.images = [
                plots.ColourTriangle(ax, mode=mode, whole_quad=whole_quad)
                for ax, mode in zip(axes, ("affine", "perspective"), strict=True)
            ]

        super().__init__(controls, (9, 3.6), build)

    def draw(self, **v: float) -> None:
        camera = camera_from(v)
        for image in self.images:
            image.update(camera=camera)


class Checkerboards(App):
    """Lesson 6: affine beside perspective-correct, and the error in texels."""

    def __init__(self) -> None:
        controls = {
            **camera_controls(),
            "frequency": slider(8.0, 1.0, 64.0, 1.0, "checks per side", readout_format=".0f"),
            "resolution": choice("320 x 240", RESOLUTIONS, "resolution"),
            "mode": choice("affine", ["affine", "subdivided"], "left panel"),
            "span": int_slider(16, 2, 64, "span (subdivided)"),
            "quads": int_slider(1, 1, 32, "quads per side"),
            "filtered": choice("filtered", ["filtered", "nearest"], "texture"),
        }

        def build(figure: Figure) -> None:
            self.panels = plots.CheckerPanels(figure.subplots(1, 3))

        super().__init__(controls, (9.5, 2.9), build)

    def draw(self, **v: object) -> None:
        width, height = RESOLUTIONS[str(v["resolution"])]
        self.panels.update(
            camera=camera_from(v),
            frequency=v["frequency"],
            width=width,
            height=height,
            mode=v["mode"],
            span=v["span"],
            quads=v["quads"],
            filtered=v["filtered"] == "filtered",
        )


class UV(App):
    """Lesson 6: u and v as images, in either mode."""

    def __init__(self) -> None:
        controls = {
            **camera_controls(),
            "mode": choice("perspective", ["perspective", "affine"], "mode"),
        }

        def build(figure: Figure) -> None:
            self.uv = plots.UVImages(figure.subplots(1, 2))

        super().__init__(controls, (9, 3.4), build)

    def draw(self, **v: object) -> None:
        self.uv.update(camera=camera_from(v), mode=v["mode"])


class Clipping(App):
    """Lesson 7: move the camera down through the ground and watch clipping make triangles."""

    def __init__(self) -> None:
        controls = {**camera_controls(), "quads": int_slider(2, 1, 8, "quads per side")}
        controls["height"].value = 0.3

        def build(figure: Figure) -> None:
            self.view = plots.ClippingView(figure.add_subplot())

        super().__init__(controls, (6.5, 5), build)

    def draw(self, **v: object) -> None:
        self.view.update(camera=camera_from(v), quads=v["quads"])


class Approximations(App):
    """Lesson 7: error against divides per pixel, spans against tessellation."""

    def __init__(self) -> None:
        controls = camera_controls(LAB_CAMERA, roll=True)

        def build(figure: Figure) -> None:
            self.lab = plots.ApproximationLab(figure.add_subplot())

        super().__init__(controls, (6.5, 4.6), build)

    def draw(self, **v: float) -> None:
        self.lab.update(camera=camera_from(v, LAB_CAMERA))


def depth() -> Depth:
    """Lesson 4's app."""
    return Depth()


def attributes() -> Attributes:
    """Lesson 5's app: right and wrong interpolation along a line."""
    return Attributes()


def colour_quad() -> ColourQuad:
    """Lesson 5's app: a colour gradient across a quad, affine and perspective-correct."""
    return ColourQuad(whole_quad=True)


def barycentrics() -> ColourQuad:
    """Lesson 7's app: one triangle coloured by its barycentrics, screen-space and clip-space."""
    return ColourQuad(whole_quad=False)


def checkerboards() -> Checkerboards:
    """Lesson 6's app."""
    return Checkerboards()


def uv_images() -> UV:
    """Lesson 6's app: u and v as images."""
    return UV()


def clipping() -> Clipping:
    """Lesson 7's app: near-plane clipping as the camera moves through the plane."""
    return Clipping()


def approximations() -> Approximations:
    """Lesson 7's app: the approximation lab."""
    return Approximations()
