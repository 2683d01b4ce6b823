"""Figures of texture filtering: pixel footprints in the texture, the level of detail per pixel,
the filtered image, and the mipmap pyramid."""

from __future__ import annotations

from collections.abc import Sequence

import matplotlib
import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.patches import Patch

from interp import mipmap
from interp.camera import Camera
from interp.plots._base import Plot, place_pixels
from interp.plots._style import AFFINE, CORRECT, bare
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane

#: The filters the result panel can show, with their titles.
FILTERS = {
    "nearest": "point sampled (GL_NEAREST)",
    "box": "box filtered (exact average)",
    "trilinear": "trilinear, from the mipmap",
}
#: Where the image shows nothing: a light blue, distinct from the grey far checks.
SKY = "#d6e6f2"
#: The colour range of the λ panel: half a texel per pixel to a 256-texel texture's last level.
LOD_RANGE = (-2.0, 8.0)


def sample_pixels(width: int, height: int, columns: int, rows: int) -> np.ndarray:
    """Flat image indices of ``columns x rows`` pixels spread evenly over an image.

    Examples
    --------
    >>> sample_pixels(4, 4, 2, 2)
    array([ 5,  7, 13, 15])
    """
    x = ((np.arange(columns) + 0.5) * width / columns).astype(int)
    y = ((np.arange(rows) + 0.5) * height / rows).astype(int)
    return (y[:, None] * width + x[None, :]).ravel()


def parallelograms(centre: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Corners (N, 4, 2) of parallelograms around ``centre`` (N, 2) spanned by ``edges``
    (2, 2, N): ``centre ± e_x / 2 ± e_y / 2``.

    Examples
    --------
    >>> parallelograms(np.array([[0.0, 0.0]]), np.array([[[2.0], [0.0]], [[0.0], [1.0]]]))
    array([[[-1. , -0.5],
            [ 1. , -0.5],
            [ 1. ,  0.5],
            [-1. ,  0.5]]])
    """
    e_x, e_y = np.moveaxis(edges, 2, 0).transpose(1, 0, 2)  # (N, 2) each
    half_x, half_y = e_x / 2, e_y / 2
    return np.stack(
        [
            centre - half_x - half_y,
            centre + half_x - half_y,
            centre + half_x + half_y,
            centre - half_x + half_y,
        ],
        axis=1,
    )


class FilteringPanels(Plot):
    """Footprints in the texture | λ per pixel | the filtered image, for one camera.

    Left: the checkerboard texture in texel coordinates, with the footprints (parallelograms)
    of a grid of pixels, drawn ``scale`` times their size. Middle: OpenGL's level of detail
    λ = log2 ρ per pixel, the grid's pixels marked. Right: the image point-sampled,
    box-filtered or trilinear.

    Parameters
    ----------
    axes : three Axes
    camera : Camera
    frequency : int
        Checks per side, a power of two.
    mode : {"perspective", "affine"}
        How (u, v) and their derivatives are interpolated.
    filter : {"nearest", "box", "trilinear"}
        The right panel's filter.
    width, height : int
        Pixels of the image.
    scale : float
        How much larger than life the footprints are drawn.
    quads : int
        Squares per side of the ground plane, each two triangles (1: affine derivatives are
        constant over each half of the quad).
    grid : (int, int)
        Columns and rows of pixels whose footprints are drawn.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> panels = FilteringPanels(Figure().subplots(1, 3), width=64, height=48)
    >>> bool(panels.views.lod.min() > 0)    # 64 pixels wide: each covers several texels
    True
    """

    def __init__(
        self,
        axes: Sequence[Axes],
        camera: Camera | None = None,
        frequency: int = 8,
        mode: str = "perspective",
        filter: str = "trilinear",
        width: int = 320,
        height: int = 240,
        scale: float = 8.0,
        quads: int = 1,
        grid: tuple[int, int] = (6, 5),
    ) -> None:
        self.axes = list(axes)
        self.grid = grid
        size = mipmap.TEXTURE_SIZE
        texture_ax, lod_ax, image_ax = self.axes
        self.texture = texture_ax.imshow(
            np.zeros((size, size)),
            cmap="gray",
            vmin=-0.6,  # black checks dark grey, so the footprints show on them
            vmax=1.3,
            origin="lower",
            extent=(0, size, 0, size),
            interpolation="nearest",
        )
        self.footprints = PolyCollection(
            [], facecolors=(*_rgb(CORRECT["color"]), 0.35), edgecolors=CORRECT["color"], lw=0.8
        )
        texture_ax.add_collection(self.footprints)
        texture_ax.set_xlim(0, size)
        texture_ax.set_ylim(0, size)
        texture_ax.set_xlabel("p = 256 u (texels)")
        texture_ax.set_ylabel("q = 256 v")
        ticks = [0, 64, 128, 192, 256]
        texture_ax.set_xticks(ticks)
        texture_ax.set_yticks(ticks)
        # What the texture panel shows, as a legend: it changes only with the frequency, as the
        # texture image does, and a live canvas notices a legend change and redraws all (the
        # image stays in the saved background). Beneath the footprints, drawn over it. How much
        # the footprints are enlarged is in the panel's title, which a live canvas redraws on
        # every step: changing it costs no more than a camera step.
        self.legend = texture_ax.legend(
            handles=[
                Patch(facecolor="0.2", edgecolor="0.2", label="checks"),
                Patch(facecolor=(*_rgb(CORRECT["color"]), 0.35), edgecolor=CORRECT["color"],
                      label="pixel footprints"),
            ],
            loc="upper right",
            fontsize="x-small",
            frameon=True,
            framealpha=0.9,
        )  # fmt: skip
        self.legend.set_zorder(0.5)
        self._texture_key: int | None = None

        blank = np.zeros((height, width))
        levels = int(LOD_RANGE[1] - LOD_RANGE[0])  # one colour per whole level: bands show
        self.lod = lod_ax.imshow(
            blank,
            cmap=matplotlib.colormaps["viridis"].resampled(levels),
            vmin=LOD_RANGE[0],
            vmax=LOD_RANGE[1],
            interpolation="nearest",
        )
        figure = lod_ax.get_figure(root=False)
        self.colorbar = figure.colorbar(self.lod, ax=lod_ax, shrink=0.8)
        self.colorbar.set_label("λ (mip level)")
        lod_ax.set_title("λ per pixel", fontsize="small")
        sky = matplotlib.colormaps["gray"].with_extremes(bad=SKY)  # nothing drawn: not a grey check
        self.image = image_ax.imshow(blank, cmap=sky, vmin=0, vmax=1)
        self.marks = []
        for ax in (lod_ax, image_ax):
            bare(ax)
            (mark,) = ax.plot(
                [], [], linestyle="none", marker="o", markersize=3, markerfacecolor="white",
                markeredgecolor=AFFINE["color"],
            )  # fmt: skip
            self.marks.append(mark)
        super().__init__(
            camera=camera or LESSON_CAMERA,
            frequency=frequency,
            mode=mode,
            filter=filter,
            width=width,
            height=height,
            scale=scale,
            quads=quads,
        )

    def redraw(self) -> None:
        """Draw for the current ``camera``, ``frequency``, ``mode``, ``filter``, ``width``,
        ``height``, ``scale`` and ``quads``."""
        p = self.params
        width, height = int(p["width"]), int(p["height"])
        if p["filter"] not in FILTERS:
            raise ValueError(f"filter must be one of {', '.join(FILTERS)}; got {p['filter']!r}")
        camera = p["camera"].fitted(width, height)
        scene = ground_plane(camera, size=LESSON_SIZE, quads=int(p["quads"]))
        self.views = views = mipmap.filtering_views(
            scene, width, height, int(p["frequency"]), mode=str(p["mode"])
        )
        frags = views.fragments
        if self._texture_key != views.frequency:
            self.texture.set_data(mipmap.checker_texture(views.frequency, views.size))
            self.legend.get_texts()[0].set_text(f"{views.frequency} x {views.frequency} checks")
            self._texture_key = views.frequency
        title = f"footprints in the texture, drawn {p['scale']:g}x"
        if self.axes[0].get_title() != title:
            self.axes[0].set_title(title, fontsize="small")
        self.lod.set_data(np.ma.masked_invalid(views.lod_image))
        filtered = getattr(views, str(p["filter"]))
        self.image.set_data(np.ma.masked_array(filtered, mask=~frags.covered))
        for image in (self.lod, self.image):
            place_pixels(image, width, height)

        wanted = sample_pixels(width, height, *self.grid)
        drawn = np.isin(frags.pixel, wanted)  # the grid's pixels the plane covers
        centre = views.uv[:, drawn].T * views.size
        edges = views.footprints[..., drawn] * float(p["scale"])
        self.footprints.set_verts(list(parallelograms(centre, edges)))
        column, row = frags.column[drawn], frags.pixel[drawn] // width
        for mark in self.marks:
            mark.set_data(column, row)

        self.axes[2].set_title(FILTERS[str(p["filter"])], fontsize="small")  # fits 8.2 in

    @property
    def dynamic(self) -> list:
        return [
            self.footprints, self.lod, self.image, *self.marks, self.axes[0].title,
            self.axes[2].title,
        ]  # fmt: skip


class MipmapPyramid(Plot):
    """The first levels of the checkerboard's mipmap, each drawn at the same size.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> pyramid = MipmapPyramid(Figure().subplots(1, 6), frequency=8)
    >>> [image.get_array().shape[0] for image in pyramid.images]
    [256, 128, 64, 32, 16, 8]
    """

    def __init__(self, axes: Sequence[Axes], frequency: int = 8) -> None:
        self.axes = list(axes)
        self.images = []
        for k, ax in enumerate(self.axes):
            n = mipmap.TEXTURE_SIZE >> k
            self.images.append(
                ax.imshow(
                    np.zeros((n, n)),
                    cmap="gray",
                    vmin=0,
                    vmax=1,
                    origin="lower",
                    interpolation="nearest",
                    aspect="equal",
                )
            )
            bare(ax)
        super().__init__(frequency=frequency)

    def redraw(self) -> None:
        """Draw the levels for the current ``frequency``."""
        frequency = int(self.params["frequency"])
        levels = mipmap.mipmap(mipmap.checker_texture(frequency))
        for k, (image, ax) in enumerate(zip(self.images, self.axes, strict=True)):
            image.set_data(levels[k])
            n = levels[k].shape[0]
            per_check = n / frequency
            check = (
                f"{per_check:g} texel{'s' * (per_check != 1)} a check"
                if per_check >= 1
                else "all grey (0.5)"
            )
            ax.set_title(f"level {k}: {n}²\n{check}", fontsize="small")

    @property
    def dynamic(self) -> list:
        return [*self.images, *(ax.title for ax in self.axes)]


def _rgb(colour: str) -> tuple[float, float, float]:
    """``"#RRGGBB"`` as three floats in [0, 1]."""
    return tuple(int(colour[k : k + 2], 16) / 255 for k in (1, 3, 5))
