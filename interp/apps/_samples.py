"""Images in a live figure drawn from kept samples.

An image shown with ``interpolation="nearest"`` puts, on each screen pixel, the colour of one
of its pixels. matplotlib works out which one on every draw: it colours the whole image, then
has Agg resample it (with a mask for the coverage), 1.5-3.5 ms for a 320x240 raster on a
250x190 axes, and the raster apps show two or three images that change on every slider step.
Which pixel lands where depends only on the image's shape and where it is drawn, not on its
values. :func:`keep_samples` makes an image keep that map: the first draw at a place asks
matplotlib's own resampler which pixel each screen pixel takes (it resamples the pixels'
numbers), later draws colour the image and pick (about 1 ms), or, shown on fewer screen
pixels than it has, pick and then colour only what was picked.

Kept only where that is exactly what matplotlib draws: a nearest-neighbour image of floats on
an affine transform, with no alpha of its own, every screen pixel fully covered (the map shows
it). Otherwise the image is drawn by matplotlib. The colours are computed by the numpy steps
of matplotlib 3.11's ``_ImageBase._make_image`` (colour map, premultiplied alpha and back), on
the image rather than on its resampled copy: each step works pixel by pixel, so picking after
them gives what picking before them gives. Steps that cannot change a value (dividing by an
alpha of 1) are left out. It applies to matplotlib 3.11 only. ``tests/test_live.py`` compares
every app's figures, and 60 images of random shapes, kinds, masks and places, with
matplotlib's, pixel for pixel.
"""

from __future__ import annotations

import numpy as np
from matplotlib import colors
from matplotlib.image import AxesImage, _resample
from matplotlib.transforms import Affine2D, Bbox, IdentityTransform, TransformedBbox

from interp.apps._glyphs import APPLIES  # the same matplotlib, 3.11


def keep_samples(image: AxesImage) -> bool:
    """Make ``image`` a :class:`SampledImage`; whether it is one (it may already).

    Examples
    --------
    >>> import numpy as np
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> from matplotlib.figure import Figure
    >>> canvas = FigureCanvasAgg(Figure(figsize=(2, 2)))
    >>> image = canvas.figure.add_subplot().imshow(np.eye(4), interpolation="nearest")
    >>> keep_samples(image)
    True
    >>> canvas.draw()
    >>> [picks.size for picks in image.samples.values()]   # 154 x 154 screen pixels, each
    [23716]
    >>> int(image.samples.popitem()[1].max())   # showing one of the 16 image pixels
    15
    """
    if isinstance(image, SampledImage):
        return True
    if type(image) is not AxesImage or not APPLIES:
        return False
    image.__class__ = SampledImage  # the same object, drawn from its kept map
    image.samples = {}
    return True


class SampledImage(AxesImage):
    """An :class:`~matplotlib.image.AxesImage` that keeps, per place on the canvas, which of
    its pixels each screen pixel shows (made from an ``AxesImage`` by :func:`keep_samples`)."""

    #: Geometry -> the image pixel (flat index) each screen pixel shows, or None where
    #: matplotlib must draw (a screen pixel not fully covered).
    samples: dict[tuple, np.ndarray | None]

    def make_image(
        self, renderer: object, magnification: float = 1.0, unsampled: bool = False
    ) -> tuple:
        """The picture to draw and where: from the kept map where it applies, else
        matplotlib's."""
        picked = None if unsampled else self._picked(magnification)
        if picked is None:
            return super().make_image(renderer, magnification, unsampled)
        return picked

    def _picked(self, magnification: float) -> tuple | None:
        """``(rgba, x, y, transform)`` as ``_make_image`` returns it, or None."""
        A = self._A
        if (
            A is None
            or A.dtype.kind != "f"
            or self.get_interpolation() != "nearest"
            or self.get_alpha() is not None
            or not self.get_transform().is_affine
            or not (A.ndim == 2 or (A.ndim == 3 and A.shape[-1] in (3, 4)))
        ):
            return None
        place = self._place(magnification)
        if place is None:
            return None
        key, t, out_shape, corner = place
        if key not in self.samples:
            if len(self.samples) > 8:  # a few sizes (DPR 1 and 2, a resize); not more
                self.samples.clear()
            self.samples[key] = self._map(t, out_shape)
        picks = self.samples[key]
        if picks is None:
            return None
        first = picks.size < A.shape[0] * A.shape[1]  # fewer screen pixels: pick, then colour
        rgba = self._colours(A, t, picks, out_shape) if first else self._colours(A, t)
        if rgba is None:
            return None
        if not first:
            out = rgba.reshape(-1, 4).view(np.uint32)[:, 0].take(picks)
            rgba = out.view(np.uint8).reshape(*out_shape, 4)
        return rgba, corner[0], corner[1], t

    def _place(self, magnification: float) -> tuple | None:
        """Where the image lands: the same geometry as ``_make_image`` (rounded to whole
        pixels), and a key for it."""
        A = self._A
        x1, x2, y1, y2 = self.get_extent()
        in_bbox = Bbox(np.array([[x1, y1], [x2, y2]]))
        out_bbox = TransformedBbox(in_bbox, self.get_transform())
        clip = (
            (self.get_clip_box() or self.axes.bbox)
            if self.get_clip_on()
            else self.get_figure(root=True).bbox
        )
        clipped = Bbox.intersection(out_bbox, clip)
        if clipped is None:
            return None
        e = clipped.extents * magnification
        x0 = np.floor(e[0] + 0.5)
        y0 = np.ceil(e[1] - 0.5 - 1e-8)
        x1 = np.floor(e[2] + 0.5 + 1e-8)
        y1 = np.ceil(e[3] - 0.5)
        if x1 - x0 <= 0 or y1 - y0 <= 0:
            return None
        if self.origin == "upper":
            t0 = Affine2D().translate(0, -A.shape[0]).scale(1, -1)
        else:
            t0 = IdentityTransform()
        t0 += (
            Affine2D()
            .scale(in_bbox.width / A.shape[1], in_bbox.height / A.shape[0])
            .translate(in_bbox.x0, in_bbox.y0)
            + self.get_transform()
        )
        t = t0 + Affine2D().scale(magnification).translate(-x0, -y0)
        out_shape = (int(y1 - y0), int(x1 - x0))
        key = (
            A.shape[:2],
            tuple(t.get_matrix().ravel()),
            out_shape,
            self.origin,
            self.get_resample(),
        )
        return key, t, out_shape, (x0 / magnification, y0 / magnification)

    def _map(self, t: Affine2D, out_shape: tuple[int, int]) -> np.ndarray | None:
        """Which image pixel each screen pixel shows, as matplotlib's resampler picks it: it
        resamples the pixels' numbers (1, 2, ...), exact in float64, and a mask of ones for
        the coverage, as ``_make_image`` does."""
        h, w = self._A.shape[:2]
        numbers = np.arange(1, h * w + 1, dtype=np.float64).reshape(h, w)
        picked = _resample(self, numbers, out_shape, t)
        coverage = _resample(self, np.ones((h, w), np.float32), out_shape, t, resample=True)
        if not (coverage == 1).all() or not (picked == np.rint(picked)).all():
            return None
        if picked.min() < 1 or picked.max() > h * w:
            return None
        return (picked.astype(np.intp) - 1).ravel()

    def _colours(
        self,
        A: np.ma.MaskedArray,
        t: Affine2D,
        picks: np.ndarray | None = None,
        out_shape: tuple[int, int] | None = None,
    ) -> np.ndarray | None:
        """The image's pixels coloured as ``_make_image`` colours its resampled copy, uint8
        RGBA: the same numpy steps, each of which works pixel by pixel, in the same order
        (None where matplotlib would scale the colours to what it resampled). With ``picks``
        (flat indices) only those pixels, as an ``out_shape`` image: what is decided from the
        whole image (the stage, the colour scale's limits) is decided first."""
        stage = self._stage(A, t) if A.ndim == 2 else "rgba"
        if A.ndim == 2 and stage == "rgba":
            self.norm.autoscale_None(A)  # the limits of the whole image, before any picking
        if picks is not None:
            A = _pick(A, picks, out_shape)
        if A.ndim == 2 and stage == "data":
            scaled = np.ma.getdata(A).astype(np.dtype("f8" if A.dtype.itemsize > 4 else "f4"))
            if isinstance(self.norm, colors.NoNorm):
                scaled = scaled.astype(A.dtype)
            if not self.norm.scaled():  # it would scale to the resampled values
                return None
            # The mask's coverage is 1 on every screen pixel (see _map): alpha stays as it is.
            normed = self.norm(np.ma.masked_array(scaled, np.ma.getmaskarray(A)))
            return self.to_rgba(normed, bytes=True, norm=False)
        if A.ndim == 2:  # stage "rgba"; the limits are set above
            lut = getattr(self.cmap, "_lut", None)
            if lut is not None and np.isin(lut[:, 3], (0.0, 1.0)).all():
                # Every pixel opaque or clear: the premultiplying below leaves the opaque
                # ones as they are and makes the clear ones 0, bytes as the colour map's.
                rgba = self.to_rgba(A, bytes=True)
                rgba.view(np.uint32)[rgba[..., 3:] == 0] = 0
                return rgba
            A = self.to_rgba(A)
        elif A.shape[2] == 3 and A.dtype == np.float64:  # opaque: divided by 1 below
            return self.to_rgba(np.ma.getdata(A), bytes=True, norm=False)
        if A.shape[2] == 3:
            A = np.dstack([A, np.ones(A.shape[:2])])
        alpha_in = A[..., 3]
        if (alpha_in != 1).any():  # resampled premultiplied
            A = A * alpha_in[..., None]
            A[..., 3] = alpha_in
        res = np.array(A, dtype=A.dtype)  # what the resampler reads: the values, unmasked
        alpha_out = res[..., 3].copy()  # and divided back
        res /= np.where(alpha_out != 0, alpha_out, 1)[..., None]
        res[..., 3] = alpha_out
        return self.to_rgba(res, bytes=True, norm=False)

    def _stage(self, A: np.ndarray, t: Affine2D) -> str:
        """Whether matplotlib resamples the data or the colours (its "auto": the data when
        each image pixel is three screen pixels or more)."""
        stage = self._interpolation_stage
        if stage not in ("antialiased", "auto"):
            return stage
        disp = t.transform(np.array([[0, 0], [A.shape[1], A.shape[0]]]))
        dispx = np.abs(np.diff(disp[:, 0])) / A.shape[1]
        dispy = np.abs(np.diff(disp[:, 1])) / A.shape[0]
        return "rgba" if (dispx < 3) or (dispy < 3) else "data"


def _pick(A: np.ma.MaskedArray, picks: np.ndarray, shape: tuple[int, int]) -> np.ma.MaskedArray:
    """The pixels of ``A`` (H, W) or (H, W, C) at the flat indices ``picks``, as a ``shape``
    image with their mask (a plain array stays plain)."""
    channels = A.shape[2:]
    data = np.ma.getdata(A).reshape(-1, *channels).take(picks, axis=0).reshape(*shape, *channels)
    if not isinstance(A, np.ma.MaskedArray):
        return data
    mask = np.ma.getmask(A)
    if mask is np.ma.nomask:
        return np.ma.masked_array(data)
    return np.ma.masked_array(
        data, mask.reshape(-1, *channels).take(picks, axis=0).reshape(data.shape)
    )
