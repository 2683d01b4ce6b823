"""The course on one page: the formulas, what is linear on the screen, the notation of each source,
and the classic mistakes.

One text, two readers: lesson 10 (``10_cheat_sheet.ipynb``) prints it as Markdown (its formulas
are the strings below, and ``tests/test_cheatsheet.py`` checks that the notebook holds each one
and that each formula is right), and ``interp-figures`` draws it as a page of ``handout.pdf``
with :func:`draw`. The formulas are written in the part of TeX that both MathJax (the notebook)
and matplotlib's mathtext (the handout) understand.
"""

from __future__ import annotations

from matplotlib.figure import Figure

#: (what, formula): the formulas of the course, in the kit's notation.
FORMULAS: list[tuple[str, str]] = [
    ("projection onto the image plane at distance d", r"$p = d\,x/w$, with $w = -z$"),
    ("where the point at t shows (CS5500)", r"$s(t) = \dfrac{t\,w_2}{(1-t)\,w_1 + t\,w_2}$"),
    ("which point shows at s", r"$t(s) = \dfrac{s\,w_1}{s\,w_1 + (1-s)\,w_2}$"),
    ("the gap |t - s| peaks at", r"$s^* = \dfrac{\sqrt{w_2}}{\sqrt{w_1} + \sqrt{w_2}}$"),
    ("depth (Low, eq. 12)", r"$\dfrac{1}{w(s)} = \dfrac{1-s}{w_1} + \dfrac{s}{w_2}$"),
    (
        "an attribute (Low, eq. 16)",
        r"$a(s) = \dfrac{(1-s)\,a_1/w_1 + s\,a_2/w_2}{(1-s)/w_1 + s/w_2}$",
    ),
    (
        "NDC z (interp.perspective; n, f the near and far planes)",
        r"$z_\mathrm{ndc} = \dfrac{f+n}{f-n} - \dfrac{2\,f\,n}{(f-n)\,w}$",
    ),
    (
        "triangle weights (OpenGL 4.6, eq. 14.9)",
        r"$\lambda_i = \dfrac{b_i/w_i}{b_0/w_0 + b_1/w_1 + b_2/w_2}$, $a = \sum_i \lambda_i\,a_i$",
    ),
    ("clipping at the near plane z = -w", r"$t_C = \dfrac{z_1 + w_1}{(z_1 + w_1) - (z_2 + w_2)}$"),
    (
        "level of detail, u_x = du/dx, N x N texels",
        r"$\lambda = \log_2\left(N\,\max\left(\sqrt{u_x^2 + v_x^2},\ "
        r"\sqrt{u_y^2 + v_y^2}\right)\right)$",
    ),
]

#: (quantity, linear on the screen?, why).
LINEAR: list[tuple[str, str, str]] = [
    ("w (view depth, clip w)", "no", "1/w is"),
    ("1/w", "yes", "the plane equation"),
    ("NDC z, window z", "yes", "affine in 1/w"),
    ("a: u, v, a colour", "no", "linear in space, not on the screen"),
    ("a/w", "yes", "like 1/w"),
    ("t, the object parameter", "no", "t(s) is a curve"),
    ("b, the screen barycentrics", "yes", "by definition"),
    ("lambda, OpenGL's weights", "no", "the object-space barycentrics"),
]

#: (source, screen parameter, object parameter, depth, ends numbered, notes).
NOTATION: list[tuple[str, str, str, str, str, str]] = [
    ("this kit", "s", "t", "w = -z (clip w)", "1, 2", "looks down -z; NDC z in [-1, 1]"),
    ("Low (2002)", "s", "t", "Z", "1, 2", "looks down +z; image plane at d"),
    ("CS5500 (2006)", "s", "t", "w", "1, 2", "any matrix M"),
    ("Lengyel", "t", "(none)", "z", "1, 2", "his t is the screen parameter; plane at z = -e"),
    ("Ek (2019)", "q", "(none)", "z", "0, 1", "attribute c"),
    (
        "rasterization blog",
        "(none)",
        "(none)",
        "z_view",
        "0, 1, 2",
        "t_i: any affine weights; Direct3D: NDC z in [0, 1]",
    ),
    ("OpenGL 4.6", "a, b, c (eq. 14.9)", "(none)", "w", "a, b, c", "texture coords (s, t)!"),
]

#: (mistake, what it gives, the fix).
MISTAKES: list[tuple[str, str]] = [
    ("interpolating a itself on the screen", "affine: right only at equal depths"),
    ("dividing by window z (the depth buffer's)", "window z is not 1/w: use the interpolated 1/w"),
    ("multiplying a/w by a screen-linear w", "w is not linear: divide by the interpolated 1/w"),
    ("giving a clip vertex its old vertex's attribute", "it needs a_1 + t_C (a_2 - a_1)"),
    ("dividing by w in the vertex shader (w = 1)", "smooth becomes noperspective"),
    ("interpolating NDC z to find where to clip", "clip in clip space: z + w is linear"),
    ("sampling a texture at one point per pixel", "far away it aliases: filter (a mipmap at λ)"),
]


def markdown() -> str:
    """The cheat sheet as the Markdown of lesson 10."""
    lines = ["## Formulas", "", "| what | formula |", "| --- | --- |"]
    lines += [f"| {what} | {formula} |" for what, formula in FORMULAS]
    lines += [
        "",
        "## Linear on the screen?",
        "",
        "| quantity | linear? | why |",
        "| --- | --- | --- |",
    ]
    lines += [f"| {q} | {yes} | {why} |" for q, yes, why in LINEAR]
    lines += [
        "",
        "## Notation across the sources",
        "",
        "| source | screen parameter | object parameter | depth | ends | notes |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    lines += ["| " + " | ".join(row) + " |" for row in NOTATION]
    lines += ["", "## Classic mistakes", "", "| mistake | what goes wrong |", "| --- | --- |"]
    lines += [f"| {mistake} | {fix} |" for mistake, fix in MISTAKES]
    return "\n".join(lines)


def draw(page: Figure) -> None:
    """Draw the cheat sheet on a page (an A4 figure), with the style's fonts."""
    y = 0.95
    page.text(
        0.08, y, "Cheat sheet: perspective-correct interpolation", size="x-large", weight="bold"
    )

    def heading(text: str) -> None:
        nonlocal y
        y -= 0.035
        page.text(0.08, y, text, size="large", weight="bold")
        y -= 0.012

    heading("Formulas")
    for k, (what, formula) in enumerate(FORMULAS):
        y -= 0.037 if k else 0.025  # row centres; the formulas are about 0.035 tall
        page.text(0.08, y, what, size="small", va="center")
        page.text(0.42, y, formula, size="large", va="center")
    heading("Linear on the screen?")
    for quantity, yes, why in LINEAR:
        y -= 0.016
        page.text(0.08, y, quantity, size="small")
        page.text(0.42, y, yes, size="small", weight="bold")
        page.text(0.5, y, why, size="small")
    heading("Notation across the sources")
    columns = (0.08, 0.22, 0.37, 0.47, 0.62, 0.7)
    for k, row in enumerate([("source", "screen", "object", "depth", "ends", "notes"), *NOTATION]):
        y -= 0.016
        for x, cell in zip(columns, row, strict=True):
            page.text(x, y, cell, size="x-small", weight="bold" if k == 0 else "normal")
    heading("Classic mistakes")
    for mistake, fix in MISTAKES:
        y -= 0.016
        page.text(0.08, y, mistake, size="x-small")
        page.text(0.5, y, fix, size="x-small")
