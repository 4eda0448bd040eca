"""The HTML report of a shaft on several bearings: inputs, shaft lines, every bearing, system life.

SI inside; this module converts only for display (mm, µm, mrad, kN, MPa, r/min, h) and names the unit
in every header. It reads one :class:`~bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis` (its
``to_dict`` for the numbers, the shaft result for the figure, each bearing's pipeline ``Analysis`` for
the bearing subsections, drawn by the single-bearing renderers of :mod:`bearingkit.report.html`) and
never recomputes mechanics. Self-contained like the bearing report: inline figures and style, no
script.

>>> analysis = ShaftAnalysis(load_shaft_file("examples/shaft_countershaft.toml"))  # doctest: +SKIP
>>> analysis.report("out/shaft.html")                                             # doctest: +SKIP
"""

from __future__ import annotations

import math
from pathlib import Path

from bearingkit.errors import InputError
from bearingkit.report import write_report
from bearingkit.report.html import _CSS, _case_html, _references_html
from bearingkit.report.html_format import _badge, _e, _figure_html, _table, _warning_list, fmt
from bearingkit.report.html_inputs import geometry_rows, rows_table
from bearingkit.report.html_operating import operating_html
from bearingkit.report.systems.shaft_plots import shaft_figure
from bearingkit.systems.shaft.shaft_analysis import SHAFT_RENDERERS

__all__ = ["build_shaft_report", "render_shaft"]

RPM = 30.0 / math.pi
#: Citation keys of the shaft model itself (beam elements, gear forces, system life), shown first.
SHAFT_REFERENCES = ("lundberg1947", "harris2007")
#: Display of the reaction and seat-state columns: (JSON key, header, factor SI → display, digits).
REACTION_COLUMNS = (
    ("F_x_N", "F_x [N]", 1.0, 5),
    ("F_y_N", "F_y [N]", 1.0, 5),
    ("F_z_N", "F_z [N]", 1.0, 5),
    ("M_x_Nm", "M_x [N·m]", 1.0, 4),
    ("M_y_Nm", "M_y [N·m]", 1.0, 4),
)
SEAT_COLUMNS = (
    ("u_x_m", "u_x [µm]", 1e6, 4),
    ("u_y_m", "u_y [µm]", 1e6, 4),
    ("u_z_m", "u_z [µm]", 1e6, 4),
    ("theta_x_rad", "θ_x [mrad]", 1e3, 4),
    ("theta_y_rad", "θ_y [mrad]", 1e3, 4),
)
#: Display of the per-bearing results: (summary key, header, factor SI → display, digits).
RESULT_COLUMNS = (
    ("radial_load_N", "F_r [N]", 1.0, 5),
    ("axial_load_N", "F_a [N]", 1.0, 5),
    ("max_pressure_Pa", "p_max [MPa]", 1e-6, 5),
    ("static_safety", "s0 [-]", 1.0, 4),
    ("L10h_iso281_h", "L10h ISO 281 [h]", 1.0, 4),
    ("Lnm_iso281_h", "L_nmh ISO 281 [h]", 1.0, 4),
    ("L10h_h", "L10rh ISO/TS 16281 [h]", 1.0, 4),
    ("Lnmr_h", "L_nmrh ISO/TS 16281 [h]", 1.0, 4),
    ("kappa_min", "κ min [-]", 1.0, 3),
    ("friction_torque_Nm", "M_fr [N·m]", 1.0, 4),
    ("power_loss_W", "P_loss [W]", 1.0, 4),
    ("temperature_C", "T [°C]", 1.0, 4),
)
#: Forces [N] at or below this print as 0 (solver round-off of an unloaded direction).
FORCE_NOISE = 1e-6


def _mm(v) -> str:
    return fmt(v, 5, 1e3)


def _inputs_html(data: dict, analysis) -> str:
    inp = data["inputs"]
    m = inp["material"]
    gravity = inp["gravity_m_per_s2"]
    parts = ['<section id="inputs" data-section="inputs"><h2>1. Inputs</h2>']
    parts.append(
        _table(
            ["item", "value"],
            [
                ["file", _e(data["file"])],
                ["shaft", _e(data["shaft"])],
                [
                    "material",
                    f"{_e(m['name'])}: E = {fmt(m['youngs_modulus_Pa'], 4, 1e-9)} GPa, ν = "
                    f"{fmt(m['poisson_ratio'])}, ρ = {fmt(m['density_kg_per_m3'])} kg/m³",
                ],
                ["beam elements", "Timoshenko" if inp["shear_deformation"] else "Euler–Bernoulli"],
                ["gravity [m/s²]", "none" if gravity is None else _e(", ".join(fmt(g, 4) for g in gravity))],
                ["lubricant (bearings without their own)", _e(inp["lubricant"] or "none given")],
                ["friction model", _e(data["friction_model"])],
            ],
            left=2,
        )
    )
    parts.append("<h3>Sections</h3>")
    parts.append(
        _table(
            ["#", "start [mm]", "end [mm]", "d_o [mm]", "d_i [mm]"],
            [
                [
                    str(i),
                    _mm(s["start_m"]),
                    _mm(s["end_m"]),
                    _mm(s["outer_diameter_m"]),
                    _mm(s["inner_diameter_m"]),
                ]
                for i, s in enumerate(inp["sections"])
            ],
        )
    )
    parts.append("<h3>Bearings</h3>")
    rows = []
    for b in inp["bearings"]:
        housing = b["housing_stiffness_SI"]
        rows.append(
            [
                f'<a href="#bearing-{_e(b["name"])}">{_e(b["name"])}</a>',
                _e(b["bearing"]),
                _e(b["file"] or "—"),
                _mm(b["position_m"]),
                _e(b["orientation"]),
                _e(b["axial"]),
                fmt(b["axial_offset_m"], 4, 1e6),
                "rigid"
                if housing is None
                else _e(", ".join("rigid" if k is None else f"{k:.3g}" for k in housing)),
            ]
        )
    parts.append(
        _table(
            [
                "name",
                "bearing",
                "file",
                "z [mm]",
                "orientation",
                "axial",
                "axial offset [µm]",
                "housing [SI]",
            ],
            rows,
            left=3,
        )
    )
    if inp["gears"]:
        parts.append("<h3>Gears</h3>")
        parts.append(
            _table(
                ["name", "z [mm]", "d [mm]", "α_n [°]", "β [°]", "mesh angle [°]", "mass [kg]"],
                [
                    [
                        _e(g["name"]),
                        _mm(g["position_m"]),
                        _mm(g["pitch_diameter_m"]),
                        fmt(math.degrees(g["pressure_angle_rad"]), 4),
                        fmt(math.degrees(g["helix_angle_rad"]), 4),
                        fmt(math.degrees(g["mesh_angle_rad"]), 4),
                        fmt(g["mass_kg"], 4),
                    ]
                    for g in inp["gears"]
                ],
            )
        )
    if inp["masses"]:
        parts.append("<h3>Point masses</h3>")
        parts.append(
            _table(
                ["name", "z [mm]", "mass [kg]"],
                [[_e(x["name"]), _mm(x["position_m"]), fmt(x["mass_kg"], 4)] for x in inp["masses"]],
            )
        )
    parts.append("<h3>Load cases</h3>")
    rows = []
    for c in inp["load_cases"]:
        torques = "; ".join(f"{g} {fmt(t, 5)} N·m" for g, t in c["gear_torques_Nm"].items())
        forces = "; ".join(
            f"{f['name']} at {_mm(f['position_m'])} mm: "
            + ", ".join(
                f"{k.rsplit('_', 1)[0]} {fmt(v, 5)}" for k, v in f.items() if k[:2] in ("F_", "M_") and v
            )
            for f in c["forces"]
        )
        lines = "; ".join(f"{q['name']} {_mm(q['start_m'])}–{_mm(q['end_m'])} mm" for q in c["line_loads"])
        rows.append(
            [
                _e(c["name"]),
                fmt(c["speed_rad_s"], 5, RPM),
                fmt(c["temperature_C"], 4),
                _e(torques or "—"),
                _e(forces or "—"),
                _e(lines or "—"),
            ]
        )
    parts.append(
        _table(
            ["case", "speed [r/min]", "temperature [°C]", "gear torques", "forces [N, N·m]", "line loads"],
            rows,
            left=1,
        )
    )
    parts.append("</section>")
    return "".join(parts)


def _cell(value, factor, digits, key="") -> str:
    tiny = FORCE_NOISE if key.endswith("_N") else 0.0
    return fmt(value, digits, factor, tiny)


def _case_section(data: dict, analysis, case: int, number: int) -> str:
    c = data["cases"][case]
    name = c["case"]
    ok = c["converged"]
    parts = [f'<section class="case" id="case-{case}" data-section="shaft-case" data-case="{_e(name)}">']
    parts.append(f"<h2>{number}. Load case “{_e(name)}” {_badge(ok)}</h2>")
    reason = "" if ok else f"; reason: {_e(c['reason'] or '—')}"
    speed = "—" if c["speed_rad_s"] is None else fmt(c["speed_rad_s"], 5, RPM)
    parts.append(
        f'<p class="sub">{c["iterations"]} iterations, residual {c["residual_norm"]:.2e} (relative to the '
        f"load scale); shaft speed {speed} r/min{reason}</p>"
    )
    s = c["shaft"]
    parts.append(
        f"<p>Largest radial deflection <b>{fmt(s['max_radial_deflection_m'], 4, 1e6)} µm</b> at "
        f"{_mm(s['max_radial_deflection_at_m'])} mm; largest bending moment "
        f"<b>{fmt(s['max_bending_moment_Nm'], 4)} N·m</b> at {_mm(s['max_bending_moment_at_m'])} mm.</p>"
    )
    parts.append(
        _figure_html(
            shaft_figure(analysis.result, case),
            f"shaft outline, deflection and bending moment, case {name}",
            "Top: outline, bearings (▲ locating, △ floating) and gears. Middle: deflection of the shaft "
            "axis u_x, u_y, |u| [µm]. Bottom: bending moment M_x, M_y, |M| [N·m] (M = E I dθ/dz).",
        )
    )
    parts.append(f"<h4>{number}.1. Reactions on the shaft and seat state (shaft frame)</h4>")
    rows = []
    for b in c["bearings"]:
        sm = b["summary"]
        rows.append(
            [f'<a href="#bearing-{_e(b["name"])}">{_e(b["name"])}</a>', _mm(b["position_m"])]
            + [_cell(sm["reaction_on_shaft"][k], f, d, k) for k, _, f, d in REACTION_COLUMNS]
            + [_cell(sm["seat_displacement"][k], f, d) for k, _, f, d in SEAT_COLUMNS]
            + [fmt(sm["misalignment_rad"], 4, 1e3)]
        )
    heads = (
        ["bearing", "z [mm]"] + [h for _, h, _, _ in REACTION_COLUMNS] + [h for _, h, _, _ in SEAT_COLUMNS]
    )
    parts.append(_table([*heads, "misalignment [mrad]"], rows, left=1, cls="reactions"))
    parts.append(
        "<p>Reaction: force and moment of the bearing on the shaft. Seat: displacement and tilt of the "
        "shaft at the bearing. Misalignment: tilt |(θ_x, θ_y)| of the inner ring against the outer ring "
        "(the housing's compliance included).</p>"
    )
    parts.append(f"<h4>{number}.2. Bearing results (each bearing's own frame)</h4>")
    rows = [
        [f'<a href="#bearing-{_e(b["name"])}">{_e(b["name"])}</a>']
        + [_cell(b["summary"][k], f, d, k) for k, _, f, d in RESULT_COLUMNS]
        + [str(b["summary"]["warnings"])]
        for b in c["bearings"]
    ]
    parts.append(
        _table(
            ["bearing"] + [h for _, h, _, _ in RESULT_COLUMNS] + ["warnings"], rows, left=1, cls="bearings"
        )
    )
    parts.append(heat_balance_html(c))
    sysd = c["rating"]["system"]
    parts.append(f"<h4>{number}.3. System life</h4>")
    iso = [
        "ISO 281",
        fmt(sysd.get("L10_iso281_rev"), 4),
        fmt(sysd.get("L10h_iso281_h"), 4),
        fmt(sysd.get("Lnm_iso281_rev"), 4),
        fmt(sysd.get("Lnm_iso281_h"), 4),
    ]
    ts = [
        "ISO/TS 16281",
        fmt(sysd["L10r_rev"], 4),
        fmt(sysd["L10h_h"], 4),
        fmt(sysd["Lnmr_rev"], 4),
        fmt(sysd["Lnmr_h"], 4),
    ]
    first = (sysd.get("headline") or {}).get("method", "ISO 281")
    parts.append(
        _table(
            ["method", "L10 [rev]", "L10h [h]", "L_nm [rev]", "L_nm [h]"],
            [iso, ts] if first == "ISO 281" else [ts, iso],
            left=1,
            cls="system",
        )
    )
    parts.append(f"<p>Power loss of the bearings: {fmt(c['power_loss_W'], 4)} W.</p>")
    parts.append(
        "<p>The bearings as independently failing Weibull members: L_sys = (Σ L_i^(−e))^(−1/e) (e = 10/9 "
        "balls, 9/8 rollers; mixed slopes solved exactly). ISO 281 (listed first): one member per bearing, "
        "its ISO 281 L10 (L_nm: its a1 a_ISO L10); ISO/TS 16281: the rows of every bearing, their L10r "
        "(L_nm: the rows' modified lives).</p>"
    )
    if sysd.get("life_difference"):
        parts.append(f'<p class="note">Why they differ: {_e(sysd["life_difference"])}</p>')
    parts.append(f"<h4>{number}.4. Warnings</h4>")
    parts.append(_warning_list(c["warnings"]))
    parts.append("</section>")
    return "".join(parts)


def heat_balance_html(c: dict) -> str:
    """Each bearing's found temperature and its heat balance in one case ("" when they were inputs)."""
    found = [
        (b["summary"]["name"], b["analysis"]["thermal"])
        for b in c["bearings"]
        if "thermal" in b.get("analysis", {})
    ]
    if not found:
        return ""
    rows = [
        [
            _e(name),
            fmt(t["temperature_C"], 4),
            fmt(t["friction_heat_W"], 5),
            fmt(t["conducted_heat_W"], 5),
            fmt(t["oil_heat_W"], 5),
            fmt(t["heat_dissipation_W_K"], 4),
            _e(t["heat_dissipation_from"]),
            fmt(t["ambient_C"], 4),
            f"{t['balance_residual_W']:.2g}",
            f"{t['balance_relative']:.1e}",
            str(t["iterations"]),
            _e(t["friction_model"]),
        ]
        for name, t in found
    ]
    heads = ["bearing", "T [°C]", "P(T) [W]", "seats/housing [W]", "oil [W]", "H [W/K]", "H from",
             "T_amb [°C]", "residual [W]", "residual / P", "iterations", "friction model"]  # fmt: skip
    return (
        '<p class="thermal"><b>Operating temperatures FOUND by each bearing\'s heat balance</b> '
        f"({_e(found[0][1]['method'])}): the friction heat P(T) of the bearing at the load the system "
        "puts on it equals the heat through its seats and housing H (T − T_amb) plus that carried away by a "
        "circulating oil; viscosity, κ, a_ISO, L_nm and friction above are at T.</p>"
        + _table(heads, rows, left=1, cls="thermal")
    )


def _bearing_section(data: dict, analysis, name: str, number: int) -> str:
    seat = analysis.system.bearing(name)
    a = analysis.bearings.get(name)
    parts = [f'<section id="bearing-{_e(name)}" data-section="bearing" data-bearing="{_e(name)}">']
    title = getattr(seat.bearing, "name", "linear bearing")
    parts.append(f"<h2>{number}. Bearing “{_e(name)}” — {_e(title)}</h2>")
    if a is None:
        parts.append("<p>A linear stiffness: no rows, so no pressures, lives or friction.</p></section>")
        return "".join(parts)
    src = seat.source
    parts.append(
        _table(
            ["item", "value"],
            [
                ["file", _e(getattr(src, "source", None) or "—")],
                ["bearing type", f"<code>{_e(a.input.bearing_type)}</code>"],
                ["position [mm]", _mm(seat.position)],
                ["orientation, axial", _e(f"{seat.orientation}, {seat.axial}")],
                ["lubricant", _e("none" if a.operating.lubricant is None else a.operating.lubricant.name)],
                ["contamination e_C", fmt(a.operating.contamination, 4)],
            ],
            left=2,
        )
    )
    if src is not None:
        parts.append("<h3>Geometry</h3>")
        parts.append(_table(["field", "as given", "SI value", "SI unit"], geometry_rows(src), left=2))
    parts.append("<h3>Rows as modelled</h3>")
    parts.append(rows_table(seat.bearing))
    parts.append(
        "<p>Each load case below is this bearing at the state the shaft solution gives it: the inner "
        "ring's displacement and tilt against the outer ring (bearing frame) imposed on all five DOFs; "
        "the load is what the shaft puts on the bearing.</p>"
    )
    friction = a.friction
    native = friction.native if friction is not None and hasattr(friction.native, "by_row") else None
    statics = a.statics_dict()["cases"]
    lub = a.lubrication
    for c in range(analysis.n_cases):
        extra = lambda n, c=c: operating_html(statics[c], None if lub is None else lub.to_dict(c), n)  # noqa: E731
        parts.append(
            _case_html(
                a.input,
                a.statics,
                native,
                a.rating,
                c,
                a.warnings,
                extra,
                number=f"{number}.{c + 1}",
                anchor=f"bearing-{name}-case-{c}",
                level=3,
            )
        )
    parts.append("</section>")
    return "".join(parts)


def _summary_html(data: dict) -> str:
    rows = []
    for i, c in enumerate(data["cases"]):
        s, sysd = c["shaft"], c["rating"]["system"]
        rows.append(
            [
                f'<a href="#case-{i}">{_e(c["case"])}</a>',
                _badge(c["converged"]),
                fmt(s["max_radial_deflection_m"], 4, 1e6),
                fmt(s["max_bending_moment_Nm"], 4),
                fmt(sysd.get("L10h_iso281_h"), 4),
                fmt(sysd.get("Lnm_iso281_h"), 4),
                fmt(sysd["L10h_h"], 4),
                fmt(sysd["Lnmr_h"], 4),
                fmt(c["power_loss_W"], 4),
                str(len(c["warnings"])),
            ]
        )
    heads = ["case", "status", "max deflection [µm]", "max |M| [N·m]", "system L10h ISO 281 [h]"]
    heads += ["system L_nmh ISO 281 [h]", "system L10rh ISO/TS 16281 [h]", "system L_nmrh ISO/TS 16281 [h]"]
    return _table([*heads, "power loss [W]", "warnings"], rows, left=2, cls="summary")


def build_shaft_report(analysis, *, title=None, notes=()) -> str:
    """The self-contained HTML report (text) of a shaft analysis.

    Parameters
    ----------
    analysis : bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis
    title : str, optional
    notes : sequence of str
        Extra run notes shown before the analysis's own.
    """
    from bearingkit import __version__
    from bearingkit.io.loader import MAX_REPORT_CASES

    if analysis.n_cases > MAX_REPORT_CASES:  # before anything is computed: figures grow with the cases
        raise InputError(
            f"{analysis.input.source}: load_cases ({analysis.n_cases} cases) must be at most "
            f"{MAX_REPORT_CASES} for a report; split the file (the JSON output has no such limit)"
        )
    data = analysis.to_dict()
    title = title or f"bearingkit shaft report — {data['shaft']}"
    n = analysis.n_cases
    names = [b.name for b in analysis.system.bearings]
    nav = "".join(
        ['<li><a href="#inputs">Inputs</a></li>']
        + [f'<li><a href="#case-{c}">Load case “{_e(x)}”</a></li>' for c, x in enumerate(analysis.case_names)]
        + [f'<li><a href="#bearing-{_e(x)}">Bearing “{_e(x)}”</a></li>' for x in names]
        + ['<li><a href="#warnings">Warnings</a></li>', '<li><a href="#references">References</a></li>']
    )
    all_notes = [*notes, *data["notes"]]
    body = [
        f"<h1>{_e(title)}</h1>",
        f'<p class="sub">{_e(data["shaft"])} on {len(names)} bearings · {n} load case(s) · bearingkit '
        f"{_e(__version__)} · SI results shown in engineering units (unit in every header)</p>",
        _summary_html(data),
        f"<nav><b>Contents</b><ol>{nav}</ol></nav>",
    ]
    if all_notes:
        body.append("<h3>Run notes</h3><ul>" + "".join(f"<li>{_e(x)}</li>" for x in all_notes) + "</ul>")
    body.append(_inputs_html(data, analysis))
    body.extend(_case_section(data, analysis, c, c + 2) for c in range(n))
    body.extend(_bearing_section(data, analysis, x, n + 2 + i) for i, x in enumerate(names))
    k = n + 2 + len(names)
    everything = [f"[{c['case']}] {w}" for c in data["cases"] for w in c["warnings"]]
    body.append(f'<section id="warnings" data-section="warnings"><h2>{k}. Warnings</h2>')
    body.append("<p>Every warning of every bearing and of the system, per load case.</p>")
    body.append(_warning_list(everything) + "</section>")
    keys = list(SHAFT_REFERENCES)
    for a in analysis.bearings.values():
        keys += a.references
    body.append(_references_html(list(dict.fromkeys(keys)), k + 1))
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{_e(title)}</title><style>{_CSS}</style></head>"
        f"<body><main>{''.join(body)}</main></body></html>\n"
    )


def render_shaft(analysis, path, *, title=None, notes=()) -> Path:
    """Write :func:`build_shaft_report` to ``path`` atomically; returns the path."""
    return write_report(path, build_shaft_report(analysis, title=title, notes=notes))


SHAFT_RENDERERS["html"] = render_shaft
