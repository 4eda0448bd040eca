"""The seed studies of issue 9 run through the study machinery, and their post-processing.

SI units throughout (N, m, N·m, rad); DataFrame columns carry their unit. Every study here is one of
the example files in ``examples/studies`` run by :func:`bearingkit.studies.runner.run_study` (the same
path as ``bearingkit study FILE``); the helpers only change sizes (population, samples) or one fixed
value, and post-process the :class:`~bearingkit.studies.runner.StudyResult`:

- seed 000 (Tian et al. 2025) — ``seed000_l9.toml``: the L9(3^4) design of Tables 2–3, friction torque
  per run matched to Table 3 (:func:`seed000_table3`) and the range ranking (:func:`ranking`);
- seed 004 (Zheng et al. 2022) — ``seed004_{axial,radial}_nsga2.toml``: §6 NSGA-II of the PTRB,
  Pareto front and the selections nearest Table 6 (:func:`seed004_optimize`, :func:`table6_comparison`);
- seed 001 (Liu et al. 2022) — ``seed001_monte_carlo.toml``: roller-diameter scatter, one run per S_d
  with common random numbers (:func:`seed001_monte_carlo`, :func:`seed001_summary`);
- seed 002 (Li et al. 2025) — ``seed002_clearance_map.toml``: roller share of the radial load over
  ball × roller clearance at a light and a heavy load (:func:`seed002_clearance_map`).

``python -m bearingkit.studies.seed_studies OUT_DIR [--small]`` runs all of them and writes CSV/PNG.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from bearingkit.studies.definition import StudyDefinition, load_study
from bearingkit.studies.runner import StudyResult, run_study

__all__ = [
    "SEED000_PUBLISHED_RANKING",
    "STUDIES_DIR",
    "example",
    "export_front",
    "ranking",
    "resized",
    "run_example",
    "seed000_published_ranges",
    "seed000_table3",
    "seed001_monte_carlo",
    "seed001_summary",
    "seed002_clearance_map",
    "seed004_optimize",
    "table6_comparison",
]

#: The example study files (src/bearingkit/studies/seed_studies.py → ../../../examples/studies).
STUDIES_DIR = Path(__file__).resolve().parents[3] / "examples" / "studies"
#: Seed 000 §6.2 / Fig. 20: eccentricity D > axial roller clearance A > groove curvature C > ball clearance B.
SEED000_PUBLISHED_RANKING = ("D", "A", "C", "B")
#: Factor label of each Table 3 column (Table 2).
SEED000_LABELS = {
    "clearance_axial_roller": "A",
    "clearance_axial_ball": "B",
    "groove_curvature": "C",
    "eccentricity": "D",
}


def example(name: str) -> Path:
    """Path of ``examples/studies/<name>.toml``."""
    from bearingkit.errors import InputError

    path = STUDIES_DIR / f"{name}.toml"
    if not path.is_file():
        raise InputError(f"example study ({name!r}) not found at {path} (run from a source checkout)")
    return path


def resized(
    definition: StudyDefinition,
    *,
    pop_size: int | None = None,
    generations: int | None = None,
    samples: int | None = None,
    fixed: dict | None = None,
) -> StudyDefinition:
    """A copy of ``definition`` with a new optimiser size, sample count or extra ``[fixed]`` values (SI).

    The copy has its own fingerprint, so a store never mixes it with the original study.
    """
    update: dict = {}
    opt = {k: v for k, v in (("pop_size", pop_size), ("generations", generations)) if v is not None}
    if opt:
        update["optimizer"] = definition.optimizer.model_copy(update=opt)
    if samples is not None:
        update["samples"] = int(samples)
    if fixed:
        update["fixed"] = {**definition.fixed, **fixed}
    return definition.model_copy(update=update)


def run_example(name: str, *, executor=None, store=None, progress=False, **resize) -> StudyResult:
    """Run ``examples/studies/<name>.toml`` (optionally :func:`resized`) and return its result."""
    d = load_study(example(name))
    if resize:
        d = resized(d, **resize)
    return run_study(d, executor=executor, store=store, progress=progress)


# ------------------------------------------------------------------------------------------ seed 000
def ranking(range_table) -> tuple[str, ...]:
    """Factor labels by decreasing range (the ``range`` table of a study's analysis)."""
    return tuple(range_table.sort_values("rank")["label"])


def _table3():
    from bearingkit.validation.seed000_friction import TABLE3

    return TABLE3


def seed000_table3(result: StudyResult):
    """Table 3 run k (1–9) beside the study's case with the same factor values.

    Returns
    -------
    DataFrame
        ``run``, ``case``, the four factor values (SI), ``torque_Nm`` (computed), ``published_Nm``,
        ``rel_error``. Raises if a Table 3 run is missing from the study's design.
    """
    import pandas as pd

    from bearingkit.errors import InputError

    res = result.results
    rows = []
    for k, (a, b, c, e, m) in enumerate(_table3(), start=1):
        hit = (
            np.isclose(res["clearance_axial_roller"], a * 1e-6, rtol=0, atol=1e-9)
            & np.isclose(res["clearance_axial_ball"], b * 1e-6, rtol=0, atol=1e-9)
            & np.isclose(res["groove_curvature"], c, rtol=0, atol=1e-9)
            & np.isclose(res["eccentricity"], e, rtol=0, atol=1e-9)
        )
        if hit.sum() != 1:
            raise InputError(f"Table 3 run {k} ({a} um, {b} um, {c}, {e} m) is not one case of the study")
        row = res[hit].iloc[0]
        t = float(row["friction_torque_Nm"])
        rows.append(
            dict(
                run=k,
                case=int(row["case"]),
                clearance_axial_roller=a * 1e-6,
                clearance_axial_ball=b * 1e-6,
                groove_curvature=c,
                eccentricity=e,
                torque_Nm=t,
                published_Nm=m / 1e3,
                rel_error=t / (m / 1e3) - 1.0,
            )
        )
    return pd.DataFrame(rows)


def seed000_published_ranges() -> dict:
    """Range R [N·m] of each factor label computed from the published Table 3 torques (§6.2 method)."""
    import pandas as pd

    from bearingkit.studies import analysis

    t = pd.DataFrame(_table3(), columns=[*SEED000_LABELS, "torque_Nmm"])
    t["torque_Nm"] = t["torque_Nmm"] / 1e3
    r = analysis.range_analysis(t, list(SEED000_LABELS), "torque_Nm", SEED000_LABELS)
    return dict(zip(r["label"], r["range"].astype(float), strict=True))


# ------------------------------------------------------------------------------------------ seed 004
def seed004_optimize(case: str = "axial", *, pop_size=None, generations=None, **run) -> StudyResult:
    """Run the §6 NSGA-II study of ``case`` ("axial" or "radial"), optionally with a smaller size."""
    from bearingkit.errors import InputError

    if case not in ("axial", "radial"):
        raise InputError(f"case ({case!r}) must be 'axial' or 'radial'")
    return run_example(f"seed004_{case}_nsga2", pop_size=pop_size, generations=generations, **run)


def table6_comparison(result: StudyResult, case: str | None = None):
    """The selections nearest the Table 6 points beside the published design and performance.

    Parameters
    ----------
    result : StudyResult
        A :func:`seed004_optimize` result (its ``selections`` name the Table 6 points).
    case : {"axial", "radial"} or None
        Default: the study's fixed ``load_case``.

    Returns
    -------
    DataFrame
        One row per point: computed ``C0_N``, ``C_N``, ``mu`` and design (α [deg], n, R_rr [mm],
        d_R [mm]) of the selected front solution, the published values (``*_pub``), the relative errors
        ``C0_err``, ``C_err``, ``mu_err``, and ``nearest_distance`` — the distance of the front to the
        published point in (C0, C, μ) scaled by the published values
        (:func:`bearingkit.studies.seed004.nearest_table6`).
    """
    import pandas as pd

    from bearingkit.studies.seed004 import TABLE6, TABLE6_OBJECTIVES, nearest_table6

    case = case or result.definition.fixed.get("load_case", "axial")
    s = "a" if case == "axial" else "r"
    front = result.pareto
    near = nearest_table6({"C0": front["C0_N"], "C": front["C_N"], "mu": front["mu"]}, case)
    near = near.set_index("point")
    rows = []
    for _, sel in result.selections.iterrows():
        name = sel["selection"]
        if name not in TABLE6_OBJECTIVES:
            continue
        pub, x = TABLE6_OBJECTIVES[name], TABLE6[name]
        c0p, cp, mup = pub[f"C0{s}_kN"] * 1e3, pub[f"C{s}_kN"] * 1e3, pub[f"mu_{s}_1e3"] * 1e-3
        rows.append(
            dict(
                point=name,
                C0_N=sel["C0_N"],
                C_N=sel["C_N"],
                mu=sel["mu"],
                M_Nm=sel["M_Nm"],
                alpha_deg=np.degrees(sel["contact_angle"]),
                n=int(np.rint(sel["n_teeth"])),
                R_rr_mm=sel["roller_contact_radius"] * 1e3,
                d_R_mm=sel["roller_pitch_diameter"] * 1e3,
                C0_pub_N=c0p,
                C_pub_N=cp,
                mu_pub=mup,
                alpha_deg_pub=x["alpha_deg"],
                n_pub=x["n"],
                R_rr_mm_pub=x["R_rr_mm"],
                d_R_mm_pub=x["d_R_mm"],
                C0_err=sel["C0_N"] / c0p - 1.0,
                C_err=sel["C_N"] / cp - 1.0,
                mu_err=sel["mu"] / mup - 1.0,
                nearest_distance=float(near.loc[name, "distance"]) if name in near.index else np.nan,
            )
        )
    return pd.DataFrame(rows)


def export_front(result: StudyResult, out_dir) -> dict:
    """Write the Pareto front, the selections and the Table 6 comparison (CSV) and a front plot (PNG)."""
    from bearingkit.studies import analysis

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    name = result.definition.name
    paths = {
        "pareto": out / f"{name}_pareto.csv",
        "selections": out / f"{name}_selections.csv",
        "table6": out / f"{name}_table6.csv",
        "plot": out / f"{name}_pareto.png",
    }
    result.pareto.to_csv(paths["pareto"], index=False)
    result.selections.to_csv(paths["selections"], index=False)
    table6_comparison(result).to_csv(paths["table6"], index=False)
    analysis.plot_pareto(result.pareto, ["C0_N", "M_Nm"], paths["plot"], result.selections)
    return paths


# ------------------------------------------------------------------------------------------ seed 001
def seed001_monte_carlo(magnitudes=None, *, samples=None, store_dir=None, executor=None, progress=False):
    """Run ``seed001_monte_carlo.toml`` once per S_d with the same unit draws (common random numbers).

    Parameters
    ----------
    magnitudes : sequence of float [m] or None
        S_d values (default seed 001's 0.5, 1, 1.5 µm).
    samples : int or None
        Realisations per S_d (default the file's).
    store_dir : path or None
        Parquet stores ``<store_dir>/sd_<S_d in nm>`` (resumable); None keeps results in memory.

    Returns
    -------
    DataFrame
        Every realisation of every S_d: the study's results plus ``magnitude_m``.
    """
    import pandas as pd

    from bearingkit.analysis.trb_friction import SEED001_MAGNITUDES

    mags = SEED001_MAGNITUDES if magnitudes is None else tuple(float(m) for m in magnitudes)
    base = load_study(example("seed001_monte_carlo"))
    frames = []
    for m in mags:
        d = resized(base, samples=samples, fixed={"magnitude": m})
        d = d.model_copy(update={"name": f"{base.name}_sd{m * 1e9:.0f}nm"})
        store = None if store_dir is None else Path(store_dir) / f"sd_{m * 1e9:.0f}nm"
        res = run_study(d, executor=executor, store=store, progress=progress)
        frames.append(res.results.assign(magnitude_m=m))
    return pd.concat(frames, ignore_index=True)


def seed001_summary(realisations):
    """Distribution of the max contact force and of the sliding-friction increment per S_d.

    Returns one row per ``magnitude_m``: count, converged fraction, mean/std/5th/50th/95th percentile/max
    of ``max_contact_force_N`` and ``sliding_increment_N``, mean of ``sliding_increment_ratio``.
    """
    import pandas as pd

    rows = []
    for m, g in realisations.groupby("magnitude_m", sort=True):
        row = {"magnitude_m": m, "n_realisations": len(g), "converged_fraction": g["converged"].mean()}
        for col in ("max_contact_force_N", "sliding_increment_N"):
            v = g[col].to_numpy(float)
            stem = col.removesuffix("_N")
            row.update(
                {
                    f"{stem}_mean_N": v.mean(),
                    f"{stem}_std_N": v.std(ddof=1) if v.size > 1 else 0.0,
                    f"{stem}_p05_N": np.percentile(v, 5),
                    f"{stem}_p50_N": np.percentile(v, 50),
                    f"{stem}_p95_N": np.percentile(v, 95),
                    f"{stem}_max_N": v.max(),
                }
            )
        row["ideal_max_contact_force_N"] = g["ideal_max_contact_force_N"].iloc[0]
        row["ideal_max_sliding_inner_N"] = g["ideal_max_sliding_inner_N"].iloc[0]
        row["sliding_increment_ratio_mean"] = g["sliding_increment_ratio"].mean()
        rows.append(row)
    return pd.DataFrame(rows)


def plot_seed001(realisations, path):
    """Histograms of the max contact force and of the sliding increment, one colour per S_d (PNG)."""
    from bearingkit.studies.analysis import _plt

    plt = _plt()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for m, g in realisations.groupby("magnitude_m", sort=True):
        lab = f"S_d = {m * 1e6:g} µm"
        axes[0].hist(g["max_contact_force_N"], bins=40, alpha=0.5, label=lab)
        axes[1].hist(g["sliding_increment_N"], bins=40, alpha=0.5, label=lab)
    axes[0].set(xlabel="max roller–cup contact force [N]", ylabel="realisations")
    axes[1].set(xlabel="increment of max cone sliding friction [N]", ylabel="realisations")
    for ax in axes:
        ax.legend()
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# ------------------------------------------------------------------------------------------ seed 002
def seed002_clearance_map(result: StudyResult):
    """Pivot a ``seed002_clearance_map`` result: one row per (ball, roller) clearance, one share column
    per radial load (``roller_share_<load in N>N``), plus ``gradient`` = heavy − light share."""
    table = result.results.pivot_table(
        index=["clearance_ball", "clearance_roller"], columns="radial_load", values="roller_radial_share"
    )
    loads = sorted(table.columns)
    table.columns = [f"roller_share_{f:.0f}N" for f in table.columns]
    table = table.reset_index()
    table["gradient"] = table[f"roller_share_{loads[-1]:.0f}N"] - table[f"roller_share_{loads[0]:.0f}N"]
    return table


def plot_clearance_map(table, path):
    """Heat maps of the roller share at each load over ball × roller clearance [µm] (PNG)."""
    from bearingkit.studies.analysis import _plt

    plt = _plt()
    cols = [c for c in table.columns if c.startswith("roller_share_")]
    fig, axes = plt.subplots(1, len(cols), figsize=(5 * len(cols), 4), squeeze=False)
    for ax, col in zip(axes[0], cols, strict=True):
        grid = table.pivot(index="clearance_roller", columns="clearance_ball", values=col)
        im = ax.imshow(grid.to_numpy(), origin="lower", vmin=0.0, vmax=1.0, aspect="auto", cmap="viridis")
        ax.set_xticks(range(grid.shape[1]), [f"{v * 1e6:g}" for v in grid.columns])
        ax.set_yticks(range(grid.shape[0]), [f"{v * 1e6:g}" for v in grid.index])
        ax.set(xlabel="ball-row clearance [µm]", ylabel="roller-row clearance [µm]", title=col)
        fig.colorbar(im, ax=ax, label="roller share of F_r [–]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# ------------------------------------------------------------------------------------------ all
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
