"""One self-contained HTML report of a solved bearing: inputs, load distribution, friction, ratings.

SI inside: the result objects hold SI values (m, N, Pa, rad, N·m, rad/s); this module converts only for
display (mm, µm, kN, MPa, degrees, N·mm, r/min) and names the unit in every column header. Faces never
recompute physics: the page reads :class:`~bearingkit.io.loader.BearingInput`,
:class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult`,
:class:`~bearingkit.analysis.friction.components.FrictionResult` and
:class:`~bearingkit.analysis.rating.assembly.RatingResult`.

The file needs no network: figures are inline SVG or PNG data URIs (:mod:`bearingkit.report.plots`), the style
sheet is inline, and there is no script. The only web addresses a report may hold are inside the
citation texts of its reference list.

>>> html = build_report(bearing, result, friction=fr, rating=rt)     # doctest: +SKIP
>>> bearingkit.report.write_report("out/report.html", html)          # doctest: +SKIP
"""

from __future__ import annotations

import math

import numpy as np

from bearingkit.analysis.rating.iso281 import caption as iso281_caption
from bearingkit.errors import InputError
from bearingkit.report import plots
from bearingkit.report.html_duty import duty_cycle_html
from bearingkit.report.html_format import (
    DISPLACEMENT_DISPLAY,
    FORCE_NOISE,
    LOAD_DISPLAY,
    _badge,
    _e,
    _figure_html,
    _table,
    _warning_list,
    case_warnings,
    fmt,
)
from bearingkit.report.html_inputs import _inputs_html
from bearingkit.report.slewing import slewing_section_html

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


def _load_html(result, case: int) -> str:
    """The applied load; at a fixed DOF (e.g. the tilt of a single bearing) the solve's load is the
    reaction that holds the ring, listed apart: it is not a load the user applied."""
    free = np.asarray(getattr(result, "free", np.ones(5, bool)), bool)
    load = result.load[case]
    applied = [
        fmt(v, 5, k, FORCE_NOISE) if f else "held"
        for v, f, (_, _, _, k) in zip(load, free, LOAD_DISPLAY, strict=True)
    ]
    out = _table([f"{n} [{d}]" for n, _, d, _ in LOAD_DISPLAY], [applied], left=0)
    if not free.all():
        held = [i for i in range(5) if not free[i]]
        out += "<p>Reaction at the fixed DOFs (what holds the inner ring there; not an applied load):</p>"
        out += _table(
            [f"{LOAD_DISPLAY[i][0]} [{LOAD_DISPLAY[i][2]}]" for i in held],
            [[fmt(load[i], 5, LOAD_DISPLAY[i][3], FORCE_NOISE) for i in held]],
            left=0,
            cls="fixed-dof-reactions",
        )
    return out


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
    model = _e(getattr(friction, "model", "") or "components")
    power = getattr(friction, "power_loss", None)
    shown_power = "" if power is None else f", power loss P = <b>{fmt(float(power[case]), 4)} W</b>"
    if friction.torque_inner is None and len(friction.by_row) > 1:  # a matched set: per bearing, summed
        split = (
            f" ({model} catalogue model per bearing of the set, each row one bearing at its own loads, "
            "summed; no split between the rings)."
        )
    elif friction.torque_inner is None:  # a catalogue model: the whole bearing, no split between the rings
        split = f" ({model} catalogue model of the whole bearing; no split between the rings)."
    else:
        split = (
            f"; on the inner ring {fmt(friction.torque_inner[case], 5)} N·m, on the outer ring "
            f"{fmt(friction.torque_outer[case], 5)} N·m (about +z)."
        )
    why = getattr(friction, "why", "")
    chosen = f'<p class="sub">Friction model: {model} — {_e(why)}.</p>' if why else ""
    return (
        f"<h4>{n}. Friction torque and power loss</h4>"
        f"<p>Total M = <b>{fmt(total, 5)} N·m</b>{shown_power}{split}</p>{chosen}"
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
    heads = ["system (ISO/TS 16281)", "L10r [rev]", "L10h [h]", "L_nmr [h]"]
    cells = ["bearing", fmt(s["L10r_rev"], 4), fmt(s["L10h_h"], 4), fmt(s["Lnmr_h"], 4)]
    if d["a1"] != 1.0:
        heads.append(f"L{fmt((1 - d['reliability']) * 100, 3)}r [rev]")
        cells.append(fmt(s["Lnr_rev"], 4))
    system = _table([*heads, "static safety s0"], [[*cells, fmt(s["static_safety"], 4)]])
    iso281 = iso281_caption(s)
    first = s.get("headline", {}).get("method") == "ISO 281"
    iso_html = ""
    if iso281:
        iso_html = (
            f"<p><b>{_e(iso281)}</b>.</p><p>ISO 281 basic rating life of the whole bearing from "
            "P = X F_r + Y F_a of the applied load (the catalogue method, shown first), beside the "
            "ISO/TS 16281:2008 life L10r from the load distribution.</p>"
        )
    system = iso_html + system if first else system + iso_html
    if s.get("life_difference"):
        system += f"<p>Why they differ: {_e(s['life_difference'])}.</p>"
    if s.get("static_safety_difference"):
        system += f"<p>Static safety: {_e(s['static_safety_difference'])}.</p>"
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


def _case_html(
    bearing, result, friction, rating, case: int, warnings, extra=None, *, number=None, anchor=None, level=2
) -> str:
    """One load case; ``number`` (default case + 2), ``anchor`` (``case-N``) and the heading ``level``
    let another report (the shaft's) nest it."""
    lc = bearing.cases[case]
    data = result.to_dict(case)
    ok = bool(result.converged[case])
    disp = result.displacement[case]
    num = str(case + 2) if number is None else str(number)
    anchor = f"case-{case}" if anchor is None else anchor
    parts = [f'<section class="case" id="{_e(anchor)}" data-section="case" data-case="{_e(lc.name)}">']
    parts.append(f"<h{level}>{num}. Load case “{_e(lc.name)}” {_badge(ok)}</h{level}>")
    reason = "" if ok else f"; reason: {_e(result.reason[case] or '—')}"
    parts.append(
        f'<p class="sub">{int(result.iterations[case])} iterations, residual '
        f"{float(result.residual_norm[case]):.2e} (relative to the load scale){reason}</p>"
    )
    parts.append(f"<h4>{num}.1. Load and displacement of the inner ring</h4>")
    parts.append(_load_html(result, case))
    parts.append(
        _table(
            [f"{n} [{u}]" for n, u, _ in DISPLACEMENT_DISPLAY],
            [[fmt(v, 5, k) for v, (_, _, k) in zip(disp, DISPLACEMENT_DISPLAY, strict=True)]],
            left=0,
            cls="displacement",
        )
    )
    parts.append(f"<h4>{num}.2. Rows</h4>")
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
        parts.append(f"<h4>{num}.{k}. Slice pressure map of the roller rows</h4>")
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
        parts.append(_friction_html(friction, case, f"{num}.{k}"))
        k += 1
    if rating is not None:
        parts.append(_rating_html(rating, case, f"{num}.{k}"))
        k += 1
    for part in extra if isinstance(extra, list | tuple) else [extra] if extra else []:
        parts.append(part(f"{num}.{k}"))  # each extra part its own number
        k += 1
    parts.append(f"<h4>{num}.{k}. Warnings</h4>")
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
        "power loss [W]",
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
                "—"
                if getattr(friction, "power_loss", None) is None
                else fmt(float(friction.power_loss[c]), 4),
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
    bearing_input,
    result,
    *,
    friction=None,
    rating=None,
    title=None,
    notes=(),
    warnings=None,
    case_extras=None,
    load_diagram=None,
    duty_cycle=None,
    after_cases=(),
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
    load_diagram : SlewingLoadDiagram, optional
        The static load diagram of a slewing ring (:attr:`bearingkit.pipeline.Analysis.load_diagram`).
    warnings : list of list of str, optional
        Per case, the warnings to show (those of :attr:`bearingkit.pipeline.Analysis.warnings`);
        default: non-convergence and the rating's warnings (:func:`case_warnings`).
    case_extras : list of callables (or of lists of them), optional
        Per case, ``f(section_number) -> html`` of further sections, each numbered in turn (the operating
        conditions, the bearing in its structure).
    duty_cycle : dict, optional
        The duty cycle (:meth:`bearingkit.pipeline.duty_cycle.DutyCycleResult.to_dict`): a section with
        every bin's life and the combined life, after the load cases.
    after_cases : sequence of (title, callable)
        Further sections after the load cases (and the duty cycle): ``f(section_number) -> html``, listed
        in the contents as ``title`` (the subsurface section).

    Returns
    -------
    str
        HTML5 text, no external resources (figures are inline SVG or PNG data URIs).
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
        + (['<li><a href="#duty-cycle">Duty cycle</a></li>'] if duty_cycle is not None else [])
        + [f'<li><a href="#{_e(anchor)}">{_e(heading)}</a></li>' for heading, anchor, _ in after_cases]
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
    body.append(slewing_section_html(bearing_input, load_diagram))  # slewing rings only
    extras = case_extras or [None] * n_cases
    body.extend(
        _case_html(bearing_input, result, friction, rating, c, warnings, extras[c]) for c in range(n_cases)
    )
    k = n_cases + 2  # the number of the next section
    if duty_cycle is not None:
        body.append(duty_cycle_html(duty_cycle, k))
        k += 1
    for _, _, section in after_cases:
        body.append(section(k))
        k += 1
    body.append(f'<section id="warnings" data-section="warnings"><h2>{k}. Warnings</h2>')
    body.append(
        "<p>Edge loading, truncated contact ellipses, stress above the ISO 76 limit, an overloaded hardened "
        "layer and non-convergence, per load case.</p>"
    )
    body.append(_warning_list([f"[{case}] {w}" for case, w in all_warnings]) + "</section>")
    refs = used_references(result, friction, rating)
    if duty_cycle is not None:
        refs = list(dict.fromkeys([*refs, *duty_cycle["references"]]))
    body.append(_references_html(refs, k + 1))
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{_e(title)}</title><style>{_CSS}</style></head>"
        f"<body><main>{''.join(body)}</main></body></html>\n"
    )
