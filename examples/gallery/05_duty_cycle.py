"""A duty cycle: each bin's life and the Palmgren–Miner combination of a 6209.

The bearing file's ``[[duty_cycle]]`` gives bins of load, speed and time share; they are rated in one
batch and combined by Palmgren–Miner (revolution fractions). The damage share of each bin says which
operating condition uses the bearing up.
"""

from pathlib import Path

from _common import figure, out_dir

import bearingkit as bk

a = bk.analyze(Path("examples") / "dgbb_6209_duty_cycle.toml")
cycle = a.duty_cycle.to_dict()
print(f"rule: {cycle['rule']}")
print(f"combined life: L10r = {cycle['L10r_rev'] / 1e6:.0f} 10⁶ rev = {cycle['L10r_h']:.0f} h")
names, shares = [], []
for b in cycle["bins"]:
    names.append(b["bin"])
    shares.append(b["damage_share"])
    print(f"  {b['bin']:>12}: time {b['time_fraction']:.0%}, L10r = {b['L10r_rev'] / 1e6:9.1f} 10⁶ rev, "
          f"damage share {b['damage_share']:.1%}")  # fmt: skip
    for w in b["warnings"]:
        print(f"    warning: {w}")
fig, ax = figure()
ax.bar(names, [s * 100 for s in shares])
ax.set_ylabel("share of the damage [%]")
ax.set_title(f"Palmgren–Miner: L10 = {cycle['L10r_h']:.0f} h")
fig.savefig(out_dir("05_duty_cycle") / "damage_shares.png", dpi=110)
