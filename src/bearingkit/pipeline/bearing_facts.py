"""What a standard bearing's catalogue says beyond its geometry: type, series, seals, lubrication method.

SI units (m). The catalogue friction model (SKF), the speed and load limits and the default friction
model all need facts the statics do not: the bearing type the catalogue models know, the dimension
series (its SKF constants: a 6209 is series 62, not 60), the seals or shields (the seal term and the lip
speed), the width and the catalogue ratings. :func:`bearing_facts` gathers them once per input, each
with where it came from:

- the catalogue row: the designation's, or for a file without one the row of the file's type whose bore
  and outer diameter equal the file's (a 6209 file finds 6209);
- ``series``: ``[bearing] series``, else the catalogue row's;
- ``seal``: ``[bearing] seal``, else the designation's seal suffix (:mod:`bearingkit.catalogue.seals`);
- ``seal_counterface_diameter``: ``[bearing] seal_counterface_diameter``, else d + 0.25 (D − d)
  (:data:`SEAL_DIAMETER_SHARE`);
- the lubrication method: ``[lubrication] method``, else grease for a grease or a capped (sealed or
  shielded) bearing — greased for life — else an oil bath; ``oil_level`` and ``drag_loss_factor``
  from ``[lubrication]``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError

__all__ = ["ENGINEERING_TYPES", "SEAL_DIAMETER_SHARE", "SET_TYPES", "BearingFacts", "bearing_facts"]

#: Input bearing type → bearing type of the catalogue models (SKF friction, speed and load limits).
#: A pair of single bearings (``angular_contact_pair`` from a file, a tapered DB/DF pair) keeps the type
#: of each bearing; a double-row angular contact bearing from a designation becomes
#: ``angular_contact_ball_double`` (:func:`bearing_facts`).
ENGINEERING_TYPES = {
    "deep_groove_ball": "deep_groove_ball",
    "angular_contact_ball": "angular_contact_ball",
    "angular_contact_pair": "angular_contact_ball",
    "four_point_contact_ball": "four_point_contact_ball",
    "self_aligning_ball": "self_aligning_ball",
    "thrust_ball": "thrust_ball",
    "cylindrical_roller": "cylindrical_roller",
    "cylindrical_roller_thrust": "cylindrical_roller_thrust",
    "tapered_roller": "tapered_roller",
    "spherical_roller": "spherical_roller",
    "spherical_roller_thrust": "spherical_roller_thrust",
    "needle_roller": "needle_roller",
}
#: Seal counterface diameter over the section height above the bore, d_s ≈ d + SHARE (D − d) [-]: the
#: inner-ring shoulder d1 where SKF's contact seals run lies about a quarter of the section above the
#: bore for deep groove ball bearings [M] (an estimate; give ``[bearing] seal_counterface_diameter``).
SEAL_DIAMETER_SHARE = 0.25
#: Input type of a matched set of single bearings → type of the single bearing (its catalogue families).
_SET_TYPES = {"angular_contact_pair": "angular_contact_ball"}
#: Catalogue model types whose bearings come in matched sets (DB/DF/DT), each row one bearing.
SET_TYPES = ("angular_contact_ball", "tapered_roller")
#: Bore and outer diameter of a file equal a catalogue row's when within this [m].
_DIMENSION_TOL = 1.0e-6


@dataclass(frozen=True)
class BearingFacts:
    """The catalogue facts of an analysed bearing (module docstring); None where unknown.

    Attributes
    ----------
    engineering_type : str or None
        Type of the catalogue models; None for bearings they do not describe (seed composites,
        slewing rings, models built in code).
    single : bool
        One bearing (one row, or the two rows of one spherical roller / self-aligning ball bearing).
    arrangement : str or None
        ``"DB"``, ``"DF"`` or ``"DT"`` for a matched set of single angular contact ball or tapered roller
        bearings (a designation such as ``7209 B DB``, or a file pairing two single rows): each row is one
        bearing of the catalogue row; None otherwise.
    entry : catalogue Entry or None
    series, series_source : str or None
    seal : catalogue.seals.Seal or None
    seal_source : str or None
    seal_diameter : float or None [m]
    seal_diameter_source : str or None
    bore, outer_diameter, width : float or None [m]
    pitch_diameter : float [m]
        (d + D)/2 when both are known, else the rows' largest pitch diameter.
    lubrication, lubrication_source : str
    oil_level, drag_loss_factor : float or None [m, -]
    C, C0 : float or None [N]
        Catalogue ratings of the row (None without one).
    suffixes : tuple of str
        The designation's suffixes (empty without a designation).
    notes : list of str
    """

    engineering_type: str | None
    single: bool
    entry: object
    series: str | None
    series_source: str | None
    seal: object
    seal_source: str | None
    seal_diameter: float | None
    seal_diameter_source: str | None
    bore: float | None
    outer_diameter: float | None
    width: float | None
    pitch_diameter: float
    lubrication: str
    lubrication_source: str
    oil_level: float | None = None
    drag_loss_factor: float | None = None
    C: float | None = None
    C0: float | None = None
    suffixes: tuple = ()
    notes: list = field(default_factory=list)
    arrangement: str | None = None


def _entry_by_designation(header):
    from bearingkit.catalogue import parse, tables

    des = parse(header.designation)
    return tables.entries(des.family).get(des.base), des


def _entry_by_dimensions(bearing_type: str, bore: float, outer: float, width: float | None):
    """The catalogue rows of the input type with the file's d and D (and B when given)."""
    from bearingkit.catalogue import tables

    families = [f for f, (_, t, _) in tables.FAMILIES.items() if t == bearing_type]
    found = [
        e
        for f in families
        for e in tables.entries(f).values()
        if abs(e.bore - bore) < _DIMENSION_TOL and abs(e.outer_diameter - outer) < _DIMENSION_TOL
    ]
    if width is not None:
        found = [e for e in found if abs(e.width - width) < _DIMENSION_TOL] or found
    return found


def _lubrication(bearing, seal, lub) -> tuple[str, str, float | None, float | None]:
    from bearingkit.pipeline.conditions import _sections

    spec = _sections(bearing).lubrication
    level = None if spec is None else spec.oil_level
    vm = None if spec is None else spec.drag_loss_factor
    lub = getattr(bearing, "lubricant", None) if lub is None else lub
    if spec is not None and spec.method is not None:
        method, why = spec.method, "[lubrication] method"
    elif lub is not None and lub.base == "grease":
        method, why = "grease", f"the lubricant {lub.name} is a grease"
    elif seal is not None and seal.sides == 2:
        method, why = "grease", f"capped on both sides ({seal.suffix}): greased for life"
    else:
        method, why = "oil_bath", "the default for an oil; [lubrication] method sets another"
    if level is not None and method != "oil_bath":
        raise InputError(
            f"{bearing.source}: lubrication.oil_level ({level * 1e3:g} mm) applies to method 'oil_bath', "
            f'not {method!r}; remove it or set [lubrication] method = "oil_bath"'
        )
    return method, why, level, vm


def bearing_facts(bearing, lubricant=None) -> BearingFacts:
    """The :class:`BearingFacts` of a loaded input (a BearingInput; a ModelInput has none of them);
    ``lubricant``: the analysis's (the file's ``[lubricant]`` when None).

    Bad ``[bearing] series`` or ``seal`` raise :class:`~bearingkit.errors.InputError` (one line naming
    the valid ones).
    """
    from bearingkit.catalogue.seals import seal_of_suffix

    model = bearing.model
    dm_rows = max(float(np.max(getattr(r, "pitch_diameter", 0.0))) for r in model.rows)
    header = bearing.spec.bearing
    etype = ENGINEERING_TYPES.get(bearing.bearing_type)
    try:
        geometry = bearing.geometry.model_dump()
    except InputError:  # a model built in code has no [geometry]
        geometry = {}
    kinds = {r.kind for r in model.rows}
    single = len(model.rows) == 1 or kinds <= {"spherical_roller", "self_aligning_ball"}
    notes: list[str] = []
    entry, des = None, None
    if getattr(header, "designation", None):
        entry, des = _entry_by_designation(header)
        if des.family == "double_row_angular_contact_ball":
            etype, single = "angular_contact_ball_double", True
    bore, outer = geometry.get("bore"), geometry.get("outer_diameter")
    width = geometry.get("width")
    if entry is None and etype is not None and bore is not None and outer is not None:
        lookup = _SET_TYPES.get(bearing.bearing_type, bearing.bearing_type)
        found = _entry_by_dimensions(lookup, float(bore), float(outer), width)
        given = getattr(header, "series", None)
        same = [e for e in found if given is None or e.series == str(given)]
        if len({e.series for e in same}) == 1:
            entry = same[0]
        elif found and given is None:
            notes.append(
                f"d and D match catalogue series {', '.join(sorted({e.series for e in found}))}: give "
                "[bearing] series for the SKF constants and the minimum load"
            )
    if entry is not None:
        bore = entry.bore if bore is None else bore
        outer = entry.outer_diameter if outer is None else outer
        width = entry.width if width is None else width
    series, series_source = getattr(header, "series", None), "[bearing] series"
    if series is None and entry is not None:
        series = entry.series
        series_source = (
            f"designation {header.designation}"
            if des is not None
            else f"catalogue row {entry.designation} (same d and D)"
        )
    if series is None:
        series_source = None
    given_seal = getattr(header, "seal", None)
    if given_seal is not None:
        seal, seal_source = seal_of_suffix(given_seal, "bearing.seal"), "[bearing] seal"
    elif des is not None and des.seal is not None:
        seal = seal_of_suffix(des.seal)
        seal_source = f"designation {header.designation}"
    else:
        seal, seal_source = None, None
    ds = getattr(header, "seal_counterface_diameter", None)
    ds_source = "[bearing] seal_counterface_diameter" if ds is not None else None
    if ds is None and seal is not None and seal.rubbing and bore is not None and outer is not None:
        ds = float(bore) + SEAL_DIAMETER_SHARE * (float(outer) - float(bore))
        ds_source = f"estimated d + {SEAL_DIAMETER_SHARE:g} (D - d) = {ds * 1e3:.4g} mm"
    dm = 0.5 * (float(bore) + float(outer)) if bore is not None and outer is not None else dm_rows
    method, why, level, vm = _lubrication(bearing, seal, lubricant)
    c = c0 = None
    if entry is not None:
        c, c0 = entry.C, entry.C0
    if getattr(header, "C", None) is not None:
        c = float(header.C)
    if getattr(header, "rating_C", None) is not None:  # a maker's ratings (io.sections.BearingHeader)
        c = float(header.rating_C)
        c0 = float(header.rating_C0) if getattr(header, "rating_C0", None) is not None else c0
    return BearingFacts(
        engineering_type=etype,
        single=single,
        entry=entry,
        series=None if series is None else str(series),
        series_source=series_source,
        seal=seal,
        seal_source=seal_source,
        seal_diameter=None if ds is None else float(ds),
        seal_diameter_source=ds_source,
        bore=None if bore is None else float(bore),
        outer_diameter=None if outer is None else float(outer),
        width=None if width is None else float(width),
        pitch_diameter=dm,
        lubrication=method,
        lubrication_source=why,
        oil_level=level,
        drag_loss_factor=vm,
        C=c,
        C0=c0,
        suffixes=() if des is None else tuple(des.suffixes),
        notes=notes,
        arrangement=_arrangement(etype, single, model, geometry),
    )


def _arrangement(etype, single: bool, model, geometry: dict) -> str | None:
    """DB/DF/DT of a matched set of single bearings (each row one bearing of the same kind), else None."""
    arrangement = geometry.get("arrangement")
    kinds = {r.kind for r in model.rows}
    if single or etype not in SET_TYPES or arrangement not in ("DB", "DF", "DT") or len(kinds) != 1:
        return None
    return str(arrangement)
