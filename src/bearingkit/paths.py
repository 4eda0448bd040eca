"""Where bearingkit's example files are: the repository's ``examples/`` or the copy a wheel installs.

A source checkout (and an editable install) has ``examples/`` beside ``src/``. A wheel installs the same
files as data under ``<prefix>/share/bearingkit/examples`` (``[tool.setuptools.data-files]`` in
``pyproject.toml``), so ``bearingkit validate`` (the seed studies), the web app's example list and the
flagship demonstration work from an installed package too.
"""

from __future__ import annotations

import sys
import sysconfig
from pathlib import Path

#: The repository's examples (src/bearingkit/paths.py → ../../examples).
REPOSITORY_EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
#: Where a wheel's data files put them, below an installation prefix.
INSTALLED_EXAMPLES = Path("share") / "bearingkit" / "examples"


def examples_dir() -> Path:
    """The examples folder: the repository's if present, else the installed copy (first found of the
    environment's prefix, the user prefix); the repository's path when neither exists (messages name it)."""
    if REPOSITORY_EXAMPLES.is_dir():
        return REPOSITORY_EXAMPLES
    prefixes = [sysconfig.get_path("data"), sys.prefix]
    try:
        prefixes.append(sysconfig.get_path("data", f"{sysconfig.get_default_scheme().split('_')[0]}_user"))
    except KeyError:  # no user scheme on this platform
        pass
    for prefix in prefixes:
        candidate = Path(prefix) / INSTALLED_EXAMPLES
        if candidate.is_dir():
            return candidate
    return REPOSITORY_EXAMPLES
