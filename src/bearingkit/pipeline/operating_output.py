"""The operating-condition results of an analysis: preload per row, lubrication, speed per row, warnings.

SI units (N, m, m²/s, rad, rad/s, s; temperatures in °C). Used by :class:`bearingkit.pipeline.Analysis`
(its ``preload``, ``lubrication`` and the operating parts of ``statics_dict``/``to_dict``/``warnings``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError

__all__ = [
    "KAPPA_LOW",
    "LAMBDA_LOW",
    "LubricationOutcome",
    "contamination_values",
    "lubrication",
    "operating_warnings",
    "preload_state",
    "resolve_contamination",
    "rest_speed_dicts",
    "row_speed_dicts",
]

#: κ below which ISO 281 lubrication is insufficient for a full film (a_ISO penalises it) [-].
KAPPA_LOW = 1.0
#: Film parameter below which the contacts run in mixed lubrication (surface distress risk) [-].
LAMBDA_LOW = 1.0
#: Skidding criterion: the most loaded ball's inner contact load below this multiple of the ball's
#: centrifugal force means the inner ring barely drives the ball set (a documented choice; minimum-load
#: rules of catalogues serve the same purpose with empirical factors) [-].
SKID_RATIO = 1.0
HOUR = 3600.0


def _pitch_diameter(row) -> float:
    """d_m of a row [m] (ISO 281 Table 13 reads it): its ``pitch_diameter``, or its geometry's (a
    threaded roller row keeps it in its ``PTRBGeometry``)."""
    dm = getattr(row, "pitch_diameter", None)
    if dm is None:
        dm = getattr(getattr(row, "geometry", None), "pitch_diameter", 0.0)
    return float(np.max(dm))


def resolve_contamination(bearing, value):
    """(e_C, level name or None) from a number, an ISO 281 level name, or the file's ``[lubrication]``."""
    from bearingkit.physics.life.iso281_contamination import contamination_factor, contamination_levels
    from bearingkit.pipeline.conditions import _sections

    lub = _sections(bearing).lubrication
    if value is None and lub is not None:
        value = lub.contamination
    if value is None:
        return None, None
    if isinstance(value, str) and value.strip() in contamination_levels():
        dm = max(_pitch_diameter(r) for r in bearing.model.rows)
        return contamination_factor(value.strip(), dm), value.strip()
    if isinstance(value, str):
        from bearingkit.units import parse

        try:
            return parse(value, "dimensionless", "contamination"), None
        except InputError:
            contamination_factor(value, 1.0)  # raises the one-line error listing the levels
    return float(value), None


def contamination_values(bearing) -> dict[str, float]:
    """ISO 281 level name → e_C for ``bearing`` (its pitch diameter selects the Table 13 column): what a
    level name means wherever a contamination is given (files, command line, studies)."""
    from bearingkit.physics.life.iso281_contamination import contamination_levels

    return {level: resolve_contamination(bearing, level)[0] for level in contamination_levels()}


def preload_state(analysis) -> dict | None:
    """Axial force [N] per row at rest without external load (the preload), or None when none.

    Solved for bearings whose rows face each other and that are preloaded: by ``[operating]
    preload_*``, by a negative clearance, or by a fit that takes the clearance away.
    """
    from bearingkit.analysis.solver.quasistatic import solve
    from bearingkit.pipeline.conditions import _opposed

    setup, model = analysis.setup, analysis.input.model
    if _opposed(model) is None:
        return None
    negative = any(np.any(np.asarray(getattr(r, "clearance", 0.0)) < 0) for r in model.rows)
    chain = setup.clearance
    lost = chain is not None and any(np.any(v < 0) for v in chain.operating.values())
    if setup.preload_offset is None and not negative and not lost:
        return None
    offsets = None
    if setup.offsets:
        offsets = {k: v.take(np.array([0])) for k, v in setup.offsets.items()}
    res = solve(
        model,
        np.zeros(5),
        free=[False, False, True, False, False],
        options=analysis.input.options,
        raceway_offsets=offsets,
    )
    if not res.converged[0]:
        return None
    return {r.name: float(abs(res.row_load(r.name)[0, 2])) for r in model.rows}


@dataclass
class LubricationOutcome:
    """Lubrication of every case: films per contact, ν, ν1, κ, e_C, a_ISO, L_nm and grease life.

    Attributes
    ----------
    result : LubricationResult
    contamination : float or None
        e_C used for a_ISO.
    contamination_level : str or None
        The ISO 281 level it came from.
    grease_life : ndarray (C,) or None [s]
    notes : list of str
    """

    result: object
    contamination: float | None
    contamination_level: str | None
    grease_life: np.ndarray | None
    rating: object = None
    notes: list = field(default_factory=list)

    def to_dict(self, case: int) -> dict:
        """JSON-ready lubrication of one case (SI, units in keys)."""
        res = self.result
        a_iso = {}
        if self.rating is not None:
            for r in self.rating.rows:
                value = np.ma.asarray(r.life_modification)
                a_iso[r.name] = None if np.ma.getmaskarray(value)[case] else float(np.ma.getdata(value)[case])
        rows = []
        for f in res.films:
            kappa = float(res.kappa[f.row][case])
            nu1 = float(res.reference_viscosity[f.row][case])
            lam = float(f.min_lambda()[case])
            rows.append(
                {
                    "name": f.row,
                    "reference_viscosity_m2_s": None if np.isnan(nu1) else nu1,
                    "kappa": None if np.isnan(kappa) else kappa,
                    "a_ISO": a_iso.get(f.row),
                    "min_film_parameter": None if not np.isfinite(lam) else lam,
                    "film_minimum_inner_m": f.film_minimum_inner[case].tolist(),
                    "film_minimum_outer_m": f.film_minimum_outer[case].tolist(),
                    "film_central_inner_m": f.film_central_inner[case].tolist(),
                    "film_central_outer_m": f.film_central_outer[case].tolist(),
                    "film_parameter_inner": f.lambda_inner[case].tolist(),
                    "film_parameter_outer": f.lambda_outer[case].tolist(),
                }
            )
        life = None
        life_h = None
        if self.rating is not None:
            value = np.ma.asarray(self.rating.modified_life)
            if not np.ma.getmaskarray(value)[case]:
                life = float(np.ma.getdata(value)[case])
                hours = np.ma.asarray(self.rating.hours(self.rating.modified_life))
                life_h = None if np.ma.getmaskarray(hours)[case] else float(np.ma.getdata(hours)[case])
        grease = None
        if self.grease_life is not None and np.isfinite(self.grease_life[case]):
            grease = float(self.grease_life[case] / HOUR)
        return {
            "viscosity_m2_s": float(res.viscosity[case]),
            "contamination_factor": self.contamination,
            "contamination_level": self.contamination_level,
            "rows": rows,
            "Lnm_rev": life,
            "Lnm_h": life_h,
            "grease_life_h": grease,
            "skipped_rows": list(res.skipped),
            "notes": list(self.notes),
        }


def lubrication(analysis):
    """The :class:`LubricationOutcome` of an analysis, or None without a lubricant."""
    from bearingkit.analysis.lubrication import ROUGHNESS_ELEMENT, ROUGHNESS_RACEWAY
    from bearingkit.analysis.lubrication import lubrication as films

    op, b = analysis.operating, analysis.input
    if op.lubricant is None:
        return None
    from bearingkit.pipeline.conditions import _sections

    spec = _sections(b).lubrication
    opsec = _sections(b).operating
    rough_e = ROUGHNESS_ELEMENT if spec is None or spec.roughness_element is None else spec.roughness_element
    rough_r = ROUGHNESS_RACEWAY if spec is None or spec.roughness_raceway is None else spec.roughness_raceway
    zero = np.zeros_like(op.speed)
    w_i, w_o = (op.speed, zero) if op.rotating == "inner" else (zero, op.speed)
    res = analysis._in_file(films, analysis.statics, w_i, w_o, op.lubricant, op.temperature, rough_e, rough_r)
    notes = []
    if not np.all(op.abs_speed > 0):
        notes.append("no speed in some cases: no film, ν1 or κ there")
    grease = None
    grease_class = None if spec is None else spec.grease
    if grease_class is None and spec is not None and spec.grease_limiting_speed is not None:
        if op.lubricant.is_grease:  # the grease's own class (its data) when [lubrication] names none
            grease_class = op.lubricant.grease.life_class
    if grease_class is not None:
        if spec.grease_limiting_speed is None:
            notes.append(
                "grease life: give [lubrication] grease_limiting_speed (the catalogue limiting speed)"
            )
        elif analysis.input.bearing_type != "deep_groove_ball":
            notes.append("grease life: the NSK formula is for sealed deep groove ball bearings only")
        else:
            from bearingkit.physics.lubrication.grease_life import grease_life

            outer = op.temperature
            if opsec is not None and opsec.temperature_outer_ring is not None:
                outer = np.full_like(op.temperature, opsec.temperature_outer_ring)
            grease = grease_life(op.abs_speed, spec.grease_limiting_speed, outer, grease_class)
            notes.append(
                "grease life: NSK catalogue formula for sealed deep groove ball bearings (loads ≤ C/10)"
            )
    return LubricationOutcome(
        res, op.contamination, getattr(analysis, "contamination_level", None), grease, analysis.rating, notes
    )


#: Keys of the speed results of a row, by row kind: every case dict has them, at any speed
#: (:func:`rest_speed_dicts` gives their values where the statics were solved without element inertia).
SPEED_KEYS = {
    "ball": (
        "contact_angle_inner_rad",
        "contact_angle_outer_rad",
        "loads_inner_N",
        "loads_outer_N",
        "centrifugal_force_N",
        "gyroscopic_moment_Nm",
        "spin_to_roll_inner",
        "spin_to_roll_outer",
        "attitude_angle_rad",
        "cage_speed_rad_s",
        "ball_spin_speed_rad_s",
    ),
    "cylindrical": ("loads_inner_N", "loads_outer_N", "centrifugal_force_N", "cage_speed_rad_s"),
}


def rest_speed_dicts(row: dict) -> dict:
    """The speed keys of :data:`SPEED_KEYS` a row dict lacks (solved at rest, or without speed effects),
    with the values of a solve without element inertia: contact angles and loads of the statics (inner =
    outer), zero centrifugal force and gyroscopic moment, and None for what such a solve does not give
    (spin-to-roll ratios, cage and ball spin speed)."""
    keys = SPEED_KEYS.get(row.get("kind"), ())
    zeros = [0.0] * len(row.get("loads_N", ()))
    rest = {
        "contact_angle_inner_rad": row.get("contact_angle_rad"),
        "contact_angle_outer_rad": row.get("contact_angle_rad"),
        "loads_inner_N": row.get("loads_N"),
        "loads_outer_N": row.get("loads_N"),
        "centrifugal_force_N": zeros,
        "gyroscopic_moment_Nm": zeros,
        "spin_to_roll_inner": None,
        "spin_to_roll_outer": None,
        "attitude_angle_rad": zeros,
        "cage_speed_rad_s": None,
        "ball_spin_speed_rad_s": None,
    }
    return {k: rest[k] for k in keys if k not in row}


def row_speed_dicts(state, case: int) -> dict:
    """The speed results of one row and case (empty for a row solved without speed)."""
    ex = state.extras
    out = {}
    pairs = (
        ("contact_angle_inner", "contact_angle_inner_rad"),
        ("contact_angle_outer", "contact_angle_outer_rad"),
        ("load_inner", "loads_inner_N"),
        ("load_outer", "loads_outer_N"),
        ("centrifugal_force", "centrifugal_force_N"),
        ("gyroscopic_moment", "gyroscopic_moment_Nm"),
        ("spin_to_roll_inner", "spin_to_roll_inner"),
        ("spin_to_roll_outer", "spin_to_roll_outer"),
        ("attitude_angle", "attitude_angle_rad"),
    )
    if "centrifugal_force" not in ex:
        return out
    for key, name in pairs:
        if key in ex:
            out[name] = np.asarray(ex[key][case], dtype=float).tolist()
    if "cage_speed" in ex:
        out["cage_speed_rad_s"] = float(np.asarray(ex["cage_speed"][case]).ravel()[0])
    if "ball_spin_speed" in ex:
        out["ball_spin_speed_rad_s"] = float(np.abs(np.asarray(ex["ball_spin_speed"][case])).max())
    return out


def operating_warnings(analysis, case: int) -> list[str]:
    """Warnings the operating conditions imply for one case: lost clearance, κ < 1, Λ < 1, skidding."""
    out = []
    chain = analysis.clearance
    if chain is not None:
        for name in chain.rows:
            value = float(np.broadcast_to(chain.operating[name], (analysis.n_cases,))[case])
            if value < 0 <= float(np.max(chain.initial[name])):
                out.append(
                    f"row {name!r}: clearance lost to the fits and temperatures (operating clearance "
                    f"{value * 1e6:.3g} µm: a preload)"
                )
        out += [w for w in chain.warnings if "clearance is lost" not in w]
    res = analysis.statics
    for state in res.rows:
        ex = state.extras
        if "centrifugal_force" in ex and state.kind == "ball":
            q_max = float(ex["load_inner"][case].max())
            f_c = float(ex["centrifugal_force"][case].max())
            if q_max < SKID_RATIO * f_c:
                out.append(
                    f"row {state.name!r}: even the most loaded ball presses the inner ring less "
                    f"({q_max:.3g} N) than "
                    f"its centrifugal force presses the outer ({f_c:.3g} N): the inner ring can hardly "
                    "drive the "
                    "ball set — ball–cage overspeed / skidding risk; add load or preload"
                )
    lube = analysis.operating.lubricant
    limit = None if lube is None or lube.grease is None else lube.grease.temperature_max_C
    t = float(analysis.operating.temperature[case])
    if limit is not None and t > limit:
        found = "found " if getattr(analysis, "thermal", None) is not None else ""
        out.append(
            f"the {found}operating temperature {t:.4g} °C is above the upper limit of grease {lube.name!r} "
            f"({limit:g} °C, its data sheet): choose a grease for higher temperatures or cool the bearing"
        )
    lub = analysis.lubrication
    if lub is not None:
        for f in lub.result.films:
            kappa = float(lub.result.kappa[f.row][case])
            if np.isfinite(kappa) and kappa < KAPPA_LOW:
                out.append(
                    f"row {f.row!r}: viscosity ratio κ = {kappa:.3g} < 1: the lubricant is too thin for a "
                    "full film "
                    "(ISO 281 a_ISO penalises it; choose a more viscous oil or run cooler)"
                )
            lam = float(f.min_lambda()[case])
            if np.isfinite(lam) and lam < LAMBDA_LOW:
                out.append(
                    f"row {f.row!r}: film parameter Λ = {lam:.3g} < 1 at the most loaded contact: mixed "
                    "lubrication, asperity contact (surface distress risk)"
                )
    return out
