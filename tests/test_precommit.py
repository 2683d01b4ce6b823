"""The pre-commit hooks: local only (no hosted hook repository is fetched), ruff and nbstripout,
valid, passing on the repository as it is, and catching what they are there to catch.

The hooks' tools are installed by pre-commit from PyPI the first time (into .venv/.pre-commit,
a few seconds); later runs reuse them.
"""

from __future__ import annotations

import importlib.metadata
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parent.parent
CONFIG = ROOT / ".pre-commit-config.yaml"
PRE_COMMIT = Path(sys.executable).parent / "pre-commit"


def config() -> dict:
    return yaml.safe_load(CONFIG.read_text())


def hooks() -> dict[str, dict]:
    return {hook["id"]: hook for repo in config()["repos"] for hook in repo["hooks"]}


def test_only_local_hooks_ruff_and_nbstripout_keeping_ids():
    assert [repo["repo"] for repo in config()["repos"]] == ["local"]
    assert set(hooks()) == {"ruff-check", "ruff-format", "nbstripout"}
    assert "--keep-id" in hooks()["nbstripout"]["entry"].split()
    assert hooks()["nbstripout"]["types"] == ["jupyter"]


def test_the_hooks_ruff_is_the_ruff_of_make_lint():
    pins = {
        dependency
        for hook in hooks().values()
        for dependency in hook.get("additional_dependencies", [])
        if dependency.startswith("ruff")
    }
    assert pins == {f"ruff=={importlib.metadata.version('ruff')}"}
    pyproject = (ROOT / "pyproject.toml").read_text()
    assert re.search(rf'"{re.escape(pins.pop())}"', pyproject)


def run(*args: str, cwd: Path, check: bool = True) -> subprocess.CompletedProcess:
    env = {**os.environ, "PRE_COMMIT_HOME": str(ROOT / ".venv" / ".pre-commit")}
    env.update(GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@t", GIT_COMMITTER_NAME="t")
    env.update(GIT_COMMITTER_EMAIL="t@t")
    result = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)
    if check:
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return result


@pytest.fixture(scope="module")
def clone(tmp_path_factory) -> Path:
    """The repository's tracked files as they are in the working tree, in a new git repo."""
    if not PRE_COMMIT.exists():
        pytest.skip(f"no {PRE_COMMIT} (make test installs it)")
    if shutil.which("git") is None:
        pytest.skip("no git")
    listed = subprocess.run(
        ["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True, check=True
    )
    target = tmp_path_factory.mktemp("clone")
    for name in filter(None, listed.stdout.split("\0")):
        source = ROOT / name
        if source.is_file():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / name)
    shutil.copy2(CONFIG, target / CONFIG.name)  # also while it is not committed yet
    run("git", "init", "--quiet", cwd=target)
    run("git", "add", "-A", cwd=target)
    run("git", "commit", "--quiet", "--no-verify", "-m", "as it is", cwd=target)
    return target


def test_config_is_valid():
    if not PRE_COMMIT.exists():
        pytest.skip(f"no {PRE_COMMIT} (make test installs it)")
    run(str(PRE_COMMIT), "validate-config", str(CONFIG), cwd=ROOT)


def test_every_hook_passes_on_the_repository(clone):
    result = run(str(PRE_COMMIT), "run", "--all-files", cwd=clone, check=False)
    assert result.returncode == 0, result.stdout[-4000:]
    for hook in ("ruff check", "ruff format", "nbstripout --keep-id"):
        assert re.search(rf"^{re.escape(hook)}\.+Passed$", result.stdout, re.M), result.stdout
    status = run("git", "status", "--porcelain", cwd=clone).stdout
    assert status == "", f"a hook changed files: {status}"


def test_the_hooks_catch_outputs_and_lint(clone):
    lesson = clone / "lessons" / "01_the_problem.ipynb"
    notebook = json.loads(lesson.read_text())
    code = next(c for c in notebook["cells"] if c["cell_type"] == "code")
    code["execution_count"] = 7
    code["outputs"] = [{"output_type": "stream", "name": "stdout", "text": ["ran\n"]}]
    lesson.write_text(json.dumps(notebook, indent=1) + "\n")
    sloppy = clone / "interp" / "sloppy.py"
    sloppy.write_text("import os\nx=1\n")
    run("git", "add", "-A", cwd=clone)
    try:
        result = run(str(PRE_COMMIT), "run", "--all-files", cwd=clone, check=False)
        assert result.returncode != 0
        assert re.search(r"^ruff check\.+Failed$", result.stdout, re.M), result.stdout
        assert "F401" in result.stdout  # `import os` unused
        assert re.search(r"^nbstripout --keep-id\.+Failed$", result.stdout, re.M)
        stripped = json.loads(lesson.read_text())
        assert [c["id"] for c in stripped["cells"]] == [c["id"] for c in notebook["cells"]]
        code = next(c for c in stripped["cells"] if c["cell_type"] == "code")
        assert code["outputs"] == [] and code["execution_count"] is None
        assert "x = 1" in sloppy.read_text()  # ruff format rewrote it
    finally:
        run("git", "checkout", "--", "lessons", cwd=clone)
        sloppy.unlink()
        run("git", "add", "-A", cwd=clone)
