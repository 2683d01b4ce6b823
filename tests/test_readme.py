"""The README's promises: its code runs and its two commands exist."""

from __future__ import annotations

import itertools
import re
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text()


def test_readme_python_runs_and_shows_true_results():
    blocks = re.findall(r"```python\n(.*?)```", README, flags=re.S)
    assert len(blocks) >= 2
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)
        # "# -> value" lines state what the line above returns.
        lines = block.splitlines()
        for above, line in itertools.pairwise(lines):
            if line.startswith("# -> "):
                expression = above.split("#")[0].strip()
                assert np.isclose(eval(expression, namespace), float(line[5:])), expression
    assert namespace["covered"].any() and namespace["error"].max() > 0


def test_the_two_commands_exist():
    assert "make lessons" in README and "make test" in README
    makefile = (ROOT / "Makefile").read_text()
    assert re.search(r"^lessons:", makefile, flags=re.M)
    assert re.search(r"^test:", makefile, flags=re.M)
    assert "make test" in (ROOT / ".ci" / "run").read_text()
