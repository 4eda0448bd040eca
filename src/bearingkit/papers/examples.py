"""Running the papers' example studies: locate, resize and run ``examples/studies/<name>.toml``.

SI units throughout (N, m, N·m, rad); DataFrame columns carry their unit. Every study here is one of
the example files in ``examples/studies`` run by :func:`bearingkit.studies.run.runner.run_study` (the same
path as ``bearingkit study FILE``); the helpers only change sizes (population, samples) or one fixed
value, and post-process the :class:`~bearingkit.studies.run.cases.StudyResult`:

- seed 000 (Tian et al. 2025) — ``seed000_l9.toml``: the L9(3^4) design of Tables 2–3, friction torque
  per run matched to Table 3 (:func:`seed000_table3`) and the range ranking (:func:`ranking`);
- seed 004 (Zheng et al. 2022) — ``seed004_{axial,radial}_nsga2.toml``: §6 NSGA-II of the PTRB,
  Pareto front and the selections nearest Table 6 (:func:`seed004_optimize`, :func:`table6_comparison`);
- seed 001 (Liu et al. 2022) — ``seed001_monte_carlo.toml``: roller-diameter scatter, one run per S_d
  with common random numbers (:func:`seed001_monte_carlo`, :func:`seed001_summary`);
- seed 002 (Li et al. 2025) — ``seed002_clearance_map.toml``: roller share of the radial load over
  ball × roller clearance at a light and a heavy load (:func:`seed002_clearance_map`).

``python -m bearingkit.papers OUT_DIR [--small]`` runs all of them and writes CSV/PNG. The
post-processing of each paper's study lives in its package (``study_runs.py``).
"""

from __future__ import annotations

from pathlib import Path

from bearingkit.paths import examples_dir
from bearingkit.studies.definition.load import StudyDefinition, load_study
from bearingkit.studies.run.cases import StudyResult
from bearingkit.studies.run.runner import run_study

__all__ = ["STUDIES_DIR", "example", "resized", "run_example"]

#: The example study files (the repository's examples/studies, or the copy a wheel installs).
STUDIES_DIR = examples_dir() / "studies"


def example(name: str) -> Path:
    """Path of ``examples/studies/<name>.toml``."""
    from bearingkit.errors import InputError

    path = STUDIES_DIR / f"{name}.toml"
    if not path.is_file():
        raise InputError(
            f"example study ({name!r}) not found at {path} (a source checkout or an installed wheel has it)"
        )
    return path


def resized(
    definition: StudyDefinition,
    *,
    pop_size: int | None = None,
    generations: int | None = None,
    samples: int | None = None,
    fixed: dict | None = None,
) -> StudyDefinition:
    """A copy of ``definition`` with a new optimiser size, sample count or extra ``[fixed]`` values (SI).

    The copy has its own fingerprint, so a store never mixes it with the original study.
    """
    update: dict = {}
    opt = {k: v for k, v in (("pop_size", pop_size), ("generations", generations)) if v is not None}
    if opt:
        update["optimizer"] = definition.optimizer.model_copy(update=opt)
    if samples is not None:
        update["samples"] = int(samples)
    if fixed:
        update["fixed"] = {**definition.fixed, **fixed}
    return definition.model_copy(update=update)


def run_example(name: str, *, executor=None, store=None, progress=False, **resize) -> StudyResult:
    """Run ``examples/studies/<name>.toml`` (optionally :func:`resized`) and return its result."""
    d = load_study(example(name))
    if resize:
        d = resized(d, **resize)
    return run_study(d, executor=executor, store=store, progress=progress)
