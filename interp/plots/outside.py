"""The scene seen from outside the camera: ground quad, camera, frustum, image plane, pixel rays,
and what clipping did, in world space on matplotlib's 3D axes.

Beside a camera's image it answers the questions the image cannot: where the camera is and
where it looks, why the picture is empty, which part of the quad the near plane cut off, where
clipping made new vertices. The viewer can orbit it with the mouse (ipympl) or pick one of
:data:`VIEWS`, which handouts use.
"""

from __future__ import annotations

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from interp import frustum
from interp.camera import Camera
from interp.plots._base import Plot
from interp.plots._style import AFFINE, CORRECT, OTHERS
from interp.scenes import LESSON_CAMERA, LESSON_SIZE, ground_plane

#: The fixed viewpoints, as matplotlib's (elevation, azimuth) in degrees with y up. World-fixed:
#: "behind" looks from behind the lessons' camera at yaw 0 (from +z), "side" from +x, "above"
#: straight down with +x to the right.
VIEWS = {
    "three-quarter": (22.0, 40.0),
    "behind": (18.0, 0.0),
    "side": (0.0, 90.0),
    "above": (90.0, 0.0),
}
#: What the ground shows.
SHOWS = ("checkerboard", "triangles")
#: Half-widths of the box drawn (world units): the smallest that holds the quad and the eye.
HALF_WIDTHS = (2.5, 3.5, 4.5, 6.0, 9.0)
#: Heights of the box drawn above the ground.
TOPS = (1.5, 2.5, 3.5, 4.5)
#: The least room between the eye and the box's side or top. Not half of a box step: the
#: lessons' default eyes stand at round distances and heights, which would then sit exactly on
#: the edge between two boxes, and a key press from the default would change the box (and a
#: new box redraws the whole figure rather than the camera alone).
EYE_ROOM = 0.4
#: Lowest point of the box (a camera may stand below the ground).
BOTTOM = -0.6
#: How much larger than matplotlib's default the box is drawn in its axes.
ZOOM = 1.05
#: View depth of the image plane drawn.
IMAGE_DISTANCE = 1.0

RAY = OTHERS[0]["color"]
INK = "#000000"


def _snap(value: float, steps: tuple[float, ...]) -> float:
    """The first of ``steps`` at least ``value`` (the last if none is)."""
    return next((step for step in steps if step >= value), steps[-1])


def _checks(frequency: int, size: float) -> np.ndarray:
    """The black checks of a ``frequency x frequency`` board on the quad: (N, 4, 3) corners."""
    edges = (np.arange(frequency + 1) / frequency - 0.5) * size  # along x and along -z
    i, j = np.meshgrid(np.arange(frequency), np.arange(frequency))
    black = (i + j) % 2 == 0  # the check at the origin of (u, v) is black
    i, j = i[black], j[black]
    x0, x1 = edges[i], edges[i + 1]
    z0, z1 = -edges[j], -edges[j + 1]  # v runs along -z
    zero = np.zeros_like(x0)
    return np.stack(
        [
            np.stack([x0, zero, z0], 1),
            np.stack([x1, zero, z0], 1),
            np.stack([x1, zero, z1], 1),
            np.stack([x0, zero, z1], 1),
        ],
        axis=1,
    )


def _loops(polygons: np.ndarray) -> np.ndarray:
    """Closed outlines (N, k + 1, 3) of polygons (N, k, 3)."""
    return np.concatenate([polygons, polygons[:, :1]], axis=1)


class OutsideView(Plot):
    """The camera and the ground quad from outside, in world space (y up), on 3D axes.

    Drawn: the ground quad with its checkerboard or its triangles; the eye; the frustum to the
    far plane or, where that lies beyond the scene, as far as the camera sees the quad (dashed);
    the near plane; the image plane at view depth 1; rays through ``rays x rays`` pixels of the
    image, solid with a dot where they meet the quad, dotted where they miss it; the pieces
    clipping keeps (outlined), the vertices it made (diamonds) and what the near plane cuts off
    (hatched: nearer than the near plane, or behind the eye).

    Parameters
    ----------
    ax : Axes3D
        Made with ``projection="3d"``.
    camera : Camera
    width, height : int
        The camera image's size: its aspect, and the pixels the rays go through.
    quads : int
        Squares per side of the ground plane (each two triangles), as the image's.
    frequency : int
        Checks per side of the board.
    show : {"checkerboard", "triangles"}
        What the ground shows.
    view : {"three-quarter", "behind", "side", "above"}
        The viewpoint (:data:`VIEWS`); the mouse may orbit from there.
    rays : int
        Rays per side of the image.
    legend_ax : Axes, optional
        Where to put the legend (its frame and ticks are turned off); in ``ax`` if None.

    Notes
    -----
    The ground changes only with ``show``, ``quads`` and ``frequency``, and then so does its
    legend entry: they are not :attr:`dynamic` (a live canvas keeps them in its background and
    draws the whole figure when they change). Everything else is redrawn from ``camera``.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot(projection="3d")
    >>> view = OutsideView(ax, Camera(height=0.3, pitch=15, distance=1.0), quads=2,
    ...                    show="triangles")
    >>> view.counts["pieces"] > view.counts["visible triangles"], view.counts["cut off"] > 0
    (True, True)
    """

    def __init__(
        self,
        ax: Axes,
        camera: Camera | None = None,
        width: int = 320,
        height: int = 240,
        quads: int = 1,
        frequency: int = 8,
        show: str = "checkerboard",
        view: str = "three-quarter",
        rays: int = 3,
        legend_ax: Axes | None = None,
    ) -> None:
        if getattr(ax, "name", "") != "3d":
            raise TypeError('ax must be 3D axes: add_subplot(projection="3d")')
        self.ax = ax
        # A fixed drawing order, so that a blitted frame matches a full draw: the ground first
        # (zorder 1), then everything that changes above the axes' titles (3), which then stay
        # in the saved background.
        ax.computed_zorder = False
        # Close to the box: the view often sits beside another panel. The vertical axis' label
        # would land far to the left, over a neighbour: the title says which way is up.
        ax.set_xlabel("x", labelpad=-4)
        ax.set_zlabel("z", labelpad=-4)
        ax.tick_params(labelsize="x-small", pad=0)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(MaxNLocator(4))

        # The ground: static unless show, quads or frequency change.
        self.ground = Poly3DCollection([], facecolor="0.96", edgecolor=INK, linewidth=0.8, zorder=1)
        self.checks = Poly3DCollection([], facecolor="0.3", edgecolor="none", zorder=1.1)
        self.edges = Line3DCollection([], colors="0.45", linewidths=0.6, zorder=1.2)
        # What clipping did, and the camera: redrawn on every change.
        self.cut_off = Poly3DCollection(
            [],
            facecolor=(*_rgb(AFFINE["color"]), 0.25),
            edgecolor=AFFINE["color"],
            linestyle=":",
            linewidth=1.0,
            hatch="////",
            zorder=3.1,
        )
        self.pieces = Line3DCollection([], colors=CORRECT["color"], linewidths=1.3, zorder=3.2)
        self.image_plane = Poly3DCollection(
            [], facecolor=(0.5, 0.5, 0.5, 0.35), edgecolor="0.25", linestyle="-.", zorder=3.5
        )
        # The camera's lines, one collection (each a style of its own): frustum edges, near
        # plane, far plane or cut-off, rays that hit the quad, rays that miss it.
        self.lines = Line3DCollection([], zorder=4)
        collections = (
            self.ground,
            self.checks,
            self.edges,
            self.cut_off,
            self.pieces,
            self.image_plane,
            self.lines,
        )
        for collection in collections:
            ax.add_collection3d(collection, autolim=False)
        (self.hit_points,) = ax.plot(
            [], [], [], linestyle="none", marker="o", markersize=3.5, color=RAY, zorder=4.6
        )
        (self.new_vertices,) = ax.plot(
            [],
            [],
            [],
            linestyle="none",
            marker="D",
            markersize=4,
            markerfacecolor="white",
            markeredgecolor=INK,
            zorder=5,
        )
        (self.eye,) = ax.plot([], [], [], linestyle="none", marker="o", markersize=6, color=INK)
        self.eye.set_zorder(6)

        handles = [
            Patch(facecolor="0.96", edgecolor=INK, label="ground"),
            Line2D([], [], color=CORRECT["color"], linewidth=1.3, label="pieces the camera draws"),
            Line2D(
                [],
                [],
                linestyle="none",
                marker="D",
                markerfacecolor="white",
                markeredgecolor=INK,
                label="vertices clipping made",
            ),
            Patch(
                facecolor=(*_rgb(AFFINE["color"]), 0.25),
                edgecolor=AFFINE["color"],
                hatch="////",
                linestyle=":",
                label="cut off by the near plane",
            ),
            Line2D([], [], color=INK, marker="o", linewidth=0.7, label="eye and frustum"),
            Line2D([], [], color=INK, linewidth=1.8, label="near plane"),
            Line2D([], [], color=INK, linewidth=0.8, linestyle="--", label="far plane, or cut-off"),
            Patch(
                facecolor=(0.5, 0.5, 0.5, 0.25),
                edgecolor="0.35",
                linestyle="-.",
                label="image plane (depth 1)",
            ),
            Line2D([], [], color=RAY, marker="o", markersize=3.5, label="pixel rays"),
            Line2D([], [], color=RAY, linestyle=":", label="rays that miss the quad"),
        ]
        if legend_ax is None:
            self.legend = ax.legend(
                handles=handles, loc="upper left", fontsize="xx-small", framealpha=0.8
            )
        else:
            legend_ax.set_axis_off()
            self.legend = legend_ax.legend(
                handles=handles, loc="center", fontsize="x-small", frameon=False
            )
        self._shown: dict[str, object] = {}
        super().__init__(
            camera=camera or LESSON_CAMERA,
            width=width,
            height=height,
            quads=quads,
            frequency=frequency,
            show=show,
            view=view,
            rays=rays,
        )

    # ------------------------------------------------------------------ drawing

    def redraw(self) -> None:
        """Draw for the current parameters (see the class)."""
        p = self.params
        width, height = int(p["width"]), int(p["height"])
        camera = p["camera"].fitted(width, height)
        quads, frequency, show = int(p["quads"]), int(p["frequency"]), str(p["show"])
        if show not in SHOWS:
            raise ValueError(f"show must be one of {', '.join(SHOWS)}; got {show!r}")
        if p["view"] not in VIEWS:
            raise ValueError(f"view must be one of {', '.join(VIEWS)}; got {p['view']!r}")
        scene = ground_plane(camera, size=LESSON_SIZE, quads=quads)

        self._set_view(str(p["view"]))
        self._set_box(camera.eye)
        self._set_ground(scene, show, quads, frequency)

        clipped = frustum.clipped_in_world(scene, width, height)
        # The frustum is drawn as far as the camera sees the quad (or to its far corner).
        corners = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]) * LESSON_SIZE / 2
        seen = clipped.visible.reshape(-1, 3) if len(clipped.visible) else corners
        reach = frustum.reach_of(camera, seen, default=2 * LESSON_SIZE)
        near, image, far = frustum.section(camera, np.array([camera.near, IMAGE_DISTANCE, reach]))
        rays = frustum.pixel_rays(camera, width, height, int(p["rays"]), LESSON_SIZE, reach)
        eye = camera.eye

        self.cut_off.set_verts(list(clipped.cut_off))
        self.pieces.set_segments(list(_loops(clipped.visible)))
        self.image_plane.set_verts([image])
        self._set_lines(eye, near, far, rays, solid_far=reach == camera.far)
        self.hit_points.set_data_3d(*rays.end[rays.hits].T)
        self.new_vertices.set_data_3d(*clipped.new_vertices.T)
        self.eye.set_data_3d([eye[0]], [eye[1]], [eye[2]])
        self._project()

        self.counts = {
            "visible triangles": clipped.in_view,
            "pieces": len(clipped.visible),
            "new vertices": len(clipped.new_vertices),
            "cut off": len(clipped.cut_off),
            "rays": len(rays.hits),
            "hits": int(rays.hits.sum()),
            "reach": reach,
        }

    def _set_view(self, view: str) -> None:
        """Turn to a preset viewpoint when ``view`` changes (not otherwise: the mouse may have
        orbited since). The title names it; both change only here, where the whole figure must
        be redrawn anyway."""
        if self._shown.get("view") != view:
            elev, azim = VIEWS[view]
            self.ax.view_init(elev=elev, azim=azim, roll=0.0, vertical_axis="y")
            self.ax.set_title(f"from outside ({view}; y up)")
            self._shown["view"] = view

    def _set_box(self, eye: np.ndarray) -> None:
        """Axis ranges with equal units that hold the quad and the eye, from a few sizes (so
        that most slider steps keep them)."""
        half = _snap(max(abs(eye[0]), abs(eye[2]), LESSON_SIZE / 2) + EYE_ROOM, HALF_WIDTHS)
        top = _snap(eye[1] + EYE_ROOM, TOPS)
        box = (half, top)
        if self._shown.get("box") != box:
            self.ax.set_xlim(-half, half)
            self.ax.set_zlim(-half, half)
            self.ax.set_ylim(BOTTOM, top)
            self.ax.set_box_aspect((2 * half, top - BOTTOM, 2 * half), zoom=ZOOM)
            self._shown["box"] = box

    def _set_ground(self, scene: object, show: str, quads: int, frequency: int) -> None:
        """Redo the (static) ground when what it shows changes, and say so in the legend."""
        key = (show, frequency if show == "checkerboard" else quads)  # what is drawn
        if self._shown.get("ground") == key:
            return
        half = LESSON_SIZE / 2
        quad = np.array([[-half, 0, -half], [half, 0, -half], [half, 0, half], [-half, 0, half]])
        self.ground.set_verts([quad])
        if show == "checkerboard":
            self.checks.set_verts(list(_checks(frequency, LESSON_SIZE)))
            self.edges.set_segments([])
            label = f"ground: {frequency} x {frequency} checks"
        else:
            world = frustum.clip_to_world(scene.camera, scene.clip)
            self.checks.set_verts([])
            self.edges.set_segments(list(_loops(world[scene.triangles])))
            label = f"ground: {quads} x {quads} quads, {2 * quads * quads} triangles"
        self.legend.get_texts()[0].set_text(label)
        self._shown["ground"] = key

    def _set_lines(
        self,
        eye: np.ndarray,
        near: np.ndarray,
        far: np.ndarray,
        rays: frustum.Rays,
        solid_far: bool,
    ) -> None:
        """The camera's lines with their styles: edges, near plane, far plane (solid) or cut-off
        (dashed), rays that hit (solid) and miss (dotted)."""
        hit, miss = rays.end[rays.hits], rays.end[~rays.hits]
        segments = [
            *(np.stack([eye, corner]) for corner in far),
            _loops(near[None])[0],
            _loops(far[None])[0],
            *(np.stack([eye, end]) for end in hit),
            *(np.stack([eye, end]) for end in miss),
        ]
        styles = [
            *[(INK, 0.7, "-")] * 4,
            (INK, 1.8, "-"),
            (INK, 0.8, "-" if solid_far else "--"),
            *[(RAY, 0.9, "-")] * len(hit),
            *[(RAY, 0.9, ":")] * len(miss),
        ]
        colours, widths, dashes = zip(*styles, strict=True)
        self.lines.set_segments(segments)
        self.lines.set_color(colours)
        self.lines.set_linewidth(widths)
        self.lines.set_linestyle(dashes)

    def _project(self) -> None:
        """Project the changed 3D collections now, as a full draw would: a blitted frame draws
        them without the axes' own projection pass."""
        self.ax.M = self.ax.get_proj()
        for collection in (self.cut_off, self.pieces, self.image_plane, self.lines):
            collection.do_3d_projection()

    @property
    def dynamic(self) -> list[Artist]:
        return [
            self.cut_off,
            self.pieces,
            self.image_plane,
            self.lines,
            self.hit_points,
            self.new_vertices,
            self.eye,
        ]

    def view_angles(self) -> tuple[float, float, float]:
        """(elevation, azimuth, roll) the axes show now (after any orbiting by the mouse)."""
        return (float(self.ax.elev), float(self.ax.azim), float(self.ax.roll))


def _rgb(colour: str) -> tuple[float, float, float]:
    """``"#RRGGBB"`` as three floats in [0, 1]."""
    return tuple(int(colour[k : k + 2], 16) / 255 for k in (1, 3, 5))
