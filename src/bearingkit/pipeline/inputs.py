"""Where an analysis starts: a bearing input from a file, a dict, or an already loaded input.

SI units inside; units are parsed here only for the load overrides (``{"F_x": "5 kN"}``, via the
loader's load-case schema). :func:`load_input` is the one entry the pipeline, the CLI, the report, the
studies and the app use to turn "what the user named" into a
:class:`~bearingkit.io.loader.BearingInput` with the load cases to analyse.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from bearingkit.errors import InputError
from bearingkit.io import loader

__all__ = ["load_cases_from", "load_input"]


def _as_items(load) -> list[str]:
    """``{"F_x": "5 kN"}`` or ``["Fr=5kN", …]`` → ``["F_x=5 kN", …]`` (the ``--load`` syntax)."""
    if isinstance(load, Mapping):
        return [f"{k}={v}" for k, v in load.items()]
    if isinstance(load, str):
        return [load]
    return [str(item) for item in load]


def load_cases_from(load, name: str = "load") -> list:
    """Load cases from one override or a list of overrides.

    Parameters
    ----------
    load : Mapping or sequence of str, or a sequence of those
        One case (``{"F_x": "5 kN", "speed": "3000 rpm"}`` or ``["Fr=5kN", "Fa=1kN"]``) or several
        (a list of mappings). Names as ``bearingkit analyze --load`` (F_x/Fr, F_z/Fa, M_y, speed …),
        values with their unit.
    name : str
        Case name (``load``, or ``load_1``, ``load_2`` … for several).
    """
    if isinstance(load, Sequence) and not isinstance(load, str) and load and isinstance(load[0], Mapping):
        return [loader.parse_load_options(_as_items(one), f"{name}_{i}") for i, one in enumerate(load, 1)]
    return [loader.parse_load_options(_as_items(load), name)]


def _is_designation(source) -> bool:
    """Text that names no existing file and no TOML/JSON path is a bearing designation (``6205-2RS C3``)."""
    path = Path(source)
    return not path.exists() and path.suffix.lower() not in (".toml", ".json") and "/" not in str(source)


def load_input(source, *, load=None, cases: Sequence[str] | None = None) -> loader.BearingInput:
    """The bearing input an analysis runs on.

    Parameters
    ----------
    source : str, Path, dict or BearingInput
        An input file (docs/input-format.md), a standard bearing designation (``"6205-2RS C3"``,
        docs/catalogue.md: its internal geometry is estimated), an already parsed file (dict), or a
        loaded input.
    load : optional
        Load case(s) replacing the file's (see :func:`load_cases_from`).
    cases : sequence of str, optional
        Only the file's load cases with these names (not with ``load``).

    Returns
    -------
    BearingInput
        Bad input raises :class:`~bearingkit.errors.InputError` with one line.
    """
    if isinstance(source, loader.BearingInput):
        bearing = source
    elif isinstance(source, Mapping):
        bearing = loader.from_dict(dict(source))
    elif isinstance(source, (str, Path)):
        if _is_designation(source):
            bearing = loader.from_dict({"bearing": {"designation": str(source)}}, source=str(source))
        else:
            bearing = loader.load_file(Path(source))
    else:
        raise InputError(
            f"source ({type(source).__name__}) must be an input file path, a dict or a BearingInput"
        )
    if load is not None:
        if cases:
            raise InputError("cases select the file's load cases; they cannot be combined with load")
        return bearing.with_cases(load_cases_from(load))
    return bearing.select(cases)
