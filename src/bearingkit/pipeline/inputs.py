"""Where an analysis starts: a bearing input from a file, a dict, or an already loaded input.

SI units inside; units are parsed here only for the load overrides (``{"F_x": "5 kN"}``, via the
loader's load-case schema). :func:`load_input` is the one entry the pipeline, the CLI, the report, the
studies and the app use to turn "what the user named" into a
:class:`~bearingkit.io.loader.BearingInput` with the load cases to analyse.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io import loader
from bearingkit.lazy import cached_property

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


#: Endings of input files: a text ending so is a path even when no such file exists.
_FILE_SUFFIXES = (".toml", ".json")


def _is_designation(source) -> bool:
    """Text that names no existing file and does not end in .toml/.json is a bearing designation.

    Designations contain slashes (``6308-2RS1/C3``, ``7014 CD/P4A``, ``302/22``): a slash alone does not
    make a path (the command line hands every argument over as a Path).
    """
    text = str(source)
    if text.strip().lower().endswith(_FILE_SUFFIXES):
        return False
    try:
        return not Path(text).exists()
    except (OSError, ValueError):  # a name the file system refuses (too long, NUL) is no file
        return True


def load_input(source, *, load=None, cases: Sequence[str] | None = None, preload=None) -> loader.BearingInput:
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
    preload : str, optional
        Preload of a pair named by designation (``"7014 C DB"``): ``"light"`` … or a force ``"480 N"``
        (``[bearing] preload``, docs/catalogue.md); only with a designation.

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
            header = {"designation": str(source)}
            if preload is not None:
                header["preload"] = str(preload)
            bearing = loader.from_dict({"bearing": header}, source=str(source))
        elif preload is not None:
            raise InputError(
                f"{source}: preload sets a pair named by designation ('7014 C DB'); in a bearing file give "
                "[operating] preload_force"
            )
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


@dataclass(frozen=True)
class _ModelHeader:
    type: str
    source: str | None = None
    designation: str | None = None
    name: str = ""
    C: float | None = None  # the bearing file's [bearing] ratings, where the model came from one
    rating_C: float | None = None
    rating_C0: float | None = None


@dataclass(frozen=True)
class _ModelSolver:
    free: tuple | None = None


@dataclass(frozen=True)
class _ModelSpec:
    bearing: _ModelHeader
    solver: _ModelSolver
    geometry: dict = field(default_factory=dict)


@dataclass(frozen=True)
class ModelInput:
    """A bearing model and its loads as an analysis input: what studies and papers build in code.

    It has the attributes of a loaded file the pipeline reads (``cases``, ``model``, ``free``,
    ``solve()`` …), so :class:`~bearingkit.pipeline.Analysis` runs on it unchanged; the model may carry
    per-case geometry (e.g. a clearance per case), which a file cannot.

    Parameters
    ----------
    model : BearingModel
    load : ndarray (C, 5) [N, N, N, N·m, N·m]
        (F_x, F_y, F_z, M_x, M_y) on the inner ring per case.
    free : ndarray (5,) of bool, optional
        Free DOFs (default all).
    lubricant : Lubricant or str, optional
    source : str
        Name used in messages.
    options : SolverOptions, optional
    material : Material, optional
        Element material (densities for speed effects); default GCr15 bearing steel.
    hardness : HardnessProfile, optional
        The raceways' hardness against depth (subsurface check); default the material's.
    """

    model: object
    load: np.ndarray
    free: np.ndarray | None = None
    lubricant: object = None
    source: str = "<model>"
    options: object = None
    material: object = None
    hardness: object = None

    def __post_init__(self):
        from bearingkit.analysis.solver.options import SolverOptions
        from bearingkit.lubricants import as_lubricant

        load = np.atleast_2d(np.asarray(self.load, dtype=float))
        if load.ndim != 2 or load.shape[1] != 5:
            raise InputError(f"load (shape {load.shape}) must be (cases, 5): F_x, F_y, F_z, M_x, M_y")
        object.__setattr__(self, "load", load)
        free = np.ones(5, bool) if self.free is None else np.asarray(self.free, bool).reshape(5)
        object.__setattr__(self, "free", free)
        if self.lubricant is not None:
            object.__setattr__(self, "lubricant", as_lubricant(self.lubricant))
        if self.options is None:
            object.__setattr__(self, "options", SolverOptions())
        if self.material is None:  # the bearing steel the builders assume by default
            from bearingkit.materials import get_material

            object.__setattr__(self, "material", get_material("GCr15"))

    @cached_property
    def cases(self) -> tuple:
        """One load case per row of ``load`` (named ``case 0`` …)."""
        return tuple(loader.LoadCase(f"case {i}", self.load[i]) for i in range(self.load.shape[0]))

    @property
    def bearing_type(self) -> str:
        return str(self.model.metadata.get("bearing_type", "model"))

    @property
    def sections(self):
        """No [operating]/[fits]/[lubrication] sections: a model built in code has no file."""
        return None

    @property
    def spec(self) -> _ModelSpec:
        free = tuple(n for n, f in zip(loader.DOF_NAMES, self.free, strict=True) if f)
        # the code that built the model chose its free DOFs: no file defaults (such as fixed tilts) apply
        return _ModelSpec(_ModelHeader(self.bearing_type, name=self.model.name), _ModelSolver(free))

    @property
    def geometry(self):
        raise InputError(f"{self.source}: a model built in code has no [geometry] section (needs a file)")

    def load_matrix(self) -> np.ndarray:
        return self.load

    def solve(self):
        """All cases in one batched solve (QuasiStaticResult)."""
        from bearingkit.analysis.solver.quasistatic import solve

        return solve(self.model, self.load, free=self.free, options=self.options)
