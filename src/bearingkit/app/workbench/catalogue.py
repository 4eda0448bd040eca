"""The catalogue page: browse and filter the standard bearings, select by life, compare up to four.

SI inside; the form's bounds are text with units (``"40 mm"``, ``"30 kN"``) parsed by
:func:`bearingkit.units.parse`. Nothing is computed here: the rows are
:func:`bearingkit.catalogue.search.search`'s, the selection :func:`bearingkit.pipeline.selection.select`'s
and a comparison is one :func:`bearingkit.pipeline.analyze` per designation, under the SAME operating
point, through the bearing page's own request (:class:`~bearingkit.app.form.AnalyzeRequest`), so a
compared bearing opened on the bearing page shows the same numbers.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from bearingkit.app.form import FRICTION_CHOICES, AnalyzeRequest, FormText, Source, StrictModel
from bearingkit.errors import InputError

__all__ = [
    "MAX_COMPARED",
    "MAX_ROWS",
    "CompareRequest",
    "SearchRequest",
    "SelectRequest",
    "compare_requests",
    "compared",
    "run_search",
    "run_select",
]

#: Bearings compared side by side at most (the page's columns).
MAX_COMPARED = 4
#: Catalogue rows one answer lists at most (the count says how many matched).
MAX_ROWS = 300
#: Candidates a selection asks for at most (each is a full analysis).
MAX_CANDIDATES = 10
#: Bounds of a search [m or N] → (``search`` keyword, dimension).
_BOUNDS = {
    "d": ("d", "length"),
    "d_min": ("d_min", "length"),
    "d_max": ("d_max", "length"),
    "D_min": ("D_min", "length"),
    "D_max": ("D_max", "length"),
    "B_max": ("B_max", "length"),
    "C_min": ("C_min", "force"),
    "C0_min": ("C0_min", "force"),
}
Designation = Annotated[str, Field(min_length=1, max_length=64)]


class SearchRequest(StrictModel):
    """Filters of the catalogue (texts with units; "" = no bound)."""

    pattern: str = Field("", max_length=32, description="Shell pattern of the designation, e.g. 62*.")
    kind: str = Field("", max_length=48, description="A kind (deep_groove, tapered …) or a family; '' all.")
    bounds: dict[Literal["d", "d_min", "d_max", "D_min", "D_max", "B_max", "C_min", "C0_min"], FormText] = (
        Field(default_factory=dict)
    )
    limit: int = Field(MAX_ROWS, ge=1, le=MAX_ROWS)


def _bounds(values: dict) -> dict:
    from bearingkit.units import parse

    out = {}
    for key, text in values.items():
        if not text.strip():
            continue
        name, dimension = _BOUNDS[key]
        try:
            out[name] = parse(text.strip(), dimension, key)
        except InputError as exc:
            raise InputError(f"catalogue.{key}: {exc}") from None
    return out


def row_dict(row) -> dict:
    """A search row for the page (SI, units in keys): the search's dict and the ratings it compares."""
    return {**row.to_dict(), "C_N": row.C, "C0_N": row.C0, "rating_source": row.rating_source}


def run_search(request: SearchRequest) -> dict:
    """``{"count", "rows", "kinds"}``: the rows meeting every filter, in table order (at most ``limit``)."""
    from bearingkit.catalogue.search import KINDS, search

    kind = request.kind.strip() or None
    try:
        rows = search(request.pattern.strip() or None, kind=kind, **_bounds(request.bounds))
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith("catalogue.") else f"catalogue.kind: {text}") from None
    return {"count": len(rows), "rows": [row_dict(r) for r in rows[: request.limit]], "kinds": list(KINDS)}


class OperatingPoint(StrictModel):
    """The one operating point every compared (or selected) bearing is analysed at."""

    loads: dict[Literal["F_x", "F_y", "F_z", "M_x", "M_y"], FormText] = Field(default_factory=dict)
    speed: FormText = ""
    temperature: FormText = ""
    lubricant: FormText = ""
    contamination: FormText = ""
    friction_model: Literal[FRICTION_CHOICES] = "auto"


class CompareRequest(StrictModel):
    """Up to :data:`MAX_COMPARED` designations at one operating point."""

    designations: list[Designation] = Field(min_length=1, max_length=MAX_COMPARED)
    point: OperatingPoint = Field(default_factory=OperatingPoint)


def compare_requests(request: CompareRequest) -> list[AnalyzeRequest]:
    """The bearing page's request of every compared bearing (same loads, speed, lubricant, e_C, model)."""
    p = request.point
    names = [" ".join(d.split()) for d in request.designations]
    doubles = sorted({n for n in names if names.count(n) > 1})
    if doubles:
        raise InputError(f"compare: {doubles[0]!r} is listed twice; compare different bearings")
    return [
        AnalyzeRequest(
            source=Source(kind="designation", name=name),
            loads=dict(p.loads),
            speed=p.speed,
            temperature=p.temperature,
            lubricant=p.lubricant,
            contamination=p.contamination,
            friction_model=p.friction_model,
        )
        for name in names
    ]


def _catalogue_row(designation: str) -> dict:
    """Dimensions, catalogue and estimated ratings and mass of a designation's catalogue row."""
    from bearingkit.catalogue import parse, tables
    from bearingkit.catalogue.search import row_of

    des = parse(designation)
    entry = tables.entries(des.family).get(des.base)
    return {} if entry is None else row_dict(row_of(entry))


def compared(designation: str, key: str, data: dict) -> dict:
    """One column of the comparison from an analysis's ``to_dict()`` (first case): lives by both methods,
    s0, friction, stiffness, speed limits, warnings (SI, units in keys)."""
    c = data["cases"][0]
    system = (c.get("rating") or {}).get("system") or {}
    friction = c.get("friction") or {}
    limits = c.get("limits") or {}
    k = c["stiffness_SI"]
    headline = system.get("headline") or {}
    return {
        "designation": designation,
        "id": key,
        "bearing_name": data["bearing_name"],
        "bearing_type": data["bearing_type"],
        "catalogue": _catalogue_row(designation),
        "converged": bool(c["converged"]),
        "max_load_N": max((r["max_load_N"] for r in c["rows"]), default=None),
        "max_pressure_Pa": max((r["max_pressure_Pa"] for r in c["rows"]), default=None),
        "headline_method": headline.get("method"),
        "L10h_iso281_h": system.get("L10h_iso281_h"),
        "Lnm_iso281_h": system.get("Lnm_iso281_h"),
        "L10h_iso16281_h": system.get("L10h_h"),
        "Lnmr_h": system.get("Lnmr_h"),
        "life_difference": system.get("life_difference"),
        "static_safety": system.get("static_safety"),
        "friction_model": friction.get("model"),
        "friction_torque_Nm": friction.get("total_Nm"),
        "power_loss_W": friction.get("power_loss_W"),
        "k_radial_N_per_m": k[0][0],
        "k_axial_N_per_m": k[2][2],
        "k_tilt_Nm_per_rad": k[3][3],
        "limiting_speed_rad_s": limits.get("limiting_speed_rad_s"),
        "thermal_reference_speed_rad_s": limits.get("thermal_reference_speed_rad_s"),
        "minimum_load_N": limits.get("minimum_load_N"),
        "limit_flags": limits.get("flags"),
        "free_dofs": data["free_dofs"],
        "warnings": list(c["warnings"]),
    }


class SelectRequest(StrictModel):
    """Bearing selection: a load, a speed and a required life (texts with units)."""

    radial: FormText = ""
    axial: FormText = ""
    speed: FormText
    life: FormText
    kind: str = Field("", max_length=48)
    static_safety: float = Field(1.0, gt=0, le=20)
    count: int = Field(5, ge=1, le=MAX_CANDIDATES)
    bounds: dict[Literal["d_min", "d_max", "D_max", "B_max"], FormText] = Field(default_factory=dict)


def run_select(request: SelectRequest) -> dict:
    """:func:`bearingkit.pipeline.selection.select` of the form (its ``to_dict()``)."""
    from bearingkit.pipeline.selection import select

    load = {}
    if request.radial.strip():
        load["F_x"] = request.radial.strip()
    if request.axial.strip():
        load["F_z"] = request.axial.strip()
    if not load:
        raise InputError("select.radial: give a radial or an axial load, e.g. 5 kN")
    bounds = {k: v.strip() for k, v in request.bounds.items() if v.strip()}
    try:
        out = select(
            load,
            request.speed.strip(),
            request.life.strip(),
            kind=request.kind.strip() or None,
            static_safety=request.static_safety,
            count=request.count,
            **bounds,
        )
    except InputError as exc:
        raise InputError(f"select: {exc}") from None
    return out.to_dict()
