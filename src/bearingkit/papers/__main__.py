"""``python -m bearingkit.papers OUT_DIR [--small]``: run every paper's example study, write CSV/PNG.

SI units in every table (units in column names). ``--small`` runs the optimisations and the Monte Carlo
at CI sizes.
"""

from __future__ import annotations

import sys
from pathlib import Path

from bearingkit.papers.examples import run_example
from bearingkit.papers.li2025.study_runs import plot_clearance_map, seed002_clearance_map
from bearingkit.papers.liu2022.study_runs import plot_seed001, seed001_monte_carlo, seed001_summary
from bearingkit.papers.tian2025.study_runs import ranking, seed000_table3
from bearingkit.papers.zheng2022.study_runs import export_front, seed004_optimize, table6_comparison


def main(argv=None) -> int:
    """Run every seed study (``--small``: CI sizes) and write tables and plots to OUT_DIR."""
    args = list(sys.argv[1:] if argv is None else argv)
    small = "--small" in args
    args = [a for a in args if a != "--small"]
    out = Path(args[0] if args else "out/seed_studies")
    out.mkdir(parents=True, exist_ok=True)
    l9 = run_example("seed000_l9")
    seed000_table3(l9).to_csv(out / "seed000_table3.csv", index=False)
    l9.analysis["range"].to_csv(out / "seed000_range.csv", index=False)
    print(f"seed 000 ranking: {' > '.join(ranking(l9.analysis['range']))} (published D > A > C > B)")
    size = {"pop_size": 40, "generations": 30} if small else {}
    for case in ("axial", "radial"):
        res = seed004_optimize(case, **size)
        export_front(res, out)
        print(table6_comparison(res).to_string(index=False))
    mc = seed001_monte_carlo(samples=100 if small else None)
    seed001_summary(mc).to_csv(out / "seed001_summary.csv", index=False)
    plot_seed001(mc, out / "seed001_histograms.png")
    cmap = seed002_clearance_map(run_example("seed002_clearance_map"))
    cmap.to_csv(out / "seed002_clearance_map.csv", index=False)
    plot_clearance_map(cmap, out / "seed002_clearance_map.png")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
