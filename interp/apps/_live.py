"""Making a live ipympl figure answer a slider within a frame or two.

A slider step must reach the screen fast, and a fast drag must not leave a queue of stale frames
behind it. These things make that so (measured in the browser by ``make bench-browser``):

- **Blitting.** The figure's static parts (axes, ticks, labels, legends, colorbars) are drawn
  once and kept as a background; a step restores it and draws only the artists the figure's
  plots change (:attr:`interp.plots.LessonFigure.dynamic`), which is a fraction of a full
  redraw. A legend drawn above changing curves is kept as a picture too (it is opaque), and
  put back instead of being laid out and drawn again: that was a third of a step in the 1D
  apps; so is a title that looks as it did last time (text is costly to render). A change of
  axis limits, legend or size is noticed and redraws everything once.
- **Kept glyphs.** Text that is drawn is laid out once per string and rendered once per glyph
  and place within a pixel (:mod:`interp.apps._glyphs`), the same pixels as matplotlib's.
- **Kept samples.** A changing raster image keeps which of its pixels each screen pixel shows
  (:mod:`interp.apps._samples`) and is coloured and picked instead of resampled; the same
  pixels as matplotlib's.
- **Latest value wins.** A slider change only marks the figure out of date; the drawing happens
  once the kernel has taken in the messages already waiting, with the newest values. A drag
  never builds a backlog, and the last value is always drawn. A change that comes when
  nothing was drawn for a while (a key press, the first move of a drag) is drawn at the
  event loop's next turn, without waiting for more.
- **Cheap, whole frames.** Each frame is the whole figure as a PNG written for speed (see
  :func:`png`): one row filter for every row (:class:`FrameFilter` picks it), ISA-L's fast
  deflate; a fraction of the time of ipympl's default diff frames, and a frame the browser
  drops can never leave a figure half drawn.
- **Nothing drawn twice.** pyplot redraws a figure when it changes, in two ways: at once,
  through the figure's ``stale_callback`` (the apps remove it), and, with ``%matplotlib
  widget``, after each widget message, for every figure still marked stale. So a blitted
  figure is marked up to date (unless it was changed from outside, see ``App.refresh``);
  ipympl turned each of those redraws into a round trip through the browser and a second,
  full redraw of every step and mouse move.
- **Frames decoded off the page's main thread, and no picture of the picture per frame**
  (:data:`FRAME_JS`).
- **A control's last value sent as it is let go** (:data:`SEND_HELD_JS`), not after the
  kernel's answer to the value before: it comes with that one and is drawn in the same frame.
- **Fewer pixels while dragging on a HiDPI screen.** At a device pixel ratio of 2, a step that
  follows another (a drag, a key held down) is drawn at ratio 1 (:data:`LIVE_RATIO`): a quarter
  of the pixels to draw, write, send, decode and copy, which the page scales up to the figure's
  place. The first step of a series (a key press) and the figure once the changes stop are
  drawn at the screen's ratio (:func:`drawn_at`, ``App.refresh``).

And one thing makes them right: **drawing takes turns** (:data:`DRAW_LOCK`). ipykernel 7 handles
widget messages on a subshell thread beside the main one (JupyterLab 4.6 sends comm messages
over subshells by default), so a slider's redraw, ipympl's own full draw and a cell's
``app.set`` can run at the same moment; two draws into one Agg buffer tore each other's frames,
and a torn background stayed on screen until the next full draw.
"""

from __future__ import annotations

import asyncio
import math
import struct
import threading
import time
import zlib
from collections import OrderedDict
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import MethodType
from typing import TYPE_CHECKING

import matplotlib
import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.image import AxesImage
from matplotlib.legend import Legend
from matplotlib.spines import Spine
from matplotlib.text import Text
from matplotlib.transforms import Bbox

from interp.apps._glyphs import keep_glyphs
from interp.apps._samples import keep_samples

if TYPE_CHECKING:
    from interp.plots._base import Backdrop

try:  # Intel's ISA-L: deflate streams any PNG decoder reads, 6-14 times faster than zlib's
    from isal.isal_zlib import compress as deflate
except ImportError:  # where it has no wheel, pyproject.toml does not install it
    deflate = zlib.compress

#: Deflate level of live frames (PIL's default is 6; ISA-L's levels are 0 to 3).
PNG_LEVEL = 1
#: Every this many frames a figure's frame is written with both row filters, to choose again.
PNG_TRIAL = 16
#: The eight bytes every PNG file starts with.
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
#: How long a pending redraw waits for more slider messages to arrive, in seconds.
SETTLE = 0.004
#: A request this long after the last draw ended (seconds) finds no messages waiting: the
#: kernel took in those that came during the draw long ago. It is drawn without the wait.
IDLE = 0.05
#: The device pixel ratio of the frames drawn while a control moves on after a first step (a
#: drag, a key held down) on a screen of a higher ratio (HiDPI): at ratio 2 a quarter of the
#: pixels to draw, write, send, decode and copy, which the page scales up (:data:`FRAME_JS`);
#: once the changes stop for :data:`SHARPEN`, the figure is drawn once more at the screen's
#: ratio. The first step of a series (a key press, the start of a drag) is drawn sharp at once.
LIVE_RATIO = 1.0
#: The memory a blitter may spend on backgrounds it keeps for settings a slider may come back
#: to (bytes): ten at lesson 6's default size and ratio 1, two at ratio 2 (see
#: :class:`Blitter`).
KEPT_BACKGROUNDS = 16 * 2**20
#: How many pictures of a legend drawn over the base (one per texts it showed) a blitter
#: keeps: 90 kB each for lesson 6's, at ratio 1.
LEGEND_PICTURES = 16
#: How long after a live frame of a lower ratio, with no change since, the figure is drawn at
#: the screen's ratio (seconds): as long as :data:`IDLE`, after which a change counts as the
#: first of a new series. Half of it (a trial) drew sharp frames in the middle of drags on a
#: busy two-core machine, where a slider's next message came later than that: at ratio 2 the
#: picture floor's drag fell back from 18 to 12-13 pictures a second.
SHARPEN = IDLE
#: How long after the page says a control was let go (a mouse button or a key up, within a
#: second of a frame of its figure on a HiDPI screen) a step is drawn at the screen's ratio at once
#: (seconds): the control's last value often comes after that message, as ipywidgets holds a
#: value back until the kernel has taken in the one before. Drawn sharp, it needs no live
#: frame and no wait of :data:`SHARPEN`.
RELEASED = 0.25
#: Held while an app changes or draws its figure, on whichever thread: matplotlib is not
#: thread-safe, and the style sheet is applied through the global rcParams.
DRAW_LOCK = threading.RLock()


#: The class of a figure canvas whose every frame is the whole figure (see :data:`FRAME_JS`).
WHOLE_FRAMES = "interp-whole-frames"

#: Run in the page first by :data:`FRAME_JS` and :data:`SEND_HELD_JS` (once a page): ipympl's
#: canvas model class, as the promise ``window.interpCanvasModel`` (of null where it cannot be
#: loaded), taken from the page's module federation (``window._JUPYTERLAB``); where that has
#: no ipympl, the promise is not made and both scripts change nothing.
CANVAS_MODEL_JS = """
(() => {
  const container = window._JUPYTERLAB && window._JUPYTERLAB['jupyter-matplotlib'];
  if (!container || window.interpCanvasModel) return;
  window.interpCanvasModel = container.get('./index')
    .then((factory) => factory().MPLCanvasModel || null)
    .catch(() => null);
})();
"""

#: Run in the page (JupyterLab, Voilà) once an app is shown; it changes how ipympl's view model
#: (0.9 - 0.12 at least) takes in a frame, in three ways, on the browser's main thread:
#:
#: - ipympl loads each frame's PNG as an ``<img>`` from a blob URL (a fetch through the
#:   browser process) and decodes it when it draws it, on the main thread: 6-11 ms from the
#:   frame's arrival to its picture in a busy JupyterLab, 2-3 ms of them on the main thread.
#:   A figure whose every frame is whole (:func:`cheap_frames` marks its canvas with the class
#:   :data:`WHOLE_FRAMES`) has its frames decoded off the main thread instead, by WebCodecs'
#:   ``ImageDecoder`` (in a secure context: https or localhost; 0.1 ms of the main thread) or
#:   else ``createImageBitmap`` (1.2 ms: making the Blob), and drawn as ipympl's
#:   ``image.onload`` draws an ``<img>`` (clear, draw, each view copies it), the same pixels.
#:   Frames are shown in the order they came, and one decoded after a newer one was shown is
#:   dropped (each is whole). The last is kept, to be drawn again when the canvas is resized,
#:   as ipympl draws its last ``<img>``. A frame that comes while ipympl is loading an
#:   ``<img>``, and every frame of other figures (whose frames may be differences, which must
#:   all be drawn in turn) go ipympl's way.
#: - On every frame ipympl also encodes its whole previous picture as a PNG data URL,
#:   ``offscreen_canvas.toDataURL()``: 13 ms for an 820 x 474 figure in Chromium, for a data
#:   URL read only when the notebook is saved (the figure's static picture). This waits until
#:   frames stop coming for 300 ms, and then encodes the picture on show.
#: - On a HiDPI screen, a frame of a lower ratio (:data:`LIVE_RATIO`) is drawn into canvases of
#:   its own size, which the page scales up to the figure's place; after it says it does so
#:   (``interp_scaled_frames``), a mouse button or key let go anywhere on the page within a
#:   second of a frame's arrival sends ``interp_released`` (:data:`RELEASED`).
#:
#: It reaches ipympl's model class through :data:`CANVAS_MODEL_JS` (the page's module
#: federation, ``window._JUPYTERLAB``); where that is missing, or ipympl's ``handle_binary`` is
#: not the one this was written against, it changes nothing.
FRAME_JS = (
    CANVAS_MODEL_JS
    + """
(async () => {
  if (!window.interpCanvasModel || window.interpFramesPatched) return;
  window.interpFramesPatched = true;
  const model = await window.interpCanvasModel;  // null: another ipympl, frames stay its own
  const proto = model && model.prototype;
  if (!proto || !String(proto.handle_binary).includes('toDataURL')) return;
  const handleBinary = proto.handle_binary;
  const saveLater = (model) => {  // the picture saved with the notebook, once frames stop
    clearTimeout(model.interpDataUrl);
    model.interpDataUrl = setTimeout(
      () => model.set('_data_url', model.offscreen_canvas.toDataURL()), 300);
  };
  const byImage = function (message, buffers) {  // ipympl's way, without its data URL
    const canvas = this.offscreen_canvas;
    const last = this.get('_data_url');
    canvas.toDataURL = () => last;  // for now: the picture saved, as it was
    try {
      return handleBinary.call(this, message, buffers);
    } finally {
      delete canvas.toDataURL;
      saveLater(this);
      // ipympl draws the <img> when it has loaded (its onload, which runs first): the picture
      // to save is that one, so wait 300 ms from then (a load slower than 300 ms left the
      // picture before it saved).
      if (this.image) this.image.addEventListener('load', () => saveLater(this), {once: true});
    }
  };
  const decode = (bytes) => {  // a picture drawImage takes, and close() frees
    if (typeof ImageDecoder === 'function') {
      const decoder = new ImageDecoder({data: bytes, type: 'image/png'});
      return decoder.decode().then((result) => result.image).finally(() => decoder.close());
    }
    return createImageBitmap(new Blob([bytes], {type: 'image/png'}));
  };
  const sizeOf = (picture) => [picture.displayWidth || picture.width,
                                picture.displayHeight || picture.height];
  // The width and height a PNG file's header gives.
  const pngSize = (bytes) => {
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    return bytes.byteLength >= 24 ? [view.getUint32(16), view.getUint32(20)] : null;
  };
  // A frame drawn at a lower device pixel ratio than the page's (the kernel's live frames on a
  // HiDPI screen while a control is dragged) is narrower than ipympl's canvas: the canvases
  // take its size, and the page scales them up to the figure's place (their style's size),
  // until a frame of the page's own ratio comes. (Frames of the page's ratio may be a pixel
  // wider than its canvas: ipympl rounds the figure's size down.)
  const isLow = (model, size) => !!size && size[0] < model.size[0] * model.ratio - 2;
  // The figures that had a frame in the last second on a screen of ratio above 1, after the
  // page said it scales frames up. When a control is let go (a mouse button or a key up,
  // anywhere on the page) each tells the kernel, which then draws the control's last value at
  // the page's ratio at once (RELEASED in interp.apps._live). Figures closed since (a kernel
  // restarted, say) and figures without a frame for a second are dropped.
  const recent = new Set();
  const arrived = (model) => {
    if (!(model.ratio > 1) || !model.interpToldKernel) return;
    if (!model.interpWatched) {
      model.interpWatched = true;
      model.once('destroy', () => recent.delete(model));
    }
    model.interpArrived = performance.now();
    recent.add(model);
  };
  const released = () => {
    const now = performance.now();
    recent.forEach((model) => {
      if (!model.comm_live || now - model.interpArrived > 1000) recent.delete(model);
      else model.send_message('interp_released');
    });
  };
  window.addEventListener('pointerup', released, true);
  window.addEventListener('keyup', released, true);
  const fitCanvases = (model, size) => {
    if (isLow(model, size)) {
      const [width, height] = size;
      const fit = (canvas) => {  // setting a canvas's size clears it: only where it differs
        if (canvas.width !== width || canvas.height !== height) {
          canvas.width = width;
          canvas.height = height;
        }
      };
      fit(model.offscreen_canvas);
      model._for_each_view((view) => fit(view.canvas));
      model.interpLow = true;
    } else if (model.interpLow) {  // back to ipympl's own sizes
      model.interpLow = false;
      model.resize_canvas();
      model._for_each_view((view) => view.resize_and_update_canvas(model.size));
    }
  };
  const keep = (model, picture) => {  // the picture on show, to draw again on a resize
    if (model.interpPicture) model.interpPicture.close();
    model.interpPicture = picture;
    if (picture && !model.interpResizes) {
      model.interpResizes = true;
      // After ipympl's own handler, which draws its last <img> into the resized canvas.
      model.on('change:_size', () => {
        const kept = model.interpPicture, canvas = model.offscreen_canvas;
        if (!kept) return;
        if (isLow(model, sizeOf(kept))) {
          model.offscreen_context.drawImage(kept, 0, 0, canvas.width, canvas.height);
        } else {
          model.offscreen_context.drawImage(kept, 0, 0);
        }
      });
    }
  };
  // ipympl's way for a frame of ours: its <img>, drawn when loaded into canvases of the
  // frame's size (of a lower ratio, or ipympl's own).
  const byImageFitted = function (message, buffers, bytes) {
    this.interpImageSize = pngSize(bytes);
    if (this.image && !this.interpOnload) {
      const onload = this.interpOnload = this.image.onload;
      this.image.onload = (...args) => {
        fitCanvases(this, this.interpImageSize);
        return onload.apply(this.image, args);
      };
    }
    return byImage.call(this, message, buffers);
  };
  proto.handle_binary = function (message, buffers) {
    const loading = this.image && this.image.src && !this.image.complete;
    const whole = (this.get('_dom_classes') || []).includes('WHOLE_FRAMES');
    const frame = this.interpSent = (this.interpSent || 0) + 1;
    const decodes = typeof ImageDecoder === 'function' || typeof createImageBitmap === 'function';
    if (!whole) return byImage.call(this, message, buffers);  // another figure's frames
    const data = buffers[0];
    const bytes = ArrayBuffer.isView(data)
      ? new Uint8Array(data.buffer, data.byteOffset, data.byteLength) : new Uint8Array(data);
    arrived(this);
    if (!decodes || this.disabled || loading) {
      this.interpShown = frame;  // any frame still decoding is older: dropped
      keep(this, null);
      return byImageFitted.call(this, message, buffers, bytes);
    }
    this.waiting_for_image = false;
    decode(bytes).then((picture) => {
      if (!this.interpToldKernel) {  // frames of a lower ratio may come: they are scaled here
        this.interpToldKernel = true;
        this.send_message('interp_scaled_frames');
      }
      if (frame < (this.interpShown || 0) || this.disabled) {
        picture.close();
        return;
      }
      this.interpShown = frame;
      fitCanvases(this, sizeOf(picture));
      const canvas = this.offscreen_canvas;
      if (this.get('_image_mode') === 'full') {
        this.offscreen_context.clearRect(0, 0, canvas.width, canvas.height);
      }
      this.offscreen_context.drawImage(picture, 0, 0);
      keep(this, picture);
      this._for_each_view((view) => view.update_canvas());
      saveLater(this);
    }, () => {
      if (frame < (this.interpShown || 0)) return;
      this.interpShown = frame;
      keep(this, null);
      byImageFitted.call(this, message, buffers, bytes);
    });
  };
})();
""".replace("WHOLE_FRAMES", WHOLE_FRAMES)
)


#: Run in the page with :data:`FRAME_JS` (once): stops the cursor blink of JupyterLab's code
#: editors that are not focused. CodeMirror 6 restarts a 1.2 s blink animation on an editor's
#: cursor layer at each change of its selection, focused or not (it sets the layer's inline
#: ``animation-name``), though an unfocused editor's cursor is not shown (``display: none``);
#: Chromium runs such an animation on the page's main thread, so the page drew a whole frame
#: (style, paint, layers) 60 times a second while the apps were idle. In lesson 6's page after
#: Run All, with a slider focused: 120 frames in 2 s, 3 ms of the main thread each; 4 with this.
#: A focused editor blinks as before.
QUIET_CURSORS_JS = """
(() => {
  if (document.getElementById('interp-quiet-cursors')) return;
  const style = document.createElement('style');
  style.id = 'interp-quiet-cursors';
  style.textContent = '.cm-editor:not(.cm-focused) > .cm-scroller > .cm-cursorLayer'
    + ' { animation: none !important; }';
  document.head.appendChild(style);
})();
"""

#: Run in the page with :data:`FRAME_JS` (once): when a mouse button or a key is let go, the
#: change a control's widget holds back is sent at once. ipywidgets sends a widget's change
#: only once the kernel has handled the one before (its "idle" status for it: one message on
#: its way at a time) and holds newer ones back meanwhile, so a slider's last value, set by a
#: drag's last mouse move, left the page only after that (12-45 ms after mouse-up in lesson
#: 6's drags), and was drawn as a frame of its own after the next-to-last one. Sent at once,
#: it reaches the kernel with that one, and the two are usually drawn as one frame (when it
#: comes within the :class:`Coalescer`'s wait; else it is drawn next, sooner than before).
#: Any widget's held change is sent so (a text box's too, at a key's release): at most one
#: more message on its way, in order, and ipywidgets' own bookkeeping (the pending count, the
#: echo it expects) kept as its own flush keeps it.
#: It reaches ipywidgets' model class through ipympl's (its subclass, from
#: :data:`CANVAS_MODEL_JS`); where the model's way of holding changes back is not the one this
#: was written against (ipywidgets 8.1), it changes nothing.
SEND_HELD_JS = (
    CANVAS_MODEL_JS
    + """
(async () => {
  if (!window.interpCanvasModel || window.interpSendsHeld) return;
  window.interpSendsHeld = true;
  const model = await window.interpCanvasModel;
  let proto = model && model.prototype;
  while (proto && !Object.prototype.hasOwnProperty.call(proto, 'send_sync_message')) {
    proto = Object.getPrototypeOf(proto);  // up to ipywidgets' WidgetModel
  }
  if (!proto || typeof proto.sync !== 'function'
      || typeof proto.rememberLastUpdateFor !== 'function') return;
  const holding = new Set();  // models that hold a change back
  const sync = proto.sync;
  proto.sync = function (...args) {
    const result = sync.apply(this, args);
    if (this._msg_buffer) holding.add(this);
    return result;
  };
  const sendHeld = () => {  // what ipywidgets does once the kernel has answered, done now
    holding.forEach((model) => {
      holding.delete(model);
      if (!model._msg_buffer || !model.comm_live) return;
      const sent = model.send_sync_message(model._msg_buffer, model._msg_buffer_callbacks);
      model.rememberLastUpdateFor(sent);
      model._msg_buffer = null;
      model._msg_buffer_callbacks = null;
    });
  };
  // At once, before the control sees the event: its last value came with the last mouse move
  // or key press. (A task queued for later waited 18-46 ms behind the drag's frames.)
  window.addEventListener('pointerup', sendHeld, true);
  window.addEventListener('keyup', sendHeld, true);
})();
"""
)


def static_key(figure: Figure, backdrop: frozenset[int] = frozenset()) -> tuple:
    """What must stay the same for a saved background to still be right; an axes, or the
    texts of a legend, whose id is in ``backdrop`` are left out (its backdrop's state says
    when it changed).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> figure, ax = plt.subplots()
    >>> before = static_key(figure)
    >>> _ = ax.set_ylim(0, 2)
    >>> static_key(figure) == before
    False
    """
    key: list = [tuple(figure.bbox.bounds), figure.canvas.device_pixel_ratio]
    for ax in figure.axes:
        if id(ax) in backdrop:  # drawn anew when its backdrop's state changes
            key.append(None)
            continue
        legend = ax.get_legend()
        key.append(
            (
                ax.get_xlim(),
                ax.get_ylim(),
                ax.get_xscale(),
                ax.get_yscale(),
                id(legend),
                tuple(t.get_text() for t in legend.get_texts())
                if legend and id(legend) not in backdrop
                else (),
                len(ax.texts),
                _viewpoint(ax),
            )
        )
    return tuple(key)


def _viewpoint(ax: object) -> tuple:
    """Where a 3D axes is seen from, which the mouse changes by orbiting and zooming (its
    panes, grid and ticks are in the saved background); () for 2D axes.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot(projection="3d")
    >>> before = _viewpoint(ax)
    >>> ax.view_init(elev=10.0, azim=20.0)
    >>> _viewpoint(ax) == before
    False
    """
    if getattr(ax, "name", "") != "3d":
        return ()
    return (ax.elev, ax.azim, ax.roll, ax.get_zlim(), tuple(ax.get_box_aspect()), ax._focal_length)


def _pixels_of(box: Bbox, renderer: object) -> Bbox:
    """The whole pixels a box touches, within the canvas.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> renderer = FigureCanvasAgg(Figure(figsize=(1, 1), dpi=100)).get_renderer()
    >>> _pixels_of(Bbox.from_extents(-3.5, 10.2, 20.7, 150.0), renderer).extents.tolist()
    [0.0, 10.0, 21.0, 100.0]
    """
    return Bbox.from_extents(
        max(0, math.floor(box.x0)),
        max(0, math.floor(box.y0)),
        min(renderer.width, math.ceil(box.x1)),
        min(renderer.height, math.ceil(box.y1)),
    )


def _reach_of(ax: Axes, renderer: object) -> list[Bbox]:
    """Where an axes draws: its tight box (with its labels), or, for an axes drawn without
    its frame and axis, the boxes of the artists it shows (each clipped to its clip box).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> figure, (left, right) = plt.subplots(1, 2)
    >>> right.axis("off")
    (np.float64(0.0), np.float64(1.0), np.float64(0.0), np.float64(1.0))
    >>> renderer = figure.canvas.get_renderer()
    >>> len(_reach_of(left, renderer)), len(_reach_of(right, renderer))   # right: empty
    (1, 0)
    """
    if ax.axison and ax.get_frame_on():
        return [ax.get_tightbbox(renderer) or ax.bbox]
    frame = {id(ax.patch), *map(id, ax.spines.values()), *map(id, ax._axis_map.values())}
    boxes = []
    for child in ax.get_children():
        if id(child) in frame or not child.get_visible():
            continue
        if isinstance(child, Text) and not child.get_text():
            continue
        box = child.get_window_extent(renderer)
        if not np.isfinite(box.extents).all():
            return [ax.get_tightbbox(renderer) or ax.bbox]
        clip = child.get_clip_box() if child.get_clip_on() else None
        if clip is not None:
            box = Bbox.intersection(box, clip)
            if box is None:
                continue
        boxes.append(box.padded(2))
    return boxes


class Blitter:
    """Redraws a figure over a saved background, or whole when the background is out of date.

    Parameters
    ----------
    figure : Figure
        On a canvas that can copy and restore regions (Agg, and so ipympl's).
    dynamic : list of Artist, or None
        The artists that change; None to always redraw the whole figure.
    backdrop : Backdrop, optional
        Artists that change with only some controls (lesson 6's ground with its checks per
        side), and their state: part of the saved background, drawn anew over a background
        kept without them (the *base*) when their state changes, instead of the whole figure.

    Notes
    -----
    The blit draws, in each axes, the dynamic artists and every static one stacked above them
    (spines, legends), in the order a full draw uses; the background is everything else. So a
    blitted frame matches a full redraw. An opaque legend among them is drawn once; after that
    the blit draws only its box and puts back the picture of its inside (see
    :meth:`_draw_legend`); a title drawn as it was last time is put back the same way (see
    :meth:`_draw_title`).

    A background is kept for each of the last few settings whose static parts differ (their
    :func:`static_key`; up to :data:`KEPT_BACKGROUNDS` bytes): a slider dragged back and forth
    across a change of an axis's limits or a colour scale redraws the whole figure the first
    time it crosses, and after that puts back the background it kept (lesson 6's pitch: 28 ms
    for a full redraw, 5 for a blit, in the kernel).

    The backdrop's artists, and every static one stacked above them in their axes (its
    *middle*), are drawn over the base in the order a full draw uses, which is then the
    background; so the frame still matches a full redraw, as long as nothing of another axes
    (or of the figure itself) is drawn where they reach. Where something is, the figure is
    drawn whole (see :meth:`_middle_is_alone`). In lesson 6's app a change of the checks per
    side then costs 31 ms instead of 44 (in the kernel, medians); a full redraw, which keeps
    the base too, 58 ms instead of 50. A backdrop may be a whole axes (lesson 6's colour bar,
    whose scale follows the largest error): of the 48 steps of its checks-per-side slider in
    the kernel survey, 1 redraws the whole figure instead of 12 (p90 39-61 ms, not 82-97).
    """

    def __init__(
        self, figure: Figure, dynamic: list[Artist] | None, backdrop: Backdrop | None = None
    ) -> None:
        self.figure = figure
        self.dynamic = dynamic
        self._dynamic_ids = {id(a) for a in dynamic or ()}
        self.backdrop = backdrop if dynamic is not None else None
        self._backdrop_ids = frozenset(id(a) for a in backdrop.artists) if backdrop else frozenset()
        #: The background without the backdrop and its middle, for the static key it is for:
        #: (key, saved region, the middle's artists, where other axes and the figure's own
        #: artists reach, the layers and title ids that go with it); None where there is none.
        self.base: tuple | None = None
        #: The static key for which the middle was found to reach other axes: drawn whole.
        self._crowded: tuple | None = None
        self.background = None
        self.key: tuple | None = None
        self.layers: list[Artist] = []
        #: The inside of each opaque legend among the layers, as drawn: id -> saved region.
        self.legends: dict[int, object] = {}
        #: Each title among the layers as last drawn: id -> (what it looked like, region).
        self.titles: dict[int, tuple[tuple, object]] = {}
        self._title_ids: set[int] = set()
        #: Where each spine among the layers reaches on the canvas, measured once per background.
        self._reach: dict[int, Bbox] = {}
        #: Where each other unclipped layer reaches, measured once per frame.
        self._reach_now: dict[int, Bbox] = {}
        #: Backgrounds kept for the last settings drawn, newest last: key -> what
        #: :meth:`_capture_background` made for it.
        self.kept: OrderedDict[tuple, tuple] = OrderedDict()
        self.full_draws = self.blits = self.backdrops = 0
        #: Where each axes of the backdrop reaches, for its limits (see :meth:`_drawn_in`).
        self._axes_reach: dict[tuple, Bbox] = {}
        for artist in dynamic or ():
            if isinstance(artist, AxesImage):
                keep_samples(artist)  # which pixel lands where, kept per place

    def draw(self) -> None:
        """Show the figure's current state."""
        canvas = self.figure.canvas
        keep_glyphs(canvas.get_renderer(), self.figure)  # anew when the size changes it
        if self.dynamic is None:
            self.full_draws += 1
            canvas.draw()
            return
        static = static_key(self.figure, self._backdrop_ids)
        key = (static, self.backdrop.state()) if self.backdrop else static
        if self.key is not None and self._static(key)[:2] != self._static(self.key)[:2]:
            # Another size or pixel ratio: axes of a fixed aspect (images, a 3D box, colour
            # bars) are placed anew only by a full draw, so what was kept at another size may
            # not match where they are now, even back at that size.
            self.forget()
        if (self.background is not None and key == self.key) or self._bring_back(key):
            canvas.restore_region(self.background)
            self.blits += 1
        elif self.base is not None and self.base[0] == static and self._over_base():
            self.key = key
            self._keep()
            self.backdrops += 1
        else:
            if self.base is not None and self.base[0] == static:  # _over_base found it crowded
                self._crowded = static
            self._capture_background(None if static == self._crowded else static)
            self.key = key
            self._keep()
            self.full_draws += 1
        self._reach_now = {}
        for artist in self.layers:
            if isinstance(artist, Legend) and self._keeps(artist):
                self._draw_legend(artist)
            elif id(artist) in self._title_ids:
                self._draw_title(artist)
            else:
                self.figure.draw_artist(artist)
        canvas.blit(self.figure.bbox)
        # What is on screen is now up to date. Left stale, the figure would be drawn again by
        # pyplot, which (with ``%matplotlib widget``) redraws every stale figure after each
        # widget message the kernel handles: every slider step and mouse move then cost a
        # second, full redraw, asked for by the browser, and a drag left seconds of them queued.
        self.figure.stale = False

    def _static(self, key: tuple) -> tuple:
        """The static key within ``key`` (which holds the backdrop's state too, if any)."""
        return key[0] if self.backdrop else key

    def _over_base(self) -> bool:
        """Make the background anew from the base: the middle drawn over it (the backdrop
        changed, nothing else did). False, with the canvas to be drawn whole, if the middle
        now reaches something of another axes or of the figure."""
        _, base, middle, others, self.layers, self._title_ids, pictures = self.base
        self.figure.canvas.restore_region(base)
        self._draw_middle(middle, pictures)
        if not self._middle_is_alone(middle, others):
            return False
        self.background = self._copy_all()
        self.legends, self.titles, self._reach = {}, {}, {}
        return True

    def _draw_middle(self, middle: list[Artist], pictures: dict) -> None:
        """Draw the middle's artists in turn over the base; a 3D axes' collections and patches
        projected first with its view, as its own draw does (hidden from the base's, they
        were not).

        A legend fixed in place that nothing drawn before it reaches has only the base behind
        it: its picture there, kept in ``pictures`` (the base's) for the texts it shows, is
        what drawing it gives. So a change of another part of the backdrop (lesson 6's colour
        bar) puts it back instead of laying it out and drawing it again (12 ms for the
        outside view's legend of ten entries)."""
        renderer = self.figure.canvas.get_renderer()
        drawn: list[Artist] = []
        for artist in middle:
            if not artist.get_visible():
                continue
            if hasattr(artist, "do_3d_projection"):
                artist.do_3d_projection()
            if isinstance(artist, Legend) and artist._loc != 0 and not artist.get_draggable():
                box = _pixels_of(artist.get_window_extent(renderer).padded(2), renderer)
                # Those of other axes are not there, or the middle is not alone (then the
                # figure is drawn whole, and this picture is not used).
                before = [self._drawn_in(a, renderer) for a in drawn if a.axes is artist.axes]
                if all(b is not None and not b.overlaps(box) for b in before):
                    texts = tuple(t.get_text() for t in artist.get_texts())
                    key = (id(artist), texts, tuple(box.bounds))
                    if key in pictures:
                        self.figure.canvas.restore_region(pictures[key])
                    else:
                        self.figure.draw_artist(artist)
                        pictures[key] = self.figure.canvas.copy_from_bbox(box)
                        if len(pictures) > LEGEND_PICTURES:  # the oldest goes
                            del pictures[next(iter(pictures))]
                    drawn.append(artist)
                    continue
            self.figure.draw_artist(artist)
            drawn.append(artist)

    def _middle_is_alone(self, middle: list[Artist], others: list[tuple]) -> bool:
        """Whether nothing drawn elsewhere (``others``: another axes, the figure's own
        artists) is where the ``middle``'s artists reach, as they are now drawn: then drawing
        them over the base gives what a full draw gives. An artist clipped to a box or a path
        reaches no further than that; any other as far as its extent, two pixels more
        (antialiasing)."""
        renderer = self.figure.canvas.get_renderer()
        for artist in middle:
            if not artist.get_visible():
                continue
            reach = self._drawn_in(artist, renderer)
            if reach is None:
                return False
            if any(reach.overlaps(where) for owner, where in others if owner is not artist.axes):
                return False
        return True

    def _drawn_in(self, artist: Artist, renderer: object) -> Bbox | None:
        """Where a drawn artist may have set pixels: its clip box or path's extent, or else
        its own extent two pixels wider (antialiasing); a whole axes (a colour bar) with its
        labels, kept for its limits (its tight box takes 9 ms to measure, and its labels
        follow its limits); None where that is not known (an infinite extent)."""
        if isinstance(artist, Axes):
            key = (id(artist), artist.get_xlim(), artist.get_ylim())
            if key not in self._axes_reach:
                self._axes_reach[key] = artist.get_tightbbox(renderer).padded(2)
            return self._axes_reach[key]
        clip = None
        if artist.get_clip_on():
            clip = artist.get_clip_box()
            path = artist.get_clip_path()
            if clip is None and path is not None:
                clip = path.get_fully_transformed_path().get_extents()
        if clip is not None:
            return clip
        reach = artist.get_window_extent(renderer)
        if not np.isfinite(reach.extents).all():
            return None
        return reach.padded(2)

    def _middle(self) -> list[Artist]:
        """The backdrop's artists and the static ones stacked above them in their axes,
        below the layers a blit draws, in draw order (as :meth:`_layers`, one level down);
        a backdrop artist that is among those layers is drawn there instead."""
        if not self.backdrop:
            return []
        backdrop, layered = self._backdrop_ids, {id(a) for a in self.layers}
        middle: list[Artist] = []
        for ax in self.figure.axes:
            children = ax.get_children()
            mine = [a for a in children if id(a) in backdrop and id(a) not in layered]
            if not mine:
                continue
            lowest = min(a.get_zorder() for a in mine)
            skip = {id(ax.patch), *map(id, ax._axis_map.values()), *layered}
            if not (ax.axison and ax.get_frame_on()):
                skip |= set(map(id, ax.spines.values()))
            above = [
                a
                for a in children
                if id(a) not in skip
                and (id(a) in backdrop or (a.get_visible() and a.get_zorder() > lowest))
            ]
            middle += sorted(above, key=lambda a: a.get_zorder())
        placed = {id(a) for a in middle} | layered
        return middle + [a for a in self.backdrop.artists if id(a) not in placed]

    def _others(self) -> list[tuple[object, Bbox]]:
        """Where each axes, and each of the figure's own artists, reaches (for
        :meth:`_middle_is_alone`): measured once per base. An axes drawn without its frame
        and axis (one that holds a legend) reaches only as far as what it holds."""
        renderer = self.figure.canvas.get_renderer()
        others: list[tuple[object, Bbox]] = []
        for ax in self.figure.axes:
            others += [(ax, box) for box in _reach_of(ax, renderer)]
        for artist in self.figure.get_children():
            if artist is self.figure.patch or artist in self.figure.axes:
                continue
            if artist.get_visible():
                others.append((None, artist.get_window_extent(renderer)))
        return others

    def _copy_all(self) -> object:
        """The renderer's every pixel: the figure's box, of a fractional size (8.2 in at 100
        dpi is 819.99... px), would leave out the last column or row, which a background
        brought back for another setting (see _keep) must also set."""
        renderer = self.figure.canvas.get_renderer()
        return self.figure.canvas.copy_from_bbox(
            Bbox.from_bounds(0, 0, renderer.width, renderer.height)
        )

    def _keeps(self, legend: Legend) -> bool:
        """Whether a legend can be kept as a picture: opaque, static, and fixed in place (not
        ``loc="best"``, which moves it as the curves move, and not draggable)."""
        return (
            _opaque(legend)
            and legend._loc != 0  # "best"
            and legend.get_draggable() is False
            and id(legend) not in self._dynamic_ids
            and id(legend) not in self._backdrop_ids
        )

    def _draw_legend(self, legend: Legend) -> None:
        """Draw a static, opaque legend: whole the first time, keeping the picture of its
        inside; then its box alone (whose edge pixels blend with what is behind) and that
        picture put back, which is what drawing it whole would give, pixel for pixel.

        The box is placed as it was when the legend was drawn whole: a legend sets its box's
        place (in the canvas's pixels) and its corners' size only when drawn whole, and another
        blitter of the figure (:class:`App`'s at another pixel ratio) may have done that since.
        """
        patch = legend.legendPatch
        kept = self.legends.get(id(legend))
        if kept is not None:
            inside, bounds, scale = kept
            patch.set_bounds(*bounds)
            patch.set_mutation_scale(scale)
            self.figure.draw_artist(patch)
            self.figure.canvas.restore_region(inside)
            return
        self.figure.draw_artist(legend)
        box = patch.get_window_extent()
        inside = Bbox.from_extents(
            math.ceil(box.x0) + 1,
            math.ceil(box.y0) + 1,
            math.floor(box.x1) - 1,
            math.floor(box.y1) - 1,
        )
        if inside.width > 0 and inside.height > 0:
            self.legends[id(legend)] = (
                self.figure.canvas.copy_from_bbox(inside),
                (patch.get_x(), patch.get_y(), patch.get_width(), patch.get_height()),
                patch.get_mutation_scale(),
            )

    def _draw_title(self, title: Text) -> None:
        """Draw an axes title, or put back its picture when it looks as when last drawn.

        A title sits above its axes; if its box (two pixels wider all round) meets no axes and
        nothing else the blit draws, only the background is behind it, and if its text, place,
        size and colour are the same as last time, the saved picture of that box is what
        drawing it would give. Many titles change only with some of the controls (the mode,
        not the camera); their glyphs are then not rendered again on every step. A title that
        changed since the last step is drawn and not kept: one that changes on every step (it
        quotes a slider's value) would only pay for the check that its box is free."""
        if (
            not title.get_visible()
            or not title.get_text()
            or title.get_bbox_patch() is not None
            or title.get_path_effects()
        ):
            self.figure.draw_artist(title)
            return
        renderer = self.figure.canvas.get_renderer()
        extent = self._reach_now.get(id(title))  # measured this frame for another title's box
        if extent is None:
            extent = self._reach_now[id(title)] = title.get_window_extent(renderer)
        look = (
            title.get_text(),
            tuple(extent.bounds),
            title.get_color(),
            title.get_alpha(),
            hash(title.get_fontproperties()),
            title.get_rotation(),
            title.get_antialiased(),
            title.get_usetex(),
            getattr(title, "_multialignment", None),
            repr(getattr(title, "get_fontfeatures", lambda: None)()),
            repr(getattr(title, "get_language", lambda: None)()),
            matplotlib.rcParams["text.hinting"],
        )
        last, kept = self.titles.get(id(title), (None, None))
        if last is not None and last != look:  # changed since the last step: may change again
            self.figure.draw_artist(title)
            self.titles[id(title)] = (look, None)
            return
        box = Bbox.from_extents(
            math.floor(extent.x0) - 2,
            math.floor(extent.y0) - 2,
            math.ceil(extent.x1) + 2,
            math.ceil(extent.y1) + 2,
        )
        if not self._alone(title, box, renderer):
            self.figure.draw_artist(title)
        elif kept is not None:
            self.figure.canvas.restore_region(kept)  # the same look, so the same picture
        else:
            self.figure.draw_artist(title)
            self.titles[id(title)] = (look, self.figure.canvas.copy_from_bbox(box))

    def _alone(self, title: Text, box: Bbox, renderer: object) -> bool:
        """Whether ``box`` (around ``title``) meets no axes and nothing else the blit draws: an
        artist clipped to its axes stays inside them; any other (a label, an annotation, a
        legend) may reach up into a title's box, where the saved picture would erase it.
        Where a spine reaches (with its ticks) is measured once per background, where any
        other reaches once per frame."""
        if any(ax.bbox.overlaps(box) for ax in self.figure.axes):
            return False
        for other in self.layers:
            if other is title or not other.get_visible():
                continue
            if other.get_clip_on() and other.get_clip_box() is not None:
                reach = other.get_clip_box()
            else:
                reach = self._reach.get(id(other), self._reach_now.get(id(other)))
            if reach is None:
                reach = other.get_window_extent(renderer)
                if isinstance(other, Spine):  # moves only with its axes, as the background
                    self._reach[id(other)] = reach
                else:  # a static label may still follow a changing artist it points at
                    self._reach_now[id(other)] = reach
            if reach.width > 0 and reach.height > 0 and reach.overlaps(box):
                return False
        return True

    def forget(self) -> None:
        """Draw the whole figure next time, and forget every kept background: something the
        key does not see has changed (a cell changed a label, the figure's size changed)."""
        self.background = None
        self.key = None
        self.base = None
        self.kept.clear()
        self._axes_reach.clear()

    def _keep(self) -> None:
        """Keep the background just made, and what belongs to it, for its key; forget the
        oldest beyond :data:`KEPT_BACKGROUNDS`."""
        self.kept[self.key] = (
            self.background, self.layers, self._title_ids, self.legends, self.titles, self._reach
        )  # fmt: skip
        x0, y0, x1, y1 = self.background.get_extents()
        keep = max(1, KEPT_BACKGROUNDS // max(1, 4 * (x1 - x0) * (y1 - y0)))
        while len(self.kept) > keep:
            self.kept.popitem(last=False)

    def _bring_back(self, key: tuple) -> bool:
        """Make the background kept for ``key`` the one to draw over, if there is one."""
        kept = self.kept.get(key)
        if kept is None:
            return False
        self.kept.move_to_end(key)
        self.background, self.layers, self._title_ids, self.legends, self.titles, self._reach = kept
        self.key = key
        return True

    def _capture_background(self, static: tuple | None = None) -> None:
        """Render everything but the layers a blit draws, and keep that picture; with a
        backdrop, render the base first (without the middle too), keep it for ``static``,
        then draw the middle over it (unless it reaches other axes: then all at once)."""
        self.legends = {}
        self.titles = {}
        self._reach = {}
        self.layers = self._layers()
        self._title_ids = {
            id(t) for ax in self.figure.axes for t in (ax.title, ax._left_title, ax._right_title)
        }
        self.base = None
        middle = self._middle() if static is not None else []
        if middle:
            self._render_without(self.layers + middle)
            base, others, pictures = self._copy_all(), self._others(), {}
            self._draw_middle(middle, pictures)
            if self._middle_is_alone(middle, others):
                self.background = self._copy_all()
                self.base = (static, base, middle, others, self.layers, self._title_ids, pictures)
                return
            self._crowded = static
        self._render_without(self.layers)
        self.background = self._copy_all()

    def _render_without(self, hidden: list[Artist]) -> None:
        """Render the figure with ``hidden`` left out (sending nothing to a page)."""
        shown = [(a, a.get_visible()) for a in hidden]
        # A hidden title has no extent, and matplotlib would then lift it off the axes: keep
        # where the titles are.
        places = [(a, a.get_position()) for a in hidden if isinstance(a, Text)]
        for artist in hidden:
            artist.set_visible(False)
        try:
            FigureCanvasAgg.draw(self.figure.canvas)  # render only: ipympl sends no frame yet
        finally:
            for artist, visible in shown:
                artist.set_visible(visible)
            for text, place in places:
                text.set_position(place)

    def _layers(self) -> list[Artist]:
        """The artists a blit draws: dynamic ones, and static ones above them, in draw order.

        As in ``Axes.draw``: spines only where the axes has its frame and axis on. The axis
        objects themselves (ticks, tick labels) are left in the background: the style puts
        ticks outside the axes, where no clipped artist reaches.
        """
        dynamic = self._dynamic_ids
        layers: list[Artist] = []
        for ax in self.figure.axes:
            children = ax.get_children()
            mine = [a for a in children if id(a) in dynamic]
            if not mine:
                continue
            lowest = min(a.get_zorder() for a in mine)
            framed = ax.axison and ax.get_frame_on()
            skip = {id(ax.patch), *map(id, ax._axis_map.values())}
            if not framed:
                skip |= set(map(id, ax.spines.values()))
            above = [
                a
                for a in children
                if id(a) in dynamic
                or (id(a) not in skip and a.get_visible() and a.get_zorder() > lowest)
            ]
            layers += sorted(above, key=lambda a: a.get_zorder())  # stable, as Axes.draw sorts
        in_axes = {id(a) for a in layers}
        layers += [a for a in self.dynamic if id(a) not in in_axes]
        return layers


def _opaque(legend: Legend) -> bool:
    """Whether nothing behind a legend shows through the inside of its box.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> ax = plt.figure().add_subplot()
    >>> _ = ax.plot([0, 1], label="a")
    >>> _opaque(ax.legend(framealpha=1)), _opaque(ax.legend(framealpha=0.8))
    (True, False)
    """
    patch = legend.legendPatch
    return (
        legend.get_visible()
        and patch.get_visible()
        and patch.get_facecolor()[3] == 1.0
        and not legend.shadow
        and legend.get_alpha() in (None, 1.0)
    )


class Coalescer:
    """Calls ``draw`` once for any number of :meth:`request` calls that arrive meanwhile.

    Inside a running event loop (a kernel), a request schedules ``draw`` unless one is already
    scheduled: ``settle`` seconds later if the last draw ended less than ``idle`` seconds ago
    (the messages that came during it may still be waiting), else at the loop's next turn.
    Requests arriving before it runs are absorbed, so ``draw`` sees only the newest state.
    Without a running loop (tests, scripts) ``draw`` runs at once.

    While ``draw`` runs, :attr:`following` says whether it is the first of a series (False: a
    key press, a drag's first step, a change without an event loop) or follows the last draw
    within ``idle`` (True: a drag, a key held down).
    """

    def __init__(
        self, draw: Callable[[], None], settle: float = SETTLE, idle: float = IDLE
    ) -> None:
        self._draw = draw
        self._settle = settle
        self._idle = idle
        self._scheduled = False
        self._ended = -math.inf
        self._follows = False
        self.following = False
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
            self._follows = time.monotonic() - self._ended <= self._idle
            if self._follows:
                loop.call_later(self._settle, self._run)
            else:
                loop.call_soon(self._run)

    def _run(self) -> None:
        self._scheduled = False
        self.draws += 1
        self.following, self._follows = self._follows, False
        try:
            self._draw()
        finally:
            self.following = False
            self._ended = time.monotonic()


@contextmanager
def drawn_at(canvas: FigureCanvasAgg, ratio: float) -> Iterator[None]:
    """Inside, ``canvas`` draws its figure at device pixel ratio ``ratio``, into a renderer
    kept for that ratio; afterwards the ratio, the renderer and the figure's staleness are as
    before, so pyplot's and ipympl's own draws keep the screen's. (Artists that keep places in
    pixels from their last draw, as a legend keeps its box's, keep this draw's: see
    ``Blitter._draw_legend``.)

    Examples
    --------
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> from matplotlib.figure import Figure
    >>> canvas = FigureCanvasAgg(Figure(figsize=(2, 1), dpi=100))
    >>> canvas._set_device_pixel_ratio(2)
    True
    >>> with drawn_at(canvas, 1):
    ...     canvas.draw()
    ...     canvas.buffer_rgba().shape
    (100, 200, 4)
    >>> canvas.device_pixel_ratio, canvas.figure.dpi
    (2, 200)
    """
    shown = canvas.device_pixel_ratio
    if ratio == shown:
        yield
        return
    stale = canvas.figure.stale
    kept = canvas.__dict__.setdefault("interp_renderers", {})
    saved = (getattr(canvas, "renderer", None), canvas._lastKey)
    canvas._set_device_pixel_ratio(ratio)
    if ratio in kept:
        canvas.renderer, canvas._lastKey = kept[ratio]
    try:
        yield
    finally:
        kept[ratio] = (getattr(canvas, "renderer", None), canvas._lastKey)
        canvas._set_device_pixel_ratio(shown)
        canvas.renderer, canvas._lastKey = saved
        canvas.figure.stale = stale


def png(rgba: np.ndarray, level: int = PNG_LEVEL, rows: str = "none") -> bytes:
    """An RGBA image as a PNG file, written for speed: deflated at ``level`` (by ISA-L,
    :func:`deflate`, where installed), every row with the same filter, ``rows``: ``"none"``
    (the bytes as they are) or ``"up"`` (each byte minus the one above it).

    PIL tries five filters on every row and keeps the best; for a figure of flat colours and
    text the unfiltered rows compress about as well and take less than half the time (an
    820 x 474 frame: 4.7 ms against PIL's 11.7 ms at zlib level 1, 91 kB against 99 kB). A
    figure of smooth gradients (lesson 4's colour quad) is another matter: "up" leaves small
    differences that compress to a quarter (144 kB -> 39 kB). ISA-L deflates as small as
    zlib's level 1 (within a few per cent either way) and much faster: that frame in 0.7 ms
    instead of 4.1, the checkerboard app's at a device pixel ratio of 2 (1640 x 948) in 2.0
    ms instead of 13.4.

    Examples
    --------
    >>> import io
    >>> from PIL import Image
    >>> rgba = np.zeros((2, 3, 4), np.uint8); rgba[..., 0] = 255; rgba[..., 3] = 255
    >>> picture = Image.open(io.BytesIO(png(rgba)))
    >>> picture.mode, picture.size, picture.getpixel((2, 1))
    ('RGBA', (3, 2), (255, 0, 0, 255))
    >>> Image.open(io.BytesIO(png(rgba, rows="up"))).getpixel((2, 1))
    (255, 0, 0, 255)
    """
    if rgba.dtype != np.uint8 or rgba.ndim != 3 or rgba.shape[2] != 4:
        raise ValueError(
            f"rgba must be an (height, width, 4) array of uint8, got {rgba.dtype} {rgba.shape}"
        )
    if rows not in PNG_FILTERS:
        raise ValueError(f"rows must be one of {', '.join(PNG_FILTERS)}, got {rows!r}")
    height, width, _ = rgba.shape
    flat = rgba.reshape(height, 4 * width)
    data = np.empty((height, 1 + 4 * width), np.uint8)
    data[:, 0] = PNG_FILTERS[rows]
    if rows == "up":  # modulo 256, as PNG's filter is defined
        data[0, 1:] = flat[0]
        np.subtract(flat[1:], flat[:-1], out=data[1:, 1:])
    else:
        data[:, 1:] = flat

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
        )

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8-bit RGBA, no interlace
    return (
        PNG_SIGNATURE
        + chunk(b"IHDR", header)
        + chunk(b"IDAT", deflate(data.data, level))
        + chunk(b"IEND", b"")
    )


#: The row filters :func:`png` writes, by name: PNG's filter type bytes.
PNG_FILTERS = {"none": 0, "up": 2}


class FrameFilter:
    """Which row filter a figure's frames compress best with, chosen again now and then.

    Every ``trial`` frames (the first included) the frame is written both ways and the smaller
    file is sent; the filter that made it is used until the next trial. A figure keeps its
    character (flat colours, or gradients) as its sliders move, so one frame in ``trial``
    pays for writing twice.

    Examples
    --------
    >>> gradient = np.zeros((64, 64, 4), np.uint8)
    >>> gradient[..., 0] = np.arange(64)[:, None] * 3 + np.arange(64) * 7 // 3 % 251
    >>> gradient[..., 3] = 255
    >>> frames = FrameFilter()
    >>> _ = frames.png(gradient)
    >>> frames.rows
    'up'
    """

    def __init__(self, trial: int = PNG_TRIAL) -> None:
        self.trial = trial
        self.rows = "none"
        self.frames = 0

    def png(self, rgba: np.ndarray) -> bytes:
        """The frame as a :func:`png`, with the chosen filter (choosing it on trial frames)."""
        self.frames += 1
        if (self.frames - 1) % self.trial:
            return png(rgba, rows=self.rows)
        written = {rows: png(rgba, rows=rows) for rows in PNG_FILTERS}
        self.rows = min(written, key=lambda rows: len(written[rows]))
        return written[self.rows]


def _frame_image(canvas: object) -> bytes | None:
    """The frame to send: the whole figure as a :func:`png`.

    Replaces matplotlib's ``FigureCanvasWebAggCore.get_diff_image``, which sends only the pixels
    that changed since the last frame. ipympl's view drops a frame that is still loading when
    the next one arrives; with frames sent as fast as the kernel draws them, a lost full frame
    followed by a diff left a figure blank but for the changed pixels. A whole frame written
    by :func:`png` costs less than half of a diff at PIL's default level 6, and any frame
    stands alone.
    """
    if not canvas._png_is_old:
        return None
    pixels = np.asarray(canvas.get_renderer().buffer_rgba())
    if getattr(canvas, "syncing_data_url", False):
        # No view has said it is ready (a cell still running, or no browser at all): ipympl
        # then keeps a static picture of the figure from the last frame's pixels, which
        # matplotlib's own diff frames would have left in ``_last_buff``.
        canvas._last_buff = pixels.copy().view(np.uint32)[..., 0]
    canvas.set_image_mode("full")
    canvas._force_full = False
    canvas._png_is_old = False
    frames = getattr(canvas, "interp_frames", None)
    if frames is None:
        frames = canvas.interp_frames = FrameFilter()
    return frames.png(pixels)


def take_turns(canvas: object) -> None:
    """Make ``canvas.draw`` hold :data:`DRAW_LOCK` (ipympl calls it from whichever thread its
    'draw' or 'refresh' message arrives on).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> figure = plt.figure()
    >>> take_turns(figure.canvas)
    >>> figure.canvas.draw()
    """
    canvas.draw = _in_turn(canvas.draw)


def _in_turn(method: Callable) -> Callable:
    """``method``, holding :data:`DRAW_LOCK` while it runs."""

    def in_turn(*args: object, **kwargs: object) -> object:
        with DRAW_LOCK:
            return method(*args, **kwargs)

    return in_turn


def cheap_frames(canvas: object) -> None:
    """Make an ipympl canvas send whole frames written by :func:`png`, and say so to the page
    (the class :data:`WHOLE_FRAMES`, for :data:`FRAME_JS`)."""
    if hasattr(canvas, "get_diff_image"):
        canvas.get_diff_image = MethodType(_frame_image, canvas)
        # The page's message that it scales frames of a lower ratio up (see LIVE_RATIO); read
        # by FigureCanvasWebAggCore.handle_event, which finds a handler by the message's type.
        canvas.interp_scaled_frames = False
        canvas.handle_interp_scaled_frames = lambda event: setattr(
            canvas, "interp_scaled_frames", True
        )
        # The page's message that a control was let go: when (see RELEASED).
        canvas.interp_released_at = -math.inf
        canvas.handle_interp_released = lambda event: setattr(
            canvas, "interp_released_at", time.monotonic()
        )
        # Every message of the page (a mouse move, a size, a pixel ratio) is taken in holding
        # DRAW_LOCK, whichever thread it comes on: a live frame changes the canvas's pixel ratio
        # while it is drawn (drawn_at), and a mouse event's place in the figure, or a new
        # ratio, must be read and set at the screen's.
        canvas.handle_event = _in_turn(canvas.handle_event)
        if hasattr(canvas, "add_class"):
            canvas.add_class(WHOLE_FRAMES)
