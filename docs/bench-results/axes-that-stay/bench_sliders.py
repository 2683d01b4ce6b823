"""Lesson 4's near plane and lesson 5's a1, stepped and dragged by the browser benchmark.

Run from anywhere: ``/work/main/.venv/bin/python bench_sliders.py [--tree DIR]``; the
benchmark's own options follow.
"""

import sys

sys.path.insert(0, "/work/main/tests")
import bench_browser as bb

bb.STEP_PARAM["depth"] = "near"
bb.STEP_PARAM["attributes"] = "a1"
ONLY = ["--only", "depth", "attributes", "--no-dpr2", "--no-endpoints", "--no-floor"]
sys.exit(bb.main([*ONLY, *sys.argv[1:]]))
