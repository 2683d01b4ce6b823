"""Grading with nbgrader, end to end (`make course`).

The course edition (interp.editions.course_edition) turns each exercise into nbgrader's answer
cell and a locked, graded test cell that asserts the checker's verdict. nbgrader itself then runs
the loop in its no-exchange layout: generate the release, autograde one right and one wrong
submission, score them, and write feedback that carries the checker's explanation.

nbgrader lives in .venv-nbgrader (make test installs it, with this package, which the notebooks
it grades import): its JupyterLab extension breaks Voilà's page, so it stays out of .venv.
"""

from __future__ import annotations

import html
import json
import re
import shutil
import subprocess
from pathlib import Path

import nbformat
import pytest

from interp import check, editions

from helpers import NBGRADER_BIN, nbgrader, need_nbgrader

ROOT = Path(__file__).resolve().parent.parent
SOURCES = editions.sources(ROOT)

#: The lesson the grading loop runs (one keeps it short: it is run once per submission).
GRADED = ["05_attributes"]


def cells(notebook: nbformat.NotebookNode, prefix: str) -> list[nbformat.NotebookNode]:
    return [
        c
        for c in notebook.cells
        if c.get("metadata", {}).get("nbgrader", {}).get("grade_id", "").startswith(prefix)
    ]


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: p.stem)
def test_each_exercise_is_an_answer_cell_and_a_locked_graded_test(path):
    source = nbformat.read(path, as_version=4)
    course = editions.course_edition(source)
    exercises = [c for c in source.cells if editions.is_exercise(c)]
    assert exercises or path.stem.endswith("cheat_sheet"), "a lesson without an exercise"
    tests = []
    for exercise in exercises:
        name, function = editions.CHECKER_CALL.search(exercise.source).groups()
        assert name in check.__all__
        index = next(i for i, c in enumerate(course.cells) if c.id == exercise.id)
        answer, test = course.cells[index], course.cells[index + 1]
        assert answer.metadata.nbgrader == exercise.metadata.nbgrader  # nbgrader's answer cell
        assert answer.source.rstrip().endswith(editions.END) and "check." not in answer.source
        grading = test.metadata.nbgrader
        assert grading["grade"] and grading["locked"] and not grading["solution"]
        assert grading["points"] == editions.EXERCISE_POINTS
        assert f"verdict = check.{name}({function})\nassert verdict, verdict" in test.source
        tests.append(test.id)
    # everything else is the source's, in order
    others = [c for c in course.cells if c.id not in tests]
    assert [c.id for c in others] == [c.id for c in source.cells]
    grade_ids = [c.metadata.nbgrader["grade_id"] for c in course.cells if "nbgrader" in c.metadata]
    assert len(set(grade_ids)) == len(grade_ids)


def test_write_course_keeps_the_teachers_files(tmp_path):
    course = tmp_path / "course"
    (course / "submitted" / "ada" / "lessons").mkdir(parents=True)
    (course / "gradebook.db").write_text("grades")
    (course / "source" / "lessons").mkdir(parents=True)
    (course / "source" / "lessons" / "00_removed.ipynb").write_text("{}")
    written = editions.write_course(ROOT, course)
    assert sorted(p.name for p in (course / "source" / "lessons").iterdir()) == [
        p.name for p in SOURCES
    ]
    assert course / "nbgrader_config.py" in written
    (course / "nbgrader_config.py").write_text("# the teacher's own settings\n")
    editions.write_course(ROOT, course)
    assert (course / "nbgrader_config.py").read_text() == "# the teacher's own settings\n"
    assert (course / "gradebook.db").read_text() == "grades"
    assert (course / "submitted" / "ada" / "lessons").is_dir()


def test_make_course_builds_and_releases_the_assignment():
    makefile = (ROOT / "Makefile").read_text()
    recipe = re.search(r"^course:.*\n((?:\t.+\n)+)", makefile, re.M).group(1)
    assert "-m interp.editions course --out $(COURSE)" in recipe
    assert "nbgrader generate_assignment lessons" in recipe
    assert "$(NBGRADER_VENV))/bin:$$PATH" in recipe  # nbgrader runs alembic from its bin


#: nbgrader's code stub in a released answer cell, with its indentation.
STUB = re.compile(r"( *)# YOUR CODE HERE\n\1raise NotImplementedError\(\)")


def submit(release: Path, to: Path, answers: dict[str, str]) -> None:
    """A student's submission: the released notebooks, the stub of each exercise named in
    ``answers`` (by its grade id) replaced by the answer; the other exercises left unanswered."""
    to.mkdir(parents=True)
    for path in sorted(release.glob("*.ipynb")):
        notebook = nbformat.read(path, as_version=4)
        for answer in cells(notebook, "exercise-"):
            if answer.metadata.nbgrader["grade_id"] in answers:
                lines = answers[answer.metadata.nbgrader["grade_id"]].split("\n")
                answer.source, replaced = STUB.subn(
                    lambda m, lines=lines: "\n".join(m[1] + line for line in lines),
                    answer.source,
                )
                assert replaced == 1, answer.source
        nbformat.write(notebook, to / path.name)


def solutions(name: str) -> dict[str, str]:
    """The teacher's solution body of each exercise of a lesson, unindented, by grade id."""
    source = nbformat.read(ROOT / "source" / "lessons" / f"{name}.ipynb", as_version=4)
    bodies = {}
    for exercise in [c for c in source.cells if editions.is_exercise(c)]:
        body = exercise.source.split(editions.BEGIN)[1].split(editions.END)[0]
        lines = [line for line in body.split("\n")[1:] if line.strip()]
        indent = min(len(line) - len(line.lstrip()) for line in lines)
        bodies[exercise.metadata.nbgrader["grade_id"]] = "\n".join(line[indent:] for line in lines)
    return bodies


#: The grade id of lesson 5's perspective_lerp exercise.
LERP = "exercise-05-09"
AFFINE = "return a1 + s * (a2 - a1)"  # the classic mistake: interpolating on the screen


def test_nbgrader_grades_a_right_and_a_wrong_submission(tmp_path):
    need_nbgrader()
    root = tmp_path / "repo"
    (root / "source" / "lessons").mkdir(parents=True)
    for name in GRADED:
        shutil.copy(ROOT / "source" / "lessons" / f"{name}.ipynb", root / "source" / "lessons")
    course = tmp_path / "course"
    editions.write_course(root, course)

    # 1. The release: nbgrader's own stubs, the graded test cells locked and kept.
    nbgrader("generate_assignment", "lessons", cwd=course)
    release = course / "release" / "lessons"
    for name in GRADED:
        released = nbformat.read(release / f"{name}.ipynb", as_version=4)
        text = json.dumps(released)
        assert "BEGIN SOLUTION" not in text and "YOUR CODE HERE" in text
        tests = cells(released, "check-")
        assert len(tests) == len(cells(released, "exercise-")) >= 1
        for test in tests:
            assert test.metadata.get("editable") is False
            assert test.metadata.get("deletable") is False

    # 2. Two submissions, in nbgrader's no-exchange layout: submitted/STUDENT/ASSIGNMENT/.
    right = {grade_id: body for name in GRADED for grade_id, body in solutions(name).items()}
    submit(release, course / "submitted" / "ada" / "lessons", right)
    # Bob answers the perspective_lerp exercise with the classic mistake and leaves the recap.
    assert (
        "def perspective_lerp("
        in nbformat.writes(nbformat.read(release / "05_attributes.ipynb", as_version=4))
        and LERP in right
    )
    submit(release, course / "submitted" / "bob" / "lessons", {LERP: AFFINE})

    # 3. Autograde, and read the scores from the gradebook.
    nbgrader("autograde", "lessons", cwd=course)
    script = (
        "import json\n"
        "from nbgrader.api import Gradebook\n"
        "with Gradebook('sqlite:///gradebook.db') as gb:\n"
        "    out = {}\n"
        "    for s in ('ada', 'bob'):\n"
        "        sub = gb.find_submission('lessons', s)\n"
        "        grades = [g for nb in sub.notebooks for g in nb.grades]\n"
        "        out[s] = {g.name: [g.score, g.max_score] for g in grades}\n"
        "print(json.dumps(out))\n"
    )
    result = subprocess.run(
        [str(NBGRADER_BIN / "python"), "-c", script],
        cwd=course,
        capture_output=True,
        text=True,
        check=True,
    )
    grades = json.loads(result.stdout)
    points = editions.EXERCISE_POINTS
    right_ids = {f"check-{grade_id.removeprefix('exercise-')}" for grade_id in right}
    assert set(grades["ada"]) >= right_ids and set(grades["bob"]) >= right_ids
    for check_id in right_ids:
        assert grades["ada"][check_id] == [points, points], (check_id, grades["ada"])
        assert grades["bob"][check_id] == [0, points], (check_id, grades["bob"])

    # 4. Feedback: the wrong submission's says what the checker says, the right one's says ✓.
    nbgrader("generate_feedback", "lessons", cwd=course)

    def feedback(student: str, name: str) -> str:
        page = (course / "feedback" / student / "lessons" / f"{name}.html").read_text()
        return html.unescape(re.sub(r"<[^>]+>", "", page))

    namespace: dict[str, object] = {}
    exec("def perspective_lerp(a1, a2, w1, w2, s):\n    " + AFFINE, namespace)
    verdict = check.perspective_lerp(namespace["perspective_lerp"])
    assert not verdict
    assert "AssertionError" in feedback("bob", "05_attributes")
    assert verdict.message in feedback("bob", "05_attributes")
    for name in GRADED:
        assert "✓" in feedback("ada", name) and "AssertionError" not in feedback("ada", name)


def test_course_command_line(tmp_path, capsys):
    assert editions.main(["course", "--root", str(ROOT), "--out", str(tmp_path)]) == 0
    assert sorted(p.name for p in (tmp_path / "source" / "lessons").iterdir()) == [
        p.name for p in SOURCES
    ]
    assert "nbgrader_config.py" in capsys.readouterr().out
