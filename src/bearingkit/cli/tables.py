"""Rich tables of the command line: load distribution, ratings, friction, warnings (faces only).

SI values come in (the JSON-ready dicts of :class:`bearingkit.pipeline.Analysis`); the tables show
µm, mrad, MPa, kN and r/min, rounded to meaningful digits (no round-off noise such as "-0.0").
"""

from __future__ import annotations

import math

from rich.console import Group
from rich.markup import escape
from rich.table import Table
from rich.text import Text

#: Displacements [m] and angles [rad] below this are the solver's round-off, shown as 0 (the solve
#: converges to ~1e-10 of the load scale; 1e-12 m is a thousandth of a nanometre).
DISPLACEMENT_NOISE = 1.0e-12


def _shown(x: float, scale: float, noise: float) -> str:
    """``x * scale`` with 4 significant digits; values below ``noise`` (and -0) print as 0."""
    return f"{(x if abs(x) > noise else 0.0) * scale + 0.0:.4g}"


def _f1(x: float) -> str:
    """One decimal, without "-0.0"."""
    return f"{(x if abs(x) >= 0.05 else 0.0) + 0.0:.1f}"


def _g(x: float) -> str:
    """Compact number without '-0' and without round-off noise below 1e-9 of a newton."""
    return f"{(x if abs(x) > 1e-9 else 0.0) + 0.0:.6g}"


#: Load component held by each DOF, in the solver's order.
_DOF_OF_LOAD = {"F_x": "u_x", "F_y": "u_y", "F_z": "u_z", "M_x": "theta_x", "M_y": "theta_y"}


def _load_text(ld: dict, free_dofs: list[str] | None) -> str:
    """``F = (…) N, M = (…) N·m``; a component at a fixed DOF is the reaction holding it: marked ``*``."""

    def one(name: str, unit: str) -> str:
        value = _g(ld[f"{name}_{unit}"])
        fixed = free_dofs is not None and _DOF_OF_LOAD[name] not in free_dofs
        return f"{value}*" if fixed and value != "0" else value

    f = ", ".join(one(n, "N") for n in ("F_x", "F_y", "F_z"))
    m = ", ".join(one(n, "Nm") for n in ("M_x", "M_y"))
    return f"F = ({f}) N, M = ({m}) N·m"


def case_table(c: dict, free_dofs: list[str] | None = None) -> Table:
    """A rich table of one case dict (from :func:`bearingkit.io.export.case_dict`).

    ``free_dofs`` (the analysis' ``free_dofs``) marks load components that are reactions at fixed DOFs.
    """
    d = c["displacement"]
    status = "converged" if c["converged"] else f"NOT converged: {c['reason']}"
    u = ", ".join(_shown(d[k], 1e6, DISPLACEMENT_NOISE) for k in ("u_x_m", "u_y_m", "u_z_m"))
    th = ", ".join(_shown(d[k], 1e3, DISPLACEMENT_NOISE) for k in ("theta_x_rad", "theta_y_rad"))
    caption = f"u = ({u}) µm, θ = ({th}) mrad; {status}, {c['iterations']} iterations"
    ld = c["load"]
    title = f"case {c['case']!r}: {_load_text(ld, free_dofs)}"
    if "*" in title:
        caption += "; * reaction holding a fixed DOF"
    # wide enough for its title and caption on one line each (a narrow table would wrap them)
    width = min(max(len(title), len(caption)) + 2, 110)
    table = Table(title=escape(title), caption=escape(caption), min_width=width)
    for col in ("row", "loaded", "Q_max N", "p_max MPa", "F_axial N", "F_radial N"):
        table.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for r in c["rows"]:
        table.add_row(
            r["name"],
            f"{r['loaded_count']}/{len(r['loads_N'])}",
            _f1(r["max_load_N"]),
            _f1(r["max_pressure_Pa"] / 1e6),
            _f1(r["axial_load_N"]),
            _f1(r["radial_load_N"]),
        )
    return table


def _num(x, scale: float = 1.0, fmt: str = ".4g") -> str:
    """A JSON value for a table: ``—`` for None (masked, not available)."""
    return "—" if x is None else format(x * scale, fmt)


def _compact(x, scale: float = 1.0) -> str:
    """Three significant digits, short exponent (``7.45e4``, ``4.00e3``); ``—`` for None.

    Trailing zeros are kept (``#``): a life of 4003 reads ``4.00e3``, not ``4e3`` (one digit).
    """
    if x is None:
        return "—"
    text = f"{x * scale:#.3g}"
    mantissa, e, exponent = text.partition("e")
    mantissa = mantissa.rstrip(".")  # '#' leaves '100.' for 100
    return f"{mantissa}e{int(exponent)}" if e else mantissa


def _lnm(value) -> str:
    """L_nmr in 10⁶ rev, or why it is missing (a_ISO needs e_C, a lubricant, a temperature and a speed)."""
    if value is None:
        # no flag named: run-flagship has none, rating takes --contamination, a file [operating]
        return "— (no a_ISO: it needs the contamination factor e_C, a lubricant, a temperature and a speed)"
    return f"{_num(value, 1e-6)} 10⁶ rev"


def rating_table(c: dict) -> Table:
    """A rich table of one case dict of :func:`bearingkit.io.export.rating_dict`."""
    speed = "speed not given" if c["speed_rad_s"] is None else f"{c['speed_rad_s'] * 30 / math.pi:.4g} r/min"
    title = f"case {c['case']!r}: {c['rotating']} ring rotating, {speed}, reliability {c['reliability']:g}"
    s = c["system"]
    ts = (
        f"ISO/TS 16281: L10r = {_num(s['L10r_rev'], 1e-6)} 10⁶ rev, L10h = {_num(s['L10h_h'])} h, "
        f"L_nr = {_num(s['Lnr_rev'], 1e-6)} 10⁶ rev, L_nmr = {_lnm(s['Lnmr_rev'])}; "
        f"bearing s0 = {_num(s['static_safety'], fmt='.3g')}"
    )
    from bearingkit.analysis.rating.iso281 import caption as iso281_caption

    iso281 = iso281_caption(s)
    # the headline life first: ISO 281 where it rates the bearing (analysis.rating.compare.headline)
    lines = [iso281, ts] if s.get("headline", {}).get("method") == "ISO 281" else [ts, iso281]
    if s.get("life_difference"):
        lines.append(f"why they differ: {s['life_difference']}")
    if s.get("static_safety_difference"):
        lines.append(f"static safety: {s['static_safety_difference']}")
    caption = "\n".join(line for line in lines if line)
    # as wide as its title and caption lines (up to 120 columns): a narrow table wraps them mid-phrase
    width = min(max(len(line) for line in (title, *caption.split("\n"))) + 2, 120)
    table = Table(title=escape(title), caption=escape(caption), min_width=width, caption_justify="left")
    for col in ("row", "C kN", "C0 kN", "L10r 10⁶rev", "L10h h", "s0", "flags"):
        justify = "left" if col in ("row", "flags") else "right"
        table.add_column(
            col,
            justify=justify,
            no_wrap=col != "flags",
            overflow="fold",
            min_width=9 if col == "flags" else None,
        )
    for r in c["rows"]:
        table.add_row(
            r["name"],
            _num(r["C_N"], 1e-3),
            _num(r["C0_N"], 1e-3),
            _compact(r["L10r_rev"], 1e-6),
            _compact(r["L10r_h"]),
            _num(r["static_safety"], fmt=".3g"),
            escape(", ".join(k for k, v in r["flags"].items() if v)),
        )
    return table


def duty_cycle_table(d: dict) -> Table:
    """A rich table of a duty cycle (:meth:`bearingkit.pipeline.duty_cycle.DutyCycleResult.to_dict`): ISO 281
    first (per-bin L10, L_nm and damage share, the Miner-combined L10 and L_nm), ISO/TS 16281 beside it."""
    kind = d["fraction_kind"]
    title = f"duty cycle: {len(d['bins'])} bins, {kind} fractions, Palmgren–Miner"
    iso = (
        f"ISO 281: L10 = {_compact(d.get('L10_iso281_rev'), 1e-6)} 10⁶ rev = "
        f"{_compact(d.get('L10h_iso281_h'))} h, "
        f"L_nm = {_compact(d.get('Lnm_iso281_rev'), 1e-6)} 10⁶ rev = {_compact(d.get('Lnm_iso281_h'))} h"
    )
    ts = (
        f"ISO/TS 16281: L10r = {_compact(d['L10r_rev'], 1e-6)} 10⁶ rev = {_compact(d['L10r_h'])} h, "
        f"L_nmr = {_compact(d['Lnmr_rev'], 1e-6)} 10⁶ rev = {_compact(d['Lnmr_h'])} h"
    )
    first = (d.get("headline") or {}).get("method", "ISO 281")
    lines = [iso, ts] if first == "ISO 281" else [ts, iso]
    caption = "over the cycle: " + "; ".join(lines)
    if d.get("life_difference"):
        caption += f"\nwhy they differ: {d['life_difference']}"
    table = Table(title=escape(title), caption=escape(caption))
    for col in (
        "bin",
        f"{kind} %",
        "rev %",
        "speed r/min",
        "F_r kN",
        "F_a kN",
        "L10 ISO 281 10⁶rev",
        "L_nm ISO 281 10⁶rev",
        "damage % ISO 281",
        "L10r TS 10⁶rev",
        "L_nmr TS 10⁶rev",
        "damage % TS",
        "s0",
    ):
        table.add_column(col, justify="left" if col == "bin" else "right", no_wrap=True)
    for b in d["bins"]:
        load = b["load"]
        no_load = "no load" if b["no_load"] else None
        table.add_row(
            escape(b["bin"]),
            _num(b[f"{kind}_fraction"], 100.0, ".3g"),
            _num(b["revolution_fraction"], 100.0, ".3g"),
            _num(b["speed_rad_s"], 30 / math.pi),
            _num(math.hypot(load["F_x_N"], load["F_y_N"]), 1e-3),
            _num(load["F_z_N"], 1e-3),
            no_load or _compact(b.get("L10_iso281_rev"), 1e-6),
            _compact(b.get("Lnm_iso281_rev"), 1e-6),
            _num(b.get("damage_share_iso281"), 100.0, ".3g"),
            no_load or _compact(b["L10r_rev"], 1e-6),
            _compact(b["Lnmr_rev"], 1e-6),
            _num(b["damage_share"], 100.0, ".3g"),
            _num(b["static_safety"], fmt=".3g"),
        )
    return table


def warnings_text(warnings, notes=()) -> Group:
    """Warnings (yellow) and notes (dim) of one case, one line each, for the console."""
    lines = [Text(f"  warning: {w}", style="yellow") for w in warnings]
    lines += [Text(f"  note: {n}", style="dim") for n in notes]
    return Group(*lines)


def friction_table(c: dict):
    """Rich tables (components, rows) of one case dict of :func:`bearingkit.io.export.friction_case_dict`."""
    f = c["friction"]
    total = f["total_Nm"]
    if "speed_rad_s" in c:  # engineering model: relative speed only, no per-row breakdown
        rpm, lube = c["speed_rad_s"] * 30 / math.pi, ""
    else:
        rpm = (c["speed_inner_rad_s"] - c["speed_outer_rad_s"]) * 30 / math.pi
        lube = f", {c['lubricant']}"
    model = f" ({f.get('model', 'components')} model)"
    power = f", P = {f['power_loss_W']:.4g} W" if f.get("power_loss_W") is not None else ""
    title = (
        f"case {c['case']!r}{model}: M = {total:.4g} N·m{power} at {rpm:.4g} r/min{lube} at "
        f"{c['temperature_C']:g} °C"
    )
    # the title as its own line: a table title wraps to the (narrow) table's width
    parts = Table()
    for col in ("component", "N·m", "share"):
        parts.add_column(col, justify="left" if col == "component" else "right", no_wrap=True)
    for name, value in f["components_Nm"].items():
        parts.add_row(name, f"{value:.4g}", f"{value / total:.1%}" if total > 0 else "—")
    heading = Text(title, style="italic")
    if "rows_Nm" not in f:  # the model's notes follow once, with the run's notes (not per case)
        return Group(heading, parts)
    rows = Table(title="by row")
    for col in ("row", "N·m", "share"):
        rows.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for name, value in f["rows_Nm"].items():
        rows.add_row(name, f"{value:.4g}", f"{value / total:.1%}" if total > 0 else "—")
    return Group(heading, parts, rows)


def structure_table(f: dict) -> Table:
    """Rigid against flexible rings of one case (the ``flexible`` dict of a ``[structure]``): per row the
    loaded elements, peak load and pressure each way; the caption the static safety, the life and each
    ring's largest deflection and fibre stress."""
    how = f["coupling"]
    status = "converged" if f["converged"] else "NOT converged"
    balance = how.get("force_balance")
    if balance is not None:  # Σ element forces against the load: the coupled solution's equilibrium
        status += f", equilibrium {max(balance, 1e-16):.0e}"
    title = (
        f"case {f['case']!r} in its structure: rigid → flexible rings "
        f"({how['iterations']} Newton its, {status})"
    )
    ch = f.get("change", {})
    parts = []
    if ch.get("static_safety_rigid") is not None:
        s0 = (_num(ch["static_safety_rigid"], fmt=".3g"), _num(ch.get("static_safety_flexible"), fmt=".3g"))
        parts.append(f"s0 {s0[0]} → {s0[1]}")
    if ch.get("life_rev_rigid") is not None:
        flex = ch.get("life_rev_flexible")
        life = (_compact(ch["life_rev_rigid"] / 1e6), _compact(None if flex is None else flex / 1e6))
        parts.append(f"L10 {life[0]} → {life[1]} 10⁶ rev")
    for ring in f.get("structure", {}).get("rings", []):
        if "radial_deflection_m" in ring:
            # round-off of a ring held in its plane (1e-15 µm) prints as 0
            w = round(max(abs(v) for v in ring["radial_deflection_m"]) * 1e6, 4)
            u = round(max(abs(v) for v in ring["axial_deflection_m"]) * 1e6, 4)
            text = f"{ring['side']} ring: |w| ≤ {w:.3g} µm, |u| ≤ {u:.3g} µm"
            if "max_fibre_stress_Pa" in ring:
                text += f", σ ≤ {ring['max_fibre_stress_Pa'] / 1e6:.3g} MPa"
            parts.append(text)
    caption = "; ".join(parts)
    width = min(max(len(title), len(caption)) + 2, 110)
    table = Table(title=escape(title), caption=escape(caption), min_width=width)
    columns = (
        "row",
        "loaded",
        "Q_max N rigid",
        "Q_max N flex",
        "change",
        "p_max MPa rigid",
        "p_max MPa flex",
    )
    for col in columns:
        table.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for name, r in f["rigid_vs_flexible"].items():
        change = r["max_load_change"]
        table.add_row(
            name,
            f"{r['loaded_count_rigid']} → {r['loaded_count_flexible']}",
            _f1(r["max_load_rigid_N"]),
            _f1(r["max_load_flexible_N"]),
            "—" if change is None else f"{change:+.1%}",
            _f1(r["max_pressure_rigid_Pa"] / 1e6),
            _f1(r["max_pressure_flexible_Pa"] / 1e6),
        )
    return table
