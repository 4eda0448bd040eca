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


def one_way_row(model):
    """The row of a bearing whose single row carries axial load one way only, and that way (+1/−1):
    a lone tapered row (its ``direction``) or a lone one-sided angular contact ball row (sign of α);
    None for any other bearing."""
    rows = model.rows
    if len(rows) != 1:
        return None
    row = rows[0]
    if row.kind == "tapered":
        return row, int(row.direction)
    if row.kind == "ball":
        from bearingkit.rows.ball.row import one_sided_row

        alpha = np.asarray(row.contact_angle, float)
        if alpha.size == 1 and float(alpha) != 0.0 and one_sided_row(row, alpha):
            return row, int(np.sign(float(alpha)))
    return None


def mounted_free(source: str, model, cases, free, user_set: bool = False, loads=None):
    """The DOFs a single one-way row is solved with, and the note of an automatic hold.

    A lone tapered or angular contact row carries axial load one way only: with u_z free it needs
    F_z·direction > 0 in every case (otherwise the inner ring lifts off: no equilibrium). When every case
    gives F_z = 0 and the user set no DOFs, u_z is held at 0 — the bearing as mounted against an opposite
    one with zero end play, which is how commercial tools answer for a single bearing — and the axial
    reaction is that bearing's load. A tapered row with a case of F_z·direction < 0, or with some cases at
    F_z = 0 and others not, is refused (one line naming the remedy).

    Returns
    -------
    (ndarray (5,) of bool, tuple of str)
        The free DOFs and the notes (empty when nothing was held). ``loads``: the cases' loads (C, 5)
        when the caller has them as one array (a study's group).
    """
    found = one_way_row(model)
    free = np.asarray(free, bool)
    if found is None or not free[2] or not len(cases):
        return free, ()
    row, sign = found
    fz = (np.asarray(loads)[:, 2] if loads is not None else np.array([c.load[2] for c in cases])) * sign
    if np.all(fz > 0.0):
        return free, ()
    what = "tapered roller" if row.kind == "tapered" else "angular contact ball"
    if np.all(fz == 0.0) and not user_set:
        held = free.copy()
        held[2] = False
        note = (
            f"u_z held: a single {what} row under no axial load cannot balance the axial force its radial "
            "load induces, so it is solved with the axial displacement held at 0, as mounted against an "
            "opposite bearing with zero end play; the axial reaction F_z (* in the tables) is the load that "
            "bearing takes. Give F_a towards the row to solve it with u_z free"
        )
        return held, (note,)
    if row.kind != "tapered":
        return free, ()  # the solver says why a reversed load on a ball row has no equilibrium
    word = "positive" if sign > 0 else "negative"
    c = cases[int(np.flatnonzero(~(fz > 0.0))[0])]
    raise InputError(
        f"{source}: load case {c.name!r}: F_z ({c.load[2]:.6g} N) must be {word}: a single tapered "
        "row carries axial load one way only and lifts off otherwise; hold u_z (--hold u_z, or leave "
        "u_z out of [solver] free) to solve it against an opposite bearing, give F_z in every case, "
        "or use arrangement DB or DF for reversing loads"
    )


def check_single_tapered(source: str, model, cases, free) -> None:
    """A lone tapered row with u_z free must get F_z·direction > 0 in every case (:func:`mounted_free`
    with the user's DOFs: nothing is held automatically)."""
    mounted_free(source, model, cases, free, user_set=True)


def override_free(source: str, free, hold=(), release=()):
    """``free`` with the DOFs named in ``hold`` fixed and those in ``release`` freed (names of
    :data:`DOF_NAMES`); InputError for an unknown name or a DOF both held and freed."""
    out = np.array(free, bool)
    for names, value, option in ((hold, False, "--hold"), (release, True, "--free")):
        for name in names:
            if name not in DOF_NAMES:
                raise InputError(
                    f"{source}: {option} ({name!r}) must name a DOF: one of {', '.join(DOF_NAMES)}"
                )
            out[DOF_NAMES.index(name)] = value
    both = set(hold) & set(release)
    if both:
        raise InputError(
            f"{source}: {', '.join(sorted(both))} both held (--hold) and freed (--free); give one"
        )
    return out


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
            f"acts on {DOF_NAMES[i]}, which is held ([solver] free or --hold); free it or remove the load"
        )
