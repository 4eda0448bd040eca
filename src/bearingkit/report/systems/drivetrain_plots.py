"""Figures of a drivetrain: the layout (end view with the pitch circles, side view with the shafts,
bearings and gears) and every shaft's deflection and bending-moment lines. Reads results only."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from bearingkit.systems.drivetrain.model import HOUSING


def layout_figure(drivetrain) -> Figure:
    """End view (x–y: shaft axes, pitch circles, planets) and side view (z: shafts, bearings, gears)."""
    fig = Figure(figsize=(11.0, 5.0))
    end, side = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.4]})
    for s in drivetrain.shafts:
        x, y = (v * 1e3 for v in s.centre)
        end.plot([x], [y], "k+", ms=8)
        end.annotate(s.name, (x, y), xytext=(4, 4), textcoords="offset points", fontsize=7)
        for g in s.gears:
            r = g.geometry.reference_diameter / 2 * 1e3
            end.add_patch(_circle(x, y, r, "#8e44ad"))
        z0 = s.axial_offset * 1e3
        for sec in s.shaft.sections:
            za, zb = z0 + sec.start * 1e3, z0 + sec.end * 1e3
            side.fill_between(
                [za, zb],
                y - sec.outer_diameter / 2 * 1e3,
                y + sec.outer_diameter / 2 * 1e3,
                color="#bdc3c7",
                lw=0,
            )
        for g in s.gears:
            r = g.geometry.reference_diameter / 2 * 1e3
            side.plot([z0 + g.position * 1e3] * 2, [y - r, y + r], color="#8e44ad", lw=3, alpha=0.5)
    for g, centre, _z in drivetrain.housing_gears:
        end.add_patch(
            _circle(centre[0] * 1e3, centre[1] * 1e3, g.geometry.reference_diameter / 2 * 1e3, "#c0392b")
        )
    for b in drivetrain.bearings:
        if b.inner.body == HOUSING:
            continue
        s = drivetrain.body(b.inner.body)
        z = (s.axial_offset + b.inner.position + b.inner.arm[2]) * 1e3
        y = (s.centre[1] + b.inner.arm[1]) * 1e3
        face = "#2c3e50" if b.seat.axial == "locating" else "white"
        side.plot([z], [y], marker="s", ms=7, mfc=face, mec="#2c3e50")
    end.set_aspect("equal")
    end.autoscale_view()
    end.set_title("end view: axes and pitch circles [mm]", fontsize=9)
    side.set_title("side view (y–z): shafts, gears, bearings (■ locating, □ floating) [mm]", fontsize=9)
    side.set_xlabel("z [mm]")
    end.set_xlabel("x [mm]")
    end.set_ylabel("y [mm]")
    fig.tight_layout()
    return fig


def _circle(x, y, r, color):
    from matplotlib.patches import Circle

    return Circle((x, y), r, fill=False, color=color, lw=1.2)


def shaft_lines_figure(result, case: int) -> Figure:
    """Radial deflection and bending moment of every shaft along its axis (one case)."""
    fig = Figure(figsize=(10.0, 6.0))
    defl, mom = fig.subplots(2, 1, sharex=False)
    for s in result.drivetrain.shafts:
        sr = result.shaft_result(s.name)
        u = sr.displacement[case]
        defl.plot(sr.z * 1e3, np.hypot(u[:, 0], u[:, 1]) * 1e6, label=s.name)
        z, m = sr.moment_line()
        mom.plot(z * 1e3, np.hypot(m[case, :, 0], m[case, :, 1]), label=s.name)
    defl.set_ylabel("|u| [µm]")
    mom.set_ylabel("|M| [N·m]")
    mom.set_xlabel("local z [mm]")
    defl.legend(fontsize=7, ncol=3)
    defl.set_title(f"{result.case_names[case]}: deflection and bending moment of every shaft", fontsize=10)
    fig.tight_layout()
    return fig
