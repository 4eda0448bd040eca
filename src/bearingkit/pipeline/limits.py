"""Speed and load limits of an analysed standard bearing: what every catalogue prints beside the ratings.

SI units (rad/s, m/s, N; n·d_m in mm·r/min as catalogues print it). For a bearing type the catalogue
models know (:mod:`bearingkit.pipeline.bearing_facts`), per case:

- the **limiting speed** n_lim (kinematic: cage, elements; by type, lubrication method and cage,
  :func:`bearingkit.physics.limits.limiting_speed`) — above it, a warning;
- the **thermal reference speed** n_θr of ISO 15312 by the SKF model
  (:mod:`bearingkit.pipeline.thermal.reference`)
  — above it the bearing runs hotter than 70 °C in the reference housing unless cooled: a warning that
  points to the heat balance; computed only when a case runs above :data:`REFERENCE_CHECK_SHARE` of n_lim
  (below it no bearing of the tables reaches n_θr, and the bisection costs a few hundred friction calls);
- the **seal lip speed** of a rubbing seal against :data:`bearingkit.physics.limits.SEAL_LIP_SPEED_LIMIT`;
- the **requisite minimum load** (:func:`bearingkit.physics.limits.minimum_load`) against the load the
  bearing carries: F_r + F_a for radial bearings (an axial load loads the elements too), F_a for thrust
  bearings — below it, a warning (skidding, smearing).

Every face shows the warnings (:attr:`bearingkit.pipeline.Analysis.warnings`), the values
(``limits`` in the JSON of ``analyze``/``rating``, a line in the tables, the report's operating part)
and studies read them as outputs (``above_limiting_speed`` …).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.physics import limits as physics

__all__ = ["REFERENCE_CHECK_SHARE", "THRUST_TYPES", "OperatingLimits", "operating_limits"]

#: The thermal reference speed is computed when a case runs above this share of the limiting speed [-]
#: (module docstring; SKF's reference speeds lie above 0.5 n_lim for the SKF types of speed_limits.csv, and
#: at 0.29-0.39 of the precision row's n_lim for 15° spindle bearings — a review found the 718 C at 0.288).
REFERENCE_CHECK_SHARE = 0.2
#: Bearing types whose minimum load is an axial one.
THRUST_TYPES = ("thrust_ball", "cylindrical_roller_thrust")
_RPM = 30.0 / np.pi
_MM = 1.0e3


def _a(noun: str) -> str:
    return f"{'an' if noun[:1] in 'aeiou' else 'a'} {noun}"


@dataclass
class OperatingLimits:
    """Speed and load limits of every case (module docstring). Arrays (C,).

    Attributes
    ----------
    bearing_type : str
    lubrication : str
    n_dm : ndarray [mm·r/min]
    speed : ndarray [rad/s]
        |relative ring speed|.
    limiting_speed : float [rad/s]
    limiting_source : str
    reference_speed : float or None [rad/s]
    reference_note : str or None
    seal : str or None
        Suffix of a rubbing seal whose lip speed is checked.
    seal_lip_speed : ndarray or None [m/s]
    minimum_load, load : ndarray or None [N]
        Requisite minimum load and the load compared with it.
    minimum_load_rule : str or None
    notes : list of str
    """

    bearing_type: str
    lubrication: str
    n_dm: np.ndarray
    speed: np.ndarray
    limiting_speed: float
    limiting_source: str
    reference_speed: float | None = None
    reference_note: str | None = None
    seal: str | None = None
    seal_lip_speed: np.ndarray | None = None
    minimum_load: np.ndarray | None = None
    load: np.ndarray | None = None
    minimum_load_rule: str | None = None
    notes: list = field(default_factory=list)

    def flags(self, case: int) -> dict:
        """Which limit case ``case`` exceeds (bool per limit; False where a limit was not evaluated)."""
        n = float(self.speed[case])
        seal = self.seal_lip_speed is not None and self.seal_lip_speed[case] > physics.SEAL_LIP_SPEED_LIMIT
        low = self.minimum_load is not None and n > 0 and self.load[case] < self.minimum_load[case]
        return {
            "above_limiting_speed": bool(n > self.limiting_speed),
            "above_reference_speed": bool(self.reference_speed is not None and n > self.reference_speed),
            "seal_lip_speed_exceeded": bool(seal),
            "below_minimum_load": bool(low),
        }

    def warnings(self, case: int) -> list[str]:
        """One line per limit exceeded by case ``case``."""
        f, out = self.flags(case), []
        rpm = float(self.speed[case]) * _RPM
        if f["above_limiting_speed"]:
            kind = _a(self.bearing_type.replace("_", " "))
            out.append(
                f"speed {rpm:.5g} r/min (n·d_m = {self.n_dm[case]:.3g} mm·r/min) is above the limiting speed "
                f"{self.limiting_speed * _RPM:.4g} r/min of {kind} bearing "
                f"with {self.lubrication.replace('_', ' ')} ({self.limiting_source}): cage and rolling "
                "elements beyond their kinematic limit; choose a bearing for higher speeds"
            )
        if f["above_reference_speed"]:
            out.append(
                f"speed {rpm:.5g} r/min is above the ISO 15312 thermal reference speed "
                f"{self.reference_speed * _RPM:.4g} r/min (SKF model): in a reference housing the bearing "
                "runs hotter than 70 °C unless cooled; check the heat balance (bearingkit friction --heat)"
            )
        if f["seal_lip_speed_exceeded"]:
            out.append(
                f"seal {self.seal}: lip sliding speed {self.seal_lip_speed[case]:.3g} m/s is above "
                f"{physics.SEAL_LIP_SPEED_LIMIT:g} m/s of a rubbing NBR lip: it overheats and wears; use "
                "low-friction (RSL) or non-contact (RZ, Z) closures at this speed"
            )
        if f["below_minimum_load"]:
            out.append(
                f"load {self.load[case]:.4g} N is below the requisite minimum load "
                f"{self.minimum_load[case]:.4g} N ({self.minimum_load_rule}): lightly loaded elements skid "
                "and smear the raceways; add load or preload"
            )
        return out

    def to_dict(self, case: int) -> dict:
        """JSON-ready limits of one case (SI, units in keys; the same keys for every bearing)."""

        def pick(a):
            return None if a is None else float(a[case])

        return {
            "bearing_type": self.bearing_type,
            "lubrication": self.lubrication,
            "n_dm_mm_rpm": float(self.n_dm[case]),
            "limiting_speed_rad_s": self.limiting_speed,
            "limiting_speed_source": self.limiting_source,
            "thermal_reference_speed_rad_s": self.reference_speed,
            "thermal_reference_speed_note": self.reference_note,
            "seal": self.seal,
            "seal_lip_speed_m_s": pick(self.seal_lip_speed),
            "seal_lip_speed_limit_m_s": None if self.seal is None else physics.SEAL_LIP_SPEED_LIMIT,
            "minimum_load_N": pick(self.minimum_load),
            "load_compared_N": pick(self.load),
            "minimum_load_rule": self.minimum_load_rule,
            "flags": self.flags(case),
            "notes": list(self.notes),
        }


def _reference_speed(analysis, facts, n_lim: float) -> tuple[float | None, str | None]:
    from bearingkit.pipeline.friction.choice import SKF_TYPES
    from bearingkit.pipeline.thermal import reference as thermal

    if float(np.max(analysis.operating.abs_speed)) <= REFERENCE_CHECK_SHARE * n_lim:
        return None, f"not computed: every case runs below {REFERENCE_CHECK_SHARE:.0%} of the limiting speed"
    if facts.engineering_type not in SKF_TYPES or not facts.single:
        return None, "not computed: the SKF model does not cover this bearing"
    try:
        value = float(analysis._in_file(thermal.thermal_reference_speed, analysis, "skf"))
    except InputError as exc:
        return None, f"not computed: {exc}"
    return (None, "not reached below 10^4 rad/s") if np.isnan(value) else (value, None)


def _minimum_load(analysis, facts):
    """(F_min, F compared, rule text) per case, or (None, None, note)."""
    etype = facts.engineering_type
    rule = physics.minimum_load_row(etype, facts.series)
    c, c0 = facts.C, facts.C0
    if c is None or c0 is None:
        rating = analysis.rating
        if rating is None or not facts.single:
            return None, None, "minimum load: no load rating of the bearing"
        rows = rating.to_dict(0)["rows"]
        c = sum(r["C_N"] for r in rows) if c is None else c
        c0 = sum(r["C0_N"] for r in rows) if c0 is None else c0
    op = analysis.operating
    nu = None
    if rule["law"] == "skf_viscous":
        if op.lubricant is None:
            return None, None, "minimum load: SKF's rule needs the lubricant's viscosity (none given)"
        nu = op.lubricant.kinematic_viscosity(op.temperature)
    f_min = physics.minimum_load(
        rule, C=c, C0=c0, viscosity=nu, speed=op.abs_speed, pitch_diameter=facts.pitch_diameter
    )
    load = analysis.input.load_matrix()
    f_r, f_a = np.hypot(load[:, 0], load[:, 1]), np.abs(load[:, 2])
    compared = f_a if etype in THRUST_TYPES else f_r + f_a
    law = {"skf_viscous": f"k_r = {rule['factor']:g} (ν n/1000)^(2/3) (d_m/100)² kN"}.get(
        rule["law"], f"{rule['factor']:g} {'C0' if rule['law'] == 'share_C0' else 'C'}"
    )
    text = f"SKF rule {law} [{rule['tag']}]"
    return np.broadcast_to(np.asarray(f_min, float), (op.n_cases,)).copy(), compared, text


def _contact_angle_deg(analysis) -> float | None:
    """Nominal contact angle [deg] of the bearing's rows — the model's own (a designation's suffix or a
    file's ``contact_angle``, not a catalogue row found by its dimensions); None for rows without one or
    rows of different angles."""
    angles = set()
    for r in analysis.input.model.rows:
        value = np.asarray(getattr(r, "contact_angle", np.nan), dtype=float).ravel()
        angles.update(np.round(np.abs(np.degrees(value)), 6).tolist())
    if len(angles) != 1:
        return None
    angle = angles.pop()
    return None if np.isnan(angle) else angle


def operating_limits(analysis) -> OperatingLimits | None:
    """The :class:`OperatingLimits` of an analysis; None for a bearing the catalogue models do not know."""
    from bearingkit.pipeline.bearing_facts import bearing_facts
    from bearingkit.pipeline.inputs import ModelInput

    if isinstance(analysis.input, ModelInput):
        return None
    facts = bearing_facts(analysis.input, analysis.operating.lubricant)
    etype = facts.engineering_type
    if etype not in physics.speed_limit_types():
        return None
    op = analysis.operating
    angle = _contact_angle_deg(analysis) if etype == "angular_contact_ball" else None
    key = physics.speed_limit_key(etype, angle)
    row = physics.speed_limit_row(key)
    n_lim = float(
        physics.limiting_speed(
            row["n_dm_limit"], facts.pitch_diameter, facts.lubrication, grease_factor=row["grease_factor"]
        )
    )
    grease = f"; × {row['grease_factor']:g} for grease" if facts.lubrication == "grease" else ""
    matched = ""
    if facts.arrangement is not None and etype == "angular_contact_ball":
        # a matched set runs slower than its single bearings (NSK prints both for every size)
        n_lim *= physics.MATCHED_SET_SPEED_FACTOR
        factor = physics.MATCHED_SET_SPEED_FACTOR
        matched = f"; × {factor:g} for a matched set ({facts.arrangement}, NSK E1102)"
    source = f"n·d_m ≤ {row['n_dm_limit']:.4g} mm·r/min, {row['note']} [{row['tag']}]{grease}{matched}"
    notes = []
    seal, lip = None, None
    if facts.seal is not None and facts.seal.construction == "contact" and facts.seal_diameter is not None:
        seal = facts.seal.suffix
        lip = physics.seal_lip_speed(facts.seal_diameter, op.abs_speed)
        notes.append(f"seal lip at d_s {facts.seal_diameter_source}")
    ref, ref_note = _reference_speed(analysis, facts, n_lim)
    f_min, compared, rule = _minimum_load(analysis, facts)
    if f_min is None:
        notes.append(rule)
        rule = None
    return OperatingLimits(
        bearing_type=etype,
        lubrication=facts.lubrication,
        n_dm=op.abs_speed * _RPM * facts.pitch_diameter * _MM,
        speed=op.abs_speed,
        limiting_speed=n_lim,
        limiting_source=source,
        reference_speed=ref,
        reference_note=ref_note,
        seal=seal,
        seal_lip_speed=lip,
        minimum_load=f_min,
        load=compared,
        minimum_load_rule=rule,
        notes=notes,
    )
