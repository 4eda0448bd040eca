"""Time to refuse hostile input (issue 24 items 4–5): files in at most 1 s (3 s for a 1 MiB file the
TOML parser must read), values in at most 100 ms.

Each refusal is timed once after a warm-up (pint's registry and the loader imported), as the CLI
would meet it: ``load_file`` on a device, a directory, a FIFO, a sparse 100 MB file and a deeply
nested file; ``units.parse`` on values that made pint's expression evaluator crawl or overflow.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

#: Values refused by the syntax check (targets 100 ms each).
VALUES = {
    "value_9**9**9": "9**9**9 N",
    "value_100000_chars": "1" * 100_000 + " N",
    "value_10**400": "10**400 N",
    "value_30_letters": "1 " + "a" * 30,
}


def _time_refusal(fn) -> float:
    from bearingkit.errors import InputError

    t0 = time.perf_counter()
    try:
        fn()
    except InputError:
        return time.perf_counter() - t0
    raise AssertionError("accepted")  # pragma: no cover - a refusal is what is timed


def run(quick: bool) -> list[dict]:
    from bearingkit.io import reading
    from bearingkit.io.loader import load_file
    from bearingkit.units import parse, registry

    parse("5 kN", "force", "warm-up")
    # "5 kN" takes the fast path, which never builds pint's registry; an unknown unit does, once per
    # process (~0.5-0.8 s). Built here, so each refusal is timed as a CLI meets it after start-up.
    registry()
    out = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        fifo = folder / "pipe.toml"
        os.mkfifo(fifo)
        big = folder / "big.toml"
        with big.open("wb") as f:
            f.truncate(100 * 2**20)
        deep = folder / "deep.toml"
        deep.write_text("[bearing]\ntype = 'x'\nx = " + "[" * 5000 + "]" * 5000 + "\n", encoding="utf-8")
        files = {"file_dev_zero": "/dev/zero", "file_directory": folder, "file_fifo": fifo, "file_100MB": big}
        files["file_nested_5000"] = deep
        quotes = folder / "quotes.toml"  # 1 MiB line of escaped quotes: the nesting scan is linear
        quotes.write_text('x = "' + '\\"' * (reading.MAX_INPUT_BYTES // 2 - 4) + "\n[", encoding="utf-8")
        files["file_escaped_quotes_1MiB"] = quotes
        for name, path in files.items():
            out.append(
                {
                    "name": name,
                    "value": _time_refusal(lambda p=path: load_file(p)),
                    "unit": "s",
                    "target": 3.0 if name == "file_escaped_quotes_1MiB" else 1.0,
                }
            )
    for name, text in VALUES.items():
        dt = _time_refusal(lambda t=text: parse(t, "force", "F_x"))
        out.append({"name": name, "value": dt * 1e3, "unit": "ms", "target": 100.0})
    return out


if __name__ == "__main__":
    for r in run(quick=False):
        print(r)
