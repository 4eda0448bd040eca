"""Report sections of the operating conditions: speed per row, clearance chain, preload, lubrication.

SI values come in (the JSON-ready dicts of :class:`bearingkit.pipeline.Analysis`: ``statics_dict`` and
the ``lubrication`` part); shown in µm, degrees, r/min, mm²/s, hours with the unit in every header.
"""

from __future__ import annotations

import math

from bearingkit.report.html_format import _e, _table, fmt

RPM = 30.0 / math.pi


def _deg(values) -> str:
    lo, hi = math.degrees(min(values)), math.degrees(max(values))
    return f"{lo:.2f}" if abs(hi - lo) < 0.005 else f"{lo:.2f} – {hi:.2f}"


def thermal_html(thermal: dict) -> str:
    """The found operating temperature and its heat balance (the ``thermal`` dict of a case)."""
    oil = thermal["oil_flow_m3_s"] > 0
    rows = [
        ["friction heat P(T)", fmt(thermal["friction_heat_W"], 5)],
        [
            f"through seats and housing, {fmt(thermal['heat_dissipation_W_K'], 4)} W/K × (T − "
            f"{fmt(thermal['ambient_C'], 4)} °C)",
            fmt(thermal["conducted_heat_W"], 5),
        ],
    ]
    if oil:
        rows.append(
            [
                f"circulating oil {fmt(thermal['oil_flow_m3_s'] * 6e4, 3)} l/min from "
                f"{fmt(thermal['oil_inlet_C'], 4)} °C",
                fmt(thermal["oil_heat_W"], 5),
            ]
        )
    rows.append(["residual P − Φ", f"{thermal['balance_residual_W']:.2g}"])
    return (
        f'<p class="thermal"><b>Operating temperature FOUND by the heat balance: '
        f"{fmt(thermal['temperature_C'], 4)} °C</b> ({_e(thermal['method'])}; "
        f"{_e(thermal['friction_model'])} friction; H from {_e(thermal['heat_dissipation_from'])}; closed to "
        f"{thermal['balance_relative']:.1e} of the heat in {thermal['iterations']} iterations). "
        "Viscosity, κ, "
        "a_ISO, friction and the operating clearance below are at this temperature.</p>"
        + _table(["term", "heat [W]"], rows, left=1, cls="thermal")
    )


def operating_html(case: dict, lubrication: dict | None, number: str) -> str:
    """HTML of one case: found temperature, rows at speed, clearance chain, preload, lubrication (empty
    when none apply)."""
    parts = []
    if "thermal" in case:
        parts.append(thermal_html(case["thermal"]))
    speed_rows = [r for r in case["rows"] if r.get("cage_speed_rad_s")]  # turning (the keys exist at rest)
    if speed_rows:
        rows = [
            [
                _e(r["name"]),
                _deg(r["contact_angle_inner_rad"]) if "contact_angle_inner_rad" in r else "—",
                _deg(r["contact_angle_outer_rad"]) if "contact_angle_outer_rad" in r else "—",
                fmt(max(r["centrifugal_force_N"]), 4),
                fmt(r["cage_speed_rad_s"], 5, RPM),
            ]
            for r in speed_rows
        ]
        parts.append(
            "<p>Rolling elements at speed (centrifugal force; balls: gyroscopic moment under the "
            "raceway-control "
            "hypothesis): the inner and outer contact angles part.</p>"
            + _table(["row", "α inner [°]", "α outer [°]", "F_c max [N]", "cage [r/min]"], [*rows], left=1)
        )
    preload = [r for r in case["rows"] if "preload_N" in r]
    if preload:
        parts.append(
            "<p>Preload per row (axial force at rest, without external load):</p>"
            + _table(
                ["row", "preload [N]"], [[_e(r["name"]), fmt(r["preload_N"], 5)] for r in preload], left=1
            )
        )
    chain = case.get("clearance")
    if chain:
        rows = [
            [
                _e(r["name"]),
                fmt(r["initial_m"], 4, 1e6),
                fmt(r["fit_inner_m"], 4, 1e6),
                fmt(r["fit_outer_m"], 4, 1e6),
                fmt(r["mounted_m"], 4, 1e6),
                fmt(r["thermal_m"], 4, 1e6),
                fmt(r["operating_m"], 4, 1e6),
            ]
            for r in chain["rows"]
        ]
        parts.append(
            "<p>Clearance chain (fits and temperatures):</p>"
            + _table(
                [
                    "row",
                    "initial [µm]",
                    "fit inner [µm]",
                    "fit outer [µm]",
                    "mounted [µm]",
                    "thermal [µm]",
                    "operating [µm]",
                ],
                rows,
                left=1,
                cls="clearance",
            )
        )
    if lubrication:
        level = f" ({_e(lubrication['contamination_level'])})" if lubrication["contamination_level"] else ""
        e_c = (
            "not given"
            if lubrication["contamination_factor"] is None
            else (f"{lubrication['contamination_factor']:.3g}{level}")
        )
        rows = [
            [
                _e(r["name"]),
                fmt(r["reference_viscosity_m2_s"], 4, 1e6),
                fmt(r["kappa"], 3),
                fmt(r["a_ISO"], 3),
                fmt(r["min_film_parameter"], 3),
            ]
            for r in lubrication["rows"]
        ]
        life = "n/a" if lubrication["Lnm_rev"] is None else f"{lubrication['Lnm_rev'] * 1e-6:.4g} 10⁶ rev"
        hours = "" if lubrication["Lnm_h"] is None else f" ({lubrication['Lnm_h']:.4g} h)"
        grease = (
            ""
            if lubrication["grease_life_h"] is None
            else (f"; grease life ≈ {lubrication['grease_life_h']:.3g} h")
        )
        parts.append(
            f"<p>Lubrication: ν = {lubrication['viscosity_m2_s'] * 1e6:.4g} mm²/s at the operating "
            "temperature, "
            f"e_C = {e_c}; modified life L_nm = {life}{hours}{grease}.</p>"
            + _table(["row", "ν1 [mm²/s]", "κ", "a_ISO", "min Λ"], rows, left=1, cls="lubrication")
        )
    lim = case.get("limits")
    if lim:
        parts.append(_limits_html(lim))
    if not parts:
        return ""
    return f"<h4>{number}. Operating conditions</h4>" + "".join(parts)


def _limits_html(lim: dict) -> str:
    """Speed and load limits of one case (``limits`` of the case dict), each beside what it limits."""
    ref = lim["thermal_reference_speed_rad_s"]
    flags = lim["flags"]

    def mark(key: str) -> str:
        return " ⚠" if flags[key] else ""

    rows = [
        [
            "limiting speed [r/min]",
            fmt(lim["limiting_speed_rad_s"], 4, RPM) + mark("above_limiting_speed"),
            _e(f"{lim['lubrication'].replace('_', ' ')}; {lim['limiting_speed_source']}"),
        ],
        [
            "thermal reference speed [r/min]",
            ("—" if ref is None else fmt(ref, 4, RPM)) + mark("above_reference_speed"),
            _e(lim["thermal_reference_speed_note"] or "ISO 15312 reference conditions, SKF friction model"),
        ],
    ]
    if lim["seal"] is not None:
        rows.append(
            [
                f"seal {_e(lim['seal'])} lip speed [m/s]",
                fmt(lim["seal_lip_speed_m_s"], 3) + mark("seal_lip_speed_exceeded"),
                f"limit {lim['seal_lip_speed_limit_m_s']:g} m/s (rubbing NBR lip)",
            ]
        )
    if lim["minimum_load_N"] is not None:
        rows.append(
            [
                "minimum load [N]",
                fmt(lim["minimum_load_N"], 4) + mark("below_minimum_load"),
                _e(f"{lim['minimum_load_rule']}; carried {lim['load_compared_N']:.4g} N"),
            ]
        )
    return (
        f"<p>Speed and load limits (n·d_m = {lim['n_dm_mm_rpm']:.3g} mm·r/min; ⚠ = exceeded, see the "
        "warnings):</p>" + _table(["limit", "value", "source"], rows, left=1, cls="limits")
    )
