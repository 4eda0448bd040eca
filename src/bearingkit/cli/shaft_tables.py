"""Console output of ``bearingkit shaft``: per load case the bearings' reactions, seat state and results.

SI values come in (:meth:`bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis.to_dict`); shown in mm, µm,
mrad, N, MPa, h, W. Faces only: nothing is computed here.
"""

from __future__ import annotations

from pathlib import Path

from rich.markup import escape
from rich.table import Table
from rich.text import Text

from bearingkit.cli.tables import _num


def is_shaft_file(path) -> bool:
    """True for a readable TOML file with a ``[shaft]`` table (anything else goes the bearing way, whose
    reader reports what is wrong with it). Read through the bounded reader (size, nesting)."""
    from bearingkit.errors import InputError
    from bearingkit.io.reading import load_toml

    path = Path(path)
    if path.suffix.lower() != ".toml" or not path.is_file():
        return False
    try:
        return isinstance(load_toml(path).get("shaft"), dict)
    except InputError:
        return False


def _round(value, digits: int = 1) -> str:
    """A force rounded for display without "-0.0" (round-off of an unloaded direction)."""
    return f"{round(value, digits) + 0.0:.{digits}f}"


def system_life_line(life: dict) -> str:
    """The shaft's system lives, the headline method first (ISO 281 where every bearing has one), the
    ISO/TS 16281 ones beside them, the Weibull rule and why the two differ (``rating.system`` of a case)."""
    iso = (
        f"system ISO 281: L10h = {_num(life.get('L10h_iso281_h'), fmt='.4g')} h, "
        f"L_nmh = {_num(life.get('Lnm_iso281_h'), fmt='.4g')} h"
    )
    ts = (
        f"system ISO/TS 16281: L10rh = {_num(life['L10h_h'], fmt='.4g')} h, "
        f"L_nmrh = {_num(life['Lnmr_h'], fmt='.4g')} h"
    )
    first = (life.get("headline") or {}).get("method", "ISO 281")
    text = "; ".join([iso, ts] if first == "ISO 281" else [ts, iso])
    if life.get("weibull_rule"):
        text += f"\ncombined by {life['weibull_rule']}"
    if life.get("life_difference"):
        text += f"\nwhy they differ: {life['life_difference']}"
    return text


def shaft_case_tables(c: dict) -> list:
    """Renderables of one case of ``ShaftAnalysis.to_dict()["cases"]``: two tables and the warnings."""
    s, life = c["shaft"], c["rating"]["system"]
    status = "converged" if c["converged"] else f"NOT converged: {c['reason']}"
    caption = (
        f"shaft: max deflection {s['max_radial_deflection_m'] * 1e6:.4g} µm at "
        f"{s['max_radial_deflection_at_m'] * 1e3:.4g} mm, max bending moment "
        f"{s['max_bending_moment_Nm']:.4g} N·m at {s['max_bending_moment_at_m'] * 1e3:.4g} mm; "
        f"power loss {_num(c['power_loss_W'], fmt='.4g')} W\n{system_life_line(life)}"
    )
    seat = Table(title=escape(f"case {c['case']!r}: {status} — reactions on the shaft, seat state"))
    cols = ("bearing", "z mm", "F_x N", "F_y N", "F_z N", "M_x N·m", "M_y N·m", "u_x µm", "u_y µm", "u_z µm")
    for col in (*cols, "θ_x mrad", "θ_y mrad", "tilt mrad"):
        seat.add_column(col, justify="left" if col == "bearing" else "right", no_wrap=True)
    results = Table(title=escape(f"case {c['case']!r}: bearing results"), caption=escape(caption))
    cols = ("bearing", "F_r N", "F_a N", "p_max MPa", "s0", "L10h ISO 281 h", "L_nmh ISO 281 h", "L10rh TS h")
    cols += ("L_nmrh TS h", "κ", "M_fr N·m", "P_loss W", "T °C")
    for col in (*cols, "warnings"):
        results.add_column(col, justify="left" if col == "bearing" else "right", no_wrap=True)
    for b in c["bearings"]:
        sm = b["summary"]
        r, u = sm["reaction_on_shaft"], sm["seat_displacement"]
        seat.add_row(
            b["name"],
            f"{b['position_m'] * 1e3:.4g}",
            *(_round(r[k]) for k in ("F_x_N", "F_y_N", "F_z_N")),
            *(_round(r[k], 3) for k in ("M_x_Nm", "M_y_Nm")),
            *(f"{u[k] * 1e6:.3g}" for k in ("u_x_m", "u_y_m", "u_z_m")),
            *(f"{u[k] * 1e3:.3g}" for k in ("theta_x_rad", "theta_y_rad")),
            f"{sm['misalignment_rad'] * 1e3:.3g}",
        )
        results.add_row(
            b["name"],
            _round(sm["radial_load_N"]),
            _round(sm["axial_load_N"]),
            _num(sm["max_pressure_Pa"], 1e-6, ".4g"),
            _num(sm["static_safety"], fmt=".3g"),
            _num(sm.get("L10h_iso281_h"), fmt=".4g"),
            _num(sm.get("Lnm_iso281_h"), fmt=".4g"),
            _num(sm["L10h_h"], fmt=".4g"),
            _num(sm["Lnmr_h"], fmt=".4g"),
            _num(sm["kappa_min"], fmt=".3g"),
            _num(sm["friction_torque_Nm"], fmt=".3g"),
            _num(sm["power_loss_W"], fmt=".3g"),
            _num(sm["temperature_C"], fmt=".4g") + (" found" if sm["temperature_found"] else ""),
            str(sm["warnings"]),
        )
    out = [seat, results]
    heat = heat_balance_table(c)
    if heat is not None:
        out.append(heat)
    out += [Text(f"  warning: {w}") for w in c["warnings"]]
    return out


def heat_balance_table(c: dict):
    """The per-bearing heat balance of one case (None when the temperatures were inputs)."""
    rows = [
        (b["summary"]["name"], b["analysis"]["thermal"])
        for b in c["bearings"]
        if "thermal" in b.get("analysis", {})
    ]
    if not rows:
        return None
    table = Table(
        title=escape(f"case {c['case']!r}: operating temperature FOUND by each bearing's heat balance"),
        caption="friction heat P(T) = seats/housing H (T − T_amb) + circulating oil",
    )
    cols = ("bearing", "T °C", "P(T) W", "seats/housing W", "oil W", "H W/K", "T_amb °C", "residual W")
    for col in (*cols, "iterations", "friction model"):
        table.add_column(
            col, justify="left" if col in ("bearing", "friction model") else "right", no_wrap=True
        )
    for name, t in rows:
        table.add_row(
            name,
            f"{t['temperature_C']:.4g}",
            f"{t['friction_heat_W']:.4g}",
            f"{t['conducted_heat_W']:.4g}",
            f"{t['oil_heat_W']:.4g}",
            f"{t['heat_dissipation_W_K']:.4g}",
            f"{t['ambient_C']:g}",
            f"{t['balance_residual_W']:.2g}",
            str(t["iterations"]),
            t["friction_model"],
        )
    return table
