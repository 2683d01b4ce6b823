"""One slider step, from a changed value to new pixels, with matplotlib's documented blitting.

A step goes: a control's ``observe`` callback asks the :class:`Coalescer` for a draw; the
coalescer runs it once the messages already waiting have been taken in (latest value wins);
the app calls its figure's ``update(**values)``; then :meth:`Blitter.draw` restores the saved
background, draws the artists that change over it and calls ``canvas.blit``, which ipympl sends
to the page as one frame. This is the recipe of matplotlib's "Faster rendering by using
blitting" tutorial (``copy_from_bbox``, ``restore_region``, ``draw_artist``, ``blit``, and a
``draw_event`` callback that saves the background after every full draw), with two additions:

- **The layer drawn every frame is exactly what a full draw would put there.** In each axes
  that holds a changing artist, every artist that a full draw paints after the first changing
  one (spines, legends, labels above the curves) is marked animated too and drawn again, in the
  same order: so a frame is the full redraw pixel for pixel, and nothing is painted twice.
  A 3D axes that sorts its own artists by depth as it draws is drawn whole; one with a
  fixed order (``computed_zorder`` off) is layered as a 2D axes is. In a figure, an axes drawn
  whole is drawn over by the axes after it that overlap it, and by no others.
- **A change to anything else redraws the figure once.** Animated artists do not mark the
  figure stale (that is what ``animated`` means); everything else does. So after an update,
  a stale figure (axis limits, a backdrop, a change made from a cell) gets a full draw, and a
  figure that is not stale gets a blit.

No other package's object is changed: the artists' ``animated`` flags and the ``draw_event``
connection belong to the app's own figure.
"""

from __future__ import annotations

import asyncio
import math
import threading
import time
from collections.abc import Callable, Iterable
from operator import attrgetter

from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.axis import Axis
from matplotlib.backend_bases import DrawEvent
from matplotlib.figure import Figure, SubFigure
from matplotlib.transforms import Bbox

#: How long a pending draw waits for more slider messages to arrive, in seconds.
SETTLE = 0.004
#: A change this long after the last draw ended (seconds) is the first of a new series (a key
#: press, the start of a drag): the messages that came during that draw were taken in long
#: ago, so it is drawn at the event loop's next turn, without the wait.
IDLE = 0.05
#: Held while an app changes or draws its figure: a cell's ``app.set`` runs on the kernel's
#: main thread while slider messages may be handled on another (ipykernel's subshells), and
#: matplotlib is not thread-safe.
DRAW_LOCK = threading.RLock()


def _parent(artist: Artist) -> Figure | SubFigure:
    """The (sub)figure an artist is placed in."""
    return artist.get_figure(root=False)


def _drawn_by(container: Axes | Figure | SubFigure) -> list[Artist]:
    """The artists ``container``'s own ``draw`` paints, animated or not, in its order."""
    children = [a for a in container.get_children() if a is not container.patch]
    if isinstance(container, Axes):
        if not (container.axison and container.get_frame_on()):
            spines = {id(s) for s in container.spines.values()}
            children = [a for a in children if id(a) not in spines]
        if not container.axison:
            children = [a for a in children if not isinstance(a, Axis)]
    return sorted(children, key=attrgetter("zorder"))


def _child_of(container: Axes | Figure | SubFigure, artist: Artist) -> Artist | None:
    """The child of ``container`` that is ``artist`` or holds it (a legend's text, say)."""
    for child in container.get_children():
        if child is artist or _holds(child, artist):
            return child
    return None


def _holds(parent: Artist, artist: Artist) -> bool:
    return any(c is artist or _holds(c, artist) for c in parent.get_children())


def layers(figure: Figure, dynamic: Iterable[Artist]) -> list[Artist]:
    """The artists a blitted frame draws over the background, in the order a full draw paints
    them: in every axes holding one of ``dynamic``, each artist from the first of them on (an
    axes drawn whole, and what overlaps it after it, in the order of its figure's children).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> curve, = ax.plot([0, 1], [0, 1], zorder=2)
    >>> note = ax.text(0.5, 0.5, "above", zorder=3)
    >>> [type(a).__name__ for a in layers(fig, [curve])][:2]
    ['Line2D', 'Spine']
    >>> note in layers(fig, [curve])
    True
    """
    orders: dict[int, list[Artist]] = {}  # id(container) -> what it draws, in order
    firsts: dict[int, tuple[object, int]] = {}  # id(container) -> (container, first index)
    changing: dict[int, set[int]] = {}  # id(container) -> ids of its changing children
    for artist in dynamic:
        ax = artist.axes
        container: Axes | Figure | SubFigure
        if ax is None:
            container = _parent(artist) if artist.figure is not None else figure
        elif artist is ax or getattr(ax, "computed_zorder", False):
            # Drawn whole: an axes itself, or a 3D axes that sorts its artists by depth as it
            # draws (one with a fixed order draws them as a 2D axes does).
            container, artist = _parent(ax), ax
        else:
            container = ax
        child = _child_of(container, artist)
        if child is None:
            continue
        order = orders.setdefault(id(container), _drawn_by(container))
        index = next(k for k, a in enumerate(order) if a is child)
        changing.setdefault(id(container), set()).add(id(child))
        kept = firsts.get(id(container))
        if kept is None or index < kept[1]:
            firsts[id(container)] = (container, index)
    parts = {key: orders[key][first:] for key, (_, first) in firsts.items()}
    renderer = figure.canvas.get_renderer() if hasattr(figure.canvas, "get_renderer") else None
    for key, (container, _) in firsts.items():
        if not isinstance(container, Axes) and renderer is not None:
            parts[key] = _overlapping(parts[key], changing[key], renderer)
    whole = {id(a) for part in parts.values() for a in part if isinstance(a, Axes)}
    # An axes drawn whole draws its own children: none of them may be animated.
    return [a for key, part in parts.items() if key not in whole for a in part]


def _overlapping(part: list[Artist], changing: set[int], renderer: object) -> list[Artist]:
    """Of a (sub)figure's artists from the first changing one on, those a frame must draw: the
    changing ones, and each later one whose extent meets one already kept (a full draw paints
    it over them). Axes beside a 3D axes stay in the background."""
    kept: list[Artist] = []
    boxes = []
    for artist in part:
        box = _extent(artist, renderer)
        meets = any(box is None or b is None or box.overlaps(b) for b in boxes)
        if id(artist) in changing or meets:
            kept.append(artist)
            boxes.append(box)
    return kept


def _extent(artist: Artist, renderer: object) -> Bbox | None:
    """Where ``artist`` may paint, in pixels, a pixel to spare; None if it cannot say."""
    try:
        box = artist.get_tightbbox(renderer)
    except (AttributeError, TypeError, ValueError):
        return None
    if box is None:
        return None
    if isinstance(artist, Axes):  # what it clips to, whatever its labels' extent
        box = Bbox.union([box, artist.bbox])
    return box.padded(1)


class Blitter:
    """Draws a figure's changing artists over its saved background, as matplotlib's blitting
    tutorial does (see the module's docstring).

    Parameters
    ----------
    figure : Figure
        Its canvas needs ``copy_from_bbox`` and ``restore_region`` (Agg and ipympl have them).
    dynamic : list of Artist, or None
        What the figure's updates change; None: every step redraws the whole figure.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> curve, = ax.plot([0, 1], [0, 1])
    >>> blitter = Blitter(fig, [curve])
    >>> blitter.draw()                      # the first frame is a full draw
    >>> curve.set_ydata([1, 0]); blitter.draw()
    >>> blitter.full_draws, blitter.blits
    (1, 1)
    """

    def __init__(self, figure: Figure, dynamic: list[Artist] | None) -> None:
        self.figure = figure
        self.canvas = figure.canvas
        self.layers = [] if dynamic is None else layers(figure, dynamic)
        self.whole = dynamic is None
        for artist in self.layers:
            artist.set_animated(True)
        self._background: object = None
        self._size: tuple[float, float] | None = None
        self.full_draws = self.blits = 0
        self.canvas.mpl_connect("draw_event", self._on_draw)

    def _on_draw(self, event: DrawEvent) -> None:
        """After every full draw (ours, ipympl's, a resize's): save the background and draw
        the layers over it, before the canvas sends the frame."""
        if event.canvas is not self.canvas or self.canvas.is_saving():
            return  # savefig draws animated artists itself
        self._background = self.canvas.copy_from_bbox(self.figure.bbox)
        self._size = tuple(self.figure.bbox.size)
        self._draw_layers()

    def _draw_layers(self) -> None:
        # Drawing lays out the parts of some artists (an axis's ticks, a collection's colours),
        # which marks their axes stale; the picture is up to date all the same.
        stale = self.figure.stale
        for artist in self.layers:
            self.figure.draw_artist(artist)
        self.figure.stale = stale

    def draw(self) -> None:
        """Show the figure as it is now: a blit, or a full draw where one is needed."""
        needs_full = (
            self.whole
            or self._background is None
            or self.figure.stale
            or self._size != tuple(self.figure.bbox.size)
        )
        if needs_full:
            self.full_draws += 1
            self.canvas.draw()  # _on_draw adds the layers
            return
        self.blits += 1
        self.canvas.restore_region(self._background)
        self._draw_layers()
        self.canvas.blit(self.figure.bbox)


class Coalescer:
    """Calls ``draw`` once for any number of :meth:`request` calls that arrive meanwhile.

    Inside a running event loop (a kernel), a request schedules ``draw`` unless one is already
    scheduled: ``settle`` seconds later if the last draw ended less than ``idle`` seconds ago
    (the messages that came during it may still be waiting), else at the loop's next turn.
    Requests arriving before it runs are absorbed, so ``draw`` sees only the newest state, and
    the last request is always drawn. Without a running loop (tests, scripts) ``draw`` runs at
    once.

    Examples
    --------
    >>> drawn = []
    >>> coalescer = Coalescer(lambda: drawn.append(1))
    >>> coalescer.request(); drawn       # no event loop: at once
    [1]
    """

    def __init__(
        self, draw: Callable[[], None], settle: float = SETTLE, idle: float = IDLE
    ) -> None:
        self._draw = draw
        self._settle = settle
        self._idle = idle
        self._scheduled = False
        self._ended = -math.inf
        self.requests = self.draws = 0

    @property
    def pending(self) -> bool:
        """Whether a draw is scheduled and has not run yet."""
        return self._scheduled

    def request(self) -> None:
        """The state changed: draw it, soon."""
        self.requests += 1
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            self._run()
            return
        if not self._scheduled:
            self._scheduled = True
            if time.monotonic() - self._ended <= self._idle:
                loop.call_later(self._settle, self._run)
            else:
                loop.call_soon(self._run)

    def _run(self) -> None:
        self._scheduled = False
        self.draws += 1
        try:
            self._draw()
        finally:
            self._ended = time.monotonic()
