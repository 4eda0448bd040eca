"""A designation to a life: ISO 281 and ISO/TS 16281 lives of a 6205-2RS C3 over its radial load.

One call analyses the standard bearing from its designation (geometry estimated from the catalogue's
boundary dimensions, C from the catalogue), for several load cases at once; the rating gives the
ISO 281 basic life first and the ISO/TS 16281 life from the solved load distribution beside it.
"""

import numpy as np
from _common import figure, out_dir

import bearingkit as bk

loads_kN = [0.5, 1.0, 2.0, 3.0, 4.0, 5.0]
a = bk.analyze(
    "6205-2RS C3",
    load=[{"F_x": f"{f} kN"} for f in loads_kN],
    speed="3000 rpm",
    lubricant="ISO_VG68",
    temperature="70 degC",
    contamination="normal_cleanliness",
)
print(a.input.model.name, "-", a.input.spec.bearing.source)
print(f"{'F_r kN':>7} {'L10h ISO 281':>13} {'L10h ISO/TS':>12} {'L_nmh':>10} {'s0':>6}")
iso281, ts = [], []
for i, f in enumerate(loads_kN):
    s = a.rating.to_dict(i)["system"]
    iso281.append(s["L10h_iso281_h"])
    ts.append(s["L10h_h"])
    lnm = s.get("Lnmr_h") or float("nan")
    print(f"{f:7.1f} {iso281[-1]:13.0f} {ts[-1]:12.0f} {lnm:10.0f} {s['static_safety']:6.2f}")
for case, warnings in zip(a.case_names, a.warnings, strict=True):
    for w in warnings:
        print(f"warning ({case}): {w}")

fig, ax = figure()
ax.loglog(loads_kN, iso281, "o-", label="ISO 281 L10h")
ax.loglog(loads_kN, ts, "s--", label="ISO/TS 16281 L10h")
ax.loglog(loads_kN, iso281[0] * (np.array(loads_kN) / loads_kN[0]) ** -3, ":", color="grey", label="∝ F⁻³")
ax.set_xlabel("radial load F_r [kN]")
ax.set_ylabel("L10h [h] at 3000 r/min")
ax.legend()
fig.savefig(out_dir("01_designation_to_life") / "life_vs_load.png", dpi=110)
