"""The lessons: stored without outputs, and each runs top to bottom in a fresh kernel with no
error and no warning."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from helpers import run_lesson

LESSONS = sorted((Path(__file__).resolve().parent.parent / "lessons").glob("*.ipynb"))


def test_there_are_seven_lessons():
    assert [p.name[:3] for p in LESSONS] == [f"0{k}_" for k in range(1, 8)]


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.stem)
def test_stored_without_outputs(path):
    notebook = json.loads(path.read_text())
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            assert cell["outputs"] == [] and cell["execution_count"] is None, path.name


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.stem)
def test_runs_clean_in_a_fresh_kernel(path, tmp_path):
    notebook = run_lesson(path, tmp_path)
    problems = []
    for index, cell in enumerate(notebook.cells):
        for output in cell.get("outputs", []):
            if output["output_type"] == "error" or (
                output["output_type"] == "stream" and output["name"] == "stderr"
            ):
                problems.append((index, output.get("text") or output.get("evalue")))
    assert not problems, problems
    # Every exercise cell's checker says the reference answer is right.
    verdicts = [
        output["data"]["text/plain"]
        for cell in notebook.cells
        for output in cell.get("outputs", [])
        if output["output_type"] == "execute_result" and "check." in cell.source
    ]
    assert verdicts and all(v.startswith("✓") for v in verdicts), verdicts


@pytest.mark.parametrize("name", ["01_the_problem", "06_checkerboards"])
def test_without_ipympl_each_app_shows_one_static_figure(name, tmp_path):
    """With the plain inline backend, an app cell shows its figure once, as a PNG, and the
    controls after it."""
    notebook = run_lesson(next(p for p in LESSONS if p.stem == name), tmp_path, "inline")
    app_cells = [c for c in notebook.cells if c.cell_type == "code" and "apps." in c.source]
    assert app_cells
    for cell in app_cells:
        kinds = [sorted(o.get("data", {})) for o in cell.outputs]
        pngs = [k for k in kinds if "image/png" in k]
        widgets_shown = [k for k in kinds if "application/vnd.jupyter.widget-view+json" in k]
        assert len(pngs) == 1 and len(widgets_shown) == 1, kinds
