"""The duty-cycle section of the HTML report: every bin's life and the combined life (Palmgren–Miner).

SI in (the JSON-ready dict of :meth:`bearingkit.pipeline.duty_cycle.DutyCycleResult.to_dict`); shown in
r/min, kN, 10⁶ rev and hours, the unit in every column header.
"""

from __future__ import annotations

import math

from bearingkit.report.html_format import _e, _table, _warning_list, fmt


def duty_cycle_html(d: dict, n: int) -> str:
    """Section ``n``: the bins (share, speed, load, lives, s0, damage share) and the combined lives."""
    kind = d["fraction_kind"]
    rows = []
    for b in d["bins"]:
        load = b["load"]
        rows.append(
            [
                _e(b["bin"]),
                fmt(b[f"{kind}_fraction"], 4, 100.0),
                fmt(b["revolution_fraction"], 4, 100.0),
                fmt(b["speed_rad_s"], 5, 30.0 / math.pi),
                fmt(b["temperature_C"], 4),
                fmt(math.hypot(load["F_x_N"], load["F_y_N"]), 5, 1e-3),
                fmt(load["F_z_N"], 5, 1e-3),
                "no load" if b["no_load"] else fmt(b.get("L10_iso281_rev"), 4, 1e-6),
                fmt(b.get("Lnm_iso281_rev"), 4, 1e-6),
                fmt(b.get("damage_share_iso281"), 4, 100.0),
                "no load" if b["no_load"] else fmt(b["L10r_rev"], 4, 1e-6),
                fmt(b["Lnmr_rev"], 4, 1e-6),
                fmt(b["damage_share"], 4, 100.0),
                fmt(b["static_safety"], 4),
            ]
        )
    headers = [
        "bin",
        f"{kind} share [%]",
        "revolution share U [%]",
        "speed [r/min]",
        "T [°C]",
        "F_r [kN]",
        "F_a [kN]",
        "L10 ISO 281 [10⁶ rev]",
        "L_nm ISO 281 [10⁶ rev]",
        "damage share ISO 281 [%]",
        "L10r ISO/TS 16281 [10⁶ rev]",
        "L_nmr ISO/TS 16281 [10⁶ rev]",
        "damage share ISO/TS 16281 [%]",
        "s0 [-]",
    ]
    iso = [
        "ISO 281",
        fmt(d.get("L10_iso281_rev"), 4, 1e-6),
        fmt(d.get("L10h_iso281_h"), 4),
        fmt(d.get("Lnm_iso281_rev"), 4, 1e-6),
        fmt(d.get("Lnm_iso281_h"), 4),
    ]
    ts = [
        "ISO/TS 16281",
        fmt(d["L10r_rev"], 4, 1e-6),
        fmt(d["L10r_h"], 4),
        fmt(d["Lnmr_rev"], 4, 1e-6),
        fmt(d["Lnmr_h"], 4),
    ]
    first = (d.get("headline") or {}).get("method", "ISO 281")
    combined = _table(
        ["over the cycle", "L10 [10⁶ rev]", "L10 [h]", "L_nm [10⁶ rev]", "L_nm [h]"],
        [iso, ts] if first == "ISO 281" else [ts, iso],
    )
    why = d.get("life_difference")
    warnings = [f"[{b['bin']}] {w}" for b in d["bins"] for w in b["warnings"]]
    notes = "".join(f"<li>{_e(x)}</li>" for x in d["notes"])
    return (
        f'<section id="duty-cycle" data-section="duty-cycle"><h2>{n}. Duty cycle</h2>'
        "<p>Every bin is solved and rated as a load case of one batch; the life over the cycle is the "
        "Palmgren–Miner sum of the bins' system lives, L = 1 / Σ U<sub>i</sub>/L<sub>i</sub>, with "
        "U<sub>i</sub> the share of the revolutions in bin i (ISO 281, ISO/TS 16281). Hours at the "
        "cycle's mean revolution rate. ISO 281 (L10, L_nm from each bin's equivalent load) is listed "
        "first, ISO/TS 16281 (L10r, L_nmr from each bin's load distribution) beside it.</p>"
        + _table(headers, rows)
        + combined
        + (f'<p class="note">Why they differ: {_e(why)}</p>' if why else "")
        + (f"<ul>{notes}</ul>" if notes else "")
        + (_warning_list(warnings) if warnings else "")
        + "</section>"
    )
