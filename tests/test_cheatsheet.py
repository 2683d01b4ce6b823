"""The cheat sheet (lesson 10 and the last page of handout.pdf) says what the library computes."""

from __future__ import annotations

from pathlib import Path

import nbformat
import numpy as np
import pytest
from matplotlib.figure import Figure

import interp
from interp import cheatsheet, mipmap, plots

LESSON = (
    Path(interp.__file__).resolve().parent.parent / "source" / "lessons" / "10_cheat_sheet.ipynb"
)


def test_lesson_10_prints_the_cheat_sheet():
    text = "\n".join(c.source for c in nbformat.read(LESSON, as_version=4).cells)
    assert cheatsheet.markdown() in text


def test_the_formulas_are_right():
    """Each formula on the sheet, evaluated as written, against the library."""
    rng = np.random.default_rng(9)
    for _ in range(100):
        a1, a2 = rng.uniform(-2, 2, 2)
        w1, w2 = rng.uniform(0.2, 20, 2)
        s, t = rng.uniform(0, 1, 2)
        assert np.isclose(t * w2 / ((1 - t) * w1 + t * w2), interp.s_from_t(t, w1, w2))
        assert np.isclose(s * w1 / (s * w1 + (1 - s) * w2), interp.t_from_s(s, w1, w2))
        assert np.isclose(1 / ((1 - s) / w1 + s / w2), 1 / interp.lerp_inverse_w(w1, w2, s))
        a = ((1 - s) * a1 / w1 + s * a2 / w2) / ((1 - s) / w1 + s / w2)
        assert np.isclose(a, interp.lerp_perspective(a1, a2, w1, w2, s))
        if w1 != w2:
            assert np.isclose(np.sqrt(w2) / (np.sqrt(w1) + np.sqrt(w2)), interp.gap_peak(w1, w2)[0])
        n, f = sorted(rng.uniform(0.1, 50, 2))
        w = rng.uniform(n, f)
        assert np.isclose((f + n) / (f - n) - 2 * f * n / ((f - n) * w), interp.ndc_depth(w, n, f))
        b, ws = rng.dirichlet([1, 1, 1]), rng.uniform(0.2, 20, 3)
        assert np.allclose((b / ws) / np.sum(b / ws), interp.perspective_weights(b, ws))
        u_x, v_x, u_y, v_y = rng.normal(0, 0.01, 4)
        size = 2 ** rng.integers(4, 11)
        lam = np.log2(size * max(np.hypot(u_x, v_x), np.hypot(u_y, v_y)))
        assert np.isclose(lam, mipmap.level_of_detail(u_x, v_x, u_y, v_y, size))
    # clipping at the near plane: the formula finds the point with z = -w
    P = interp.perspective(60, 1.0, 0.5, 10.0)
    inside, outside = P @ [0.3, 0.1, -3.0, 1.0], P @ [0.2, 0.0, 0.2, 1.0]
    t = (inside[2] + inside[3]) / ((inside[2] + inside[3]) - (outside[2] + outside[3]))
    point = inside + t * (outside - inside)
    assert point[2] == pytest.approx(-point[3])


def test_the_linear_table_agrees_with_the_theory():
    linear = {q: yes == "yes" for q, yes, _ in cheatsheet.LINEAR}
    assert linear["1/w"] and linear["a/w"] and linear["NDC z, window z"]
    assert not linear["w (view depth, clip w)"] and not linear["a: u, v, a colour"]
    from interp import theory

    truth = theory.ground_truth(interp.Camera(height=1.0, pitch=25.0, yaw=30.0), 48, 36)
    for name, expected in (("1/w", True), ("u/w", True), ("NDC z", True), ("w", False)):
        assert (max(f.misfit for f in theory.misfits(truth, name)) < 1e-9) == expected


def test_the_page_draws():
    with plots.styled():
        page = Figure(figsize=(8.27, 11.69))
        cheatsheet.draw(page)
        page.canvas.draw()  # mathtext parses every formula
    assert len(page.texts) > 60
    assert all(0 < t.get_position()[1] < 1 for t in page.texts), "everything on the page"
