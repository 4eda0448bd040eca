"""Packaging (issue 42): what a wheel installed outside the source tree needs from the code itself.

``scripts/check_wheel.py`` (``make wheel``, in CI) builds and installs the wheel and uses it from another
folder; these tests catch the same faults in seconds, without a build:

- an example file looked up relative to a module's own file (``Path(__file__).parents … / "examples"``)
  exists in a clone but not in an installed wheel, where the examples are data files under
  ``share/bearingkit/examples`` (a validation case did this and failed ``validate --quick`` from the
  wheel only). :func:`bearingkit.paths.examples_dir` is the one place that knows both locations;
- ``validate --quick`` takes exactly one case from every source the full run has.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from bearingkit import paths
from bearingkit.validation.registry import all_cases, quick_cases

SRC = Path(paths.__file__).resolve().parent
#: A path built towards the examples folder by hand: ``… / "examples"`` or ``Path("examples")``.
BY_HAND = re.compile(r"""/\s*["']examples["']|Path\(\s*["']examples["']""")


def test_example_files_are_found_only_through_bearingkit_paths():
    offenders = [
        f"{p.relative_to(SRC)}:{i}: {line.strip()}"
        for p in sorted(SRC.rglob("*.py"))
        if p.name != "paths.py"
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if BY_HAND.search(line) and not line.lstrip().startswith("#")
    ]
    assert offenders == [], "use bearingkit.paths.examples_dir(): " + "; ".join(offenders)


def test_the_check_finds_a_path_built_by_hand():
    assert BY_HAND.search('candidate = parent / "examples" / name')
    assert BY_HAND.search("Path('examples') / 'dgbb_6209.toml'")
    assert not BY_HAND.search('"examples": examples(),')


def test_installed_examples_are_found_when_the_repository_has_none(tmp_path, monkeypatch):
    """A wheel's layout: no examples/ beside the package, the data files under the prefix."""
    installed = tmp_path / paths.INSTALLED_EXAMPLES
    installed.mkdir(parents=True)
    monkeypatch.setattr(paths, "REPOSITORY_EXAMPLES", tmp_path / "no-such-folder")
    monkeypatch.setattr(paths.sys, "prefix", str(tmp_path))
    monkeypatch.setattr(paths.sysconfig, "get_path", lambda *a, **k: str(tmp_path / "elsewhere"))
    assert paths.examples_dir() == installed


def test_validate_quick_takes_one_case_of_every_source():
    cases = all_cases(())
    quick = quick_cases(cases)
    sources = [c.id.partition("/")[0] for c in quick]
    assert len(sources) == len(set(sources))
    assert set(sources) == {c.id.partition("/")[0] for c in cases}
    assert len(quick) < len(cases) / 5  # a few seconds, not the full run


def test_no_source_file_is_git_ignored():
    """A module the ignore rules hide is in the developer's tree but in no clone and no wheel (``build/``
    once hid ``io/build/``: its ``structure.py`` reached the integrated branch only by a later commit)."""
    out = subprocess.run(
        ["git", "ls-files", "--others", "--ignored", "--exclude-standard", "src/bearingkit"],
        cwd=SRC.parents[1],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    assert [f for f in out if "__pycache__" not in f] == []
