"""Memory is bounded by what the work will cost (issue 13).

Sizes beyond the documented limits are refused by name in ``tests/test_bad_input.py``; here,
within them, interpolation must not need memory in proportion to the image beyond its result.
"""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

import interp

FULL_VIEW = [[-1, -1, 0, 1], [3, -1, 0, 1], [-1, 3, 0, 1]]
MiB = 2**20


@pytest.mark.parametrize("mode", interp.MODES)
def test_interpolation_needs_little_beyond_its_result(mode):
    frags = interp.fragments(FULL_VIEW, np.zeros((3, 8)), [[0, 1, 2]], 1024, 1024)
    tracemalloc.start()
    try:
        values = interp.interpolate(frags, mode)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert values.nbytes == 64 * MiB  # 2**20 pixels, 8 attributes
    assert peak < values.nbytes + 100 * MiB, f"{peak / MiB:.0f} MiB"  # was 352 and 592 MiB
