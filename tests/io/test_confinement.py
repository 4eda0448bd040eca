"""Paths named by data files are confined before anything opens them (issue 41).

A study's ``bearing`` and a shaft's bearing ``file`` come from a file that may be someone else's:
``io.reading.confined_path`` checks the name as text and resolves it (no ``~``, no NUL, no control
characters, names of at most 255 bytes, inside the file's folder or its project's folder above it or
a folder given with ``--allow-path``, no hidden names). The file itself is opened only afterwards,
by the bounded reader; a file the system generates (``/proc/self/environ``) is never parsed, so its
content cannot reach a message.
"""

from __future__ import annotations

import builtins
import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.io.reading import confined_path, read_text
from bearingkit.studies.definition.load import load_study

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
runner = CliRunner()


def _study(folder: Path, bearing: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "s.toml"
    path.write_text(
        f'[study]\nname = "probe"\ndesign = "sweep"\nbearing = "{bearing}"\nload_case = "radial_4kN"\n'
        '[[factors]]\nname = "load_cases.radial_4kN.F_x"\nlevels = ["1 kN", "2 kN"]\n'
    )
    return path


@pytest.fixture
def opened(monkeypatch):
    """Every path os.open / open is asked for while the test runs."""
    seen = []
    real_os_open, real_open = os.open, builtins.open

    def os_open(path, *args, **kwargs):
        seen.append(str(path))
        return real_os_open(path, *args, **kwargs)

    def py_open(file, *args, **kwargs):
        seen.append(str(file))
        return real_open(file, *args, **kwargs)

    monkeypatch.setattr(os, "open", os_open)
    monkeypatch.setattr(builtins, "open", py_open)
    return seen


@pytest.mark.parametrize(
    ("bearing", "fragment"),
    [
        ("~/.bashrc", "'~' is not expanded"),
        ("/etc/passwd", "lies outside this file's folder"),
        ("/proc/self/environ", "lies outside this file's folder"),
        ("../../../../../../../../etc/passwd", "lies outside this file's folder"),
        ("../.ssh/config", "hidden file or folder"),
    ],
)
def test_a_study_naming_a_file_outside_is_refused_without_opening_it(tmp_path, opened, bearing, fragment):
    study = _study(tmp_path / "home" / "proj" / "studies", bearing)
    with pytest.raises(InputError, match=fragment) as err:
        load_study(study)
    assert str(err.value).startswith(f"{study}: study.bearing")
    target = bearing.replace("~", str(Path.home()))
    assert not [p for p in opened if p.endswith(("passwd", "environ", ".bashrc", "config")) or p == target]
    assert "root:" not in str(err.value)  # nothing of any such file is quoted


def test_the_command_line_refuses_it_in_one_line_and_writes_nothing(tmp_path, opened):
    study = _study(tmp_path / "p" / "studies", "/etc/passwd")
    out = tmp_path / "out"
    res = runner.invoke(app, ["study", str(study), "--out", str(out)])
    assert res.exit_code == 2
    assert res.stderr.count("\n") == 1 and "lies outside this file's folder" in res.stderr
    assert not out.exists()
    assert not [p for p in opened if p.endswith("passwd")]


def test_list_outputs_confines_the_bearing_too(tmp_path, opened):
    study = _study(tmp_path / "p" / "studies", "~/.bashrc")
    res = runner.invoke(app, ["study", str(study), "--list-outputs"])
    assert res.exit_code == 2 and "'~' is not expanded" in res.stderr
    assert not [p for p in opened if p.endswith(".bashrc")]


def test_the_project_folder_above_and_allow_path(tmp_path):
    """examples/studies/*.toml name ../x.toml: the folder above is the project's; elsewhere needs
    --allow-path (an absolute path inside an allowed folder is fine)."""
    proj = tmp_path / "a" / "proj"
    (proj / "studies").mkdir(parents=True)
    bearing = proj / "dgbb_6209.toml"
    bearing.write_text((EXAMPLES / "dgbb_6209.toml").read_text())
    assert load_study(_study(proj / "studies", "../dgbb_6209.toml")).bearing == str(bearing)
    assert load_study(_study(proj / "studies", str(bearing))).bearing == str(bearing)
    far = _study(tmp_path / "b" / "c" / "d", str(bearing))
    with pytest.raises(InputError, match="--allow-path"):
        load_study(far)
    assert load_study(far, allowed_paths=[proj]).bearing == str(bearing)


def test_a_symbolic_link_out_of_the_folder_is_resolved_and_refused(tmp_path):
    secret = tmp_path / "elsewhere" / "secret.toml"
    secret.parent.mkdir()
    secret.write_text("[bearing]\n")
    proj = tmp_path / "x" / "y" / "proj"
    proj.mkdir(parents=True)
    (proj / "b.toml").symlink_to(secret)
    with pytest.raises(InputError, match="lies outside"):
        confined_path("b.toml", proj, "study.bearing")


def test_the_folder_above_is_not_the_root_or_home(tmp_path, monkeypatch):
    """A file directly in /tmp or in the home folder reaches only its own folder."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    downloads = tmp_path / "home" / "Downloads"
    downloads.mkdir(parents=True)
    (tmp_path / "home" / "notes.toml").write_text("x = 1\n")
    with pytest.raises(InputError, match="lies outside"):
        confined_path("../notes.toml", downloads, "study.bearing")
    with pytest.raises(InputError, match="lies outside"):
        confined_path("../etc/passwd", Path("/tmp"), "study.bearing")


@pytest.mark.parametrize(
    ("name", "fragment"),
    [
        ("dgbb_6209.toml\x00", "NUL byte or a control character"),
        ("a\nb.toml", "NUL byte or a control character"),
        ("a" * 300 + ".toml", "too long a file name"),
        ("/".join(["d" * 200] * 30) + ".toml", "too long a file name"),
        ("", "must name a file"),
        (7, "must be a file name"),
    ],
)
def test_names_no_file_system_takes_are_one_line(tmp_path, name, fragment):
    with pytest.raises(InputError, match=fragment) as err:
        confined_path(name, tmp_path, "file")
    assert "\n" not in str(err.value) and len(str(err.value)) <= 300


def test_a_shaft_naming_a_bearing_file_with_a_nul_byte_is_one_line(tmp_path):
    text = (EXAMPLES / "shaft_countershaft.toml").read_text()
    shaft = tmp_path / "p" / "q" / "shaft.toml"
    shaft.parent.mkdir(parents=True)
    shaft.write_text(text.replace('file = "dgbb_6209.toml"', 'file = "dgbb_6209.toml\\u0000"'))
    res = runner.invoke(app, ["shaft", str(shaft)])
    assert res.exit_code == 2, res.stderr
    assert res.stderr.count("\n") == 1 and "NUL byte" in res.stderr
    assert "ValueError" not in res.stderr


def test_a_file_the_system_generates_is_never_parsed(tmp_path):
    """/proc/self/environ reads as a regular file of size 0 that holds data: refused, not quoted."""
    environ = Path("/proc/self/environ")  # Linux (CI)
    with pytest.raises(InputError, match="the system generates") as err:
        read_text(environ)
    assert "=" not in str(err.value).split(": ", 1)[1]
    res = runner.invoke(app, ["analyze", str(environ)])
    assert res.exit_code == 2 and "the system generates" in res.stderr
    assert os.environ.get("PATH", "PATH=")[:10] not in res.stderr


def test_an_empty_file_is_still_an_empty_file(tmp_path):
    empty = tmp_path / "e.toml"
    empty.write_text("")
    assert read_text(empty) == ""
