"""interp-figures: every figure in every format, deterministic, careful on the command line."""

from __future__ import annotations

import contextlib
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from interp import figures
from interp.plots import AFFINE, CORRECT

ALL_FILES = {f"{name}.{fmt}" for name in figures.BY_NAME for fmt in figures.FORMATS}


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """Everything, written once at a low PNG resolution to keep the suite quick."""
    out = tmp_path_factory.mktemp("handouts")
    assert figures.main(["--out", str(out), "--dpi", "60"]) == 0
    return out


def test_at_least_ten_figures_covering_every_lesson():
    assert len(figures.SPECS) >= 10
    lessons = {spec.caption.rsplit("(Lesson ", 1)[1][0] for spec in figures.SPECS}
    assert lessons == set("1234567")


def test_every_figure_in_every_format(exported):
    assert ALL_FILES | {"handout.pdf"} <= {p.name for p in exported.iterdir()}
    for name, spec in figures.BY_NAME.items():
        pdf = (exported / f"{name}.pdf").read_bytes()
        assert pdf.startswith(b"%PDF") and b"/FontFile2" in pdf  # TrueType fonts embedded
        svg = ET.parse(exported / f"{name}.svg").getroot()
        texts = [e for e in svg.iter() if e.tag.endswith("text")]
        assert texts, f"{name}.svg has no real text"
        from PIL import Image

        with Image.open(exported / f"{name}.png") as png:
            assert png.size == (round(spec.size[0] * 60), round(spec.size[1] * 60))


def test_no_temporary_files_left(exported):
    assert not [p for p in exported.iterdir() if p.name.startswith(".")]


def test_handout_has_a_cover_and_a_page_per_figure(exported):
    pdf = (exported / "handout.pdf").read_bytes()
    pages = pdf.count(b"/Type /Page") - pdf.count(b"/Type /Pages")
    assert pages == 1 + len(figures.SPECS)


def test_sizes_fit_a_column_of_a4_or_letter():
    for spec in figures.SPECS:
        assert spec.size[0] <= figures.WIDE <= 6.5
        assert spec.size[1] <= 9


def test_deterministic_bytes(exported, tmp_path):
    assert figures.main(["--out", str(tmp_path), "--dpi", "60"]) == 0
    for name in ALL_FILES | {"handout.pdf"}:
        assert (tmp_path / name).read_bytes() == (exported / name).read_bytes(), name


def test_source_date_epoch_is_honoured(tmp_path, monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")  # 2023-11-14
    assert (
        figures.main(
            ["--out", str(tmp_path), "--only", "gap-peak", "--format", "pdf", "svg", "--no-handout"]
        )
        == 0
    )
    assert b"D:20231114" in (tmp_path / "gap-peak.pdf").read_bytes()
    assert "2023-11-14" in (tmp_path / "gap-peak.svg").read_text()


def test_without_source_date_epoch_no_date(exported):
    assert b"CreationDate" not in (exported / "midpoint.pdf").read_bytes()
    assert "<dc:date>" not in (exported / "midpoint.svg").read_text()


def test_progress_lines(tmp_path, capsys):
    assert (
        figures.main(
            [
                "--out",
                str(tmp_path),
                "--only",
                "st-family",
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
    assert lines[0].split()[:2] == ["st-family", str(tmp_path / "st-family.png")]
    assert lines[0].endswith(" s") and lines[1].startswith("depth")
    assert lines[2].startswith("handout")


def test_list_names_every_figure(capsys):
    assert figures.main(["--list"]) == 0
    out = capsys.readouterr().out
    for name in figures.BY_NAME:
        assert name in out
    assert "pitch=" in out


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
        (["--set", "pitch=steep"], "--set pitch must be float, got 'steep'"),
        (["--set", "pitch=400"], "pitch must be in [-89, 90]"),
        (["--set", "quads=0", "--only", "checkerboards"], "quads must be an integer in"),
        (["--set", "zoom=2"], "no figure being drawn has a parameter 'zoom'"),
        (["--set", "depth.pitch=2"], "no figure being drawn has a parameter 'pitch'"),
        (["--set", "fan.samples=3", "--only", "midpoint"], "'fan' is not among the figures"),
        (["--set", "pitch"], "--set takes KEY=VALUE"),
        (["--dpi", "0"], "--dpi must be between 10 and 1200"),
        (["--set", "depth-precision.buffer=fixed16"], "buffer must be one of"),
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
        ('{"pitch": "up"}', "pitch must be float"),
        ('{"checkerboards": {"frequency": true}}', "frequency must be float"),
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


def test_interrupted_write_leaves_no_partial_file(tmp_path, monkeypatch):
    target = tmp_path / "depth.pdf"
    target.write_bytes(b"the old, complete file")
    figure = figures.render(figures.BY_NAME["depth"], figures.BY_NAME["depth"].params)

    def crash(name, **kwargs):
        Path(name).write_bytes(b"%PDF-half")
        raise KeyboardInterrupt

    monkeypatch.setattr(figure, "savefig", crash)
    with pytest.raises(KeyboardInterrupt):
        figures.save(figure, target, "pdf", 100)
    assert target.read_bytes() == b"the old, complete file"
    assert os.listdir(tmp_path) == ["depth.pdf"]


def test_checkerboard_content_tilted_and_straight_down():
    spec = figures.BY_NAME["checkerboards"]
    tilted = figures.render(spec, {**spec.params, "pitch": 20.0})
    panels = tilted.axes[0].images[0], tilted.axes[1].images[0]
    affine, correct = (np.asarray(p.get_array()) for p in panels)
    drawn = correct != 0.5
    differ = np.mean(np.abs(affine - correct)[drawn] > 0.5)
    assert differ > 0.05, "a tilted camera should bend the affine checkerboard"
    down = figures.render(spec, {**spec.params, "pitch": 90.0, "distance": 0.0, "height": 3.0})
    affine, correct = (np.asarray(ax.images[0].get_array()) for ax in down.axes[:2])
    np.testing.assert_allclose(affine, correct, atol=1e-9)


def test_affine_and_correct_differ_without_colour():
    for key in ("linestyle", "marker"):
        assert AFFINE[key] != CORRECT[key]


def test_console_script_is_declared():
    text = (Path(__file__).resolve().parent.parent / "pyproject.toml").read_text()
    assert 'interp-figures = "interp.figures:main"' in text
