"""The table of ``bearingkit analyze --subsurface``: maxima below the most loaded contacts and the case check.

SI dicts in (``rows[].subsurface`` of :meth:`bearingkit.pipeline.Analysis.statics_dict`), MPa and mm out,
rounded to meaningful digits.
"""

from __future__ import annotations

from rich.table import Table


def _mpa(x) -> str:
    return "–" if x is None else f"{x / 1e6:.0f}"


def _at(value, depth) -> str:
    return "–" if value is None else f"{value / 1e6:.0f} @ {depth * 1e3:.3g}"


def subsurface_table(case: dict, settings: dict) -> Table:
    """One line per row: p₀, max σ_vM, Tresca and orthogonal shear with their depths, case safety."""
    t = Table(title=f"subsurface, case {case['case']!r}: {settings['hardness_profile']}")
    for col in (
        "row",
        "raceway",
        "p0 MPa",
        "σvM max MPa @ mm",
        "σvM/p0",
        "τmax MPa @ mm",
        "τ0 MPa @ mm",
        "case safety @ mm",
        "case needed mm",
    ):
        t.add_column(col, justify="left" if col in ("row", "raceway") else "right")
    for row in case["rows"]:
        s = row.get("subsurface")
        if s is None:
            continue
        safety = s["case_safety"]
        zone = f" {s['case_safety_zone']}" if s["case_safety_zone"] else ""
        shown = "through-hardened" if safety is None and s["max_pressure_Pa"] else "–"
        if safety is not None:
            shown = f"{safety:.2f} @ {s['depth_case_safety_m'] * 1e3:.3g}{zone}"
            if safety < 1:
                shown = f"[red]{shown}[/]"
        need = s["required_case_depth_m"]
        ratio = s["von_mises_over_pressure"]
        t.add_row(
            row["name"],
            (s["raceway"] or "–") + (" (edge slice)" if s["edge_slice"] else ""),
            _mpa(s["max_pressure_Pa"]),
            _at(s["max_von_mises_Pa"], s["depth_max_von_mises_m"] or 0.0),
            "–" if ratio is None else f"{ratio:.3f}",
            _at(s["max_tresca_Pa"], s["depth_max_tresca_m"] or 0.0),
            _at(s["max_orthogonal_shear_Pa"], s["depth_max_orthogonal_shear_m"] or 0.0),
            shown,
            "–" if need is None else ("none reaches it" if need == float("inf") else f"{need * 1e3:.3g}"),
        )
    return t
