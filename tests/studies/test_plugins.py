"""A study file is data: it names an evaluator, it never makes bearingkit import code (issue 24, item 2).

Plugins come only from an explicit opt-in by the person running the study: ``--allow-plugin
module:attribute`` (``evaluators.allow_plugin``) or an installed package's entry point in the group
``bearingkit.evaluators``.
"""

import os
import subprocess
import sys
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest

from bearingkit.errors import InputError
from bearingkit.studies import evaluators
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.executors import ProcessPoolExecutor
from bearingkit.studies.run.runner import run_study

HERE = Path(__file__).resolve().parent

EVIL = """
from pathlib import Path
Path(__file__).with_name("IMPORTED").write_text("the study file ran this module")
x = None
"""


def _study(evaluator: str, chunk_size: int = 2) -> dict:
    return {
        "study": {"name": "p", "design": "factorial", "evaluator": evaluator, "chunk_size": chunk_size},
        "factors": [{"name": "x", "levels": [0.0, 1.0, 2.0]}],
    }


@pytest.fixture
def no_plugins(monkeypatch):
    """A fresh allow-list for each test (allow_plugin is process-wide)."""
    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    monkeypatch.syspath_prepend(str(HERE))


def test_module_path_in_a_file_is_refused_and_nothing_is_imported(tmp_path):
    """The audit's reproducer: evilmod.py beside the study, run from that folder."""
    (tmp_path / "evilmod.py").write_text(EVIL)
    (tmp_path / "study.toml").write_text(
        '[study]\nname = "evil"\ndesign = "factorial"\nevaluator = "evilmod:x"\n'
        '[[factors]]\nname = "x"\nlevels = [0]\n'
    )
    proc = subprocess.run(
        [sys.executable, "-m", "bearingkit.studies", "study.toml", "--no-progress"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert not (tmp_path / "IMPORTED").exists(), "the study file made bearingkit import its module"
    assert proc.returncode == 2
    err = proc.stderr.strip()
    assert len(err.splitlines()) == 1, err
    assert "study.evaluator ('evilmod:x')" in err and "--allow-plugin evilmod:x" in err
    assert not (tmp_path / "study-evil").exists(), "a refused study leaves no output folder"


def test_standard_library_module_is_not_imported_either(no_plugins, tmp_path, monkeypatch):
    (tmp_path / "sidefx_probe.py").write_text(EVIL)
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(InputError, match=r"study\.evaluator \('sidefx_probe:x'\) names Python code"):
        sd.from_dict(_study("sidefx_probe:x"))
    assert "sidefx_probe" not in sys.modules and not (tmp_path / "IMPORTED").exists()


def test_allowed_plugin_works_by_spec_and_by_name(no_plugins):
    with pytest.raises(InputError, match="cannot import code"):
        sd.from_dict(_study("bk_study_helpers:SLOW"))
    ev = evaluators.allow_plugin("bk_study_helpers:SLOW")
    assert ev.name == "slow_counter"
    for name in ("bk_study_helpers:SLOW", "slow_counter"):
        d = sd.from_dict(_study(name))
        assert evaluators.get(d.evaluator) is ev


def test_allow_plugin_checks_what_it_imports(no_plugins):
    with pytest.raises(InputError, match=r"must be 'package\.module:attribute'"):
        evaluators.allow_plugin("bk_study_helpers")
    with pytest.raises(InputError, match="not an Evaluator"):
        evaluators.allow_plugin("bk_study_helpers:EFFECTS")
    with pytest.raises(InputError, match="cannot be imported"):
        evaluators.allow_plugin("bk_no_such_module_here:X")


def test_a_plugin_cannot_take_a_builtin_name(no_plugins, tmp_path, monkeypatch):
    (tmp_path / "shadow_probe.py").write_text(
        "from bearingkit.studies.evaluators import Evaluator, Factor\n"
        "Z = Evaluator('zdt1', lambda c: c, {'x1': Factor('x1', 'dimensionless', 0.0)})\n"
        "S = Evaluator('seed000_statics', lambda c: c, {'x1': Factor('x1', 'dimensionless', 0.0)})\n"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(InputError, match="built-in or installed evaluator"):
        evaluators.allow_plugin("shadow_probe:Z")
    with pytest.raises(InputError, match="built-in or installed evaluator"):  # an entry point's name
        evaluators.allow_plugin("shadow_probe:S")
    assert evaluators.get("zdt1").function is evaluators.zdt1


def test_installed_entry_point_is_found_by_name(no_plugins, monkeypatch):
    eps = [EntryPoint("slow_model", "bk_study_helpers:SLOW", evaluators.ENTRY_POINT_GROUP)]

    def entry_points(group=None, name=None):
        return [e for e in eps if e.group == group and name in (None, e.name)]

    monkeypatch.setattr("importlib.metadata.entry_points", entry_points)
    monkeypatch.setattr(evaluators, "REGISTRY", dict(evaluators.REGISTRY))  # it registers on first use
    d = sd.from_dict(_study("slow_model"))
    assert evaluators.get(d.evaluator).name == "slow_counter"
    with pytest.raises(InputError, match="entry point group"):
        sd.from_dict(_study("not_installed"))


def test_worker_processes_get_the_resolved_evaluator(no_plugins, monkeypatch):
    """The parent resolves the plugin once; workers never resolve a name taken from the file."""
    monkeypatch.setenv("BK_SLEEP", "0")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]))
    evaluators.allow_plugin("bk_study_helpers:SLOW")
    d = sd.from_dict(_study("slow_counter", chunk_size=1))
    with ProcessPoolExecutor(workers=2) as ex:
        res = run_study(d, executor=ex, progress=False)
    assert list(res.results["y"]) == [1.0, 2.0, 5.0]
