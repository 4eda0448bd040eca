"""The seed reproductions: every published number of the four seed papers, computed vs published.

``bearingkit validate`` recomputes each published number the project reproduces; here the cases of
the four seed papers (seed 000 composite turntable bearing, 001 tapered rollers with scatter, 002 ball
column with a flexible ring, 004 planetary thread roller bearing), with how many pass within their
stated tolerance and how many are known deviations (each with its cause in the validation table).
"""

from _common import figure, out_dir

from bearingkit.validation.registry import all_cases, run_cases

papers = {"seed000": "Tian 2025", "seed001": "Liu 2022", "seed002": "Li 2025", "seed004": "Zheng 2022"}
fig, ax = figure(6.4, 4.8)
for prefix, paper in papers.items():
    results = [r for r in run_cases(all_cases([prefix + "/"])) if r.case.published != 0]
    passed = sum(r.passed for r in results)
    known = sum(1 for r in results if not r.passed and r.case.known_deviation)
    print(f"{prefix} ({paper}): {len(results)} cases, {passed} pass, {known} known deviations, "
          f"{len(results) - passed - known} failed")  # fmt: skip
    ax.loglog([abs(r.case.published) for r in results], [abs(r.computed) for r in results], "o", ms=3,
              label=f"{prefix} ({paper})", alpha=0.7)  # fmt: skip
lo, hi = ax.get_xlim()
ax.loglog([lo, hi], [lo, hi], "k:", lw=1, label="computed = published")
ax.set_xlabel("|published| (SI)")
ax.set_ylabel("|computed| (SI)")
ax.legend(fontsize=8)
fig.savefig(out_dir("06_seed_reproductions") / "computed_vs_published.png", dpi=110)
