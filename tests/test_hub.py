"""JupyterHub with nbgitpuller: a student's answers survive the teacher's updates.

The README tells teachers to hand out an nbgitpuller link. This runs nbgitpuller's own pull (from
.venv-nbgrader, where make test installs it) against local git repositories, offline: a student
clones the lessons, answers an exercise and runs the notebook; the teacher then edits the lessons
and adds one; the student's next click on the link merges.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import nbformat
import pytest

from interp import editions

ROOT = Path(__file__).resolve().parent.parent
PYTHON = ROOT / ".venv-nbgrader" / "bin" / "python"
LESSON = "05_attributes.ipynb"
GIT = ["git", "-c", "user.name=Teacher", "-c", "user.email=teacher@example.edu"]


def git(*args: str, cwd: Path) -> None:
    subprocess.run([*GIT, *args], cwd=cwd, check=True, capture_output=True)


def pull(upstream: Path, student: Path) -> None:
    """What the student's click on the nbgitpuller link runs on the hub."""
    env = {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull}  # no identity of the student's
    result = subprocess.run(
        [str(PYTHON), "-m", "nbgitpuller.pull", upstream.as_uri(), "main", str(student)],
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]


def exercise(notebook: nbformat.NotebookNode) -> nbformat.NotebookNode:
    return next(
        c
        for c in notebook.cells
        if "raise NotImplementedError" in c.source or "return ((1" in c.source
    )


@pytest.fixture
def hub(tmp_path):
    if not PYTHON.exists():
        if os.environ.get("CI"):
            pytest.fail(f"CI must have {PYTHON} with nbgitpuller (make test installs it)")
        pytest.skip(f"no {PYTHON} (make test installs it, with nbgitpuller)")
    if shutil.which("git") is None:
        pytest.skip("no git")
    upstream = tmp_path / "interp"
    shutil.copytree(ROOT / "lessons", upstream / "lessons")
    git("init", "--quiet", "--initial-branch=main", cwd=upstream)
    git("add", ".", cwd=upstream)
    git("commit", "--quiet", "-m", "the lessons", cwd=upstream)
    return upstream, tmp_path / "home" / "interp"


ANSWER = "    return ((1 - s) * a1 / w1 + s * a2 / w2) / ((1 - s) / w1 + s / w2)"


def test_nbgitpuller_keeps_the_students_answers_and_brings_the_teachers_updates(hub):
    upstream, student = hub
    pull(upstream, student)  # the first click clones
    mine = student / "lessons" / LESSON
    assert mine.read_text() == (upstream / "lessons" / LESSON).read_text()

    # The student answers the exercise and runs every cell: sources, counts and outputs change.
    notebook = nbformat.read(mine, as_version=4)
    cell = exercise(notebook)
    cell.source = cell.source.replace(
        "    # YOUR CODE HERE\n    raise NotImplementedError()", ANSWER
    )
    assert ANSWER in cell.source
    for count, code in enumerate((c for c in notebook.cells if c.cell_type == "code"), 1):
        code.execution_count = count
    cell.outputs = [
        nbformat.v4.new_output(
            "execute_result",
            {"text/plain": "✓ perspective_lerp: right"},
            execution_count=cell.execution_count,
        )
    ]
    nbformat.write(notebook, mine)

    # The teacher fixes a sentence in another section of the same lesson, edits another
    # lesson, adds a lesson, and pushes.
    theirs = nbformat.read(upstream / "lessons" / LESSON, as_version=4)
    prose = next(c for c in theirs.cells if c.source.startswith("## Across a triangle"))
    prose.source += "\n\nA sentence the teacher added."
    nbformat.write(theirs, upstream / "lessons" / LESSON)
    first = upstream / "lessons" / "01_the_problem.ipynb"
    other = nbformat.read(first, as_version=4)
    other.cells[0].source += "\n\nAnother sentence the teacher added."
    nbformat.write(other, first)
    shutil.copy(first, upstream / "lessons" / "08_new_lesson.ipynb")
    git("add", ".", cwd=upstream)
    git("commit", "--quiet", "-m", "updates", cwd=upstream)

    pull(upstream, student)  # the next click merges
    merged = nbformat.read(mine, as_version=4)
    nbformat.validate(merged)
    kept = exercise(merged)
    assert ANSWER in kept.source, "the student's answer is kept"
    assert kept.outputs and "✓" in kept.outputs[0]["data"]["text/plain"]
    assert "A sentence the teacher added." in "\n".join(c.source for c in merged.cells)
    assert "Another sentence" in (student / "lessons" / "01_the_problem.ipynb").read_text()
    assert (student / "lessons" / "08_new_lesson.ipynb").exists()


def test_where_both_changed_the_same_lines_the_student_wins(hub):
    """nbgitpuller merges with git's `-Xours`: a teacher's change to the very lines a student
    edited (here, the exercise's stub) gives way, and the student's answer stays."""
    upstream, student = hub
    pull(upstream, student)
    mine = student / "lessons" / LESSON
    notebook = nbformat.read(mine, as_version=4)
    cell = exercise(notebook)
    cell.source = cell.source.replace(
        "    # YOUR CODE HERE\n    raise NotImplementedError()", ANSWER
    )
    nbformat.write(notebook, mine)

    theirs = nbformat.read(upstream / "lessons" / LESSON, as_version=4)
    stub = exercise(theirs)
    stub.source = stub.source.replace(
        "    # YOUR CODE HERE", "    # YOUR CODE HERE (a teacher's new hint)"
    )
    nbformat.write(theirs, upstream / "lessons" / LESSON)
    git("commit", "--quiet", "-am", "a hint in the exercise", cwd=upstream)

    pull(upstream, student)
    merged = nbformat.read(mine, as_version=4)
    assert ANSWER in exercise(merged).source
    assert "a teacher's new hint" not in exercise(merged).source
    assert editions.CODE_STUB not in exercise(merged).source
