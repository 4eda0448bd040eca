"""Console output of the operating conditions: speed per row, clearance chain, preload, lubrication.

SI values come in (the dicts of :class:`bearingkit.pipeline.Analysis`); shown in µm, deg, r/min, mm²/s,
h. Faces only: nothing is computed here.
"""

from __future__ import annotations

import math

from rich.console import Group
from rich.markup import escape
from rich.table import Table
from rich.text import Text

RPM = 30.0 / math.pi


def _deg_range(values) -> str:
    """Range of angles in degrees, two decimals, without "-0.00" (a round-off below 0.005°)."""
    lo, hi = (round(math.degrees(v), 2) + 0.0 for v in (min(values), max(values)))
    return f"{lo:.2f}" if hi == lo else f"{lo:.2f}–{hi:.2f}"


def operating_text(c: dict) -> Group:
    """Lines under a case's load table: speed effects per row, clearance chain, preload per row."""
    lines = []
    for r in c["rows"]:
        if not r.get("cage_speed_rad_s"):  # at rest (the speed keys hold the values at rest)
            pass
        elif "contact_angle_outer_rad" in r:
            lines.append(
                f"  {r['name']} at speed: α_inner {_deg_range(r['contact_angle_inner_rad'])}°, α_outer "
                f"{_deg_range(r['contact_angle_outer_rad'])}°, F_c {max(r['centrifugal_force_N']):.4g} N, "
                f"cage {r['cage_speed_rad_s'] * RPM:.5g} r/min"
            )
        elif "centrifugal_force_N" in r:
            lines.append(
                f"  {r['name']} at speed: F_c {max(r['centrifugal_force_N']):.4g} N per roller, cage "
                f"{r['cage_speed_rad_s'] * RPM:.5g} r/min"
            )
        if "preload_N" in r:
            lines.append(f"  {r['name']} preload (at rest, no external load): {r['preload_N']:.4g} N axial")
    chain = c.get("clearance")
    if chain:
        for r in chain["rows"]:
            lines.append(
                f"  clearance {r['name']}: initial {r['initial_m'] * 1e6:.3g} µm − fit inner "
                f"{r['fit_inner_m'] * 1e6:.3g} − fit outer {r['fit_outer_m'] * 1e6:.3g} → mounted "
                f"{r['mounted_m'] * 1e6:.3g} µm; thermal {r['thermal_m'] * 1e6:+.3g} → operating "
                f"{r['operating_m'] * 1e6:.3g} µm"
            )
        lines.append(
            f"  fits: interference inner {chain['interference_inner_m'] * 1e6:.3g} µm "
            f"(p = {chain['pressure_inner_Pa'] / 1e6:.3g} MPa), outer "
            f"{chain['interference_outer_m'] * 1e6:.3g} µm "
            f"(p = {chain['pressure_outer_Pa'] / 1e6:.3g} MPa)"
        )
    return Group(*(Text(line) for line in lines))


def limits_lines(lim: dict | None) -> list[str]:
    """The speed and load limits of one case (``limits`` of the case dicts) in one line."""
    if not lim:
        return []
    ref = lim["thermal_reference_speed_rad_s"]
    note = lim["thermal_reference_speed_note"]
    shown_ref = f"{ref * RPM:.4g} r/min" if ref is not None else f"— ({note})"
    method = lim["lubrication"].replace("_", " ")
    line = (
        f"n·d_m = {lim['n_dm_mm_rpm']:.3g} mm·r/min; limiting speed "
        f"{lim['limiting_speed_rad_s'] * RPM:.4g} r/min ({method}; {lim['limiting_speed_source']}); "
        f"thermal reference speed (ISO 15312, SKF model) {shown_ref}"
    )
    if lim["seal"] is not None:
        lip, top = lim["seal_lip_speed_m_s"], lim["seal_lip_speed_limit_m_s"]
        line += f"; seal {lim['seal']} lip {lip:.3g} m/s (≤ {top:g})"
    if lim["minimum_load_N"] is not None:
        line += (
            f"; minimum load {lim['minimum_load_N']:.4g} N ({lim['minimum_load_rule']}), carried "
            f"{lim['load_compared_N']:.4g} N"
        )
    line += "".join(f"; {n}" for n in lim["notes"] if n.startswith("minimum load"))
    return [line]


def limits_text(c: dict) -> Group:
    """Rich text of :func:`limits_lines`."""
    return Group(*(Text(f"  limits: {line}", style="dim") for line in limits_lines(c.get("limits"))))


def _opt(x, scale=1.0, fmt=".3g") -> str:
    return "—" if x is None else format(x * scale, fmt)


def lubrication_table(c: dict):
    """ν, ν1, κ, a_ISO, min Λ per row and L_nm of one rating case dict (``lubrication`` key)."""
    lub = c.get("lubrication")
    if not lub:
        return Group()
    level = f" ({lub['contamination_level']})" if lub["contamination_level"] else ""
    e_c = "not given" if lub["contamination_factor"] is None else f"{lub['contamination_factor']:.3g}{level}"
    title = (
        f"lubrication: ν = {lub['viscosity_m2_s'] * 1e6:.4g} mm²/s at the operating temperature, e_C = {e_c}"
    )
    life = "—" if lub["Lnm_rev"] is None else f"{lub['Lnm_rev'] * 1e-6:.4g} 10⁶ rev"
    hours = "" if lub["Lnm_h"] is None else f" = {lub['Lnm_h']:.4g} h"
    caption = f"L_nm = {life}{hours}"
    if lub["grease_life_h"] is not None:
        caption += f"; grease life ≈ {lub['grease_life_h']:.3g} h"
    table = Table(title=escape(title), caption=escape(caption))
    for col in ("row", "ν1 mm²/s", "κ", "a_ISO", "min Λ"):
        table.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for r in lub["rows"]:
        table.add_row(
            r["name"],
            _opt(r["reference_viscosity_m2_s"], 1e6, ".4g"),
            _opt(r["kappa"]),
            _opt(r["a_ISO"]),
            _opt(r["min_film_parameter"]),
        )
    return table


def comparison_text(data: dict) -> Group:
    """The friction models side by side (torque and power per case) and when each applies."""
    table = Table(title="friction models side by side")
    table.add_column("model", justify="left", no_wrap=True)
    for case in data["cases"]:
        table.add_column(f"{case} N·m", justify="right", no_wrap=True)
        table.add_column(f"{case} W", justify="right", no_wrap=True)
    lines = []
    for name, m in data["models"].items():
        if "not_applicable" in m:
            table.add_row(name, *(["n/a"] * 2 * len(data["cases"])))
            lines.append(Text(f"  {name}: not applicable here: {m['not_applicable']}", style="dim"))
        else:
            cells = [f"{v:.4g}" for pair in zip(m["total_Nm"], m["power_loss_W"], strict=True) for v in pair]
            table.add_row(name, *cells)
        lines.append(Text(f"  {name}: {m['when']}"))
    lines += [Text(f"  note: {n}", style="dim") for n in data["notes"]]
    return Group(table, *lines)


def thermal_text(thermal: dict) -> Text:
    """The found operating temperature of one case and its heat balance, one line."""
    oil = ""
    if thermal["oil_flow_m3_s"] > 0:
        oil = (
            f" + oil {thermal['oil_heat_W']:.4g} W ({thermal['oil_flow_m3_s'] * 6e4:.3g} l/min from "
            f"{thermal['oil_inlet_C']:g} °C)"
        )
    return Text(
        f"  thermal equilibrium (temperature FOUND, not given): {thermal['temperature_C']:.4g} °C — "
        "friction heat "
        f"{thermal['friction_heat_W']:.4g} W = seats/housing {thermal['conducted_heat_W']:.4g} W "
        f"({thermal['heat_dissipation_W_K']:.3g} W/K to {thermal['ambient_C']:g} °C){oil}; balance closed to "
        f"{thermal['balance_relative']:.1e} in {thermal['iterations']} iterations "
        f"({thermal['friction_model']} "
        "friction)",
        style="bold",
    )


def heat_text(data: dict) -> Group:
    """Heat balance per case and the thermal reference speed."""
    lines = []
    n_ref = data["thermal_reference_speed_rad_s"]
    if n_ref is None:
        lines.append(f"  thermal reference speed: not available ({data['thermal_reference_speed_note']})")
    else:
        lines.append(
            f"  thermal reference speed (ISO 15312 method, model's friction): {n_ref * RPM:.4g} r/min"
        )
    for c in data["cases"]:
        t = (
            "no balance below 250 °C (runaway)"
            if c["temperature_C"] is None
            else f"{c['temperature_C']:.4g} °C"
        )
        lines.append(
            f"  case {c['case']!r}: heat balance at {t}, power loss {c['power_loss_W']:.4g} W, dissipation "
            f"{c['heat_dissipation_W_K']:.3g} W/K to {c['ambient_C']:g} °C ({c['friction_model']} friction)"
        )
        lines += [f"  note: {n}" for n in c["notes"]]
    return Group(*(Text(x) for x in lines))
