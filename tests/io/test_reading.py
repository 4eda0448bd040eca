"""Reading input files (issue 24 item 4; issue 23): regular files only, a size cap, bounded nesting,
a JSON hint, and no more of a file's content in a message than a short excerpt."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import MAX_MESSAGE_CHARS, InputError
from bearingkit.io import reading
from bearingkit.io.loader import load_file, loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _refused(path) -> str:
    with pytest.raises(InputError) as err:
        load_file(path)
    msg = str(err.value)
    assert msg.startswith(f"{path}: ") and "\n" not in msg and len(msg) <= MAX_MESSAGE_CHARS, msg
    return msg


def test_devices_directories_and_fifos_are_refused(tmp_path):
    """/dev/zero grew memory without limit (2.7 GB in 2.5 s): the type is checked on the opened
    descriptor before a byte is read; a FIFO without writer is opened non-blocking (no hang)."""
    assert "it is a device, not a regular file" in _refused("/dev/zero")
    assert "it is a directory" in _refused(tmp_path)
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    assert "pipe (FIFO)" in _refused(fifo)
    link = tmp_path / "zero.toml"
    link.symlink_to("/dev/zero")
    assert "device" in _refused(link)


def test_a_100_MB_file_is_refused_from_its_size(tmp_path, monkeypatch):
    big = tmp_path / "big.toml"
    with big.open("wb") as f:
        f.truncate(100 * 2**20)  # sparse: nothing is written to disk
    reads = []
    real_fdopen = os.fdopen
    monkeypatch.setattr(os, "fdopen", lambda *a, **k: reads.append(a) or real_fdopen(*a, **k))
    assert "it holds 100 MiB; input files may hold at most 1 MiB" in _refused(big)
    assert reads == []  # refused from fstat, before any read


def test_size_cap_counts_bytes_read(tmp_path):
    """A file at the cap is read; one byte more is refused (the read stops at cap + 1 bytes)."""
    at_cap = tmp_path / "at_cap.toml"
    text = (EXAMPLES / "dgbb_6209.toml").read_text(encoding="utf-8")
    at_cap.write_text(text + " " * (reading.MAX_INPUT_BYTES - len(text.encode())), encoding="utf-8")
    assert load_file(at_cap).cases
    over = tmp_path / "over.toml"
    over.write_text(at_cap.read_text(encoding="utf-8") + " ", encoding="utf-8")
    assert "input files may hold at most 1 MiB" in _refused(over)


def test_not_utf8_and_byte_order_mark(tmp_path):
    bad = tmp_path / "latin1.toml"
    bad.write_bytes("[bearing]\nname = 'Kugellager Ø45'\n".encode("latin-1"))
    assert "is not UTF-8 text (byte 29 cannot be decoded)" in _refused(bad)
    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + (EXAMPLES / "dgbb_6209.toml").read_bytes())
    assert load_file(bom).cases  # editors on Windows write a BOM


@pytest.mark.parametrize(
    "value",
    [
        "[" * 5000 + "]" * 5000,  # RecursionError in tomllib (issue 23)
        "{a = " * 1000 + "1" + "}" * 1000,
        "[" * 17 + "]" * 17,
        '["[[[[[[[[[[[[[[[[[[[[[[[[[[[[", ' + "[" * 17 + "]" * 17 + "]",
    ],
)
def test_deep_nesting_is_one_line(value):
    with pytest.raises(InputError) as err:
        loads(f"[bearing]\ntype = 'deep_groove_ball'\n[geometry]\nbore = {value}\n", "deep.toml")
    msg = str(err.value)
    assert msg.startswith("deep.toml: line 4: arrays or inline tables nested more than 16 deep"), msg


def test_brackets_inside_strings_and_comments_do_not_count():
    text = (EXAMPLES / "dgbb_6209.toml").read_text(encoding="utf-8")
    deep = "[" * 40
    text = text.replace("[bearing]", f"# {deep}\n[bearing]", 1).replace('name = "', f'name = "{deep} ', 1)
    assert loads(text, "ok.toml").cases


def test_dotted_keys_nested_deep_are_one_line():
    with pytest.raises(InputError, match="tables nested more than 16 deep"):
        loads("[bearing]\ntype = 'x'\n[geometry]\n" + "a" + ".a" * 3000 + " = 1\n", "dotted.toml")


def test_json_content_gets_a_hint():
    with pytest.raises(InputError) as err:
        loads('{"bearing": {"type": "deep_groove_ball"}, "geometry": {}}', "j.toml")
    msg = str(err.value)
    assert msg.startswith("j.toml: not valid TOML (")
    assert "looks like JSON: bearingkit reads TOML" in msg


def test_toml_errors_quote_a_short_excerpt_only(tmp_path):
    secret = "S" * 500
    path = tmp_path / "secret.toml"
    path.write_text(f"{secret} x\n", encoding="utf-8")
    msg = _refused(path)
    assert "not valid TOML" in msg and "at line 1" in msg
    assert msg.count("S") <= reading.EXCERPT_CHARS
    key = "k" * 100_000
    with pytest.raises(InputError) as err:  # tomllib's message names the key twice declared
        loads(f"[{key}]\n[{key}]\n", "dup.toml")
    assert len(str(err.value)) <= MAX_MESSAGE_CHARS


def test_cli_dev_zero_is_exit_2_one_line():
    res = CliRunner().invoke(app, ["analyze", "/dev/zero"])
    assert res.exit_code == 2 and res.stdout == ""
    assert res.stderr == "error: /dev/zero: cannot read the file (it is a device, not a regular file)\n"


@pytest.mark.parametrize(
    "opening",
    ['x = "never closed', 'x = "\\"\\"\\"\\"', "x = 'never closed", 'x = "ends in a backslash \\'],
)
def test_an_unterminated_string_ends_at_its_line(opening):
    """A basic or literal string cannot span lines: the brackets on the next line count. (The scan
    takes every string whole, closed or not: a line of escaped quotes used to make it restart at
    each quote, quadratic — 89 s for 80 kB; benchmarks/bench_input.py times it.)"""
    depth, line = reading._bracket_depth(f"{opening}\ny = {'[' * 17}{']' * 17}\n")
    assert (depth, line) == (17, 2)
