"""What users and fuzzers actually send, through the command line (issue 41): every failure is one
bounded line, never a traceback, and a refused command leaves nothing behind.
"""

from __future__ import annotations

import errno
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import MAX_MESSAGE_CHARS, MAX_SOURCE_CHARS, error_line, shown

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DGBB = str(EXAMPLES / "dgbb_6209.toml")
runner = CliRunner()


def one_line(res, code: int = 2) -> str:
    assert res.exit_code == code, (res.stdout, res.stderr)
    lines = res.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), res.stderr
    assert "Traceback" not in res.stdout + res.stderr
    return lines[0]


@pytest.mark.parametrize("as_json", [[], ["--json"]])
@pytest.mark.parametrize("designation", ["6209", "6205-2rs c3", "6205 C3"])
def test_friction_of_a_designation_without_a_load_is_one_line(designation, as_json):
    """`bearingkit friction 6209 --json` (a newcomer's first try) was an IndexError."""
    line = one_line(runner.invoke(app, ["friction", designation, *as_json]))
    assert "no load case: give --load" in line


def test_a_file_without_load_cases_is_one_line(tmp_path):
    text = (EXAMPLES / "qj_208.toml").read_text()
    cut = tmp_path / "qj.toml"
    cut.write_text(text[: text.index("[[load_cases]]")])
    for command in ("friction", "analyze", "report"):
        assert "no load case" in one_line(runner.invoke(app, [command, str(cut)]))


@pytest.mark.parametrize("n", [300, 6000, 10240])
def test_a_long_designation_is_shown_shortened(n):
    text = ("6205-2RS C3" * (n // 11 + 1))[:n]
    line = one_line(runner.invoke(app, ["analyze", text]))
    assert len(line) <= len("error: ") + MAX_SOURCE_CHARS + 2 + MAX_MESSAGE_CHARS
    assert text not in line


def test_usage_errors_are_one_line():
    for args in (["friction", "6205", "C3"], ["study", "x", "--workers", "abc"], ["nonsense"], ["analyze"]):
        line = one_line(runner.invoke(app, args))
        assert "--help" in line


def test_an_unexpected_exception_is_one_line_with_exit_70(monkeypatch):
    """A bug of bearingkit: one line naming the exception, exit 70, no traceback on screen."""
    import bearingkit.cli.common as common

    def broken(*args, **kwargs):
        raise IndexError("list index out of range")

    monkeypatch.setattr(common, "_analysis", broken)
    import bearingkit.cli.commands as commands

    monkeypatch.setattr(commands, "_analysis", broken)
    line = one_line(runner.invoke(app, ["analyze", DGBB]), code=70)
    assert "internal error (IndexError: list index out of range)" in line


def test_a_full_disk_is_one_line_and_leaves_no_file(tmp_path, monkeypatch):
    """ENOSPC while the report is written: one line saying the disk is full; no partial file, no
    temporary file, no folder the command made."""
    import bearingkit.io.export as export

    def full(tmp):
        raise OSError(errno.ENOSPC, "No space left on device", str(tmp))

    original = export.write_atomic

    def write_atomic(path, write, what="file"):
        return original(path, full, what)

    monkeypatch.setattr(export, "write_atomic", write_atomic)
    out = tmp_path / "new" / "deeper" / "report.html"
    line = one_line(runner.invoke(app, ["report", DGBB, "-o", str(out), "--case", "radial_4kN"]))
    assert "the disk is full" in line and "free some space" in line and "[Errno" not in line
    assert not (tmp_path / "new").exists()


def test_an_operating_system_error_names_the_path_and_the_reason():
    from bearingkit.errors import os_error_text

    text = os_error_text(OSError(errno.ENOSPC, "No space left on device", "/data/out/chunk-000001.parquet"))
    assert text == (
        "cannot use /data/out/chunk-000001.parquet: the disk is full (no space left on device); "
        "free some space or choose another folder"
    )
    long = os_error_text(OSError(errno.ENAMETOOLONG, "File name too long", "x" * 5000))
    assert "at most 255 bytes" in long and len(long) < 300


def test_a_name_too_long_for_the_file_system_is_one_line(tmp_path):
    name = str(tmp_path / ("a" * 300 + ".toml"))
    line = one_line(runner.invoke(app, ["analyze", name]))
    assert "cannot read the file" in line and len(line) < 7 + 2 * MAX_SOURCE_CHARS + MAX_MESSAGE_CHARS


def test_stiffness_path_refused_before_the_work(tmp_path):
    out = tmp_path / "nodir" / "deeper" / "k.html"
    line = one_line(
        runner.invoke(app, ["shaft", str(EXAMPLES / "shaft_countershaft.toml"), "--stiffness", str(out)])
    )
    assert "must end in .csv or .json" in line
    assert not (tmp_path / "nodir").exists()


def test_temperatures_below_absolute_zero_are_refused():
    line = one_line(runner.invoke(app, ["rating", DGBB, "--temperature=-300degC"]))
    assert "below absolute zero" in line


@pytest.mark.parametrize("speed", ["1e9rpm", "1e308rpm"])
def test_a_speed_no_bearing_runs_at_is_refused_at_once(speed):
    """1e9 rpm took 15 s, then gave a misleading Newton message."""
    line = one_line(runner.invoke(app, ["analyze", DGBB, "--speed", speed, "--json"]))
    assert "n·d_m" in line and "at most 5e+06 mm/min" in line


def test_validate_with_markup_in_a_prefix_is_one_line():
    line = one_line(runner.invoke(app, ["validate", "[red]x[/]"]))
    assert "no validation case matches" in line


def test_error_line_is_bounded_and_printable():
    line = error_line("x" * 100_000 + "\x00 tail", "d" * 10_000)
    assert line.isprintable() and len(line) <= 7 + MAX_SOURCE_CHARS + 2 + MAX_MESSAGE_CHARS
    assert shown("a\x00b") == "a?b"
    assert error_line("f.toml: bad", "f.toml") == "error: f.toml: bad"  # the source named once


def test_json_output_of_an_analysis_is_strict():
    res = runner.invoke(app, ["analyze", DGBB, "--json"])
    assert res.exit_code == 0
    json.loads(res.stdout, parse_constant=lambda c: pytest.fail(f"{c} in JSON"))


def test_an_aborted_command_is_one_line(capsys):
    """Ctrl-C at a prompt, or a command that aborts: one line and exit 1 (the handler once named
    ``click.Abort``, which typer's bundled click does not have, and ended in an AttributeError)."""
    import typer

    from bearingkit.cli.common import OneLineGroup

    demo = typer.Typer(cls=OneLineGroup)

    @demo.command()
    def boom():
        raise typer.Abort()

    @demo.command()
    def other():
        pass

    with pytest.raises(SystemExit) as stop:
        demo(["boom"])
    assert stop.value.code == 1
    assert capsys.readouterr().err == "error: aborted\n"


@pytest.mark.parametrize(
    "options",
    [
        ["--report", "out/report.html", "--stiffness", "k.csv", "--ross", "out/report.html"],  # fuzz #4197
        ["--report", "out", "--ross", "out/rotors"],
        ["--report", "out", "--stiffness", "out/k.csv"],
    ],
)
def test_outputs_where_one_needs_the_other_as_a_folder_are_refused_before_anything_is_written(
    tmp_path, monkeypatch, options
):
    """The fuzz (seed 20261128, #4197): the report and the stiffness table were written, then ``--ross``
    found the report's name taken and failed, leaving both behind. The extra is taken as present: without
    it ``--ross`` stops at the missing [ross] before the folder rules (make test does not install it)."""
    from bearingkit import extras

    monkeypatch.setattr(extras, "missing", lambda extra: [])
    monkeypatch.chdir(tmp_path)
    line = one_line(runner.invoke(app, ["system", str(EXAMPLES / "gearbox_two_stage.toml"), *options]))
    assert ("--ross" in line or "--stiffness" in line) and "extra" not in line, line
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_files_inside_the_rotor_folder_are_allowed(tmp_path, monkeypatch):
    """The folder rules only: ``--ross`` also needs the [ross] extra, which `make test` does not install
    (tests/test_extras.py checks that message), so the extra is taken as present here."""
    from bearingkit import extras
    from bearingkit.cli.common import check_outputs

    monkeypatch.setattr(extras, "missing", lambda extra: [])
    check_outputs(report=tmp_path / "out" / "report.html", ross=tmp_path / "out")  # no error
    check_outputs(ross=tmp_path / "out", stiffness=tmp_path / "out" / "k.csv")


def test_a_load_case_that_is_not_a_table_is_one_line_with_case(tmp_path):
    """The fuzz (seed 20261128, #2766): ``system --case NAME`` on a file whose load_cases hold a number
    was an internal error (AttributeError) before validation could name the entry."""
    import sys
    import tomllib

    sys.path.insert(0, str(Path(__file__).resolve().parent / "fuzz"))  # its TOML writer
    from bk_fuzz_inputs import toml_text

    data = tomllib.loads((EXAMPLES / "gearbox_two_stage.toml").read_text())
    data["load_cases"].insert(1, 1e8)
    path = tmp_path / "g.toml"
    path.write_text(toml_text(data))
    line = one_line(runner.invoke(app, ["system", str(path), "--case", "peak"]))
    assert "load_cases[1]" in line and "internal error" not in line


def test_a_failing_later_output_takes_the_earlier_ones_with_it(tmp_path, monkeypatch):
    """The fuzz (seed 20261129, #5399): ``system --stiffness k.csv --rexs out/x`` wrote the table, then
    the REXS writer failed (its folder did not exist), leaving the table behind. Now the REXS model is
    written as every output is (folders made, all or nothing), and one failing write undoes the others."""
    from bearingkit.errors import InputError
    from bearingkit.io.rexs import export

    monkeypatch.chdir(tmp_path)
    gearbox = str(EXAMPLES / "gearbox_two_stage.toml")
    ok = runner.invoke(app, ["system", gearbox, "--stiffness", "k.csv", "--rexs", "out/x.rexsj"])
    assert ok.exit_code == 0, ok.stderr
    assert (tmp_path / "k.csv").is_file() and (tmp_path / "out" / "x.rexsj").is_file()

    def full_disk(data, path, source=None):
        raise InputError(f"{path}: cannot write the REXS model: no space left on device")

    monkeypatch.setattr(export, "write_rexs_results", full_disk)
    (tmp_path / "b").mkdir()
    monkeypatch.chdir(tmp_path / "b")
    options = ["--report", "r/report.html", "--stiffness", "k.csv", "--rexs", "x.rexsj"]
    line = one_line(runner.invoke(app, ["system", gearbox, *options]))
    assert "no space left" in line
    assert list((tmp_path / "b").iterdir()) == []


def test_undo_outputs_keeps_what_existed_before(tmp_path):
    from bearingkit.cli.common import undo_outputs

    old = tmp_path / "old.csv"
    old.write_text("kept")
    new, folder = tmp_path / "a" / "b" / "new.html", tmp_path / "rotors"
    with pytest.raises(RuntimeError), undo_outputs([old, new, folder]):
        new.parent.mkdir(parents=True)
        new.write_text("x")
        folder.mkdir()
        (folder / "shaft.toml").write_text("x")
        raise RuntimeError("a later write failed")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old.csv"] and old.read_text() == "kept"
    with undo_outputs([new]):  # no error: nothing removed
        new.parent.mkdir(parents=True)
        new.write_text("x")
    assert new.read_text() == "x"
