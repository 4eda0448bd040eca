"""Optional parts (issue 42): a missing extra is one line naming the extra to install, on every face.

The extra's modules are hidden in a fresh interpreter (``sys.modules[name] = None``: Python then refuses
to import them, as if they were not installed), so the test runs in the full development venv.
"""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from bearingkit import extras

ROOT = Path(__file__).resolve().parents[1]
STUDY = ROOT / "examples" / "studies" / "dgbb_6209_clearance_load.toml"

#: Distribution (pyproject) → the module it installs, where the names differ.
MODULE_OF = {
    "dask[distributed]": ("dask", "distributed"),
    "tomli-w": ("tomli_w",),
    "ross-rotordynamics": ("ross",),
}


def _run(hidden, code):
    prelude = "import sys\n" + "".join(f"sys.modules[{m!r}] = None\n" for m in hidden)
    return subprocess.run([sys.executable, "-c", prelude + code], capture_output=True, text=True, cwd=ROOT)


def _cli(hidden, *argv):
    code = f"from bearingkit.cli import main\nsys.argv = ['bearingkit', *{list(map(str, argv))!r}]\nmain()\n"
    return _run(hidden, code)


def test_the_extras_are_those_of_pyproject():
    """extras.EXTRAS names the modules of the distributions each extra of pyproject.toml installs."""
    optional = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
    for extra, modules in extras.EXTRAS.items():
        names = [
            req.split(";")[0].split(">")[0].split("<")[0].split("=")[0].strip() for req in optional[extra]
        ]
        installed = {m for name in names for m in MODULE_OF.get(name, (name.replace("-", "_"),))}
        assert set(modules) <= installed, (extra, modules, names)
    assert set(optional["all"]) == {"bearingkit[studies,app]"}


@pytest.mark.parametrize(
    ("hidden", "argv", "extra"),
    [
        (("pymoo",), ("study", STUDY, "--out", "OUT"), "studies"),
        (("dask", "pyarrow"), ("study", STUDY, "--out", "OUT"), "studies"),
        (("fastapi",), ("serve",), "app"),
    ],
)
def test_a_command_without_its_extra_is_one_line_naming_it(hidden, argv, extra, tmp_path):
    argv = [str(tmp_path / "out") if a == "OUT" else a for a in argv]
    out = _cli(hidden, *argv)
    assert out.returncode == 2, out.stderr
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert lines[0].startswith("error: ") and f"pip install 'bearingkit[{extra}]'" in lines[0]
    assert f"not installed: {', '.join(hidden)}" in lines[0]
    assert not (tmp_path / "out").exists()  # nothing half-written


def test_the_core_commands_run_without_any_extra():
    """analyze and rating of a designation need no extra (every extra's modules hidden)."""
    hidden = [m for modules in extras.EXTRAS.values() for m in modules]
    out = _cli(hidden, "rating", "6205", "--load", "Fr=2kN", "--speed", "3000rpm", "--json")
    assert out.returncode == 0, out.stderr
    assert '"L10h_h"' in out.stdout


@pytest.mark.parametrize(
    ("hidden", "code", "extra"),
    [
        (("fastapi",), "import bearingkit.app", "app"),
        (("pyarrow",), "from bearingkit.studies.run.store import ParquetStore\nParquetStore('x')", "studies"),
        (("ross",), "from bearingkit.systems.ross import import_ross\nimport_ross()", "ross"),
        (
            ("distributed",),
            "from bearingkit.studies.run.executors import DaskExecutor\nDaskExecutor(workers=1)",
            "studies",
        ),
    ],
)
def test_the_python_api_raises_one_importerror_naming_the_extra(hidden, code, extra):
    wrapped = (
        "from bearingkit.extras import MissingExtra\n"
        f"try:\n    exec({code!r})\nexcept ImportError as exc:\n"
        "    print(type(exc).__name__, isinstance(exc, MissingExtra)); print(exc)\n"
    )
    out = _run(hidden, wrapped)
    assert out.returncode == 0, out.stderr
    kind, message = out.stdout.strip().splitlines()
    assert kind == "MissingExtra True"
    assert f"pip install 'bearingkit[{extra}]'" in message and "\n" not in message


def test_check_and_require_can_fail_and_pass():
    extras.check("app", "x")  # the development venv has every extra
    assert extras.missing("studies") == []
    with pytest.raises(extras.MissingExtra, match=r"needs the \[ross\] extra"):
        extras.require("a_module_that_is_not_there", "ross", "the ROSS export")
