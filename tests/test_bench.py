"""The benchmark runs and prints every figure the issue asks for."""

from __future__ import annotations

import re

from interp import bench


def test_benchmark_prints_all_figures(capsys):
    bench.main(["--repeat", "1"])
    out = capsys.readouterr().out
    for size in bench.SIZES:
        for mode in ("perspective", "affine"):
            assert re.search(rf"{size}²\s+{mode}\s+\d+\.\d+", out)
    assert out.count("slider step 512²") == 4  # filtered and nearest, both allocator settings
    assert "[default allocator]" in out and "keep_freed_memory" in out
    assert out.count("checkerboard app") == 1  # with the allocator setting apps turn on
    assert out.index("checkerboard app") > out.index("keep_freed_memory")
    if "no OpenGL" not in out:  # the target: rasterize against llvmpipe at 512², both modes
        verdict = r"perspective \d+\.\d+x, affine \d+\.\d+x \(target at most 1x: (ok|over)\)"
        assert len(re.findall(verdict, out)) == 1  # with the default allocator only
        assert out.index("target at most 1x") < out.index("keep_freed_memory")
