"""``interp-figures``: every figure of the lessons as print-ready files, plus one handout.

Teachers print. This writes the lessons' figures, the very ones the live apps show (each is a
class of :mod:`interp.plots.registry`, drawn here at its print size), as vector PDF and SVG
(TrueType fonts embedded, text kept as text) and 300 dpi PNG, sized for a column of an A4 or
Letter page, plus ``handout.pdf``: a cover page listing the figures, then each figure with its
title and a caption saying what to look at, and last the course's cheat sheet.

Running it twice gives byte-identical files: no timestamps, unless ``SOURCE_DATE_EPOCH`` is
set, in which case that date is used. Every parameter is checked against its documented range
(``--list`` shows them) and every figure is drawn before anything is written. The files are
written under temporary names in the output folder and renamed into place together at the end,
with the permissions the umask gives (0644 under the usual one): an error, Ctrl-C or ``kill``
before then leaves the folder exactly as it was. An existing output folder is reused, never
emptied.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import signal
import sys
import tempfile
import textwrap
import time
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

import matplotlib
import numpy as np

from interp import cheatsheet, plots
from interp.plots.registry import FIGURES, NARROW, WIDE, LessonFigure

__all__ = ["FIGURES", "FORMATS", "NARROW", "WIDE", "main", "render", "resolve_params"]

FORMATS = ("pdf", "svg", "png")
A4 = (8.27, 11.69)
#: The handout's title, on its cover and in its metadata.
HANDOUT_TITLE = "Perspective-correct interpolation"
MAX_DPI = 1200
#: Largest --params file read, in bytes.
MAX_PARAMS_FILE = 1 << 20


class UsageError(Exception):
    """A bad name, parameter, option or path: reported with exit status 2."""


class TerminatedError(BaseException):
    """SIGTERM arrived: stop, clean up, say so. Like KeyboardInterrupt (SIGINT's) it is not an
    Exception, so no ``except Exception`` on the way (in matplotlib, say) can swallow it."""


def _load_params_file(file: str) -> dict:
    """The JSON object in ``file``, or a UsageError saying what is wrong with it."""
    try:
        with open(file, "rb") as handle:
            raw = handle.read(MAX_PARAMS_FILE + 1)
    except OSError as error:
        raise UsageError(f"cannot read --params file {file}: {error.strerror}") from None
    if len(raw) > MAX_PARAMS_FILE:
        raise UsageError(f"--params file {file} is larger than {MAX_PARAMS_FILE} bytes")
    try:
        data = json.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise UsageError(f"--params file {file} is not UTF-8 text") from None
    except json.JSONDecodeError as error:
        raise UsageError(f"--params file {file} is not valid JSON: {error}") from None
    except (RecursionError, ValueError):  # absurd nesting, or an integer of thousands of digits
        raise UsageError(
            f"--params file {file} is nested too deeply or holds a huge number"
        ) from None
    if not isinstance(data, dict):
        raise UsageError(f"--params file {file} must hold a JSON object")
    return data


def resolve_params(
    names: Sequence[str], settings: Sequence[str], file: str | None
) -> dict[str, dict[str, object]]:
    """Each chosen figure's parameters: defaults, then the file, then ``--set`` values.

    A setting ``key=value`` applies to every chosen figure with that parameter;
    ``figure.key=value`` to one figure. A key no chosen figure has is an error, and so is a
    value outside the parameter's range (``interp-figures --list`` shows the ranges).
    """
    params = {name: FIGURES[name].defaults() for name in names}
    pairs: list[tuple[str, object, str]] = []
    if file is not None:
        for key, value in _load_params_file(file).items():
            if isinstance(value, dict):
                pairs += [(f"{key}.{k}", v, f"{file}: {key}.{k}") for k, v in value.items()]
            else:
                pairs.append((key, value, f"{file}: {key}"))
    for setting in settings:
        key, sep, value = setting.partition("=")
        if not sep or not key.strip():
            raise UsageError(f"--set takes KEY=VALUE or FIGURE.KEY=VALUE, got {setting!r}")
        pairs.append((key.strip(), value.strip(), f"--set {key.strip()}"))

    for key, value, where in pairs:
        figure, dot, name = key.rpartition(".")
        if dot and figure not in params:
            raise UsageError(f"{where}: {figure!r} is not among the figures being drawn")
        targets = [t for t in ([figure] if dot else names) if name in FIGURES[t].PARAMS]
        if not targets:
            known = sorted({k for t in ([figure] if dot else names) for k in FIGURES[t].PARAMS})
            raise UsageError(
                f"{where}: no figure being drawn has a parameter {name!r}; "
                f"they have: {', '.join(known)}"
            )
        for target in targets:
            param = FIGURES[target].PARAMS[name]
            try:
                if isinstance(value, str):
                    params[target][name] = param.parse(name, value)
                else:
                    params[target][name] = param.check(name, value)
            except (TypeError, ValueError) as error:
                raise UsageError(f"{where}: {error}") from None
    return params


def _metadata(fmt: str, title: str = "", description: str = "") -> dict[str, object]:
    """No timestamps, unless SOURCE_DATE_EPOCH asks for one (matplotlib then uses it); the
    figure's title and alt text where the format has a place for them (a PDF's Title and
    Subject, an SVG's Dublin Core title and description, a PNG's Title and Description)."""
    metadata: dict[str, object] = {}
    if not os.environ.get("SOURCE_DATE_EPOCH"):
        metadata |= {"pdf": {"CreationDate": None}, "svg": {"Date": None}}.get(fmt, {})
    if title:
        metadata["Title"] = title
    if description:
        metadata[{"pdf": "Subject"}.get(fmt, "Description")] = description
    return metadata


def _svg_with_alt_text(svg: str, title: str, description: str) -> str:
    """The SVG with ``<title>`` and ``<desc>`` as the root's first children, and the root
    marked as one image labelled by them: what screen readers announce for an SVG.

    Examples
    --------
    >>> svg = _svg_with_alt_text('<svg width="1">\\n<g/></svg>', "A & B", "shows <s>")
    >>> print(svg.replace("><", ">\\n<"))
    <svg width="1" role="img" aria-labelledby="title desc">
    <title id="title">A &amp; B</title>
    <desc id="desc">shows &lt;s&gt;</desc>
    <g/>
    </svg>
    """
    from html import escape

    start = svg.index("<svg")
    end = svg.index(">", start)
    label = (
        f'<title id="title">{escape(title, quote=False)}</title>'
        f'<desc id="desc">{escape(description, quote=False)}</desc>'
    )
    return svg[:end] + ' role="img" aria-labelledby="title desc">' + label + svg[end + 1 :]


def render(figure_class: type[LessonFigure], params: dict[str, object]) -> matplotlib.figure.Figure:
    """Draw one lesson figure at its print size, off-screen, with the package style."""
    return _draw(figure_class, params)[0]


def _draw(
    figure_class: type[LessonFigure], params: dict[str, object]
) -> tuple[matplotlib.figure.Figure, str]:
    """:func:`render`'s figure, and its alt text (see :func:`alt_text`)."""
    from matplotlib.figure import Figure

    with plots.styled():
        figure = Figure(figsize=figure_class.print_size, layout="constrained")
        try:
            plot = figure_class(figure, **params)
        except (ValueError, TypeError) as error:
            raise UsageError(f"{figure_class.name}: {error}") from None
        _settle_layout(figure)
    return figure, alt_text(figure_class, plot.readout())


def alt_text(figure_class: type[LessonFigure], readout: str = "") -> str:
    """What a figure shows, for readers who cannot see it: its caption, then its key result
    at the parameters drawn (the apps' live text readout).

    Examples
    --------
    >>> alt_text(FIGURES["st-mapping"], "The gap peaks at s = 0.634.")[-27:]
    'The gap peaks at s = 0.634.'
    """
    return f"{figure_class.caption} {readout}".strip()


def _settle_layout(figure: matplotlib.figure.Figure) -> None:
    """Lay ``figure`` out once, then pin every axes to a position rounded to 1e-6 of the figure.

    Constrained layout's solver returns positions whose last bits vary from run to run; rounded,
    the files come out byte-identical.
    """
    figure.get_layout_engine().execute(figure)
    figure.set_layout_engine("none")
    subfigures = list(figure.subfigs)
    while subfigures:  # subfigures (a handout page's title, figure and caption) first
        subfigure = subfigures.pop()
        box = subfigure.bbox_relative
        box.p0, box.p1 = np.round(box.p0, 6), np.round(box.p1, 6)
        subfigures += subfigure.subfigs
    for ax in figure.axes:
        ax.set_position(np.round(ax.get_position(original=True).bounds, 6))


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """SIGINT and SIGTERM wait until the block is done (then they are delivered)."""
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


class Staging:
    """Files written under temporary names in one folder, renamed into place together.

    Use as a context manager: whatever is still staged when the block ends (an error, an
    interruption, or no :meth:`commit`) is deleted, so the folder is left as it was.
    """

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.staged: list[tuple[str, Path]] = []
        self.names: set[str] = set()
        mask = os.umask(0)
        os.umask(mask)
        self.mode = 0o666 & ~mask  # what open() would give a new file

    def write(self, name: str, write: Callable[[str], None]) -> Path:
        """Write ``folder/name`` through ``write(temporary_path)``; returns the final path."""
        target = self.folder / name
        if target.is_dir():
            raise UsageError(f"cannot write {target}: a folder of that name is in the way")
        with _signals_held():  # no interruption between making the file and noting it
            handle, temporary = tempfile.mkstemp(
                dir=self.folder, prefix=self._prefix(name), suffix=".tmp"
            )
            os.close(handle)
            self.staged.append((temporary, target))
        try:
            write(temporary)
            os.chmod(temporary, self.mode)
        except Exception as error:
            cause = _os_error(error)
            if cause is None:
                raise
            # Name the file the user asked for, not the temporary one.
            raise OSError(cause.errno, cause.strerror, str(target)) from None
        return target

    def commit(self) -> None:
        """Rename every staged file into place, with signals held off meanwhile."""
        with _signals_held():
            while self.staged:
                temporary, target = self.staged[0]
                os.replace(temporary, target)
                self.staged.pop(0)

    def __enter__(self) -> Staging:
        return self

    def _prefix(self, name: str) -> str:
        self.names.add(name)
        return f".{name}.{os.getpid()}."

    def __exit__(self, *exc: object) -> None:
        # Also any temporary made just before a signal stopped it being noted: this process's.
        leftovers = {Path(t) for t, _ in self.staged}
        for name in self.names:
            leftovers |= set(self.folder.glob(f".{name}.{os.getpid()}.*.tmp"))
        for temporary in leftovers:
            with contextlib.suppress(OSError):
                os.unlink(temporary)
        self.staged.clear()


def _os_error(error: BaseException | None) -> OSError | None:
    """The OSError behind ``error``, if any: matplotlib's PDF writer, cleaning up after a failed
    write, raises an AttributeError of its own on top of the OSError that matters."""
    while error is not None:
        if isinstance(error, OSError) and error.errno is not None:
            return error
        error = error.__cause__ or error.__context__
    return None


def save(
    figure: matplotlib.figure.Figure,
    name: str,
    fmt: str,
    dpi: int,
    stage: Staging,
    title: str = "",
    alt: str = "",
) -> Path:
    """Stage ``figure`` as ``name`` in ``fmt``, deterministically, carrying ``title`` and the
    alt text ``alt`` (:func:`_metadata`; in an SVG also as ``<title>`` and ``<desc>``)."""

    def write(path: str) -> None:
        with plots.styled():
            if fmt != "svg":
                figure.savefig(path, format=fmt, dpi=dpi, metadata=_metadata(fmt, title, alt))
                return
            buffer = io.StringIO()
            figure.savefig(buffer, format=fmt, dpi=dpi, metadata=_metadata(fmt, title, alt))
            Path(path).write_text(_svg_with_alt_text(buffer.getvalue(), title, alt))

    return stage.write(name, write)


def write_handout(stage: Staging, chosen: Sequence[str], params: dict[str, dict]) -> Path:
    """Stage ``handout.pdf``: a cover listing the figures, one page per figure, and the cheat
    sheet (:mod:`interp.cheatsheet`)."""
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    def pages(path: str) -> None:
        with plots.styled(), PdfPages(path, metadata=_metadata("pdf", HANDOUT_TITLE)) as pdf:
            cover = Figure(figsize=A4)
            cover.text(0.1, 0.9, HANDOUT_TITLE, fontsize=20, weight="bold")
            cover.text(0.1, 0.86, "Figures from the interp lessons", fontsize=12)
            for k, figure_class in enumerate(FIGURES[n] for n in chosen):
                y = 0.8 - 0.055 * k
                cover.text(0.1, y, f"{k + 2:>2}", fontsize=10, ha="right")
                cover.text(0.13, y, figure_class.title, fontsize=10, weight="bold")
                lesson = f"lesson {figure_class.lesson}: {figure_class.description}"
                cover.text(0.13, y - 0.018, lesson, fontsize=8)
            y = 0.8 - 0.055 * len(chosen)
            cover.text(0.1, y, f"{len(chosen) + 2:>2}", fontsize=10, ha="right")
            cover.text(0.13, y, "Cheat sheet", fontsize=10, weight="bold")
            cover.text(0.13, y - 0.018, "the formulas, the notation, the mistakes", fontsize=8)
            pdf.savefig(cover)
            for figure_class in (FIGURES[n] for n in chosen):
                width, height = figure_class.print_size
                page = Figure(figsize=A4)
                body_height = height / width * 0.78 * A4[0] / A4[1]
                grid = page.add_gridspec(
                    3, 3, width_ratios=[0.11, 0.78, 0.11], height_ratios=[0.09, body_height, 0.2]
                )
                top, body, bottom = (page.add_subfigure(grid[k, 1]) for k in range(3))
                top.text(0.0, 0.3, figure_class.title, fontsize=16, weight="bold")
                scale = 0.78 * A4[0] / width
                with matplotlib.rc_context({"font.size": 9 * min(scale, 1.6)}):
                    figure_class(body, **params[figure_class.name])
                caption = "\n".join(textwrap.wrap(figure_class.caption, 80))
                bottom.text(0.0, 0.9, caption, fontsize=10, va="top")
                _settle_layout(page)
                pdf.savefig(page)
            sheet = Figure(figsize=A4)
            cheatsheet.draw(sheet)
            pdf.savefig(sheet)

    return stage.write("handout.pdf", pages)


def _parser() -> argparse.ArgumentParser:
    names = ", ".join(FIGURES)
    parser = argparse.ArgumentParser(
        prog="interp-figures",
        description="Write the interp lessons' figures as print-ready PDF, SVG and PNG files, "
        "and handout.pdf with every figure and its caption.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=textwrap.dedent(f"""\
            figures: {names}

            parameters: each figure has its own, each with a range (see --list); set one for
            every figure that has it with --set KEY=VALUE, or for one figure with
            --set FIGURE.KEY=VALUE, or put them in a JSON file:
            {{"pitch": 30, "checkerboards": {{"frequency": 12}}}}.

            example:
              interp-figures --out handouts --only checkerboards st-mapping \\
                  --format pdf png --set pitch=35 --set checkerboards.frequency=12

            Files are byte-identical from run to run; set SOURCE_DATE_EPOCH to stamp a date.
            Exit status: 0 done, 2 bad usage or a file that cannot be written (nothing is
            changed then), 130 or 143 interrupted (nothing is changed).
            """),
    )
    parser.add_argument(
        "--out",
        default="handouts",
        metavar="DIR",
        help="output folder, created if needed, never emptied (default: handouts)",
    )
    parser.add_argument(
        "--format",
        nargs="+",
        choices=FORMATS,
        default=list(FORMATS),
        dest="formats",
        metavar="FORMAT",
        help="any of pdf, svg, png (default: all three)",
    )
    parser.add_argument("--only", nargs="+", metavar="NAME", help="only these figures")
    parser.add_argument(
        "--list",
        action="store_true",
        help="list the figures with a one-line description and their parameters' ranges",
    )
    parser.add_argument("--dpi", type=int, default=300, help="PNG resolution (default: 300)")
    parser.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        dest="settings",
        help="set a parameter (repeatable)",
    )
    parser.add_argument("--params", metavar="FILE", help="a JSON file of parameters")
    parser.add_argument("--no-handout", action="store_true", help="do not write handout.pdf")
    return parser


def _list() -> None:
    width = max(len(name) for name in FIGURES)
    for f in FIGURES.values():
        print(f"{f.name:<{width}} {f.description} (lesson {f.lesson})")
        for name, param in f.PARAMS.items():
            print(f"{'':<{width + 2}}{name}={param.default}  in {param.range}")


@contextlib.contextmanager
def _interruptible() -> Iterator[None]:
    """Turn SIGTERM into :class:`TerminatedError` (SIGINT is KeyboardInterrupt already)."""

    def stop(signum: int, frame: object) -> None:
        raise TerminatedError(signal.Signals(signum).name)

    try:
        previous = signal.signal(signal.SIGTERM, stop)
    except ValueError:  # not the main thread: signals stay as they are
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (0 ok, 2 bad usage, 130/143 interrupted)."""
    matplotlib.use("agg")
    parser = _parser()
    args = parser.parse_args(argv)
    if args.list:
        _list()
        return 0

    def fail(message: str) -> int:
        print(f"interp-figures: error: {message}", file=sys.stderr)
        return 2

    try:
        with _interruptible():
            if not 10 <= args.dpi <= MAX_DPI:
                raise UsageError(f"--dpi must be between 10 and {MAX_DPI}, got {args.dpi}")
            chosen = list(dict.fromkeys(args.only or FIGURES))
            unknown = [n for n in chosen if n not in FIGURES]
            if unknown:
                raise UsageError(
                    f"unknown figure {', '.join(map(repr, unknown))}; "
                    f"choose from: {', '.join(FIGURES)}"
                )
            params = resolve_params(chosen, args.settings, args.params)
            started = time.perf_counter()
            figures = {n: _draw(FIGURES[n], params[n]) for n in chosen}  # all checked first
            out = Path(args.out)
            if out.exists() and not out.is_dir():
                raise UsageError(f"--out {out} exists and is not a folder")
            try:
                out.mkdir(parents=True, exist_ok=True)
            except OSError as error:
                raise UsageError(f"cannot create --out {out}: {error.strerror}") from None
            formats = list(dict.fromkeys(args.formats))
            with Staging(out) as stage:
                for name, (figure, alt) in figures.items():
                    start = time.perf_counter()
                    title = FIGURES[name].title
                    paths = [
                        save(figure, f"{name}.{fmt}", fmt, args.dpi, stage, title, alt)
                        for fmt in formats
                    ]
                    shown = paths[0] if len(paths) == 1 else out / f"{name}.{{{','.join(formats)}}}"
                    print(f"{name:<18} {shown}  {time.perf_counter() - start:.2f} s", flush=True)
                if not args.no_handout:
                    start = time.perf_counter()
                    path = write_handout(stage, chosen, params)
                    print(f"{'handout':<18} {path}  {time.perf_counter() - start:.2f} s")
                stage.commit()
            print(f"{len(figures)} figures in {time.perf_counter() - started:.1f} s")
            return 0
    except UsageError as error:
        parser.print_usage(sys.stderr)
        return fail(str(error))
    except OSError as error:
        where = error.filename or args.out
        return fail(f"cannot write {where}: {error.strerror or error}; nothing was changed")
    except (KeyboardInterrupt, TerminatedError) as error:
        name = "SIGINT" if isinstance(error, KeyboardInterrupt) else str(error)
        print(f"interp-figures: stopped by {name}; nothing was changed", file=sys.stderr)
        return 130 if name == "SIGINT" else 143


if __name__ == "__main__":
    raise SystemExit(main())
