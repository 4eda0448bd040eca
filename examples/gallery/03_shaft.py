"""A shaft on several bearings: the countershaft example, reactions, lives and the system life.

The shaft file (docs/systems.md) places bearings, gears and loads on a stepped shaft; one solve gives
the reactions and seat tilts, each bearing's own analysis at that state, and the system life; the
deflection and bending-moment lines are drawn by the report's plot function.
"""

from pathlib import Path

from _common import out_dir

from bearingkit.report.systems.shaft_plots import write_shaft_figure
from bearingkit.systems.shaft.input import load_shaft_file
from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

shaft = ShaftAnalysis(load_shaft_file(Path("examples") / "shaft_countershaft.toml"))
data = shaft.to_dict()
for case in data["cases"]:
    print(f"case {case['case']}: system L10h = {case['rating']['system']['L10h_h']:.0f} h")
    for b in case["bearings"]:
        s = b["summary"]
        life = "—" if s["L10h_h"] is None else f"{s['L10h_h']:.0f} h"
        forces = f"F_r = {s['radial_load_N'] / 1e3:6.2f} kN, F_a = {s['axial_load_N'] / 1e3:6.2f} kN"
        print(f"  {s['name']:>10}: {forces}, tilt = {s['misalignment_rad'] * 1e3:5.2f} mrad, L10h = {life}")
    for w in case["warnings"]:
        print(f"  warning: {w}")
write_shaft_figure(shaft.result, out_dir("03_shaft") / "shaft_lines.png", 0)
