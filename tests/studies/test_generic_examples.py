"""The example studies on standard bearings: they run from the command line in-process and on two worker
processes with identical results, and write their plots with names and units on the axes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.studies.definition.load import PlotDef
from bearingkit.studies.results import analysis, display, figures

ROOT = Path(__file__).resolve().parents[2]
STUDIES = ROOT / "examples" / "studies"
EXAMPLES = {
    "dgbb_6209_clearance_load": ("plot_1.png", "plot_2.png", "main_effects.png"),
    "acbb_7209_DB_preload_speed": ("plot_1.png", "plot_2.png", "plot_3.png"),
    "crb_nu209_misalignment": ("plot_1.png", "main_effects.png"),
    "trb_32008_DB_tolerances": ("plot_1.png", "plot_2.png", "statistics.csv"),
    "dgbb_6209_housing_wall": ("plot_1.png",),
}
runner = CliRunner()


def _run(study: Path, out: Path, *extra) -> pd.DataFrame:
    res = runner.invoke(app, ["study", str(study), "--out", str(out), *extra])
    assert res.exit_code == 0, res.output + res.stderr
    return pd.read_parquet(out / "results.parquet")


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_example_runs_in_process_and_on_two_workers_identically(tmp_path, name):
    study = STUDIES / f"{name}.toml"
    alone = _run(study, tmp_path / "in_process")
    pool = _run(study, tmp_path / "workers", "--workers", "2")
    pd.testing.assert_frame_equal(alone, pool)  # bit for bit
    assert alone["converged"].all() and (alone["error"] == "").all()
    for f in EXAMPLES[name]:
        assert (tmp_path / "in_process" / f).stat().st_size > 1000
    summary = json.loads((tmp_path / "workers" / "summary.json").read_text())
    assert summary["executor"] == "process-pool" and summary["computed"] == summary["chunks"]


def test_a_small_map_is_identical_in_process_and_on_two_workers(tmp_path):
    text = (STUDIES / "dgbb_6209_clearance_load.toml").read_text()
    # The bearing beside the study (a data file names only files in its own folder: issue 41).
    (tmp_path / "dgbb_6209.toml").write_text((ROOT / "examples" / "dgbb_6209.toml").read_text())
    text = text.replace('"../dgbb_6209.toml"', '"dgbb_6209.toml"')
    text = text.replace(
        '"0 um", "6 um", "12 um", "18 um", "24 um", "30 um", "36 um", "42 um", "50 um"', '"6 um", "30 um"'
    )
    text = text.replace(
        '"1 kN", "2 kN", "3 kN", "4.5 kN", "6 kN", "8 kN", "11 kN", "15 kN"', '"2 kN", "6 kN", "12 kN"'
    )
    text = text.replace("chunk_size = 24", "chunk_size = 2")
    study = tmp_path / "small.toml"
    study.write_text(text)
    alone = _run(study, tmp_path / "a")
    pool = _run(study, tmp_path / "b", "--workers", "2")
    assert len(alone) == 6
    pd.testing.assert_frame_equal(alone, pool)
    assert (tmp_path / "a" / "plot_1.png").exists() and (tmp_path / "a" / "plot_2.png").exists()


def test_axes_show_names_and_display_units(tmp_path):
    results = pd.DataFrame(
        {
            "geometry.clearance_radial": np.repeat([10e-6, 30e-6], 3),
            "load_cases.radial.F_x": np.tile([2e3, 4e3, 8e3], 2),
            "k_zz_N_per_m": np.linspace(2e8, 3e8, 6),
            "L10r_h": np.linspace(1e3, 5e4, 6),
        }
    )
    dims = {"geometry.clearance_radial": "length", "load_cases.radial.F_x": "force"}
    spec = PlotDef(
        kind="lines",
        x="load_cases.radial.F_x",
        y=("k_zz_N_per_m", "L10r_h"),
        series="geometry.clearance_radial",
        log_y=("L10r_h",),
    )
    labels = figures.plot(spec, results, tmp_path / "p.png", dims)
    assert labels == [
        ("load_cases.radial.F_x [kN]", "k_zz [N/µm]"),
        ("load_cases.radial.F_x [kN]", "L10r [h]"),
    ]
    spec = PlotDef(kind="map", x="load_cases.radial.F_x", series="geometry.clearance_radial", y="L10r_h")
    assert figures.plot(spec, results, tmp_path / "m.png", dims) == [
        ("load_cases.radial.F_x [kN]", "geometry.clearance_radial [µm]")
    ]
    spec = PlotDef(kind="histogram", y="L10r_h")
    assert figures.plot(spec, results, tmp_path / "h.png", dims) == [("L10r [h]", "cases")]
    np.testing.assert_allclose(display.display("u_x_m", [2e-5])[0], [20.0])
    assert display.display("theta_y_rad", [3e-3])[1] == "theta_y [mrad]"
    assert display.display("operating.speed", [314.159], "angular_velocity")[1] == "operating.speed [r/min]"


def test_main_effect_panels_are_named_factors_in_display_units(tmp_path):
    """Issue 23: factor names (not letters) and display values (not raw SI) on the main-effect plot."""
    effects = pd.DataFrame(
        {
            "factor": ["clearance_axial_ball"] * 3 + ["eccentricity"] * 3,
            "level": [1, 2, 3] * 2,
            "value": [-4e-6, -5e-6, -6e-6, 0.2, 0.3, 0.4],
            "mean": [0.23, 0.25, 0.28, 0.29, 0.25, 0.23],
            "count": [3] * 6,
        }
    )
    panels = analysis.plot_main_effects(
        effects,
        tmp_path / "me.png",
        "ball_axial_share",
        {"clearance_axial_ball": "B", "eccentricity": "D"},
        {"clearance_axial_ball": "length", "eccentricity": "length"},
    )
    assert panels[0] == ("clearance_axial_ball (B)", "level [µm]", ["-4", "-5", "-6"])
    assert panels[1] == ("eccentricity (D)", "level [mm]", ["200", "300", "400"])
