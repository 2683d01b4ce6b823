"""Text in a live figure drawn from kept glyphs.

matplotlib 3.11 draws text glyph by glyph: it lays the string out (``FT2Font._layout``, about
0.2 ms for a label of three letters, 1 ms for a line of a title) and then has FreeType render
each glyph at its place (50 us a glyph). A live figure draws the same labels and titles on
every step, mostly with the same text and often at the same place: lesson 1's two-line title
took 9 ms a step, its nine labels 6 ms. :func:`keep_glyphs` makes a figure's renderer keep
both: each string's layout, and each glyph's picture for its position within a pixel. A
glyph's picture depends only on that fraction (FreeType renders the outline moved by whole
pixels to the same picture, moved), so a kept picture is put where the glyph goes now, and the
text is the same, pixel for pixel, as matplotlib draws it (``tests/test_live.py`` compares
every app's frames with figures drawn by matplotlib alone). One difference: text placed some
300,000 pixels off the canvas, which FreeType refuses to render, is rendered here (at its
place within a pixel) and then falls outside the canvas.

A title that quotes a slider's value is a new string on every step, and laying it out takes
1-3 ms (35 us a character). Where the new string differs from one laid out before only in its
digits, its layout is that one's with the digits' glyphs swapped, once the font's digits are
found interchangeable there: every pair of digits, and every digit beside each character next
to a changed one, lays out with the same advance (:meth:`GlyphKeepingRenderer._swaps_digits`;
one layout of a short string each, kept). The places are then the same, as ``tests/test_live.py``
checks against matplotlib's own layout for four families, and where a font kerns a digit (STIX
bold italic after a comma) the string is laid out anew.

Text is measured (to align it) before it is drawn, and matplotlib measures a string with
``FT2Font.set_text``, which lays it out once more and loads every glyph: for a title that
quotes a slider's value, a new string on every step, 1 ms. The renderer measures from the kept
layout and each glyph's kept box instead, the same numbers (``tests/test_live.py`` compares
them with matplotlib's for random strings, fonts, sizes and hinting modes).

And before either, matplotlib works out every line's least height: it finds the font again and
reads two of its tables (``Text._get_layout``), 0.1-0.2 ms for each text measured or drawn,
some twenty a step in lesson 1. The renderer answers that from what it read the first time
for the font and size (:meth:`GlyphKeepingRenderer._get_font_height_metrics`, the hook
matplotlib gives renderers for it), the same numbers.

:class:`GlyphKeepingRenderer` repeats matplotlib 3.11's ``RendererAgg.draw_text`` with the two
things kept, so it applies to matplotlib 3.11 only; with another version a renderer is left as
it is.
"""

from __future__ import annotations

import itertools
import math
import re

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import RendererAgg, get_hinting_flag
from matplotlib.figure import Figure
from matplotlib.font_manager import fontManager, get_font
from matplotlib.ft2font import LoadFlags, RenderMode

#: Kept layouts and glyph pictures per renderer, at most; then they are dropped and kept anew.
LIMIT = 20_000
#: Any decimal digit, as :meth:`GlyphKeepingRenderer._laid_out` swaps them.
DIGIT = re.compile(r"[0-9]")
#: Every ordered pair of decimal digits once, each beside the next (a de Bruijn sequence).
DIGIT_PAIRS = "00102030405060708091121314151617181922324252627282933435363738394454647484955657"
DIGIT_PAIRS += "585966768697787988990"
#: The matplotlib whose text drawing :class:`GlyphKeepingRenderer` repeats.
MATPLOTLIB = (3, 11)
#: Whether the matplotlib installed is that one (``_samples`` repeats the same version's code).
APPLIES = tuple(int(part) for part in matplotlib.__version__.split(".")[:2]) == MATPLOTLIB


def _layout(font: object, s: str, flags: object, features: object, language: object) -> list:
    """matplotlib's layout of ``s`` (``FT2Font._layout``): its glyphs, one a character or a
    ligature, each with the character(s) it shows, its font and its place."""
    return font._layout(s, flags=flags, features=features, language=language)


def keep_glyphs(renderer: RendererAgg, figure: Figure | None = None) -> bool:
    """Make ``renderer`` a :class:`GlyphKeepingRenderer`; whether it is one (it may already).
    ``figure``, the figure it draws, lets it answer line heights too (they scale with the
    figure's dpi, which a measure may set apart from the renderer's).

    Examples
    --------
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> from matplotlib.figure import Figure
    >>> canvas = FigureCanvasAgg(Figure())
    >>> _ = canvas.figure.suptitle("kept")
    >>> keep_glyphs(canvas.get_renderer())
    True
    >>> canvas.draw()
    >>> len(canvas.get_renderer().glyphs)   # k, e, p and t, each at its place in a pixel
    4
    """
    if isinstance(renderer, GlyphKeepingRenderer):
        renderer.root_figure = figure or renderer.root_figure
        return True
    if type(renderer) is not RendererAgg or not APPLIES:
        return False
    renderer.__class__ = GlyphKeepingRenderer  # the same object, drawing text from kept glyphs
    renderer.layouts = {}
    renderer.glyphs = {}
    renderer.boxes = {}
    renderer.heights = {}
    renderer.shapes = {}
    renderer.swaps = {}
    renderer.root_figure = figure
    return True


class GlyphKeepingRenderer(RendererAgg):
    """matplotlib's Agg renderer, keeping each string's layout and each glyph's picture per
    place within a pixel (made from a :class:`RendererAgg` by :func:`keep_glyphs`).

    Attributes
    ----------
    layouts : dict
        (font, text, size, dpi, hinting, features, language) -> the glyphs and their offsets.
    glyphs : dict
        (font, size, dpi, glyph, slant, extend, angle, place in the pixel, hinting,
        antialiased) -> the glyph's picture and its corner relative to the whole pixel.
    boxes : dict
        (font, size, dpi, glyph, hinting) -> the glyph's bottom and top and its advance, in
        1/64 pixel, for measuring text.
    heights : dict
        (font properties, the font families' rcParams, the fonts known, dpi) -> a line's
        least ascent and descent and the line gap, in pixels.
    shapes : dict
        A layout's key with every digit of its string made 0 -> a string laid out with that
        key, one glyph a character, whose digits are the font's own glyphs.
    swaps : dict
        (font, size, dpi, hinting, a character or "digits") -> whether a digit beside that
        character (or beside another digit) may be swapped for another, keeping every place.
    root_figure : Figure or None
        The figure drawn, whose dpi line heights scale with; None: matplotlib works them out.
    """

    layouts: dict
    glyphs: dict
    boxes: dict
    heights: dict
    shapes: dict
    swaps: dict

    def _get_font_height_metrics(self, prop: object) -> tuple:
        """``(ascent, descent, line gap)`` of the font ``prop`` finds, in pixels, as
        matplotlib 3.11's ``Text._get_layout`` reads them from the font's tables (OS/2, else
        hhea); ``(None, None, None)`` where it has neither (matplotlib then measures "lp").
        Kept per font properties, the rcParams that resolve a family to a font (as
        ``findfont`` keys its own cache), the fonts known, and the figure's dpi (matplotlib
        scales by the figure's, which ``get_window_extent(dpi=...)`` sets for a moment)."""
        if self.root_figure is None:
            return (None, None, None)  # matplotlib reads the tables itself
        dpi = self.root_figure.dpi
        families = tuple(
            tuple(matplotlib.rcParams[key])
            for key in ("font.serif", "font.sans-serif", "font.cursive", "font.fantasy",
                        "font.monospace")
        )  # fmt: skip
        key = (hash(prop), families, len(fontManager.ttflist), dpi)
        found = self.heights.get(key)
        if found is None:
            if len(self.heights) >= LIMIT:
                self.heights.clear()
            font = get_font(fontManager._find_fonts_by_props(prop))
            found = (None, None, None)
            for table_name, gap, ascent, descent in (
                ("OS/2", "sTypoLineGap", "sTypoAscender", "sTypoDescender"),
                ("hhea", "lineGap", "ascent", "descent"),
            ):
                table = font.get_sfnt_table(table_name)
                if table is None:
                    continue
                size = prop.get_size_in_points()
                scale = 1 / font.get_sfnt_table("head")["unitsPerEm"] * size * dpi / 72
                found = (table[ascent] * scale, -table[descent] * scale, table[gap] * scale)
                break
            self.heights[key] = found
        return found

    def draw_text(
        self,
        gc: object,
        x: float,
        y: float,
        s: str,
        prop: object,
        angle: float,
        ismath: bool | str = False,
        mtext: object = None,
    ) -> None:
        """``RendererAgg.draw_text`` of matplotlib 3.11, with each string's layout kept."""
        if ismath:
            return super().draw_text(gc, x, y, s, prop, angle, ismath, mtext)
        font = self._prepare_font(prop)
        features = mtext.get_fontfeatures() if mtext is not None else None
        language = mtext.get_language() if mtext is not None else None
        size = prop.get_size_in_points()
        items = self._laid_out(font, s, size, features, language)
        glyphs = ((ft_object, size, index, 0, 1, dx, dy) for ft_object, index, dx, dy in items)
        return self._draw_text_glyphs_and_boxes(gc, x, y, angle, glyphs, [])

    def get_text_width_height_descent(
        self, s: str, prop: object, ismath: bool | str
    ) -> tuple[float, float, float]:
        """``RendererAgg.get_text_width_height_descent``, from the kept layout of ``s`` and
        each glyph's kept box: the width runs to the pen after the last glyph, the height and
        descent span the glyphs' boxes, as ``FT2Font.set_text`` measures them (checked against
        it for every hinting mode but none, where its sub-pixel pen differs; that mode, math,
        and strings of several lines are measured by matplotlib)."""
        flags = get_hinting_flag()
        if ismath or not s or "\n" in s or flags & LoadFlags.NO_HINTING:
            return super().get_text_width_height_descent(s, prop, ismath)
        font = self._prepare_font(prop)
        size = prop.get_size_in_points()
        items = self._laid_out(font, s, size, None, None)  # set_text's layout: no features
        if not items:
            return super().get_text_width_height_descent(s, prop, ismath)
        low, high = math.inf, -math.inf
        for ft_object, index, _x, y in items:
            key = (ft_object, size, self.dpi, index, flags)
            box = self.boxes.get(key)
            if box is None:
                if len(self.boxes) >= LIMIT:
                    self.boxes.clear()
                ft_object.set_size(size, self.dpi)
                glyph = ft_object.load_glyph(index, flags)
                box = self.boxes[key] = (glyph.bbox[1], glyph.bbox[3], glyph.horiAdvance)
            bottom, top, advance = box
            shift = round(y * 64)
            low, high = min(low, bottom + shift), max(high, top + shift)
        width = round(items[-1][2] * 64) + advance  # 1/64 pixel: the pen after the last glyph
        return width / 64, (high - low) / 64, -low / 64

    def _laid_out(
        self, font: object, s: str, size: float, features: object, language: object
    ) -> list[tuple]:
        """The glyphs of ``s`` and their offsets (``FT2Font._layout``), kept per string; for a
        string differing from one laid out before only in digits, that layout with the digits
        swapped where the font allows it (:meth:`_digits_swapped`)."""
        key = (font, s, size, self.dpi, get_hinting_flag(), repr(features), repr(language))
        items = self.layouts.get(key)
        if items is None:
            if len(self.layouts) >= LIMIT:
                self.layouts.clear()
                self.shapes.clear()
            shape = (font, DIGIT.sub("0", s), *key[2:])
            items = self._digits_swapped(font, s, shape, key)
            if items is None:
                laid_out = _layout(font, s, get_hinting_flag(), features, language)
                items = [(i.ft_object, i.glyph_index, i.x, i.y) for i in laid_out]
                if (
                    shape[1] != s
                    and len(laid_out) == len(s)
                    and all(i.char == c for i, c in zip(laid_out, s, strict=True))
                    and all(
                        i.ft_object is font and i.glyph_index == font.get_char_index(ord(c))
                        for i, c in zip(laid_out, s, strict=True)
                        if DIGIT.fullmatch(c)
                    )
                ):
                    self.shapes[shape] = s
            self.layouts[key] = items
        return items

    def _digits_swapped(self, font: object, s: str, shape: tuple, key: tuple) -> list | None:
        """The layout of ``s`` from that of a string laid out before (:attr:`shapes`) that
        differs from it only in digits, each of which may be swapped (:meth:`_swaps_digits`);
        None if there is none. Only for strings laid out without features or a language."""
        before = self.shapes.get(shape)
        if before is None or key[5] != "None" or key[6] != "None":
            return None
        items = list(self.layouts.get((font, before, *key[2:]), ()))
        if len(items) != len(s):
            return None
        for k, (new, old) in enumerate(zip(s, before, strict=True)):
            if new == old:
                continue
            for beside in s[k - 1 : k] + s[k + 1 : k + 2]:
                if not self._swaps_digits(font, key, "digits" if DIGIT.match(beside) else beside):
                    return None
            ft_object, _, x, y = items[k]
            items[k] = (ft_object, font.get_char_index(ord(new)), x, y)
        return items

    def _swaps_digits(self, font: object, key: tuple, beside: str) -> bool:
        """Whether the font (at ``key``'s size, dpi and hinting) lays any digit out as any
        other beside ``beside``: after it, and before it, the next glyph is as far on, and each
        digit is its own glyph. ``beside="digits"``: beside any digit, the same. Laid out once
        (``FT2Font._layout``) and kept."""
        check = (font, *key[2:5], beside)
        found = self.swaps.get(check)
        if found is None:
            if beside == "digits":
                text = DIGIT_PAIRS  # digit after digit, each pair once
            else:
                text = beside + beside.join("0123456789") + beside
            laid_out = _layout(font, text, key[4], None, None)
            found = len(laid_out) == len(text) and all(
                i.char == c
                and (
                    not DIGIT.fullmatch(c)
                    or (i.ft_object is font and i.glyph_index == font.get_char_index(ord(c)))
                )
                for i, c in zip(laid_out, text, strict=True)
            )
            if found:
                steps = [b.x - a.x for a, b in itertools.pairwise(laid_out)]
                found = len(set(steps[0::2])) == 1 and len(set(steps[1::2])) == 1
                if beside == "digits":
                    found = len(set(steps)) == 1
            self.swaps[check] = found
        return found

    def _draw_text_glyphs_and_boxes(
        self,
        gc: object,
        x: float,
        y: float,
        angle: float,
        glyphs: object,
        boxes: object,
    ) -> None:
        """The glyphs from kept pictures (:meth:`_draw_glyphs`), the boxes (mathtext's rules)
        as matplotlib draws them."""
        self._draw_glyphs(gc, x, y, angle, glyphs)
        if boxes:
            super()._draw_text_glyphs_and_boxes(gc, x, y, angle, (), boxes)

    def _draw_glyphs(self, gc: object, x: float, y: float, angle: float, glyphs: object) -> None:
        """The glyphs of ``RendererAgg._draw_text_glyphs_and_boxes`` (matplotlib 3.11), each
        rendered once per position within a pixel and then put back where it goes."""
        cos = math.cos(math.radians(angle))
        sin = math.sin(math.radians(angle))
        load_flags = get_hinting_flag()
        antialiased = gc.get_antialiased()
        for font, size, glyph_index, slant, extend, dx, dy in glyphs:  # dy is upwards
            # Where the glyph goes, in 1/64 pixel (FreeType's y is upwards).
            px = round(0x40 * (x + dx * cos - dy * sin))
            py = round(0x40 * (self.height - y + dx * sin + dy * cos))
            place = (px & 63, py & 63)
            key = (
                font,
                size,
                self.dpi,
                glyph_index,
                slant,
                extend,
                angle,
                place,
                load_flags,
                antialiased,
            )
            kept = self.glyphs.get(key)
            if kept is None:
                if len(self.glyphs) >= LIMIT:
                    self.glyphs.clear()
                font.set_size(size, self.dpi)
                font._set_transform(
                    (
                        0x10000
                        * np.array([[cos, -sin], [sin, cos]])
                        @ [[extend, extend * slant], [0, 1]]
                    )
                    .round()
                    .astype(int),
                    list(place),
                )
                bitmap = font._render_glyph(
                    glyph_index, load_flags, RenderMode.NORMAL if antialiased else RenderMode.MONO
                )
                buffer = bitmap.buffer
                if not antialiased:
                    buffer *= 0xFF
                kept = self.glyphs[key] = (buffer, bitmap.left, bitmap.top)
            buffer, left, top = kept
            left += px >> 6
            top += py >> 6
            # draw_text_image's y is downwards & the bitmap bottom side.
            self._renderer.draw_text_image(
                buffer, left, int(self.height) - top + buffer.shape[0], 0, gc
            )
