"""``interp-figures``: every key figure of the lessons as print-ready files, plus one handout.

Teachers print. This writes the lessons' figures, drawn by the very plot objects the live apps
use (:mod:`interp.plots`), as vector PDF and SVG (TrueType fonts embedded, text kept as text)
and 300 dpi PNG, sized for a column of an A4 or Letter page, plus ``handout.pdf``: a cover page
listing the figures, then each figure with its title and a caption saying what to look at.

Running it twice gives byte-identical files: no timestamps, unless ``SOURCE_DATE_EPOCH`` is
set, in which case that date is used. Every parameter is checked before anything is written;
each file is written to a temporary name and renamed, so an interrupted run never leaves a
half-written file; an existing output folder is reused, never emptied.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import textwrap
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import matplotlib

from interp import plots
from interp.camera import Camera
from interp.plots.gpu import LAB_CAMERA
from interp.scenes import LESSON_CAMERA

FORMATS = ("pdf", "svg", "png")
#: Widths that fit a column of an A4 or Letter page (6.3 in of text between 1 in margins).
NARROW, WIDE = 3.3, 6.3
A4 = (8.27, 11.69)
MAX_DPI = 1200

CAMERA_FIELDS = ("height", "pitch", "yaw", "distance", "fovy", "near")


def _camera(params: dict, base: Camera = LESSON_CAMERA) -> Camera:
    return Camera(
        **{**base.__dict__, **{k: params[k] for k in (*CAMERA_FIELDS, "roll") if k in params}}
    )


def _camera_defaults(base: Camera = LESSON_CAMERA, roll: bool = False) -> dict[str, float]:
    names = (*CAMERA_FIELDS, "roll") if roll else CAMERA_FIELDS
    return {name: float(getattr(base, name)) for name in names}


@dataclass(frozen=True)
class FigureSpec:
    """One exported figure: what it is called and shows, and how to draw it."""

    name: str
    title: str
    description: str  # one line, for --list
    caption: str  # what the reader should look at
    size: tuple[float, float]
    draw: Callable[..., object]  # draw(figure, **params) -> the plot object(s)
    params: dict[str, object] = field(default_factory=dict)


def _line_points(p: dict) -> dict:
    return {"A": (p["A_x"], -p["A_w"]), "B": (p["B_x"], -p["B_w"]), "d": p["d"]}


LINE = {"A_x": -1.5, "A_w": 2.0, "B_x": 2.5, "B_w": 8.0, "d": 2.0}

SPECS: list[FigureSpec] = [
    FigureSpec(
        "midpoint",
        "The midpoint mismatch",
        "a segment seen by a 1D camera: the image's middle is not the middle's image",
        "The eye (left) sees segment AB on the image plane (grey). M, the middle of AB, shows at "
        "m; the middle of the image, c, shows C. They coincide only when A and B are equally "
        "deep. (Lesson 1)",
        (NARROW, 3.0),
        lambda fig, **p: plots.LineView(fig.add_subplot(), **_line_points(p)),
        dict(LINE),
    ),
    FigureSpec(
        "fan",
        "Equally spaced pixels fan out",
        "rays through equally spaced image samples crowd towards the near end of the segment",
        "Rays through equally spaced pixels meet the segment at points that crowd towards its "
        "near end: each pixel covers more of the segment the further away it looks. (Lesson 2)",
        (NARROW, 3.0),
        lambda fig, **p: plots.LineView(fig.add_subplot(), samples=p["samples"], **_line_points(p)),
        {**LINE, "samples": 12},
    ),
    FigureSpec(
        "attribute-line",
        "An attribute along a line",
        "affine against perspective-correct interpolation along the image of a segment",
        "An attribute going from 0 at A to 1 at B, along the image from a to b. Interpolated on "
        "the screen it is a straight line (dashed); the true value (solid) lags, then catches "
        "up near the far end. (Lesson 2)",
        (NARROW, 2.6),
        lambda fig, **p: plots.ImageStrip(fig.add_subplot(), w1=p["w1"], w2=p["w2"]),
        {"w1": 2.0, "w2": 8.0},
    ),
    FigureSpec(
        "st-family",
        "The s-t curves",
        "the object parameter t against the screen parameter s, for several depth ratios",
        "Each curve maps the screen parameter s to the object parameter t for one depth ratio "
        "w2/w1; ratio 1 (an orthographic camera) is the diagonal. The bold curve is the chosen "
        "ratio. (Lesson 3)",
        (NARROW, 3.2),
        lambda fig, **p: plots.STFamily(fig.add_subplot(), ratio=p["ratio"]),
        {"ratio": 4.0},
    ),
    FigureSpec(
        "gap-peak",
        "Where |t - s| peaks",
        "the gap between object and screen parameter, with its derived maximum",
        "The gap |t - s| along the image. The circle marks the derived peak s* = "
        "sqrt(w2)/(sqrt(w1)+sqrt(w2)); the cross marks the largest of 2001 samples. They "
        "agree. (Lesson 3)",
        (NARROW, 2.8),
        lambda fig, **p: plots.GapPlot(fig.add_subplot(), w1=p["w1"], w2=p["w2"]),
        {"w1": 1.0, "w2": 9.0},
    ),
    FigureSpec(
        "depth",
        "Depth across the screen",
        "view depth w, 1/w and NDC z along the image, each rescaled to [0, 1]",
        "Along the image of a receding segment, 1/w and NDC z are straight lines, so a depth "
        "buffer may interpolate them linearly; the depth w itself is not. (Lesson 4)",
        (NARROW, 2.8),
        lambda fig, **p: plots.DepthAcross(fig.add_subplot(), **p),
        {"w1": 1.0, "w2": 8.0, "near": 0.5, "far": 20.0},
    ),
    FigureSpec(
        "depth-precision",
        "Depth-buffer precision",
        "the smallest depth step a depth buffer resolves, against depth, for three near planes",
        "How finely a depth buffer tells depths apart, against depth, on log scales. The step "
        "grows with the square of the depth, and a ten times smaller near plane makes every "
        "step ten times coarser. (Lesson 4)",
        (NARROW, 2.8),
        lambda fig, **p: plots.DepthPrecision(fig.add_subplot(), **p),
        {"near": 0.1, "far": 100.0, "buffer": "float32"},
    ),
    FigureSpec(
        "mistakes",
        "Classic mistakes",
        "perspective-correct interpolation beside affine and two classic mistakes",
        "The right attribute along a line (solid) beside affine interpolation, dividing by the "
        "depth buffer's z instead of w, and dividing too early. Only the solid curve is "
        "right. (Lesson 5)",
        (NARROW, 2.8),
        lambda fig, **p: plots.MistakesAlongALine(fig.add_subplot(), **p),
        {"w1": 1.0, "w2": 6.0, "near": 0.5, "far": 20.0},
    ),
    FigureSpec(
        "clip-vertex",
        "Forgetting the clip vertex",
        "a segment clipped at the near plane, with and without the new vertex's own attribute",
        "A segment whose far end is behind the near plane is clipped at C. With C's own "
        "attribute (solid) the visible part is right; keeping the far end's attribute (dotted) "
        "makes all of it wrong. (Lesson 5)",
        (NARROW, 2.8),
        lambda fig, **p: plots.ClipVertexMistake(fig.add_subplot(), **p),
        {"w1": 4.0, "w2": -2.0, "near": 0.5},
    ),
    FigureSpec(
        "colour-quad",
        "Colour across a quad",
        "a colour gradient across a ground quad, affine and perspective-correct",
        "The same four corner colours, interpolated affinely (left) and perspective-correctly "
        "(right). Affine colours slide along the diagonal between the two triangles. "
        "(Lesson 5)",
        (WIDE, 2.4),
        lambda fig, **p: [
            plots.ColourTriangle(ax, _camera(p), mode)
            for ax, mode in zip(fig.subplots(1, 2), ("affine", "perspective"), strict=True)
        ],
        _camera_defaults(),
    ),
    FigureSpec(
        "checkerboards",
        "Checkerboards",
        "affine beside perspective-correct texture mapping, and the error in texels",
        "A checkerboard quad drawn affinely (left) and perspective-correctly (middle); right, "
        "how far apart their texture coordinates are, in texels. The affine lines bend, and "
        "bend differently in the quad's two triangles. (Lesson 6)",
        (WIDE, 1.9),
        lambda fig, **p: plots.CheckerPanels(
            fig.subplots(1, 3),
            _camera(p),
            frequency=p["frequency"],
            quads=p["quads"],
            width=p["pixels"],
            height=p["pixels"] * 3 // 4,
        ),
        {**_camera_defaults(), "frequency": 8.0, "quads": 1, "pixels": 320},
    ),
    FigureSpec(
        "barycentrics",
        "Barycentrics, screen and clip space",
        "one triangle coloured by its barycentric coordinates: noperspective and smooth",
        "One triangle with red, green and blue corners, so its colour is its barycentric "
        "coordinates: screen-space (noperspective, left) and clip-space (smooth, OpenGL 4.6 eq. "
        "14.9, right). (Lesson 7)",
        (WIDE, 2.4),
        lambda fig, **p: [
            plots.ColourTriangle(ax, _camera(p), mode, whole_quad=False)
            for ax, mode in zip(fig.subplots(1, 2), ("affine", "perspective"), strict=True)
        ],
        _camera_defaults(),
    ),
    FigureSpec(
        "clipping",
        "Near-plane clipping",
        "the ground plane from just above it, with the outline of every clipped triangle",
        "With the camera just above the ground, triangles reach behind it; clipping in clip "
        "space cuts them at the near plane into the outlined pieces, and the image stays "
        "correct. (Lesson 7)",
        (NARROW, 2.6),
        lambda fig, **p: plots.ClippingView(fig.add_subplot(), _camera(p), quads=p["quads"]),
        {**_camera_defaults(), "height": 0.3, "quads": 2},
    ),
    FigureSpec(
        "approximations",
        "The approximation lab",
        "mean texture error against divides per pixel: Quake's spans and tessellation",
        "Mean texture error against divides per pixel, on log scales, for a rolled camera: "
        "exact every N pixels along a row (Quake's spans) against cutting the quad into n x n "
        "affine quads (PlayStation era). (Lesson 7)",
        (NARROW, 3.0),
        lambda fig, **p: plots.ApproximationLab(fig.add_subplot(), _camera(p, LAB_CAMERA)),
        _camera_defaults(LAB_CAMERA, roll=True),
    ),
]
BY_NAME = {spec.name: spec for spec in SPECS}


class UsageError(Exception):
    """A bad name, parameter or option: reported before anything is written."""


def _convert(text: str, default: object, where: str) -> object:
    """Parse a command-line value to the type of the parameter's default."""
    kind = type(default)
    try:
        if kind is bool:
            raise ValueError
        return kind(text) if kind is not str else text
    except ValueError:
        raise UsageError(f"{where} must be {kind.__name__}, got {text!r}") from None


def resolve_params(
    names: Sequence[str], settings: Sequence[str], file: str | None
) -> dict[str, dict[str, object]]:
    """Each chosen figure's parameters: defaults, then the file, then ``--set`` values.

    A setting ``key=value`` applies to every chosen figure with that parameter;
    ``figure.key=value`` to one figure. A key no chosen figure has is an error.
    """
    params = {name: dict(BY_NAME[name].params) for name in names}
    pairs: list[tuple[str, object, str]] = []
    if file is not None:
        try:
            data = json.loads(Path(file).read_text())
        except OSError as error:
            raise UsageError(f"cannot read --params file {file}: {error.strerror}") from None
        except json.JSONDecodeError as error:
            raise UsageError(f"--params file {file} is not valid JSON: {error}") from None
        if not isinstance(data, dict):
            raise UsageError(f"--params file {file} must hold a JSON object")
        for key, value in data.items():
            if isinstance(value, dict):
                pairs += [(f"{key}.{k}", v, f"{file}: {key}.{k}") for k, v in value.items()]
            else:
                pairs.append((key, value, f"{file}: {key}"))
    for setting in settings:
        key, sep, value = setting.partition("=")
        if not sep or not key:
            raise UsageError(f"--set takes KEY=VALUE or FIGURE.KEY=VALUE, got {setting!r}")
        pairs.append((key.strip(), value.strip(), f"--set {key.strip()}"))

    for key, value, where in pairs:
        figure, dot, name = key.rpartition(".")
        targets = [figure] if dot else list(names)
        if dot and figure not in params:
            raise UsageError(f"{where}: {figure!r} is not among the figures being drawn")
        hit = False
        for target in targets:
            if name in params[target]:
                default = BY_NAME[target].params[name]
                if isinstance(value, str):
                    value_converted = _convert(value, default, where)
                elif isinstance(value, bool) or not isinstance(value, (int, float, str)):
                    raise UsageError(f"{where} must be {type(default).__name__}, got {value!r}")
                else:
                    value_converted = _convert(str(value), default, where)
                params[target][name] = value_converted
                hit = True
        if not hit:
            known = sorted({k for n in targets for k in params[n]})
            raise UsageError(
                f"{where}: no figure being drawn has a parameter {name!r}; "
                f"they have: {', '.join(known)}"
            )
    return params


def _metadata(fmt: str) -> dict[str, object]:
    """No timestamps, unless SOURCE_DATE_EPOCH asks for one (matplotlib then uses it)."""
    if os.environ.get("SOURCE_DATE_EPOCH"):
        return {}
    return {"pdf": {"CreationDate": None}, "svg": {"Date": None}}.get(fmt, {})


def render(spec: FigureSpec, params: dict[str, object]) -> matplotlib.figure.Figure:
    """Draw one figure, off-screen, with the package style."""
    from matplotlib.figure import Figure

    with plots.styled():
        figure = Figure(figsize=spec.size, layout="constrained")
        try:
            spec.draw(figure, **params)
        except (ValueError, TypeError) as error:
            raise UsageError(f"{spec.name}: {error}") from None
    return figure


def _write_atomically(path: Path, write: Callable[[str], None]) -> None:
    """Write via a temporary file in the same folder, then rename over ``path``."""
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    os.close(handle)
    try:
        write(temporary)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.unlink(temporary)


def save(figure: matplotlib.figure.Figure, path: Path, fmt: str, dpi: int) -> None:
    """Save ``figure`` as ``path`` in ``fmt``, atomically and deterministically."""
    with plots.styled():
        _write_atomically(
            path, lambda name: figure.savefig(name, format=fmt, dpi=dpi, metadata=_metadata(fmt))
        )


def write_handout(path: Path, chosen: Sequence[str], params: dict[str, dict]) -> None:
    """``handout.pdf``: a cover listing the figures, then one page per figure with caption."""
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    def pages(name: str) -> None:
        with plots.styled(), PdfPages(name, metadata=_metadata("pdf")) as pdf:
            cover = Figure(figsize=A4)
            cover.text(0.1, 0.9, "Perspective-correct interpolation", fontsize=20, weight="bold")
            cover.text(0.1, 0.86, "Figures from the interp lessons", fontsize=12)
            for k, spec in enumerate(BY_NAME[n] for n in chosen):
                y = 0.8 - 0.04 * k
                cover.text(0.1, y, f"{k + 2:>2}", fontsize=10, ha="right")
                cover.text(0.13, y, spec.title, fontsize=10, weight="bold")
                cover.text(0.45, y, spec.description, fontsize=7.5, wrap=True)
            pdf.savefig(cover)
            for spec in (BY_NAME[n] for n in chosen):
                page = Figure(figsize=A4)
                body_height = spec.size[1] / spec.size[0] * 0.78 * A4[0] / A4[1]
                grid = page.add_gridspec(
                    3, 3, width_ratios=[0.11, 0.78, 0.11], height_ratios=[0.09, body_height, 0.2]
                )
                top, body, bottom = (page.add_subfigure(grid[k, 1]) for k in range(3))
                top.text(0.0, 0.3, spec.title, fontsize=16, weight="bold")
                scale = 0.78 * A4[0] / spec.size[0]
                with matplotlib.rc_context({"font.size": 9 * min(scale, 1.6)}):
                    spec.draw(body, **params[spec.name])
                caption = "\n".join(textwrap.wrap(spec.caption, 80))
                bottom.text(0.0, 0.9, caption, fontsize=10, va="top")
                pdf.savefig(page)

    _write_atomically(path, pages)


def _parser() -> argparse.ArgumentParser:
    names = ", ".join(BY_NAME)
    parser = argparse.ArgumentParser(
        prog="interp-figures",
        description="Write the interp lessons' key figures as print-ready PDF, SVG and PNG "
        "files, and handout.pdf with every figure and its caption.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=textwrap.dedent(f"""\
            figures: {names}

            parameters: each figure has its own (see --list); set one for every figure that
            has it with --set KEY=VALUE, or for one figure with --set FIGURE.KEY=VALUE, or put
            them in a JSON file: {{"pitch": 30, "checkerboards": {{"frequency": 12}}}}.

            example:
              interp-figures --out handouts --only checkerboards st-family \\
                  --format pdf png --set pitch=35 --set checkerboards.frequency=12

            Files are byte-identical from run to run; set SOURCE_DATE_EPOCH to stamp a date.
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
        help="list the figures with a one-line description and their parameters",
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


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status (0 ok, 2 bad usage)."""
    matplotlib.use("agg")
    parser = _parser()
    args = parser.parse_args(argv)
    if args.list:
        for spec in SPECS:
            defaults = ", ".join(f"{k}={v}" for k, v in spec.params.items())
            print(f"{spec.name:<16} {spec.description}\n{'':<16} parameters: {defaults}")
        return 0
    try:
        if not 10 <= args.dpi <= MAX_DPI:
            raise UsageError(f"--dpi must be between 10 and {MAX_DPI}, got {args.dpi}")
        chosen = list(dict.fromkeys(args.only or BY_NAME))
        unknown = [n for n in chosen if n not in BY_NAME]
        if unknown:
            raise UsageError(
                f"unknown figure {', '.join(map(repr, unknown))}; choose from: {', '.join(BY_NAME)}"
            )
        params = resolve_params(chosen, args.settings, args.params)
        started = time.perf_counter()
        figures = {n: render(BY_NAME[n], params[n]) for n in chosen}  # all checked first
        out = Path(args.out)
        if out.exists() and not out.is_dir():
            raise UsageError(f"--out {out} exists and is not a folder")
    except UsageError as error:
        parser.print_usage(sys.stderr)
        print(f"interp-figures: error: {error}", file=sys.stderr)
        return 2

    out.mkdir(parents=True, exist_ok=True)
    formats = list(dict.fromkeys(args.formats))
    for name, figure in figures.items():
        start = time.perf_counter()
        paths = [out / f"{name}.{fmt}" for fmt in formats]
        for path, fmt in zip(paths, formats, strict=True):
            save(figure, path, fmt, args.dpi)
        shown = paths[0] if len(paths) == 1 else out / f"{name}.{{{','.join(formats)}}}"
        print(f"{name:<16} {shown}  {time.perf_counter() - start:.2f} s", flush=True)
    if not args.no_handout:
        start = time.perf_counter()
        write_handout(out / "handout.pdf", chosen, params)
        print(f"{'handout':<16} {out / 'handout.pdf'}  {time.perf_counter() - start:.2f} s")
    print(f"{len(figures)} figures in {time.perf_counter() - started:.1f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
