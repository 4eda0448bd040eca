"""Which friction model a bearing gets by default, and the catalogue inputs of the SKF model.

SI units (m, N, rad/s). The default friction model (``"auto"``, :data:`AUTO`) depends on the bearing:

- a standard bearing the SKF model covers (deep groove, angular contact, four-point, self-aligning ball,
  cylindrical, tapered, spherical roller, thrust ball, cylindrical and spherical roller thrust) →
  ``"skf"``: the four-component model (rolling, sliding, seals, drag) with the constants of the bearing's
  own series, fitted to measured torque of such bearings; it is what SKF's calculators and the commercial
  tools print;
- a matched set (DB, DF, DT) of single angular contact ball or tapered roller bearings — a designation
  such as ``7209 B DB`` or ``32008 X DF``, or a file pairing two single rows — → ``"skf"`` per bearing:
  each row is one bearing, computed at the radial and axial load it carries in the paired solve (preload
  included) with the single bearing's constants, the set's torque the sum
  (:mod:`bearingkit.pipeline.friction.paired`); SKF's model describes one bearing under its own loads;
- a slewing ring → ``"slewing"`` (the makers' formula, built for them);
- a needle roller bearing → ``"palmgren"`` (SKF gives no constants for it, the component model has no
  needle rows);
- everything else — the seed composites, bearings of several rows that are not a matched set of single
  bearings (a double row cylindrical roller bearing) and models built in code → ``"components"``
  (the physical model per contact, built for the seed composites; tapered rows by the seed-001 model
  behind the same name).

Every face prints the model used and this reason (:func:`choose`). Where the SKF model cannot run on a
bearing it was chosen for (e.g. a thrust bearing under a radial load), the default falls back to the
component model and says why.

:func:`skf_inputs` turns :class:`~bearingkit.pipeline.bearing_facts.BearingFacts` into the keyword
arguments of :func:`bearingkit.analysis.friction.engineering.engineering_friction_torque`: series key,
seal type and count, seal counterface diameter, lubrication method, oil level and V_M, width, the
catalogue C0 and the tapered roller Y.
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError

__all__ = ["AUTO", "check_inputs", "choose", "skf_inputs", "skf_series"]

#: Name of the default friction model (resolved per bearing by :func:`choose`).
AUTO = "auto"
#: Bearing types (of the catalogue models) the SKF model covers.
SKF_TYPES = (
    "deep_groove_ball",
    "angular_contact_ball",
    "angular_contact_ball_double",
    "four_point_contact_ball",
    "self_aligning_ball",
    "cylindrical_roller",
    "tapered_roller",
    "spherical_roller",
    "thrust_ball",
    "cylindrical_roller_thrust",
    "spherical_roller_thrust",
)
#: Catalogue series → SKF constants key, where the two differ (``data/skf_friction_constants.csv``).
_SERIES_KEYS = {
    ("angular_contact_ball", "72"): "72_BECBP",
    ("angular_contact_ball_double", "32"): "32_A",
}
_SLEWING_PREFIX = "slewing_ring"


def choose(analysis) -> tuple[str, str]:
    """(model, why): the default friction model of an analysis and the one-line reason (module docstring)."""
    from bearingkit.pipeline.bearing_facts import bearing_facts

    b = analysis.input
    if b.bearing_type.startswith(_SLEWING_PREFIX):
        return "slewing", "slewing ring: the makers' formula (Rothe Erde), built for slewing rings"
    facts = bearing_facts(b)
    etype = facts.engineering_type
    if etype in SKF_TYPES and facts.single:
        return "skf", (
            f"standard {etype.replace('_', ' ')} bearing: the SKF four-component model (rolling, sliding, "
            "seals, drag) with its series' constants, fitted to measured torque of such bearings"
        )
    if etype in SKF_TYPES and facts.arrangement is not None:
        n = len(b.model.rows)
        return "skf", (
            f"matched set ({facts.arrangement}) of {n} standard {etype.replace('_', ' ')} bearings: the SKF "
            "four-component model per bearing (rolling, sliding, seals, drag; the single bearing's series "
            "constants), each at the loads its row carries in the paired solve, the set's torque their sum"
        )
    if etype == "needle_roller":
        return "palmgren", (
            "needle roller bearing: the SKF model gives no constants for it and the component model has no "
            "needle rows; Palmgren's M0 + M1 with needle-bearing factors"
        )
    if etype is not None:
        return "components", (
            f"{len(b.model.rows)} rows of {etype.replace('_', ' ')} that are not one bearing nor a matched "
            "set of single bearings: SKF gives no constants for them; the component model sums every contact"
        )
    return "components", (
        "not a catalogue bearing (seed composite or a model built in code): the physical component model, "
        "built for these bearings"
    )


def check_inputs(bearing) -> None:
    """Raise the one-line InputError of a bad ``[bearing] series``/``seal`` or ``[lubrication]`` friction
    input before anything is computed (an input built in code has none)."""
    from bearingkit.physics.friction import skf_terms
    from bearingkit.pipeline.bearing_facts import bearing_facts
    from bearingkit.pipeline.inputs import ModelInput

    if isinstance(bearing, ModelInput):
        return
    facts = bearing_facts(bearing)
    if facts.series_source == "[bearing] series":
        if facts.engineering_type in skf_terms.G_MODELS:
            skf_series(facts)
        elif facts.engineering_type is None:
            raise InputError(
                f"{bearing.source}: bearing.series ({facts.series!r}) applies to catalogue bearing types "
                f"only, not {bearing.bearing_type!r}; remove it"
            )


def skf_series(facts) -> tuple[str | None, list[str]]:
    """(SKF constants key, notes) of the bearing's series.

    A series given in the file must name a row of the SKF table (one-line error naming the valid ones);
    a series from the catalogue without SKF constants falls back to the type's first row with a note.
    """
    from bearingkit.physics.friction import skf_terms

    etype, series = facts.engineering_type, facts.series
    keys = skf_terms.series_keys(etype)
    if series is None:
        return None, []
    key = _SERIES_KEYS.get((etype, series), series)
    if etype in ("spherical_roller", "spherical_roller_thrust") and facts.entry is not None:
        design = facts.entry.extra.get("design", "")
        if f"{key}E" in keys and ("E" in design or "E" in facts.suffixes):
            key = f"{key}E"
    if key in keys:
        return key, []
    if etype == "spherical_roller_thrust" and f"{key}E" in keys and facts.series_source != "[bearing] series":
        return f"{key}E", [
            f"series {series} of standard design ({facts.series_source}): SKF gives constants for {series} E "
            "only (General Catalogue 6000 Table 3g), used here"
        ]
    if facts.series_source == "[bearing] series":
        raise InputError(
            f"bearing.series ({series!r}) has no SKF friction constants for a {etype.replace('_', ' ')} "
            f"bearing; valid: {', '.join(keys)}"
        )
    return keys[0], [
        f"series {series} ({facts.series_source}) has no SKF constants in bearingkit's table: those of "
        f"series {keys[0]} are used (the constants of a type's series differ by tens of per cent)"
    ]


def skf_inputs(analysis) -> tuple[dict, list[str]]:
    """Keyword arguments of ``engineering_friction_torque(model="skf")`` for the analysed bearing, and
    the notes saying where each came from."""
    from bearingkit.physics.friction import skf_terms
    from bearingkit.pipeline.bearing_facts import bearing_facts

    facts = bearing_facts(analysis.input, analysis.operating.lubricant)
    etype = facts.engineering_type
    if etype is None:
        return {}, []
    kw: dict = {"bearing_type": etype, "lubrication": facts.lubrication}
    notes = [*facts.notes, f"lubrication: {facts.lubrication} ({facts.lubrication_source})"]
    if facts.bore is not None and facts.outer_diameter is not None:
        kw.update(bore_diameter=facts.bore, outside_diameter=facts.outer_diameter)
    if etype in skf_terms.G_MODELS:
        key, more = skf_series(facts)
        notes += more
        if key is not None:
            kw["series"] = key
            notes.append(f"SKF constants of series {key} ({facts.series_source})")
    if facts.C0 is not None and etype == "deep_groove_ball":
        kw["static_rating"] = facts.C0  # SKF's α_F uses the catalogue C0
    if etype == "tapered_roller":
        y = _tapered_y(analysis, facts)
        if y is not None:
            kw["axial_factor"] = y
    if facts.width is not None:
        kw["width"] = facts.width
    if facts.oil_level is not None:
        kw["oil_level"] = facts.oil_level
        if facts.drag_loss_factor is not None:
            kw["drag_loss_factor"] = facts.drag_loss_factor
        else:
            notes.append(
                "drag: V_M approximated from the oil level (physics.friction.skf_drag; SKF: a diagram)"
            )
    elif facts.lubrication == "oil_bath":
        notes.append("drag: no oil level given, no drag term ([lubrication] oil_level adds it)")
    seal_kw, seal_notes = _seal_inputs(facts, etype)
    kw.update(seal_kw)
    notes += seal_notes
    return kw, notes


def _seal_inputs(facts, etype: str) -> tuple[dict, list[str]]:
    from bearingkit.physics.friction import skf_terms

    seal = facts.seal
    if seal is None:
        return {}, []
    if seal.skf_type is None:
        return {}, [f"{seal.suffix} shields ({facts.seal_source}): no contact, no seal friction"]
    if facts.seal_diameter is None or facts.outer_diameter is None:
        return {}, [f"seal {seal.suffix}: no seal friction (the bearing's D and d_s are unknown)"]
    try:
        skf_terms.seal_constants(etype, seal.skf_type, facts.outer_diameter * 1e3)
    except InputError as exc:
        return {}, [f"seal {seal.suffix} ({facts.seal_source}): no seal friction: {exc}"]
    kw = {
        "seal": seal.skf_type,
        "n_seals": seal.sides,
        "seal_counterface_diameter": facts.seal_diameter,
    }
    note = (
        f"seal {seal.suffix} ({facts.seal_source}) as SKF {seal.skf_type}, {seal.sides} side(s), "
        f"d_s {facts.seal_diameter_source}"
    )
    return kw, [note]


def _tapered_y(analysis, facts) -> float | None:
    """Y = 0.4 cot α of a single-row tapered roller bearing (ISO 281): α from the catalogue's e =
    1.5 tan α when the row has one, else the cup angle of the model."""
    entry = facts.entry
    e = None if entry is None else entry.number("e")
    if e:
        return 0.6 / e
    rows = [r for r in analysis.input.model.rows if r.kind == "tapered"]
    if not rows:
        return None
    alpha = float(np.max(rows[0].contact_angle_outer))
    return 0.4 / np.tan(alpha)
