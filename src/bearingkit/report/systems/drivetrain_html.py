"""The HTML report of a drivetrain: summary, layout drawing, per load case the meshes, the bearings, the
shaft lines and the power flow, then one section per bearing (its pipeline Analysis per case)."""

from __future__ import annotations

from pathlib import Path

from bearingkit.errors import InputError
from bearingkit.report import write_report
from bearingkit.report.html import _CSS, _case_html, _references_html
from bearingkit.report.html_format import _badge, _e, _figure_html, _table, _warning_list, fmt
from bearingkit.report.systems.drivetrain_plots import layout_figure, shaft_lines_figure
from bearingkit.report.systems.shaft_html import heat_balance_html
from bearingkit.systems.drivetrain.analysis import DRIVETRAIN_RENDERERS
from bearingkit.systems.shaft.life import SYSTEM_LIFE_DIFFERENCE

RPM = 30.0 / 3.141592653589793
#: Most load cases a drivetrain report draws (figures and bearing sections grow with them).
MAX_REPORT_CASES = 20


def _case_section(da, c: dict, i: int, number: int) -> str:
    parts = [
        f'<section id="case-{i}" data-section="case"><h2>{number}. Load case “{_e(c["case"])}” '
        f"{_badge(c['converged'])}</h2>"
    ]
    parts.append("<h3>Meshes</h3>")
    rows = [
        [
            _e(m["name"]),
            fmt(m["normal_force_N"], 5),
            fmt(m["on_a"]["tangential_N"], 5),
            fmt(m["on_a"]["radial_N"], 5),
            fmt(m["on_a"]["axial_N"], 5),
            fmt(m["on_a"]["torque_Nm"], 5),
            fmt(m["on_b"]["torque_Nm"], 5),
            fmt(m["stiffness_N_per_m"], 4, 1e-6),
            fmt(m["deflection_m"], 4, 1e6),
        ]
        for m in c["meshes"]
    ]
    parts.append(
        _table(
            [
                "mesh",
                "F_n [N]",
                "F_t on a [N]",
                "F_r on a [N]",
                "F_a on a [N]",
                "T_a [N·m]",
                "T_b [N·m]",
                "k [N/µm]",
                "δ [µm]",
            ],
            rows,
        )
    )
    parts.append("<h3>Bearings</h3>")
    rows = []
    for b in c["bearings"]:
        s = b["summary"]
        rows.append(
            [
                f'<a href="#bearing-{_e(s["name"])}">{_e(s["name"])}</a>',
                _e(f"{s['inner']} / {s['outer']}"),
                fmt(s["radial_load_N"], 5),
                fmt(s["axial_load_N"], 5),
                fmt(s["max_pressure_Pa"], 4, 1e-6),
                fmt(s["static_safety"], 3),
                fmt(s["L10h_iso281_h"], 4),
                fmt(s["L10h_h"], 4),
                fmt(s["power_loss_W"], 3),
                fmt(s["temperature_C"], 4) + (" found" if s["temperature_found"] else ""),
            ]
        )
    parts.append(
        _table(
            [
                "bearing",
                "inner / outer",
                "F_r [N]",
                "F_a [N]",
                "p_max [MPa]",
                "s0",
                "L10h ISO 281 [h]",
                "L10h ISO/TS 16281 [h]",
                "P_loss [W]",
                "T [°C]",
            ],
            rows,
            left=2,
        )
    )
    parts.append(heat_balance_html(c))
    sysd = c["system"]
    parts.append(
        f"<p>System L10h: {fmt(sysd['L10h_iso281_h'], 4)} h (ISO 281), {fmt(sysd['L10h_h'], 4)} h "
        "(ISO/TS 16281 rows), combined in hours as independent Weibull members. Why they differ: "
        f"{_e(SYSTEM_LIFE_DIFFERENCE)}</p>"
    )
    p = c["power"]
    if p is not None:
        parts.append("<h3>Power flow</h3>")
        rows = [[_e(k), fmt(v * RPM, 5)] for k, v in p["speeds_rad_s"].items()]
        parts.append(_table(["shaft", "speed [rpm]"], rows))
        rows = [["input", fmt(p["input_W"], 5)]]
        rows += [[f"loss: bearing {_e(k)}", fmt(v, 4)] for k, v in p["bearing_loss_W"].items()]
        rows += [
            [f"loss: mesh {_e(k)} (μ_mz = {_e(v['mu_mz'])}, H_V = {fmt(v['H_V'], 4)})", fmt(v["loss_W"], 4)]
            for k, v in p["mesh"].items()
        ]
        rows += [["output", fmt(p["output_W"], 5)], ["efficiency [%]", fmt(p["efficiency"], 5, 100.0)]]
        parts.append(_table(["power", "[W]"], rows))
    parts.append(
        _figure_html(
            shaft_lines_figure(da.result, i), "shaft lines", "Deflection and bending moment of every shaft."
        )
    )
    parts.append(_warning_list(c["warnings"]) + "</section>")
    return "".join(parts)


def _bearing_section(da, name: str, number: int) -> str:
    a = da.bearings.get(name)
    parts = [
        f'<section id="bearing-{_e(name)}" data-section="bearing"><h2>{number}. Bearing “{_e(name)}”</h2>'
    ]
    if a is None:
        return "".join(
            [*parts, "<p>A linear stiffness: no rows, so no pressures, lives or friction.</p></section>"]
        )
    friction = a.friction
    native = friction.native if friction is not None and hasattr(friction.native, "by_row") else None
    for c in range(da.n_cases):
        parts.append(
            _case_html(
                a.input,
                a.statics,
                native,
                a.rating,
                c,
                a.warnings,
                None,
                number=f"{number}.{c + 1}",
                anchor=f"bearing-{name}-case-{c}",
                level=3,
            )
        )
    return "".join([*parts, "</section>"])


def build_drivetrain_report(da, *, title=None) -> str:
    """The self-contained HTML report (text) of a :class:`DrivetrainAnalysis`."""
    from bearingkit import __version__

    if da.n_cases > MAX_REPORT_CASES:
        raise InputError(
            f"{da.input.source}: load_cases ({da.n_cases}) must be at most {MAX_REPORT_CASES} for a "
            "report; split the file (the JSON output has no such limit)"
        )
    data = da.to_dict()
    title = title or f"bearingkit drivetrain report — {data['drivetrain']}"
    names = [b.name for b in da.drivetrain.bearings]
    rows = [
        [
            f'<a href="#case-{i}">{_e(c["case"])}</a>',
            _badge(c["converged"]),
            fmt(c["system"]["L10h_iso281_h"], 4),
            fmt(c["system"]["L10h_h"], 4),
            fmt(None if c["power"] is None else c["power"]["efficiency"], 5, 100.0),
            str(len(c["warnings"])),
        ]
        for i, c in enumerate(data["cases"])
    ]
    body = [
        f"<h1>{_e(title)}</h1>",
        f'<p class="sub">{len(da.drivetrain.shafts)} shafts · {len(names)} bearings · '
        f"{len(da.drivetrain.meshes)} "
        f"meshes · {da.n_cases} load case(s) · bearingkit {_e(__version__)}</p>",
        _table(
            [
                "case",
                "status",
                "system L10h ISO 281 [h]",
                "system L10h ISO/TS 16281 [h]",
                "efficiency [%]",
                "warnings",
            ],
            rows,
            left=2,
            cls="summary",
        ),
    ]
    duty = data["duty_cycle"]
    if duty is not None:
        body.append(
            f"<p>Duty cycle (Palmgren–Miner over the time fractions): system L10h "
            f"{fmt(duty['system']['L10h_iso281_h'], 4)} h (ISO 281), "
            f"{fmt(duty['system']['L10h_h'], 4)} h (ISO/TS 16281).</p>"
        )
    body.append("<h3>Run notes</h3><ul>" + "".join(f"<li>{_e(x)}</li>" for x in data["notes"]) + "</ul>")
    body.append('<section id="layout" data-section="layout"><h2>1. Layout</h2>')
    body.append(_figure_html(layout_figure(da.drivetrain), "layout", "End and side view of the drivetrain."))
    body.append("</section>")
    body.extend(_case_section(da, c, i, i + 2) for i, c in enumerate(data["cases"]))
    k = da.n_cases + 2
    body.extend(_bearing_section(da, x, k + j) for j, x in enumerate(names))
    k += len(names)
    everything = [f"[{c['case']}] {w}" for c in data["cases"] for w in c["warnings"]]
    body.append(
        f'<section id="warnings" data-section="warnings"><h2>{k}. Warnings</h2>'
        f"{_warning_list(everything)}</section>"
    )
    keys = ["iso281", "iso16281"]
    for a in da.bearings.values():
        keys += a.references
    body.append(_references_html(list(dict.fromkeys(keys)), k + 1))
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        f"<title>{_e(title)}</title><style>{_CSS}</style></head><body><main>{''.join(body)}</main></body></html>\n"
    )


def render_drivetrain(da, path, *, title=None) -> Path:
    """Write :func:`build_drivetrain_report` to ``path`` atomically; returns the path."""
    return write_report(path, build_drivetrain_report(da, title=title))


DRIVETRAIN_RENDERERS["html"] = render_drivetrain
