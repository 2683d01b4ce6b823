"""The lessons, in both editions, made from one source.

- source/lessons/: every lesson has its exercises with their solutions (at least one, and the recap
  questions last), and every "Try this" prompt a written answer;
- lessons/ (the student edition, committed) is exactly what interp.editions makes of the source,
  stored without outputs; it runs top to bottom in a fresh kernel with no error and no warning, each
  checker answering "not written yet";
- the teacher edition runs with every checker saying ✓, and exports to HTML;
- nbgrader takes the source as an assignment unchanged, and makes the same exercise cells.
"""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import nbformat
import pytest
from nbconvert import HTMLExporter

from interp import check, editions

from helpers import nbgrader, need_nbgrader, run_lesson

ROOT = Path(__file__).resolve().parent.parent
LESSONS = sorted((ROOT / "lessons").glob("*.ipynb"))
SOURCES = editions.sources(ROOT)

#: The lessons: nine, and the cheat sheet (lesson 10, which has no "Try this" prompts).
COUNT = 10
#: "Try this" prompts across the lessons.
PROMPTS = 44


def source(path: Path) -> nbformat.NotebookNode:
    return nbformat.read(path, as_version=4)


def bullets(markdown: str) -> int:
    return len(re.findall(r"^- ", markdown, re.M))


def test_there_are_ten_lessons_from_ten_sources():
    assert [p.name[:3] for p in LESSONS] == [f"{k:02d}_" for k in range(1, COUNT + 1)]
    assert [p.name for p in SOURCES] == [p.name for p in LESSONS]


def test_the_student_edition_is_what_the_generator_makes():
    assert editions.stale_student(ROOT) == [], "run `python -m interp.editions student`"


def exercises(notebook: nbformat.NotebookNode) -> list[str]:
    return [c.source for c in notebook.cells if editions.is_exercise(c)]


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.stem)
def test_every_lesson_has_solved_exercises_and_every_prompt_an_answer(path):
    notebook = source(path)
    assert len(exercises(notebook)) >= 1
    for exercise in exercises(notebook):
        assert exercise.count(editions.BEGIN) == exercise.count(editions.END) == 1
        solution = exercise.split(editions.BEGIN)[1].split(editions.END)[0]
        assert "return" in solution
        assert re.search(r"\ncheck\.\w+\(\w+\)$", exercise), "the checker call ends the cell"
    lesson = int(path.name[:2])
    assert exercises(notebook)[-1].endswith(f"check.recap_{lesson}(my_answers)"), "recap last"
    # every list of prompts is followed by an answer cell with one answer per prompt
    prompts = [i for i, c in enumerate(notebook.cells) if "**Try this**" in c.source]
    answers = [i for i, c in enumerate(notebook.cells) if editions.is_answer(c)]
    assert len(prompts) == len(answers) >= (0 if lesson == COUNT else 1)
    ends = [*prompts[1:], len(notebook.cells)][: len(prompts)]
    for p, a, after in zip(prompts, answers, ends, strict=True):
        assert p < a < after
        asked = bullets(notebook.cells[p].source.split("**Try this**")[1])
        answer = notebook.cells[a].source
        assert answer.count(editions.BEGIN) == answer.count(editions.END) == 1
        assert bullets(answer) == asked, f"{asked} prompts, {bullets(answer)} answers"
    # markers only where nbgrader expects them
    for cell in notebook.cells:
        if not editions.is_solution(cell):
            assert editions.BEGIN not in cell.source and editions.END not in cell.source


def test_every_prompt_is_counted():
    total = 0
    for path in SOURCES:
        for cell in source(path).cells:
            if "**Try this**" in cell.source:
                total += bullets(cell.source.split("**Try this**")[1])
    assert total == PROMPTS


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.stem)
def test_student_edition_is_blank_and_stored_without_outputs(path):
    notebook = json.loads(path.read_text())
    ids = [cell["id"] for cell in notebook["cells"]]
    assert len(set(ids)) == len(ids) and all(i.startswith(path.name[:2] + "-") for i in ids), ids
    code = [cell for cell in notebook["cells"] if cell["cell_type"] == "code"]
    assert "".join(code[0]["source"]).startswith("%matplotlib widget")
    for cell in code:
        assert cell["outputs"] == [] and cell["execution_count"] is None, path.name
    text = path.read_text()
    assert "SOLUTION" not in text and "**Answers**" not in text and "nbgrader" not in text
    blank = [c for c in code if "raise NotImplementedError()" in "".join(c["source"])]
    solved = exercises(source(ROOT / "source" / "lessons" / path.name))
    assert len(blank) == len(solved)
    for exercise in blank:
        assert '"""' in "".join(exercise["source"]), "a docstring says what to return"
    # no line of any solution is printed anywhere in the student edition
    student_text = "\n".join("".join(c["source"]) for c in notebook["cells"])
    for solution in solved:
        body = solution.split(editions.BEGIN)[1].split(editions.END)[0]
        for line in body.strip().splitlines():
            assert re.sub(r"\s", "", line) not in re.sub(r"\s", "", student_text), line


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: p.stem)
def test_student_edition_runs_clean_and_says_not_written_yet(path, tmp_path):
    notebook = run_lesson(path, tmp_path)
    assert not editions.errors(notebook)
    verdicts = editions.verdicts(notebook)
    solved = exercises(source(ROOT / "source" / "lessons" / path.name))
    assert verdicts == ["… " + check.NOT_WRITTEN] * len(solved), verdicts


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.stem)
def test_teacher_edition_runs_with_every_exercise_right(path, tmp_path):
    notebook = editions.teacher_edition(source(path))
    editions.run(notebook, tmp_path)
    assert not editions.errors(notebook)
    verdicts = editions.verdicts(notebook)
    assert len(verdicts) == len(exercises(source(path))), verdicts
    assert all(v.startswith("✓") for v in verdicts), verdicts
    assert notebook.cells[1].source.startswith("%matplotlib widget"), "kept live for a rerun"
    html, _ = HTMLExporter().from_notebook_node(notebook)
    assert "Teacher edition" in html and ("<img" in html or int(path.name[:2]) == COUNT)
    answers = [c.source for c in notebook.cells if c.source.startswith("**Answers**")]
    assert answers or int(path.name[:2]) == COUNT
    assert all(editions.BEGIN not in a for a in answers)
    for a in answers:
        assert a.split("\n- ")[1].strip(), "a written answer"


def test_build_teacher_writes_notebooks_and_html(tmp_path):
    """The `make teacher` code path, on the shortest lesson."""
    root = tmp_path / "repo"
    (root / "source" / "lessons").mkdir(parents=True)
    shutil.copy(SOURCES[0], root / "source" / "lessons")
    written = editions.build_teacher(root, root / "teacher")
    assert sorted(p.name for p in written) == [SOURCES[0].stem + ".html", SOURCES[0].name]
    executed = source(root / "teacher" / SOURCES[0].name)
    assert editions.verdicts(executed)[0].startswith("✓")
    # Every figure in the HTML page carries its alt text: the figure's title and key result.
    page = (root / "teacher" / SOURCES[0].with_suffix(".html").name).read_text()
    images = re.findall(r"<img [^>]*>", page)
    assert images and all(re.search(r'alt="[^"]{20,}"', image) for image in images), images
    assert 'alt="The midpoint mismatch. M, the middle of AB, shows at s = 0.800' in page
    assert "No description has been provided" not in page  # nbconvert's placeholder


def test_generator_command_line(tmp_path, capsys):
    root = tmp_path / "repo"
    shutil.copytree(ROOT / "source", root / "source")
    (root / "lessons").mkdir()
    assert editions.main(["check", "--root", str(root)]) == 1
    assert editions.main(["student", "--root", str(root)]) == 0
    assert editions.main(["check", "--root", str(root)]) == 0
    for path in LESSONS:
        assert (root / "lessons" / path.name).read_text() == path.read_text()
    assert "matches" in capsys.readouterr().out


def test_nbgrader_generates_the_assignment_from_the_sources(tmp_path):
    need_nbgrader()
    shutil.copytree(ROOT / "source", tmp_path / "source")
    shutil.copy(ROOT / "nbgrader_config.py", tmp_path)
    nbgrader("generate_assignment", "lessons", "--force", cwd=tmp_path, timeout=300)
    for path in SOURCES:
        released = source(tmp_path / "release" / "lessons" / path.name)
        student = editions.student_edition(source(path))
        mine = {c.id: c.source for c in student.cells}
        for cell in released.cells:
            assert "SOLUTION" not in cell.source
            if editions.is_exercise(cell):
                assert cell.source == mine[cell.id], "nbgrader and interp.editions agree"
            elif editions.is_answer(cell):
                assert "YOUR ANSWER HERE" in cell.source
            else:
                assert cell.source == mine[cell.id]


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
