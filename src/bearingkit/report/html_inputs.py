"""The "Inputs" section of the HTML report: geometry with units, material, lubricant, rows as modelled.

SI values from the loaded input file and its model; display units in every header.
"""

from __future__ import annotations

import math
import typing

import numpy as np

from bearingkit.report.html_format import FORCE_NOISE, LOAD_DISPLAY, _e, _table, fmt

#: Row attributes of the "rows as modelled" table: (attribute, header, factor SI → display).
ROW_FIELDS = (
    ("n_elements", "Z", None),
    ("element_diameter", "D_w [mm]", 1e3),
    ("effective_length", "l [mm]", 1e3),
    ("pitch_diameter", "d_m [mm]", 1e3),
    ("contact_angle", "α [°]", 180.0 / math.pi),
    ("conformity_inner", "f_i", None),
    ("conformity_outer", "f_o", None),
    ("clearance", "clearance [µm]", 1e6),
    ("axial_position", "z_r [mm]", 1e3),
    ("n_slices", "n_s", None),
    ("orientation", "orientation", None),
    ("profile", "profile", None),
)


# ---------------------------------------------------------------------------------------------
# Inputs.
# ---------------------------------------------------------------------------------------------
def _schema_hints(annotation, metadata=()) -> list[dict]:
    """The ``WithJsonSchema`` dicts of a pydantic field (through Optional/Union/Annotated)."""
    out = [m.json_schema for m in metadata if isinstance(getattr(m, "json_schema", None), dict)]
    for arg in typing.get_args(annotation):
        meta = getattr(arg, "__metadata__", ())
        out += [a.json_schema for a in meta if isinstance(getattr(a, "json_schema", None), dict)]
        out += _schema_hints(arg)
    return out


def field_si_unit(model_cls, name: str) -> str:
    """SI unit of a geometry field from its schema annotation (``x-si-unit``); ``–`` if dimensionless."""
    info = model_cls.model_fields.get(name)
    if info is None:
        return ""
    hints = _schema_hints(info.annotation, info.metadata)
    for h in hints:
        if "x-si-unit" in h:
            return h["x-si-unit"]
    return "–" if any(h.get("x-dimension") in ("count", "dimensionless") for h in hints) else ""


def _given(value) -> str:
    if isinstance(value, dict):
        return "; ".join(f"{k} = {v}" for k, v in value.items())
    return str(value)


def geometry_rows(bearing) -> list[list[str]]:
    """[field, value as written, SI value, SI unit] for every geometry field given in the file."""
    si = bearing.geometry.model_dump()
    rows = []
    for name, raw in bearing.spec.geometry.items():
        value = si.get(name, raw)
        shown = _given(value) if isinstance(value, dict) else fmt(value, 6)
        rows.append([_e(name), _e(_given(raw)), shown, _e(field_si_unit(type(bearing.geometry), name))])
    return rows


def _row_cell(row, attr, factor):
    value = getattr(row, attr, None)
    if value is None:
        return "—"
    if attr == "profile":
        return _e(getattr(value, "name", type(value).__name__))
    if isinstance(value, str):
        return _e(value)
    arr = np.asarray(value, dtype=float)
    if arr.ndim:
        return fmt(arr.min(), 5, factor or 1.0) + "…" + fmt(arr.max(), 5, factor or 1.0)
    return fmt(arr, 6, factor or 1.0)


def rows_table(model) -> str:
    """The "rows as modelled" table of a bearing model (the fields any row has)."""
    fields = [(a, h, f) for a, h, f in ROW_FIELDS if any(getattr(r, a, None) is not None for r in model.rows)]
    return _table(
        ["row", "kind"] + [h for _, h, _ in fields],
        [[_e(r.name), _e(r.kind)] + [_row_cell(r, a, f) for a, _, f in fields] for r in model.rows],
        left=2,
    )


def _inputs_html(bearing) -> str:
    spec, model = bearing.spec, bearing.model
    parts = ['<section id="inputs" data-section="inputs"><h2>1. Inputs</h2>']
    parts.append(
        _table(
            ["item", "value"],
            [
                ["file", _e(bearing.source)],
                ["bearing type", f"<code>{_e(spec.bearing.type)}</code>"],
                ["name", _e(model.name)],
                ["source", _e(spec.bearing.source or "—")],
            ],
            left=2,
        )
    )
    parts.append("<h3>Geometry</h3>")
    parts.append(_table(["field", "as given", "SI value", "SI unit"], geometry_rows(bearing), left=2))
    parts.append("<h3>Rows as modelled</h3>")
    parts.append(rows_table(model))
    mat = bearing.material
    parts.append("<h3>Material</h3>")
    parts.append(
        _table(
            ["name", "E [GPa]", "ν [-]", "ρ [kg/m³]", "source"],
            [
                [
                    _e(mat.name),
                    fmt(mat.youngs_modulus, 4, 1e-9),
                    fmt(mat.poisson_ratio),
                    fmt(mat.density),
                    _e(getattr(mat, "source", "") or "—"),
                ]
            ],
        )
    )
    parts.append("<h3>Lubricant</h3>")
    lub = bearing.lubricant
    if lub is None:
        parts.append("<p>No lubricant given: friction needs one.</p>")
    else:
        grease = lub.grease
        kind = (
            "oil"
            if grease is None
            else f"grease: {grease.thickener}, NLGI {grease.nlgi}"
            + ("" if grease.temperature_max_C is None else f", ≤ {grease.temperature_max_C:g} °C")
        )
        vi = lub.viscosity_index
        parts.append(
            _table(
                [
                    "name",
                    "kind",
                    "base oil",
                    "ν40 [mm²/s]",
                    "ν100 [mm²/s]",
                    "VI",
                    "η const. [Pa·s]",
                    "α_p(40 °C) [1/GPa]",
                    "source",
                ],
                [
                    [
                        _e(lub.name),
                        _e(kind),
                        _e(lub.base_oil),
                        fmt(lub.kinematic_viscosity_40, 4, 1e6),
                        fmt(lub.kinematic_viscosity_100, 4, 1e6),
                        fmt(vi, 3),
                        fmt(lub.constant_viscosity),
                        fmt(lub.pressure_viscosity, 4, 1e9),
                        _e(lub.source or "—"),
                    ]
                ],
                left=3,
            )
        )
        if lub.pressure_viscosity_exponent:
            parts.append(
                "<p>α_p follows the viscosity: α_p(T) = α_p(40 °C) (η(T)/η(40 °C))^"
                f"{lub.pressure_viscosity_exponent:.3g} "
                f"(the {_e(lub.base_oil)} base-oil law).</p>"
            )
    parts.append("<h3>Load cases</h3>")
    free = [n for n, f in zip(("u_x", "u_y", "u_z", "θ_x", "θ_y"), bearing.free, strict=True) if f]
    parts.append(f"<p>Free inner-ring DOFs: {_e(', '.join(free))} (the others are held at zero).</p>")
    headers = ["case"] + [f"{n} [{d}]" for n, _, d, _ in LOAD_DISPLAY] + ["speed [r/min]", "temperature [°C]"]
    rows = []
    for c in bearing.cases:
        rows.append(
            [_e(c.name)]
            + [fmt(v, 5, k, FORCE_NOISE) for v, (_, _, _, k) in zip(c.load, LOAD_DISPLAY, strict=True)]
            + [fmt(c.speed, 5, 30.0 / math.pi), fmt(c.temperature, 4)]
        )
    parts.append(_table(headers, rows))
    parts.append("</section>")
    return "".join(parts)
