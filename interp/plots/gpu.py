"""Figures of lesson 8: the shader's view, clipping as the camera moves through a plane, and the
approximation lab."""

from __future__ import annotations

import functools

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from interp import approximation, shaders
from interp.camera import Camera
from interp.plots._base import Plot, label, place_pixels
from interp.plots._style import AFFINE, CORRECT, bare, decades, set_limits
from interp.raster import fragments, interpolate, viewport
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane
from interp.texture import checkerboard

#: What the shader figure's right panel can show: a qualifier, or the vertex-shader mistake.
SHADER_OUTPUTS = {
    "noperspective": ("noperspective", False),
    "flat": ("flat", False),
    "smooth, divided by w in the vertex shader": ("smooth", True),
}

#: Colours of the ground quad's corners (u, v) = (0, 0), (1, 0), (0, 1), (1, 1) in the shader
#: figure: red, green, blue and white, so that each flat triangle is one clear colour.
SHADER_COLOURS = np.array([[1.0, 0.0, 0.0], [0.0, 0.6, 0.0], [0.0, 0.2, 1.0], [1.0, 1.0, 1.0]])


class ShaderView(Plot):
    """A colour per corner across the ground quad, as a fragment shader receives it: ``smooth``
    on the left; on the right ``noperspective``, ``flat`` (the provoking vertex, the last of
    each triangle, gives its colour to all of it) or ``smooth`` from a vertex shader that
    divided by w itself and wrote w = 1 (:mod:`interp.shaders`).

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> view = ShaderView(Figure().subplots(1, 2), width=32, height=24)
    >>> view.difference_from("noperspective") < 1e-12   # the mistake is noperspective
    True
    """

    def __init__(
        self,
        axes: list[Axes],
        camera: Camera | None = None,
        output: str = "smooth, divided by w in the vertex shader",
        width: int = 240,
        height: int = 180,
    ) -> None:
        self.axes = list(axes)
        self.images = [
            ax.imshow(np.ones((height, width, 3)), interpolation="nearest") for ax in self.axes
        ]
        for ax in self.axes:
            ax.set_axis_off()
        self.axes[0].set_title("smooth (the default)")
        self.values: dict[str, np.ndarray] = {}
        super().__init__(camera=camera or LESSON_CAMERA, output=output, width=width, height=height)

    def _draw(self, qualifier: str, divided: bool) -> tuple[np.ndarray, np.ndarray]:
        p = self.params
        width, height = int(p["width"]), int(p["height"])
        scene = ground_plane(p["camera"].fitted(width, height), LESSON_SIZE, quads=1)
        self.behind = int(np.sum(scene.clip[:, 3] <= 0))
        return shaders.shade(
            scene.clip, SHADER_COLOURS, scene.triangles, width, height, qualifier, divided
        )

    def redraw(self) -> None:
        """Draw for the current ``camera`` and ``output`` (a key of :data:`SHADER_OUTPUTS`)."""
        output = str(self.params["output"])
        self.values = {"smooth": self._draw("smooth", False)}
        self.values[output] = self._draw(*SHADER_OUTPUTS[output])
        for image, key in zip(self.images, ("smooth", output), strict=True):
            values, covered = self.values[key]
            image.set_data(np.where(covered[..., None], np.clip(values, 0, 1), 1.0))
        self.axes[1].set_title(output.replace(", divided", ",\ndivided"))

    def difference_from(self, other: str) -> float:
        """The largest difference between the colours the right panel shows and those
        ``other`` ("smooth", "noperspective" or "flat", drawn for the same camera) would show,
        over pixels both cover; colours are shown clipped to [0, 1] (see :meth:`beyond`)."""
        output = str(self.params["output"])
        values, covered = self.values[output]
        if other == "smooth":
            reference, drawn = self.values["smooth"]
        else:
            reference, drawn = self._draw(other, False)
        both = covered & drawn
        if not both.any():
            raise ValueError(f"no pixel shows both {output!r} and {other!r}: nothing to compare")
        shown = np.abs(np.clip(values, 0, 1) - np.clip(reference, 0, 1))
        return float(shown[both].max())

    def beyond(self) -> float:
        """How far the right panel's colours run outside [0, 1], the corners' range (0 if they
        stay inside). ``smooth`` and ``flat`` never leave it; ``noperspective`` does where
        clipping cut a triangle that reaches behind the eye: linear on the screen across all of
        the triangle, its colour runs past the corners' on the part left in view."""
        values, covered = self.values[str(self.params["output"])]
        if not covered.any():
            return 0.0
        shown = values[covered]
        return float(max(shown.max() - 1.0, -shown.min(), 0.0))

    @property
    def dynamic(self) -> list:
        return [*self.images, self.axes[1].title]


class ClippingView(Plot):
    """The ground plane drawn perspective-correctly, with the outline of every triangle that
    clipping made: watch new vertices appear as the camera nears the plane.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> view = ClippingView(plt.subplots()[1], Camera(height=0.02, pitch=10, near=0.05),
    ...                     width=64, height=48)
    >>> view.counts["pieces"] > view.counts["visible triangles"]     # clipping split some
    True
    """

    def __init__(
        self,
        ax: Axes,
        camera: Camera | None = None,
        quads: int = 2,
        width: int = 320,
        height: int = 240,
        frequency: float = 8,
    ) -> None:
        self.ax = ax
        self.image = ax.imshow(np.zeros((height, width)), cmap="gray", vmin=0, vmax=1)
        self.outlines = LineCollection([], colors=CORRECT["color"], linewidths=1.0)
        ax.add_collection(self.outlines)
        bare(ax)
        super().__init__(
            camera=camera or Camera(height=0.3, pitch=15, distance=1.0),
            quads=quads,
            width=width,
            height=height,
            frequency=frequency,
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``quads``, ``width``, ``height`` and ``frequency``."""
        p = self.params
        width, height = int(p["width"]), int(p["height"])
        camera = p["camera"].fitted(width, height)
        scene = ground_plane(camera, size=LESSON_SIZE, quads=int(p["quads"]))
        frags = fragments(scene.clip, scene.uv, scene.triangles, width, height)
        uv = interpolate(frags, "perspective")
        covered = frags.covered
        self.image.set_data(
            checkerboard(
                uv[..., 0],
                uv[..., 1],
                float(p["frequency"]),
                filtered=True,
                covered=covered,
                background=0.75,
            )
        )
        place_pixels(self.image, width, height)
        window = viewport(frags.clipped.clip, width, height)[..., :2]
        window[..., 1] = height - window[..., 1]  # image rows go down
        self.outlines.set_segments([np.vstack([tri, tri[:1]]) - 0.5 for tri in window])
        visible = len(np.unique(frags.clipped.source))
        self.counts = {"pieces": len(frags.clipped), "visible triangles": visible}
        self.ax.set_title(f"{visible} triangles in view became {len(frags.clipped)} after clipping")

    @property
    def dynamic(self) -> list:
        return [self.image, self.outlines, self.ax.title]


#: The lab's camera: rolled, so that depth varies along image rows (see Camera's roll).
LAB_CAMERA = Camera(height=1.0, pitch=15.0, yaw=0.0, distance=3.0, roll=30.0)


class ApproximationLab(Plot):
    """Mean error in texels against divides per pixel: Quake's spans against PlayStation-era
    tessellation, for one camera.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> lab = ApproximationLab(plt.subplots()[1], width=48, height=36)
    >>> len(lab.spans.get_xdata()), len(lab.tessellation.get_xdata())   # N = 1 is exact
    (6, 6)
    """

    #: The axes' ranges when there is nothing to plot.
    EMPTY_X, EMPTY_Y = (1e-3, 1.0), (1e-3, 10.0)

    def __init__(
        self,
        ax: Axes,
        camera: Camera | None = None,
        width: int = 192,
        height: int = 144,
        frequency: float = 8,
    ) -> None:
        self.ax = ax
        (self.spans,) = ax.plot([], [], **{**CORRECT, "label": "spans: exact every N pixels"})
        (self.tessellation,) = ax.plot(
            [], [], **{**AFFINE, "label": "tessellation: n x n quads, affine"}
        )
        # One label per setting, made once and moved (or hidden) by redraw. A label shows only
        # while its point is inside the axes' limits: checked when the points or the limits
        # change (the toolbar's zoom and pan change them too), not on every draw as matplotlib's
        # annotation_clip does (1-2 ms a frame for the twelve).
        self.labelled: set[tuple] = set()
        self.notes = {
            (line, setting): label(
                ax,
                template.format(setting),
                (1, 1),
                (4, 2),
                fontsize="x-small",
                color=line.get_color(),
                visible=False,
                annotation_clip=False,
            )
            for line, settings, template in (
                (self.spans, approximation.SPANS, "N={:d}"),
                (self.tessellation, approximation.QUADS, "n={:d}"),
            )
            for setting in settings
        }
        for limits in ("xlim_changed", "ylim_changed"):
            ax.callbacks.connect(limits, lambda _: self._label_points_in_view())
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("divides per pixel drawn")
        ax.set_ylabel("mean |Δ(u, v)| in texels")
        ax.legend(loc="upper right")
        super().__init__(
            camera=camera or LAB_CAMERA, width=width, height=height, frequency=frequency
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``width``, ``height`` and ``frequency``."""
        p = self.params
        size = (int(p["width"]), int(p["height"]), float(p["frequency"]))
        spans, tess = _measured(p["camera"], *size)
        self.costs = {"spans": spans, "tessellation": tess}
        self.labelled = set()
        for line, costs in ((self.spans, spans), (self.tessellation, tess)):
            # Exact settings (N = 1, and every N along rows of constant depth) have no place
            # on a log axis: their errors are rounding. Nor has a plane out of view (no divides).
            shown = (costs.mean_error >= approximation.EXACT) & (costs.divides_per_pixel > 0)
            x, y, settings = (
                a[shown] for a in (costs.divides_per_pixel, costs.mean_error, costs.setting)
            )
            line.set_data(x, y)
            for xi, yi, setting in zip(x, y, settings, strict=True):
                self.notes[line, int(setting)].xy = (xi, yi)
                self.labelled.add((line, int(setting)))
        xs = np.concatenate([spans.divides_per_pixel, tess.divides_per_pixel])
        ys = np.concatenate([spans.mean_error, tess.mean_error])
        keep = (xs > 0) & (ys >= approximation.EXACT)
        if keep.any():  # whole decades, with room for the labels: small steps keep them
            set_limits(
                self.ax,
                x=decades(xs[keep].min() / 1.5, xs[keep].max() * 3),
                y=decades(ys[keep].min() / 1.5, ys[keep].max() * 1.5),
            )
            exact = [
                name
                for name, costs in (("spans", spans), ("tessellation", tess))
                if np.all(costs.mean_error < approximation.EXACT)
            ]
            self.ax.set_title(f"{exact[0]}: exact at every setting here" if exact else "")
        else:  # nothing drawn, or nothing to correct: fixed axes, so history cannot show
            set_limits(self.ax, x=self.EMPTY_X, y=self.EMPTY_Y)
            self.ax.set_title("no error to plot: the plane is out of view or exact")
        self._label_points_in_view()

    def _label_points_in_view(self) -> None:
        """Show the label of each point plotted that is inside the axes' limits, hide the rest."""
        (x0, x1), (y0, y1) = (sorted(limits) for limits in (self.ax.get_xlim(), self.ax.get_ylim()))
        for key, note in self.notes.items():
            x, y = note.xy
            note.set_visible(key in self.labelled and x0 <= x <= x1 and y0 <= y <= y1)

    @property
    def dynamic(self) -> list:
        return [self.spans, self.tessellation, *self.notes.values(), self.ax.title]


@functools.lru_cache(maxsize=512)
def _measured(
    camera: Camera, width: int, height: int, frequency: float
) -> tuple[approximation.Costs, approximation.Costs]:
    """The lab's two measurements, spans and tessellation, kept for the last 512 settings.

    Together they take about 20 ms (one rasterization of the plane, then arithmetic on its
    pixels) and depend on nothing else; a student dragging a slider back and forth comes over
    the same settings again, which are then drawn without measuring. The arrays are
    read-only, as they are shared.

    Examples
    --------
    >>> spans, _ = _measured(Camera(height=1, pitch=25, roll=30), 64, 48, 8.0)
    >>> _measured(Camera(height=1, pitch=25, roll=30), 64, 48, 8.0)[0] is spans
    True
    """
    found = (
        approximation.span_costs(camera, width, height, frequency),
        approximation.tessellation_costs(camera, width, height, frequency),
    )
    for costs in found:
        for array in (costs.setting, costs.divides_per_pixel, costs.mean_error):
            array.setflags(write=False)
    return found
