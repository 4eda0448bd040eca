"""A spindle pair's stiffness: a 7014 C DB pair with light preload, radial and axial stiffness over speed.

The pair is named by designation (``DB``: back to back) with a preload class; at speed the balls'
centrifugal force and gyroscopic moment enter the statics, and the stiffness of the solved bearing
(the Jacobian of the contact forces, 5 × 5) softens as the outer contacts take the centrifugal load.
"""

from _common import figure, out_dir

import bearingkit as bk

pair = bk.load_input("7014 C DB", preload="light")
print(pair.model.name, "-", pair.spec.bearing.source)
speeds = [0, 3000, 6000, 9000, 12000]
k_r, k_a = [], []
print(f"{'n r/min':>8} {'k_r N/um':>9} {'k_a N/um':>9}")
for n in speeds:
    a = bk.analyze(pair, load={"F_x": "1 kN"}, speed=f"{n} rpm")
    k = a.statics.stiffness[0]
    k_r.append(k[0, 0] * 1e-6)
    k_a.append(k[2, 2] * 1e-6)
    print(f"{n:8d} {k_r[-1]:9.1f} {k_a[-1]:9.1f}")
    for w in a.warnings[0]:
        print(f"warning ({n} r/min): {w}")

fig, ax = figure()
ax.plot(speeds, k_r, "o-", label="radial k_xx")
ax.plot(speeds, k_a, "s-", label="axial k_zz")
ax.set_xlabel("speed [r/min]")
ax.set_ylabel("stiffness [N/µm]")
ax.set_ylim(bottom=0)
ax.legend()
fig.savefig(out_dir("02_spindle_pair_stiffness") / "stiffness_vs_speed.png", dpi=110)
