"""One self-contained HTML report of a solved bearing: inputs, load distribution, friction, ratings.

SI inside: the result objects hold SI values (m, N, Pa, rad, N·m, rad/s); this module converts only for
display (mm, µm, kN, MPa, degrees, N·mm, r/min) and names the unit in every column header. Faces never
recompute physics: the page reads :class:`~bearingkit.io.loader.BearingInput`,
:class:`~bearingkit.analysis.quasistatic.QuasiStaticResult`,
:class:`~bearingkit.analysis.friction.FrictionResult` and :class:`~bearingkit.analysis.rating.RatingResult`.

The file needs no network: figures are inline PNG data URIs (:mod:`bearingkit.report.plots`), the style
sheet is inline, and there is no script. The only web addresses a report may hold are inside the
citation texts of its reference list.

>>> html = build_report(bearing, result, friction=fr, rating=rt)     # doctest: +SKIP
>>> bearingkit.report.write_report("out/report.html", html)          # doctest: +SKIP
"""

from __future__ import annotations

import html as _html
import math
import re
import typing

import numpy as np

from bearingkit.errors import InputError
from bearingkit.report import plots

#: Warning categories shown as badges: (label, lower-case phrases that select it), first match wins.
WARNING_KINDS = (
    ("non-convergence", ("did not converge", "not converged")),
    ("edge loading", ("edge loading",)),
    ("truncated contact ellipse", ("ellipse truncated", "truncated")),
    ("stress over limit", ("exceeds the iso 76 limit", "stress above", "over the limit")),
    ("unloaded row", ("no loaded element",)),
    ("not available", ("unavailable", "no life", "no fatigue", "not defined")),
)
#: Badge colour class of each warning category (default ``warn``).
WARNING_CLASSES = {
    "non-convergence": "bad",
    "stress over limit": "bad",
    "unloaded row": "note",
    "not available": "note",
    "note": "note",
}
#: Forces [N] and moments [N·m] at or below this size are solver round-off and print as 0.
FORCE_NOISE = 1e-9
#: Display unit of each load component: (name, SI unit, display unit, factor SI → display).
LOAD_DISPLAY = (
    ("F_x", "N", "kN", 1e-3),
    ("F_y", "N", "kN", 1e-3),
    ("F_z", "N", "kN", 1e-3),
    ("M_x", "N·m", "N·m", 1.0),
    ("M_y", "N·m", "N·m", 1.0),
)
#: Display unit of each displacement component.
DISPLACEMENT_DISPLAY = (
    ("u_x", "µm", 1e6),
    ("u_y", "µm", 1e6),
    ("u_z", "µm", 1e6),
    ("θ_x", "mrad", 1e3),
    ("θ_y", "mrad", 1e3),
)
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

_CSS = """
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;margin:0;background:#f4f6f8;color:#1c2833;
font-size:14px;line-height:1.45}
main{max-width:1140px;margin:0 auto;padding:16px 24px 48px;background:#fff}
h1{font-size:24px;margin:8px 0 4px}h2{font-size:19px;border-bottom:2px solid #2e86c1;padding-bottom:3px;
margin-top:30px}h3{font-size:16px;margin:20px 0 6px}h4{font-size:14px;margin:14px 0 4px}
.sub{color:#566573;margin:0 0 10px}
table{border-collapse:collapse;margin:6px 0 12px;font-size:13px}
th,td{border:1px solid #d5dbdb;padding:3px 8px;text-align:right;vertical-align:top}
th{background:#eaf2f8;font-weight:600}td.l,th.l{text-align:left}
figure{margin:8px 0 16px}figure img{max-width:100%;height:auto;border:1px solid #e5e8e8;display:block}
figcaption{font-size:12px;color:#566573}
.badge{display:inline-block;padding:1px 7px;border-radius:9px;font-size:12px;color:#fff;white-space:nowrap}
.ok{background:#1e8449}.bad{background:#c0392b}.warn{background:#b9770e}.note{background:#7f8c8d}
ul.warnings li{margin:3px 0}nav ol{margin:4px 0 0 0;padding-left:22px}
.refs li{margin:3px 0}code{background:#f2f3f4;padding:0 3px}
.case{border-top:1px solid #d5dbdb;margin-top:26px}
"""


# ---------------------------------------------------------------------------------------------
# Formatting helpers.
# ---------------------------------------------------------------------------------------------
def _e(text) -> str:
    return _html.escape(str(text), quote=True)


def fmt(value, digits: int = 4, factor: float = 1.0, tiny: float = 0.0) -> str:
    """A number for display (``factor`` converts from SI); masked, None, NaN or ±inf → ``—``.

    ``|value| <= tiny`` (SI, e.g. :data:`FORCE_NOISE`) and display values below 1e-12 print as 0.
    """
    if value is None or value is np.ma.masked:
        return "—"
    try:
        v = float(value)
    except (TypeError, ValueError):
        return _e(value)
    if not math.isfinite(v):
        return "—"
    x = 0.0 if abs(v) <= tiny else v * factor
    return f"{(x if abs(x) > 1e-12 else 0.0) + 0.0:.{digits}g}"


_NUMBER = re.compile(r"^(—|[-+]?[\d.]+(e[-+]?\d+)?(…[-+]?[\d.]+(e[-+]?\d+)?)?|\d+/\d+)$")


def _td(i: int, cell, left: int) -> str:
    aligned = i < left or not _NUMBER.match(str(cell))
    return f"<td{' class=l' if aligned else ''}>{cell}</td>"


def _table(headers, rows, left: int = 1, cls: str = "") -> str:
    """HTML table; the first ``left`` columns and every non-numeric cell left-aligned.

    Cells are already-escaped HTML strings.
    """
    head = "".join(f"<th{' class=l' if i < left else ''}>{h}</th>" for i, h in enumerate(headers))
    body = "".join("<tr>" + "".join(_td(i, c, left) for i, c in enumerate(r)) + "</tr>" for r in rows)
    attr = f' class="{cls}"' if cls else ""
    return f"<table{attr}><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _figure_html(fig, alt: str, caption: str) -> str:
    if fig is None:
        return ""
    width, height = (int(v * plots.DPI + 0.5) for v in fig.get_size_inches())
    return (
        f'<figure><img alt="{_e(alt)}" width="{width}" height="{height}" src="{plots.png_data_uri(fig)}">'
        f"<figcaption>{_e(caption)}</figcaption></figure>"
    )


def _badge(ok: bool, yes: str = "converged", no: str = "NOT converged") -> str:
    return f'<span class="badge {"ok" if ok else "bad"}">{_e(yes if ok else no)}</span>'


def warning_kind(message: str) -> str:
    """Category label of a warning message (:data:`WARNING_KINDS`; ``"note"`` when none matches)."""
    low = message.lower()
    for label, phrases in WARNING_KINDS:
        if any(p in low for p in phrases):
            return label
    return "note"


def case_warnings(result, rating, case: int) -> list[str]:
    """Warnings of one case: non-convergence (from ``result``) and the rating's warnings."""
    out = []
    converged = bool(result.converged[case])
    if not converged:
        out.append(
            f"did not converge: {result.reason[case] or 'no reason given'} — loads shown are not an "
            "equilibrium"
        )
    if rating is not None:
        for w in rating.warnings[case]:
            if converged or "did not converge" not in w:
                out.append(w)
    return out


def _warning_list(messages) -> str:
    if not messages:
        return '<p><span class="badge ok">no warnings</span></p>'
    items = []
    for m in messages:
        kind = warning_kind(m)
        cls = WARNING_CLASSES.get(kind, "warn")
        items.append(f'<li><span class="badge {cls}">{_e(kind)}</span> {_e(m)}</li>')
    return f'<ul class="warnings">{"".join(items)}</ul>'


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
    fields = [(a, h, f) for a, h, f in ROW_FIELDS if any(getattr(r, a, None) is not None for r in model.rows)]
    parts.append(
        _table(
            ["row", "kind"] + [h for _, h, _ in fields],
            [[_e(r.name), _e(r.kind)] + [_row_cell(r, a, f) for a, _, f in fields] for r in model.rows],
            left=2,
        )
    )
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
        parts.append(
            _table(
                ["name", "base", "ν40 [mm²/s]", "ν100 [mm²/s]", "η const. [Pa·s]", "α_p [1/GPa]", "source"],
                [
                    [
                        _e(lub.name),
                        _e(lub.base),
                        fmt(lub.kinematic_viscosity_40, 4, 1e6),
                        fmt(lub.kinematic_viscosity_100, 4, 1e6),
                        fmt(lub.constant_viscosity),
                        fmt(lub.pressure_viscosity, 4, 1e9),
                        _e(lub.source or "—"),
                    ]
                ],
                left=2,
            )
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


# ---------------------------------------------------------------------------------------------
# One load case.
# ---------------------------------------------------------------------------------------------
def _row_table(data: dict) -> str:
    headers = ["row", "kind", "loaded", "Q_max [N]", "p_max [MPa]", "F_axial [N]", "F_radial [N]"]
    rows = [
        [
            _e(r["name"]),
            _e(r["kind"]),
            f"{r['loaded_count']}/{len(r['loads_N'])}",
            fmt(r["max_load_N"], 5),
            fmt(r["max_pressure_Pa"], 5, 1e-6),
            fmt(r["axial_load_N"], 5, tiny=FORCE_NOISE),
            fmt(r["radial_load_N"], 5, tiny=FORCE_NOISE),
        ]
        for r in data["rows"]
    ]
    return _table(headers, rows, left=2, cls="rows")


def _friction_html(friction, case: int, n: int) -> str:
    total = float(friction.total[case])
    comp = [
        [_e(k), fmt(v[case], 5), fmt(v[case] / total * 100 if total else 0.0, 3)]
        for k, v in friction.components.items()
    ]
    rows = [
        [_e(k), fmt(v[case], 5), fmt(v[case] / total * 100 if total else 0.0, 3)]
        for k, v in friction.by_row.items()
    ]
    return (
        f"<h4>{n}. Friction torque</h4>"
        f"<p>Total M = <b>{fmt(total, 5)} N·m</b>; on the inner ring "
        f"{fmt(friction.torque_inner[case], 5)} N·m, on the outer ring "
        f"{fmt(friction.torque_outer[case], 5)} N·m (about +z).</p>"
        + _table(["component", "M [N·m]", "share [%]"], comp)
        + _table(["row", "M [N·m]", "share [%]"], rows)
        + _figure_html(
            plots.friction_figure(friction, case),
            "friction breakdown",
            "Friction torque by component (left) and by row (right).",
        )
    )


def _rating_html(rating, case: int, n: int) -> str:
    d = rating.to_dict(case)
    headers = [
        "row",
        "rated as",
        "C [kN]",
        "C0 [kN]",
        "L10r [rev]",
        "L10r [h]",
        "P_ref [kN]",
        "s0 [-]",
        "p_max [MPa]",
        "flags",
    ]
    rows = []
    for r in d["rows"]:
        flags = [k for k, v in r["flags"].items() if v]
        s0 = r["static_safety"]
        s0_html = (
            fmt(s0, 4)
            if s0 is None or s0 >= plots.S0_REQUIRED
            else f'<b style="color:#c0392b">{fmt(s0, 4)}</b>'
        )
        rows.append(
            [
                _e(r["name"]),
                _e(r["bearing_type"]),
                fmt(r["C_N"], 5, 1e-3),
                fmt(r["C0_N"], 5, 1e-3),
                fmt(r["L10r_rev"], 4),
                fmt(r["L10r_h"], 4),
                fmt(r["P_ref_N"], 5, 1e-3),
                s0_html,
                fmt(r["max_pressure_Pa"], 5, 1e-6),
                _e(", ".join(flags) or "—"),
            ]
        )
    s = d["system"]
    speed = "—" if d["speed_rad_s"] is None else fmt(d["speed_rad_s"], 5, 30.0 / math.pi)
    heads = ["system", "L10r [rev]", "L10h [h]"]
    cells = ["bearing", fmt(s["L10r_rev"], 4), fmt(s["L10h_h"], 4)]
    if d["a1"] != 1.0:
        heads.append(f"L{fmt((1 - d['reliability']) * 100, 3)}r [rev]")
        cells.append(fmt(s["Lnr_rev"], 4))
    system = _table([*heads, "static safety s0"], [[*cells, fmt(s["static_safety"], 4)]])
    return (
        f"<h4>{n}. Ratings and static safety</h4>"
        f"<p>Rotating ring: {_e(d['rotating'])}; speed {speed} r/min; reliability "
        f"{fmt(d['reliability'] * 100, 5)} %"
        f" (a1 = {fmt(d['a1'], 4)}).</p>"
        + _table(headers, rows, left=2)
        + system
        + _figure_html(
            plots.rating_figure(rating, case),
            "ratings and static safety",
            "Static safety s0 per row (dashed: s0 = 1, ISO 76 limit pressure) and basic reference "
            "rating life L10r per row; n/a = not available (see warnings).",
        )
    )


def _case_html(bearing, result, friction, rating, case: int, warnings) -> str:
    lc = bearing.cases[case]
    data = result.to_dict(case)
    ok = bool(result.converged[case])
    disp = result.displacement[case]
    parts = [f'<section class="case" id="case-{case}" data-section="case" data-case="{_e(lc.name)}">']
    parts.append(f"<h2>{case + 2}. Load case “{_e(lc.name)}” {_badge(ok)}</h2>")
    reason = "" if ok else f"; reason: {_e(result.reason[case] or '—')}"
    parts.append(
        f'<p class="sub">{int(result.iterations[case])} iterations, residual '
        f"{float(result.residual_norm[case]):.2e} (relative to the load scale){reason}</p>"
    )
    parts.append(f"<h4>{case + 2}.1. Load and displacement of the inner ring</h4>")
    parts.append(
        _table(
            [f"{n} [{d}]" for n, _, d, _ in LOAD_DISPLAY],
            [
                [
                    fmt(v, 5, k, FORCE_NOISE)
                    for v, (_, _, _, k) in zip(result.load[case], LOAD_DISPLAY, strict=True)
                ]
            ],
            left=0,
        )
    )
    parts.append(
        _table(
            [f"{n} [{u}]" for n, u, _ in DISPLACEMENT_DISPLAY],
            [[fmt(v, 5, k) for v, (_, _, k) in zip(disp, DISPLACEMENT_DISPLAY, strict=True)]],
            left=0,
            cls="displacement",
        )
    )
    parts.append(f"<h4>{case + 2}.2. Rows</h4>")
    parts.append(_row_table(data))
    parts.append(
        _figure_html(
            plots.polar_load_figure(result, case),
            f"polar load distribution, case {lc.name}",
            "Element load Q [kN] (radial axis) at its azimuth ψ, one panel per row (ψ from +x towards +y; "
            "grey dots: unloaded elements).",
        )
    )
    k = 3
    if plots.roller_rows(result):
        parts.append(f"<h4>{case + 2}.{k}. Slice pressure map of the roller rows</h4>")
        parts.append(
            _figure_html(
                plots.slice_pressure_figure(result, case),
                f"slice pressure map, case {lc.name}",
                "Contact pressure per roller (sorted by azimuth) and slice; bright bands at the roller ends "
                "mean edge loading.",
            )
        )
        k += 1
    if friction is not None:
        parts.append(_friction_html(friction, case, f"{case + 2}.{k}"))
        k += 1
    if rating is not None:
        parts.append(_rating_html(rating, case, f"{case + 2}.{k}"))
        k += 1
    parts.append(f"<h4>{case + 2}.{k}. Warnings</h4>")
    parts.append(_warning_list(warnings[case]))
    parts.append("</section>")
    return "".join(parts)


# ---------------------------------------------------------------------------------------------
# The page.
# ---------------------------------------------------------------------------------------------
def used_references(result, friction=None, rating=None) -> list[str]:
    """Reference keys of the run, in first-use order: model and solve, then friction, then rating."""
    keys = [*result.references, *getattr(result.model, "references", ())]
    for extra in (friction, rating):
        if extra is not None:
            keys.extend(extra.references)
    return list(dict.fromkeys(keys))


def _references_html(keys, n: int) -> str:
    from bearingkit.references import REFERENCES

    items = "".join(
        f'<li id="ref-{_e(k)}"><code>{_e(k)}</code> {_e(REFERENCES.get(k, "(citation not registered)"))}</li>'
        for k in keys
    )
    return (
        f'<section id="references" data-section="references"><h2>{n}. References</h2>'
        f'<ol class="refs">{items}</ol></section>'
    )


def _summary_html(bearing, result, friction, rating, warnings) -> str:
    headers = [
        "case",
        "status",
        "max p_max [MPa]",
        "min s0 [-]",
        "friction [N·m]",
        "system L10r [rev]",
        "warnings",
    ]
    rows = []
    for c, lc in enumerate(bearing.cases):
        p_max = max((float(np.max(s.max_pressure[c])) for s in result.rows), default=float("nan"))
        n_warn = len(warnings[c])
        rows.append(
            [
                f'<a href="#case-{c}">{_e(lc.name)}</a>',
                _badge(bool(result.converged[c])),
                fmt(p_max, 5, 1e-6),
                "—" if rating is None else fmt(rating.static_safety[c], 4),
                "—" if friction is None else fmt(friction.total[c], 5),
                "—" if rating is None else fmt(rating.life[c], 4),
                str(n_warn),
            ]
        )
    return _table(headers, rows, left=2, cls="summary")


def _check_shapes(bearing, result, friction, rating) -> None:
    n = result.n_cases
    if len(bearing.cases) != n:
        raise InputError(
            f"result ({n} cases) must be the solve of bearing_input's {len(bearing.cases)} load cases"
        )
    if friction is not None and np.shape(friction.total) != (n,):
        raise InputError(f"friction (shape {np.shape(friction.total)}) must have one value per case ({n})")
    if rating is not None and rating.n_cases != n:
        raise InputError(f"rating ({rating.n_cases} cases) must rate the result's {n} cases")


def build_report(
    bearing_input, result, *, friction=None, rating=None, title=None, notes=(), warnings=None
) -> str:
    """The self-contained HTML report (text) of a solved input file.

    Parameters
    ----------
    bearing_input : bearingkit.io.loader.BearingInput
        The loaded file (geometry, material, lubricant, load cases).
    result : QuasiStaticResult
        The solve of ``bearing_input.cases`` (same order), SI.
    friction : FrictionResult, optional
        Friction torque [N·m] of the same cases.
    rating : RatingResult, optional
        Ratings, lives and static safety of the same cases.
    title : str, optional
        Page title (default: "bearingkit report — <bearing name>").
    notes : sequence of str
        Assumptions of the run shown under "Run notes" (e.g. the friction operating point).
    warnings : list of list of str, optional
        Per case, the warnings to show (those of :attr:`bearingkit.pipeline.Analysis.warnings`);
        default: non-convergence and the rating's warnings (:func:`case_warnings`).

    Returns
    -------
    str
        HTML5 text, no external resources (figures are inline PNG data URIs).
    """
    from bearingkit import __version__

    _check_shapes(bearing_input, result, friction, rating)
    name = bearing_input.model.name
    title = title or f"bearingkit report — {name}"
    n_cases = result.n_cases
    if warnings is None:
        warnings = [case_warnings(result, rating, c) for c in range(n_cases)]
    all_warnings = [(lc.name, w) for c, lc in enumerate(bearing_input.cases) for w in warnings[c]]
    nav = "".join(
        ['<li><a href="#inputs">Inputs</a></li>']
        + [
            f'<li><a href="#case-{c}">Load case “{_e(lc.name)}”</a></li>'
            for c, lc in enumerate(bearing_input.cases)
        ]
        + ['<li><a href="#warnings">Warnings</a></li>', '<li><a href="#references">References</a></li>']
    )
    missing = []
    if friction is None:
        missing.append("friction torque")
    if rating is None:
        missing.append("ratings")
    notes = list(notes) + ([f"Not computed in this run: {', '.join(missing)}."] if missing else [])
    body = [
        f"<h1>{_e(title)}</h1>",
        f'<p class="sub">{_e(name)} · <code>{_e(bearing_input.bearing_type)}</code> · '
        f"{n_cases} load case(s) · "
        f"bearingkit {_e(__version__)} · SI results shown in engineering units (unit in every header)</p>",
        _summary_html(bearing_input, result, friction, rating, warnings),
        f"<nav><b>Contents</b><ol>{nav}</ol></nav>",
    ]
    if notes:
        body.append("<h3>Run notes</h3><ul>" + "".join(f"<li>{_e(n)}</li>" for n in notes) + "</ul>")
    body.append(_inputs_html(bearing_input))
    body.extend(_case_html(bearing_input, result, friction, rating, c, warnings) for c in range(n_cases))
    body.append(f'<section id="warnings" data-section="warnings"><h2>{n_cases + 2}. Warnings</h2>')
    body.append(
        "<p>Edge loading, truncated contact ellipses, stress above the ISO 76 limit and non-convergence, "
        "per load case.</p>"
    )
    body.append(_warning_list([f"[{case}] {w}" for case, w in all_warnings]) + "</section>")
    body.append(_references_html(used_references(result, friction, rating), n_cases + 3))
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{_e(title)}</title><style>{_CSS}</style></head>"
        f"<body><main>{''.join(body)}</main></body></html>\n"
    )
