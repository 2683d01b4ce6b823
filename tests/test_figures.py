"""interp-figures: every figure in every format, deterministic, careful on the command line."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib.figure
import numpy as np
import pytest

from interp import figures
from interp.plots import AFFINE, CORRECT

ALL_FILES = {f"{name}.{fmt}" for name in figures.FIGURES for fmt in figures.FORMATS}


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """Everything, written once at a low PNG resolution to keep the suite quick."""
    out = tmp_path_factory.mktemp("handouts")
    assert figures.main(["--out", str(out), "--dpi", "60"]) == 0
    return out


def test_every_app_figure_is_exported_and_covers_every_lesson():
    from interp import apps

    assert {name.replace("-", "_") for name in figures.FIGURES} == set(apps.ALL)
    for figure_class in figures.FIGURES.values():
        assert figure_class.caption.endswith(f"(Lesson {figure_class.lesson})")
    # lessons 1 to 9; lesson 10, the cheat sheet, has no figure
    assert {f.lesson for f in figures.FIGURES.values()} == set(range(1, 10))


def test_every_figure_in_every_format(exported):
    assert ALL_FILES | {"handout.pdf"} <= {p.name for p in exported.iterdir()}
    for name, figure_class in figures.FIGURES.items():
        pdf = (exported / f"{name}.pdf").read_bytes()
        assert pdf.startswith(b"%PDF") and b"/FontFile2" in pdf  # TrueType fonts embedded
        svg = ET.parse(exported / f"{name}.svg").getroot()
        texts = [e for e in svg.iter() if e.tag.endswith("text")]
        assert texts, f"{name}.svg has no real text"
        from PIL import Image

        with Image.open(exported / f"{name}.png") as png:
            width, height = figure_class.print_size
            assert png.size == (round(width * 60), round(height * 60))


def test_no_temporary_files_left(exported):
    assert not [p for p in exported.iterdir() if p.name.startswith(".")]


def test_handout_has_a_cover_a_page_per_figure_and_the_cheat_sheet(exported):
    pdf = (exported / "handout.pdf").read_bytes()
    pages = pdf.count(b"/Type /Page") - pdf.count(b"/Type /Pages")
    assert pages == 2 + len(figures.FIGURES)


def test_sizes_fit_a_column_of_a4_or_letter():
    for figure_class in figures.FIGURES.values():
        assert figure_class.print_size[0] <= figures.WIDE <= 6.5
        assert figure_class.print_size[1] <= 9


def test_deterministic_bytes(exported, tmp_path):
    assert figures.main(["--out", str(tmp_path), "--dpi", "60"]) == 0
    for name in ALL_FILES | {"handout.pdf"}:
        assert (tmp_path / name).read_bytes() == (exported / name).read_bytes(), name


def test_source_date_epoch_is_honoured(tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")  # 2023-11-14
    assert (
        figures.main(
            [
                "--out",
                str(tmp_path),
                "--only",
                "st-mapping",
                "--format",
                "pdf",
                "svg",
                "--no-handout",
            ]
        )
        == 0
    )
    assert b"D:20231114" in (tmp_path / "st-mapping.pdf").read_bytes()
    assert "2023-11-14" in (tmp_path / "st-mapping.svg").read_text()


def test_without_source_date_epoch_no_date(exported):
    assert b"CreationDate" not in (exported / "the-problem.pdf").read_bytes()
    assert "<dc:date>" not in (exported / "the-problem.svg").read_text()


def test_progress_lines(tmp_path, capsys):
    assert (
        figures.main(
            [
                "--out",
                str(tmp_path),
                "--only",
                "st-mapping",
                "depth",
                "--format",
                "png",
                "--dpi",
                "30",
            ]
        )
        == 0
    )
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split()[:2] == ["st-mapping", str(tmp_path / "st-mapping.png")]
    assert lines[0].endswith(" s") and lines[1].startswith("depth")
    assert lines[2].startswith("handout")


def test_list_names_every_figure(capsys):
    assert figures.main(["--list"]) == 0
    out = capsys.readouterr().out
    for name, figure_class in figures.FIGURES.items():
        assert name in out
        for param, spec in figure_class.PARAMS.items():
            assert f"{param}={spec.default}  in {spec.range}" in out
    assert "pitch=15.0  in [-10, 90]" in out


def test_help_has_an_example():
    result = subprocess.run(
        [sys.executable, "-m", "interp.figures", "--help"],
        capture_output=True,
        text=True,
        check=True,
    )
    assert "example:" in result.stdout and "--set" in result.stdout


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--only", "checkerbords"], "unknown figure 'checkerbords'"),
        (["--set", "pitch=steep"], "--set pitch: pitch must be a number, got 'steep'"),
        (["--set", "pitch=400"], "pitch must be in [-10, 90], got 400"),
        (["--set", "quads=0", "--only", "checkerboards"], "quads must be in [1, 32], got 0"),
        (["--set", "quads=2.5", "--only", "clipping"], "quads must be a whole number, got 2.5"),
        (["--set", "samples=1e9"], "samples must be in [1, 32]"),
        (["--set", "samples=-5"], "samples must be in [1, 32], got -5"),
        (["--set", "samples=" + "9" * 5000], "samples must be a finite number of at most 40"),
        (["--set", "pitch=nan"], "pitch must be a finite number"),
        (["--set", "near=0"], "near must be in [0.001, 1], got 0"),
        (["--set", "zoom=2"], "no figure being drawn has a parameter 'zoom'"),
        (["--set", "depth.pitch=2"], "no figure being drawn has a parameter 'pitch'"),
        (["--set", "clipping.quads=3", "--only", "depth"], "'clipping' is not among the figures"),
        (["--set", "pitch"], "--set takes KEY=VALUE"),
        (["--dpi", "0"], "--dpi must be between 10 and 1200"),
        (["--set", "depth.buffer=fixed16"], "buffer must be one of float32, fixed24"),
        (["--set", "resolution=100000 x 3"], "resolution must be one of 160 x 120"),
        (["--format", "jpg"], "invalid choice: 'jpg'"),
    ],
)
def test_bad_usage_fails_before_writing(tmp_path, capsys, argv, words):
    out = tmp_path / "out"
    # argparse itself rejects a bad --format (exit 2 through SystemExit)
    with pytest.raises(SystemExit) if "--format" in argv else contextlib.nullcontext():
        status = figures.main(["--out", str(out), *argv])
        assert status == 2
    assert words in capsys.readouterr().err
    assert not out.exists(), "something was written"


@pytest.mark.parametrize(
    "content, words",
    [
        ("{not json", "is not valid JSON"),
        ("[1, 2]", "must hold a JSON object"),
        ('{"pitch": "up"}', "pitch must be a number, got 'up'"),
        ('{"checkerboards": {"frequency": true}}', "frequency must be a number, got bool"),
        ('{"pitch": 1e999}', "pitch must be finite"),
        ('{"samples": ' + "9" * 5000 + "}", "nested too deeply or holds a huge number"),
        ("[" * 100000 + "]" * 100000, "nested too deeply or holds a huge number"),
    ],
)
def test_bad_params_file(tmp_path, capsys, content, words):
    file = tmp_path / "params.json"
    file.write_text(content)
    assert figures.main(["--out", str(tmp_path / "out"), "--params", str(file)]) == 2
    assert words in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_missing_params_file(tmp_path, capsys):
    assert figures.main(["--out", str(tmp_path / "o"), "--params", str(tmp_path / "no")]) == 2
    assert "cannot read --params file" in capsys.readouterr().err


def test_params_file_and_set_apply(tmp_path):
    file = tmp_path / "params.json"
    file.write_text(json.dumps({"pitch": 30, "checkerboards": {"frequency": 12}}))
    params = figures.resolve_params(["checkerboards", "colour-quad"], ["yaw=10"], str(file))
    assert params["checkerboards"]["resolution"] == "320 x 240"  # a default untouched
    assert params["checkerboards"]["pitch"] == 30.0 and params["colour-quad"]["pitch"] == 30.0
    assert params["checkerboards"]["frequency"] == 12.0
    assert params["colour-quad"]["yaw"] == 10.0


def test_existing_folder_is_reused_not_wiped(tmp_path):
    keep = tmp_path / "notes.txt"
    keep.write_text("mine")
    assert (
        figures.main(["--out", str(tmp_path), "--only", "depth", "--format", "svg", "--no-handout"])
        == 0
    )
    assert keep.read_text() == "mine" and (tmp_path / "depth.svg").exists()


def test_checkerboard_content_tilted_and_straight_down():
    checker = figures.FIGURES["checkerboards"]
    tilted = figures.render(checker, {**checker.defaults(), "pitch": 20.0})
    panels = tilted.axes[0].images[0], tilted.axes[1].images[0]
    affine, correct = (np.asarray(p.get_array()) for p in panels)
    drawn = correct != 0.5
    differ = np.mean(np.abs(affine - correct)[drawn] > 0.5)
    assert differ > 0.05, "a tilted camera should bend the affine checkerboard"
    down = figures.render(
        checker, {**checker.defaults(), "pitch": 90.0, "distance": 0.0, "height": 3.0}
    )
    affine, correct = (np.asarray(ax.images[0].get_array()) for ax in down.axes[:2])
    np.testing.assert_allclose(affine, correct, atol=1e-9)


def test_affine_and_correct_differ_without_colour():
    for key in ("linestyle", "marker"):
        assert AFFINE[key] != CORRECT[key]


def test_console_script_is_declared():
    text = (Path(__file__).resolve().parent.parent / "pyproject.toml").read_text()
    assert 'interp-figures = "interp.figures:main"' in text


# --- files: nothing half-done, whatever happens ----------------------------------------------


def _folder_state(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def _run_cli(*args: str, **kwargs) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "interp.figures", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        **kwargs,
    )


def test_files_get_the_umask_permissions(tmp_path):
    old = os.umask(0o022)
    try:
        assert figures.main(["--out", str(tmp_path), "--only", "depth", "--format", "svg"]) == 0
    finally:
        os.umask(old)
    for path in tmp_path.iterdir():
        assert path.stat().st_mode & 0o777 == 0o644, path.name


@pytest.mark.parametrize("signum, status", [(2, 130), (15, 143)], ids=["SIGINT", "SIGTERM"])
def test_a_signal_leaves_the_folder_as_it_was(tmp_path, signum, status):
    (tmp_path / "the-problem.pdf").write_bytes(b"last week's handout")
    (tmp_path / "notes.txt").write_text("mine")
    before = _folder_state(tmp_path)
    process = _run_cli("--out", str(tmp_path), "--dpi", "100")
    first = process.stdout.readline()  # one figure staged: the run is half-way
    assert first.startswith("the-problem")
    process.send_signal(signum)
    _, err = process.communicate(timeout=120)
    assert process.returncode == status
    assert "nothing was changed" in err and "Traceback" not in err
    assert _folder_state(tmp_path) == before


def test_a_file_too_large_fails_cleanly(tmp_path):
    import resource

    (tmp_path / "depth.pdf").write_bytes(b"old")
    before = _folder_state(tmp_path)

    def small_files() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (20_000, 20_000))

    process = _run_cli("--out", str(tmp_path), "--only", "depth", preexec_fn=small_files)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 2
    line = err.strip().splitlines()[-1]
    assert line.startswith("interp-figures: error: cannot write " + str(tmp_path / "depth."))
    assert "File too large" in line and "Traceback" not in err
    assert _folder_state(tmp_path) == before


@pytest.mark.parametrize(
    "error",
    [
        OSError(28, "No space left on device"),
        PermissionError(13, "Permission denied"),
        OSError(30, "Read-only file system"),
    ],
    ids=["disk-full", "no-permission", "read-only"],
)
def test_file_system_errors_exit_2_and_change_nothing(tmp_path, monkeypatch, capsys, error):
    (tmp_path / "depth.svg").write_text("old")
    before = _folder_state(tmp_path)
    real_savefig = matplotlib.figure.Figure.savefig
    calls = []

    def failing(self, name, **kwargs):  # the first file writes; the second meets the error
        calls.append(name)
        if len(calls) == 2:
            raise error
        return real_savefig(self, name, **kwargs)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", failing)
    assert figures.main(["--out", str(tmp_path), "--only", "depth", "--no-handout"]) == 2
    err = capsys.readouterr().err
    assert f"cannot write {tmp_path / 'depth.svg'}: {error.strerror}" in err
    assert _folder_state(tmp_path) == before


def test_out_below_a_file(tmp_path, capsys):
    (tmp_path / "file").write_text("x")
    assert figures.main(["--out", str(tmp_path / "file" / "sub"), "--only", "depth"]) == 2
    assert "cannot create --out" in capsys.readouterr().err
    assert (tmp_path / "file").read_text() == "x"


def test_an_output_name_taken_by_a_folder(tmp_path, capsys):
    (tmp_path / "depth.png").mkdir()
    (tmp_path / "depth.svg").write_text("old")
    before = sorted(p.name for p in tmp_path.iterdir())
    assert figures.main(["--out", str(tmp_path), "--only", "depth", "--no-handout"]) == 2
    assert "a folder of that name is in the way" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert (tmp_path / "depth.svg").read_text() == "old"


def test_params_file_not_utf8(tmp_path, capsys):
    file = tmp_path / "params.json"
    file.write_bytes(b'{"pitch": "\xff"}')
    assert figures.main(["--out", str(tmp_path / "out"), "--params", str(file)]) == 2
    assert "is not UTF-8 text" in capsys.readouterr().err


def test_every_file_carries_its_title_and_alt_text(exported):
    """Screen readers and search find what each figure shows: the caption and the key result
    (the apps' readout at the drawn parameters) in the SVG's title and desc, the PNG's text
    chunks and the PDF's Title and Subject."""
    from html import unescape

    from PIL import Image

    for name, figure_class in figures.FIGURES.items():
        _, alt = figures._draw(figure_class, figure_class.defaults())
        assert alt.startswith(figure_class.caption) and len(alt) > len(figure_class.caption)
        svg = (exported / f"{name}.svg").read_text()
        root = svg[svg.index("<svg") : svg.index(">", svg.index("<svg")) + 1]
        assert 'role="img"' in root and 'aria-labelledby="title desc"' in root
        title = svg[svg.index('<title id="title">') + 18 : svg.index("</title>")]
        desc = svg[svg.index('<desc id="desc">') + 16 : svg.index("</desc>")]
        assert (unescape(title), unescape(desc)) == (figure_class.title, alt)
        with Image.open(exported / f"{name}.png") as png:
            assert png.text["Title"] == figure_class.title and png.text["Description"] == alt
        pdf = (exported / f"{name}.pdf").read_bytes()
        assert b"/Subject" in pdf
        if figure_class.title.isascii() and "(" not in figure_class.title:
            assert f"/Title ({figure_class.title})".encode() in pdf
    assert b"/Title (Perspective-correct interpolation)" in (exported / "handout.pdf").read_bytes()
