"""Lesson figures of issue 11: the scene from outside beside the camera's image, and texture
filtering. Each is a :class:`~interp.plots.registry.LessonFigure`, for :data:`FIGURES_11`.

- :class:`CheckerboardsOutside` (lesson 6): the checkerboard app, with the outside view.
- :class:`ClippingOutside` (lesson 7): the clipping app, with the outside view.
- :class:`OutsideViewFigure` (lesson 6): the outside view alone, for handouts.
- :class:`TextureFiltering` (lesson 6): footprints, λ per pixel, the filtered image.
- :class:`MipmapPyramid` (lesson 6): the checkerboard's mipmap levels.

Each figure adds its 3D axes before its other axes: a 3D box's tick labels may reach past its
axes, and drawn first they lie under the neighbouring panels in a full draw as in a blitted one
(drawn last, a full draw would put them over a neighbour's image, a blit under it).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure, SubFigure

from interp import mipmap
from interp.plots.checker import CheckerPanels
from interp.plots.filtering import FILTERS, FilteringPanels, MipmapPyramid
from interp.plots.gpu import ClippingView
from interp.plots.outside import SHOWS, VIEWS, OutsideView
from interp.plots.params import Param, camera_from, camera_params, table
from interp.plots.registry import (
    RESOLUTIONS,
    WIDE,
    Checkerboards,
    Clipping,
    LessonFigure,
)

__all__ = [
    "FIGURES_11",
    "CheckerboardsOutside",
    "ClippingOutside",
    "MipmapPyramidFigure",
    "OutsideViewFigure",
    "TextureFiltering",
    "outside_readout",
]


def _view_param(default: str = "three-quarter") -> Param:
    return Param(default, options=tuple(VIEWS), label="seen from")


def outside_readout(view: OutsideView) -> str:
    """What the outside view shows, in two plain sentences true for its current state.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> from interp.camera import Camera
    >>> ax = Figure().add_subplot(projection="3d")
    >>> print(outside_readout(OutsideView(ax, Camera(height=1.0, pitch=90.0, distance=0.0))))
    The eye is 1.00 above the ground, 0.00 from the centre of the quad; 9 of 9 pixel rays meet \
the quad. Clipping keeps 2 of 2 triangles as 5 pieces, with 7 new vertices; the near plane cuts \
nothing off.
    """
    camera = view.params["camera"]
    c = view.counts
    eye = (
        f"The eye is {camera.height:.2f} above the ground, {camera.distance:.2f} from the "
        f"centre of the quad; {c['hits']} of {c['rays']} pixel rays meet the quad."
    )
    total = 2 * int(view.params["quads"]) ** 2
    near = "the near plane cuts part of the quad off" if c["cut off"] else "the near plane cuts "
    near += "" if c["cut off"] else "nothing off"
    clipping = (
        f"Clipping keeps {c['visible triangles']} of {total} triangles as {c['pieces']} pieces, "
        f"with {c['new vertices']} new vertices; {near}."
    )
    return f"{eye} {clipping}"


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
        **Checkerboards.PARAMS,
        ground=Param("checkerboard", options=SHOWS, label="outside: ground shows"),
        view=_view_param(),
    )

    def build(self, figure: Figure | SubFigure) -> None:
        grid = figure.add_gridspec(2, 3, width_ratios=[1.6, 1, 1])
        self.outside = OutsideView(  # the 3D axes first: see the module's notes
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
        return outside_readout(self.outside)


class ClippingOutside(Clipping):
    name = "clipping-outside"
    lesson = 7
    title = "Near-plane clipping, seen from outside"
    description = "the clipping app beside a 3D view of what the near plane cuts off"
    caption = (
        "Left: the camera's image, with the outline of every piece clipping made. Right: the "
        "same from outside: the quad's triangles, the pieces the camera draws (outlined), the "
        "vertices clipping made (diamonds) and the part of the quad the near plane cuts off "
        "(hatched: nearer than the near plane, or behind the eye). (Lesson 7)"
    )
    size = (9.0, 4.6)
    print_size = (WIDE, 3.4)
    PARAMS = table(**Clipping.PARAMS, view=_view_param())

    def build(self, figure: Figure | SubFigure) -> None:
        grid = figure.add_gridspec(2, 2, width_ratios=[1, 1.2], height_ratios=[1.1, 1])
        outside = figure.add_subplot(grid[:, 1], projection="3d")  # first: see the module's notes
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
        return outside_readout(self.outside)


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
        return outside_readout(self.outside)


#: Checks per side the filtering figures offer: powers of two, so the mipmap halves evenly.
FREQUENCIES = tuple(str(2**k) for k in range(1, 8))
#: The filtering lesson's camera: low, looking far, so the far checks are smaller than pixels.
FILTERING_CAMERA = {"height": 0.6, "pitch": 10.0}


class TextureFiltering(LessonFigure):
    name = "texture-filtering"
    lesson = 6
    title = "Texture filtering: footprints, mip levels, trilinear"
    description = "pixel footprints in the texture, OpenGL's level of detail, the filtered image"
    caption = (
        "Left: the footprints of a grid of pixels in a 256 x 256-texel texture of 64 x 64 checks "
        "(parallelograms, drawn 8 times their size): small and square near the camera, long "
        "and thin far away. Middle: OpenGL's level of detail λ = log2 of the longer footprint "
        "edge in texels, per pixel, one colour per mipmap level. Right: the image with "
        "trilinear filtering from the mipmap (GL_LINEAR_MIPMAP_LINEAR). (Lesson 6)"
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
    lesson = 6
    title = "A mipmap"
    description = "the checkerboard texture and its first halvings, each texel the mean of four"
    caption = (
        "Levels 0 to 5 of the mipmap of a 16 x 16 checkerboard in a 256 x 256 texture, each "
        "drawn at the same size: every texel of a level is the mean of 2 x 2 texels of the one "
        "before. Once a check is smaller than a texel (level 5 here) the board is uniform grey: "
        "what a pixel far away should show. (Lesson 6)"
    )
    size = (9.0, 2.2)
    print_size = (WIDE, 1.5)
    PARAMS = table(frequency=Param("16", options=FREQUENCIES, label="checks per side"))

    def build(self, figure: Figure | SubFigure) -> None:
        self.pyramid = MipmapPyramid(figure.subplots(1, 6))

    def redraw(self) -> None:
        self.pyramid.update(frequency=int(self.params["frequency"]))


#: The figures above, by name, in lesson order (to merge into ``registry.FIGURES``).
FIGURES_11: dict[str, type[LessonFigure]] = {
    figure.name: figure
    for figure in (
        OutsideViewFigure,
        CheckerboardsOutside,
        TextureFiltering,
        MipmapPyramidFigure,
        ClippingOutside,
    )
}
