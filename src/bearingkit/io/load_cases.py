"""Load cases of the input format: :class:`LoadCase` (SI), the ``--load`` options, and the checks of
loads against the solver's free DOFs.

The names and units of the five load components (in the solver's order) and of the inner-ring DOFs
live here; a load case's eccentricity becomes M_y = M_y − e·F_z once, in :func:`load_case_of`. Every
malformed load raises :class:`bearingkit.errors.InputError` with one line.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from pydantic import ValidationError

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.messages import one_line

#: Inner-ring DOF names, in the solver's order.
DOF_NAMES = schema.DOF_CHOICES
#: Load component names, in the solver's order.
LOAD_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
#: SI units of the load components.
LOAD_UNITS = ("N", "N", "N", "N*m", "N*m")
#: Names accepted for ``--load KEY=VALUE`` on the command line → load-case field.
LOAD_ALIASES: dict[str, str] = {
    **{k: k for k in (*LOAD_NAMES, "eccentricity", "speed", "temperature")},
    "Fx": "F_x",
    "Fr": "F_x",
    "Fy": "F_y",
    "Fz": "F_z",
    "Fa": "F_z",
    "Mx": "M_x",
    "My": "M_y",
    "e": "eccentricity",
    "n": "speed",
    "T": "temperature",
}


@dataclass(frozen=True)
class LoadCase:
    """One load case in SI.

    Attributes
    ----------
    name : str
    load : ndarray (5,) [N, N, N, N·m, N·m]
        (F_x, F_y, F_z, M_x, M_y) on the inner ring, eccentricity already turned into M_y.
    speed : float or None [rad/s]
    temperature : float or None [°C]
    """

    name: str
    load: np.ndarray
    speed: float | None = None
    temperature: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready dict, units in keys."""
        return {
            "case": self.name,
            "speed_rad_s": self.speed,
            "temperature_C": self.temperature,
        }


def parse_load_options(items: Sequence[str], name: str = "command line") -> LoadCase:
    """One load case from ``["Fa=5kN", "My=600N*m", …]`` (names in :data:`LOAD_ALIASES`)."""
    fields: dict[str, str] = {}
    for item in items:
        key, sep, value = item.partition("=")
        key = key.strip()
        if not sep or not value.strip():
            raise InputError(f"--load ({item!r}) must look like NAME=VALUE with a unit, e.g. Fa=5kN")
        if key not in LOAD_ALIASES:
            raise InputError(
                f"--load ({item!r}): unknown name {key!r}; expected one of {', '.join(LOAD_ALIASES)}"
            )
        canonical = LOAD_ALIASES[key]
        if canonical in fields:
            raise InputError(f"--load ({item!r}): {canonical} given twice")
        fields[canonical] = value.strip()
    try:
        spec = schema.LoadCaseSpec.model_validate({"name": name, **fields})
    except ValidationError as exc:
        raise one_line("--load", exc, (), {"": schema.LoadCaseSpec}) from None
    return load_case_of(spec)


def load_case_of(spec: schema.LoadCaseSpec) -> LoadCase:
    """The load case of a validated spec (SI): an eccentricity e along +x adds M_y = −e·F_z."""
    from bearingkit.analysis.solver.quasistatic import load_vector

    m_y = spec.M_y - (spec.eccentricity or 0.0) * spec.F_z
    load = load_vector(F_x=spec.F_x, F_y=spec.F_y, F_z=spec.F_z, M_x=spec.M_x, M_y=m_y)
    return LoadCase(spec.name, load, spec.speed, spec.temperature)


def check_single_tapered(source: str, model, cases, free) -> None:
    """A lone tapered row carries axial load one way only: F_z·direction must be positive if u_z is free.

    With u_z free and no axial load towards the row's cone the inner ring lifts off (no equilibrium).
    """
    rows = model.rows
    if len(rows) != 1 or rows[0].kind != "tapered" or not free[2]:
        return
    sign = rows[0].direction
    word = "positive" if sign > 0 else "negative"
    for c in cases:
        if not c.load[2] * sign > 0.0:
            raise InputError(
                f"{source}: load case {c.name!r}: F_z ({c.load[2]:.6g} N) must be {word}: a single tapered "
                "row carries axial load one way only and lifts off otherwise; use "
                "arrangement DB or DF for reversing loads, or fix u_z in [solver] free"
            )


def check_fixed_loads(source: str, cases, free, loads=None) -> None:
    """No load on a DOF that ``free`` keeps fixed (it would be a reaction, not a load).

    ``loads``: the cases' loads (C, 5) when the caller has them as one array already.
    """
    fixed = np.flatnonzero(~np.asarray(free))
    if not len(cases) or not fixed.size:
        return
    if loads is None:
        loads = np.stack([c.load for c in cases])
    loads = loads[:, fixed]  # one check for every case (studies: thousands)
    bad = np.argwhere(loads != 0.0)
    if bad.size:
        k, j = bad[0]  # the first case, its first fixed DOF: as a loop over cases and DOFs would find
        c, i = cases[k], fixed[j]
        raise InputError(
            f"{source}: load case {c.name!r}: {LOAD_NAMES[i]} ({c.load[i]:.6g} {LOAD_UNITS[i]}) "
            f"acts on {DOF_NAMES[i]}, which [solver] free keeps fixed; free it or remove the load"
        )
