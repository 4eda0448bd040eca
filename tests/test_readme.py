"""The README's Python examples run as shown: each ```python block executes and prints its Output block."""

from __future__ import annotations

import contextlib
import io
import os
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
#: A python block, optionally followed by "Output:" and a plain block with what it prints.
BLOCK = re.compile(r"```python\n(.*?)```\n(?:Output:\n```\n(.*?)```)?", re.S)
BLOCKS = BLOCK.findall(README)


def test_the_readme_has_examples_with_output():
    assert len(BLOCKS) >= 2
    assert sum(1 for _, out in BLOCKS if out) >= 2


@pytest.mark.parametrize("code, expected", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_block_prints_what_the_readme_shows(code, expected):
    buffer = io.StringIO()
    cwd = os.getcwd()
    os.chdir(ROOT)  # the examples name files relative to the repository
    try:
        with contextlib.redirect_stdout(buffer):
            exec(compile(code, "README.md", "exec"), {"__name__": "readme"})
    finally:
        os.chdir(cwd)
    if expected:
        assert buffer.getvalue() == expected
