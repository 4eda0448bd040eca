"""Tolerance statistics on the generic evaluator: Monte Carlo percentiles converge as 1/√n, are
reproducible from the seed, and the bearing file's [[tolerances]] become the sampled factors."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy import stats

import bearingkit as bk
from bearingkit.errors import InputError
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.runner import run_study

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DGBB = EXAMPLES / "dgbb_6209.toml"
MEAN, STD = 4000.0, 500.0  # radial load scatter [N]


def _mc(samples: int, seed: int, sampler: str = "random", quantiles=(0.5,)):
    data = {
        "study": {
            "name": "mc_probe",
            "design": "monte_carlo",
            "bearing": str(DGBB),
            "load_case": "radial_4kN",
            "samples": samples,
            "sampler": sampler,
            "seed": seed,
            "quantiles": list(quantiles),
            "outputs": ["u_x_m"],
            "chunk_size": 4096,
        },
        "factors": [
            {"name": "load_cases.radial_4kN.F_x", "distribution": "normal", "mean": "4 kN", "std": "0.5 kN"}
        ],
    }
    return run_study(sd.from_dict(data, source="mc.toml"), progress=False)


def _u_x(loads) -> np.ndarray:
    a = bk.analyze(DGBB, load=[{"F_x": f"{f!r} N"} for f in loads])
    return a.statics.displacement[:, 0]


@pytest.mark.slow
def test_percentiles_converge_as_one_over_root_n():
    """u_x grows monotonically with F_x, so the exact median of u_x is u_x at the median load; the RMS
    error of the Monte Carlo median over independent seeds falls as 1/√n and matches the asymptotic
    standard error of a sample quantile, √(p(1−p)/n) / pdf(q_p) (propagated through du_x/dF_x)."""
    exact, lo, hi = _u_x([MEAN, MEAN - 1.0, MEAN + 1.0])
    slope = (hi - lo) / 2.0  # du_x/dF_x [m/N] at the median
    seeds = range(12)
    rms = {}
    for n in (64, 256, 1024):
        errors = [_mc(n, seed).analysis["statistics"]["u_x_m_q50"].item() - exact for seed in seeds]
        rms[n] = float(np.sqrt(np.mean(np.square(errors))))
        se = np.sqrt(0.25 / n) / stats.norm.pdf(0.0, scale=STD) * slope
        # 12 seeds estimate an RMS to about ±20 % (1/√(2·12)); the bound allows 2.5 of that
        assert 0.5 < rms[n] / se < 1.5, (n, rms[n], se)
    assert 2.0 < rms[64] / rms[1024] < 8.0  # 16 times the draws: a quarter of the error


def test_monte_carlo_is_reproducible_from_the_seed():
    a, b, c = _mc(50, 3).results, _mc(50, 3).results, _mc(50, 4).results
    pd.testing.assert_frame_equal(a, b)
    assert not np.array_equal(a["load_cases.radial_4kN.F_x"], c["load_cases.radial_4kN.F_x"])
    lhs = _mc(50, 3, "lhs", quantiles=(0.05, 0.5, 0.95)).analysis["statistics"]
    assert list(lhs.columns) == [
        "n_draws", "u_x_m_mean", "u_x_m_std", "u_x_m_min", "u_x_m_max", "u_x_m_q5", "u_x_m_q50", "u_x_m_q95",
    ]  # fmt: skip
    pd.testing.assert_frame_equal(lhs, _mc(50, 3, "lhs", quantiles=(0.05, 0.5, 0.95)).analysis["statistics"])


def test_the_bearing_files_tolerances_are_the_sampled_factors(tmp_path):
    """[[tolerances]] of the file: deviations around the file's values; a clearance class is uniform over
    the ISO 5753-1 range (6209: d = 45 mm, C3 = 18–36 µm)."""
    text = DGBB.read_text() + (
        '\n[[tolerances]]\npath = "geometry.clearance_radial"\nclearance_class = "C3"\n'
        '\n[[tolerances]]\npath = "geometry.element_diameter"\ndistribution = "uniform"\n'
        'low = "-2 um"\nhigh = "2 um"\n'
        '\n[[tolerances]]\npath = "load_cases.radial_4kN.F_x"\ndistribution = "truncnormal"\n'
        'mean = "0 kN"\nstd = "0.2 kN"\nlow = "-0.4 kN"\nhigh = "0.4 kN"\n'
    )
    bearing = tmp_path / "b.toml"
    bearing.write_text(text)
    data = {
        "study": {
            "name": "tol", "design": "monte_carlo", "bearing": str(bearing), "load_case": "radial_4kN",
            "samples": 64, "seed": 1, "tolerances": True, "outputs": ["u_x_m", "converged"],
        }
    }  # fmt: skip
    d = sd.from_dict(data, source="tol.toml")
    by = {f.name: f for f in d.factors}
    assert by["geometry.clearance_radial"].distribution == "uniform"
    assert (by["geometry.clearance_radial"].low, by["geometry.clearance_radial"].high) == pytest.approx(
        (18e-6, 36e-6)
    )
    assert (by["geometry.element_diameter"].low, by["geometry.element_diameter"].high) == pytest.approx(
        (0.0127 - 2e-6, 0.0127 + 2e-6), rel=1e-12
    )
    f = by["load_cases.radial_4kN.F_x"]
    assert (f.mean, f.std, f.low, f.high) == pytest.approx((4000.0, 200.0, 3600.0, 4400.0))
    res = run_study(d, progress=False)
    x = res.results
    assert x["converged"].all()
    assert x["geometry.clearance_radial"].between(18e-6, 36e-6).all()
    assert x["load_cases.radial_4kN.F_x"].between(3600.0, 4400.0).all()
    assert "statistics" in res.analysis
    # a tolerance of a design factor scatters its levels: level + draw (levels x samples)
    data["study"].update(design="factorial", tolerances=True)
    data["factors"] = [{"name": "geometry.element_diameter", "levels": ["12.7 mm", "12.5 mm"]}]
    data["monte_carlo"] = {"per_point": 8, "seed": 2}
    lxs = run_study(sd.from_dict(data, source="tol.toml"), progress=False)
    dev = lxs.results["geometry.element_diameter"] - lxs.results["nominal_geometry.element_diameter"]
    assert dev.abs().max() <= 2e-6 and lxs.results["point"].nunique() == 2


def test_bad_tolerances_are_one_line(tmp_path):
    bearing = tmp_path / "b.toml"
    bearing.write_text(DGBB.read_text() + '\n[[tolerances]]\npath = "geometry.clearence_radial"\n'
                       'distribution = "uniform"\nlow = "-1 um"\nhigh = "1 um"\n')  # fmt: skip
    head = {"name": "t", "design": "monte_carlo", "bearing": str(bearing), "load_case": "radial_4kN"}
    data = {"study": {**head, "samples": 4, "tolerances": True}}
    message = r"tolerances\[0\].path \('geometry.clearence_radial'\) is not a path of the bearing; nearest: "
    with pytest.raises(InputError, match=message + "geometry.clearance_radial"):
        sd.from_dict(data, source="t.toml")
    bearing.write_text(DGBB.read_text() + '\n[[tolerances]]\npath = "geometry.clearance_radial"\n'
                       'distribution = "uniform"\nlow = "-1 kN"\nhigh = "1 um"\n')  # fmt: skip
    with pytest.raises(InputError, match=r"tolerances\[0\] \(geometry.clearance_radial\).low \('-1 kN'\)"):
        sd.from_dict(data, source="t.toml")


def test_tolerances_shape_and_count_are_one_line():
    from bearingkit.io.loader import from_dict

    data = tomllib.loads(DGBB.read_text())
    entry = {"path": "geometry.clearance_radial", "clearance_class": "C3"}
    for value, message in (
        ("C3", r"^x.toml: tolerances \('C3'\) must be an array of tables"),
        ([entry, "C3"], r"^x.toml: tolerances\[1\] \('C3'\) must be a table"),
        ([entry] * 101, r"^x.toml: tolerances \(101 entries\) must have at most 100 entries$"),
        ([entry] * 2, r"^x.toml: tolerances.path \(\['geometry.clearance_radial'\]\) must be unique"),
    ):
        with pytest.raises(InputError, match=message):
            from_dict({**data, "tolerances": value}, "x.toml")
