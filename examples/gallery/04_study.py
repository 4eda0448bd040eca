"""A study: radial clearance × radial load of a 6209, as a full factorial over a bearing file.

The study file names the bearing file and paths into it (``geometry.clearance_radial``,
``load_cases.radial_4kN.F_x``); every case is one row of the results table (SI values, units in the
column names). Here: the ISO/TS 16281 life over the clearance for each load.
"""

from pathlib import Path

from _common import figure, out_dir

from bearingkit.studies.run.runner import run_study

result = run_study(Path("examples") / "studies" / "dgbb_6209_clearance_load.toml")
frame = result.results
print(f"{len(frame)} cases; columns: {', '.join(map(str, frame.columns))}")
clearance, load = "geometry.clearance_radial", "load_cases.radial_4kN.F_x"
life = next(c for c in frame.columns if str(c).startswith("L10r") and str(c).endswith("_h"))
fig, ax = figure()
for f, group in frame.groupby(load):
    group = group.sort_values(clearance)
    ax.plot(group[clearance] * 1e6, group[life], "o-", label=f"F_r = {f / 1e3:g} kN")
    best = group.loc[group[life].idxmax()]
    print(
        f"F_r = {f / 1e3:g} kN: longest life {best[life]:.3g} h at clearance {best[clearance] * 1e6:.0f} µm"
    )
ax.set_yscale("log")
ax.set_xlabel("radial clearance [µm]")
ax.set_ylabel(f"{life.removesuffix('_h')} [h]")
ax.legend()
fig.savefig(out_dir("04_study") / "life_vs_clearance.png", dpi=110)
