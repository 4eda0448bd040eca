"""The seed reproductions: every published number of the four seed papers, computed vs published.

``bearingkit validate`` recomputes each published number the project reproduces; here the cases of
the four seed papers (seed 000 composite turntable bearing, 001 tapered rollers with scatter, 002 ball
column with a flexible ring, 004 planetary thread roller bearing), counted as ``bearingkit validate``
counts them: predictions passing within their stated tolerance, calibrations (the published number a
stated constant was identified on), known deviations (each with its cause: ``validate --table``) and
unexplained failures. Diagnostic cases (derived values, numbers printed twice) are left out.
"""

from collections import Counter

from _common import figure, out_dir

from bearingkit.validation.registry import all_cases, run_cases

papers = {"seed000": "Tian 2025", "seed001": "Liu 2022", "seed002": "Li 2025", "seed004": "Zheng 2022"}
fig, ax = figure(6.4, 4.8)
for prefix, paper in papers.items():
    results = run_cases(all_cases([prefix + "/"], diagnostics=False))
    status = Counter(r.status for r in results)
    predictions = [r for r in results if r.case.role == "prediction"]
    passing = sum(r.status == "pass" for r in predictions)
    print(f"{prefix} ({paper}): predictions {passing} / {len(predictions)} passing, "
          f"{status['calibrated']} calibrations met, {status['known']} known deviations, "
          f"{status['FAIL']} unexplained failures")  # fmt: skip
    shown = [r for r in results if r.case.published != 0]
    ax.loglog([abs(r.case.published) for r in shown], [abs(r.computed) for r in shown], "o", ms=3,
              label=f"{prefix} ({paper})", alpha=0.7)  # fmt: skip
lo, hi = ax.get_xlim()
ax.loglog([lo, hi], [lo, hi], "k:", lw=1, label="computed = published")
ax.set_xlabel("|published| (SI)")
ax.set_ylabel("|computed| (SI)")
ax.legend(fontsize=8)
fig.savefig(out_dir("06_seed_reproductions") / "computed_vs_published.png", dpi=110)
