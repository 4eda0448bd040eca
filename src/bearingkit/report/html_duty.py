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
                "no load" if b["no_load"] else fmt(b["L10r_rev"], 4, 1e-6),
                fmt(b["Lnmr_rev"], 4, 1e-6),
                fmt(b["static_safety"], 4),
                fmt(b["damage_share"], 4, 100.0),
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
        "L10r [10⁶ rev]",
        "L_nmr [10⁶ rev]",
        "s0 [-]",
        "damage share [%]",
    ]
    combined = _table(
        ["over the cycle", "L10r [10⁶ rev]", "L10r [h]", "L_nmr [10⁶ rev]", "L_nmr [h]"],
        [
            [
                "bearing",
                fmt(d["L10r_rev"], 4, 1e-6),
                fmt(d["L10r_h"], 4),
                fmt(d["Lnmr_rev"], 4, 1e-6),
                fmt(d["Lnmr_h"], 4),
            ]
        ],
    )
    warnings = [f"[{b['bin']}] {w}" for b in d["bins"] for w in b["warnings"]]
    notes = "".join(f"<li>{_e(x)}</li>" for x in d["notes"])
    return (
        f'<section id="duty-cycle" data-section="duty-cycle"><h2>{n}. Duty cycle</h2>'
        "<p>Every bin is solved and rated as a load case of one batch; the life over the cycle is the "
        "Palmgren–Miner sum of the bins' system lives, L = 1 / Σ U<sub>i</sub>/L<sub>i</sub>, with "
        "U<sub>i</sub> the share of the revolutions in bin i (ISO 281, ISO/TS 16281). Hours at the "
        "cycle's mean revolution rate.</p>"
        + _table(headers, rows)
        + combined
        + (f"<ul>{notes}</ul>" if notes else "")
        + (_warning_list(warnings) if warnings else "")
        + "</section>"
    )
