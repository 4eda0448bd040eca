"""The accuracy table of docs/catalogue.md is the output of scripts/catalogue_accuracy.py, line for line:
a catalogue row added or changed without regenerating the table fails here (two helpers of issue 33 found
that nothing checked it)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_docs_accuracy_table_equals_the_script_output():
    out = subprocess.run(
        [sys.executable, str(ROOT / "scripts" / "catalogue_accuracy.py")],
        capture_output=True, text=True, check=True, timeout=300,
    ).stdout  # fmt: skip
    table = [line for line in out.splitlines() if line.startswith("|")]
    doc = (ROOT / "docs" / "catalogue.md").read_text(encoding="utf-8").splitlines()
    assert table and table[0] in doc, "the table's header is not in docs/catalogue.md"
    start = doc.index(table[0])
    shown = doc[start : start + len(table) + 1]
    assert shown[: len(table)] == table, "docs/catalogue.md's accuracy table differs from the script's output"
    assert not shown[-1].startswith("|"), "docs/catalogue.md's table has rows the script does not print"
