"""The workbench's HTTP routes (FastAPI TestClient): the catalogue, selection and comparison are the
library's own results; shafts and drivetrains give the numbers of ``bearingkit shaft``/``system --json``;
a duty cycle is the pipeline's, combined by Miner's rule as written out here; a study runs in the
background with its progress, stops, resumes and downloads, and its numbers are those of ``bearingkit
study`` on the downloaded files. Bad input is one line naming its field; no path reaches a file."""

from __future__ import annotations

import io
import json
import time
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

import bearingkit as bk
from bearingkit.app import create_app
from bearingkit.app.store import Store

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
POINT = {
    "loads": {"F_x": "5 kN"},
    "speed": "3000 rpm",
    "temperature": "70 degC",
    "lubricant": "ISO_VG68",
    "contamination": "0.5",
}


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    store = Store(tmp_path_factory.mktemp("serve"))
    with TestClient(create_app(store, allowed_hosts=("testserver",))) as c:
        yield c
    store.close()


def error_of(response, status: int) -> dict:
    assert response.status_code == status, response.text
    data = response.json()
    assert set(data) == {"error", "field"}
    assert "\n" not in data["error"] and "Traceback" not in data["error"]
    return data


def cli_json(*args) -> dict:
    from typer.testing import CliRunner

    from bearingkit.cli import app

    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


# ------------------------------------------------------------------------------------------ catalogue
def test_search_lists_the_rows_of_the_library_search_within_the_bounds(client):
    from bearingkit.catalogue.search import search

    r = client.post(
        "/api/catalogue/search", json={"kind": "deep_groove", "bounds": {"d": "45 mm", "D_max": "100 mm"}}
    )
    assert r.status_code == 200, r.text
    out = r.json()
    expected = [row.entry.designation for row in search(kind="deep_groove", d=0.045, D_max=0.100)]
    assert [row["designation"] for row in out["rows"]] == expected and "6209" in expected
    for row in out["rows"]:
        assert row["d_m"] == pytest.approx(0.045) and row["D_m"] <= 0.100 + 1e-12
    assert out["count"] == len(expected)
    assert "deep_groove" in out["kinds"]


@pytest.mark.parametrize(
    ("body", "field", "start"),
    [
        ({"bounds": {"d": "45 kN"}}, "catalogue.d", "catalogue.d: "),
        ({"kind": "wheels"}, "catalogue.kind", "catalogue.kind: kind ('wheels') must be one of"),
    ],
)
def test_search_errors_name_their_field(client, body, field, start):
    data = error_of(client.post("/api/catalogue/search", json=body), 400)
    assert data["field"] == field and data["error"].startswith(start)


def test_selection_is_the_pipelines(client):
    from bearingkit.pipeline.selection import select

    body = {"radial": "5 kN", "axial": "1 kN", "speed": "3000 rpm", "life": "20000 h", "kind": "deep_groove"}
    r = client.post("/api/catalogue/select", json={**body, "count": 2})
    assert r.status_code == 200, r.text
    ref = select({"F_x": "5 kN", "F_z": "1 kN"}, "3000 rpm", "20000 h", kind="deep_groove", count=2)
    got = r.json()["candidates"]
    assert [c["designation"] for c in got] == [c["designation"] for c in ref.candidates]
    for c, e in zip(got, ref.candidates, strict=True):
        assert c["L10h_iso281_h"] == e["L10h_iso281_h"] and c["L10h_iso16281_h"] == e["L10h_iso16281_h"]
        assert min(c["L10h_iso281_h"], c["L10h_iso16281_h"]) >= 20000.0
    data = error_of(client.post("/api/catalogue/select", json={**body, "life": "20000 kg"}), 400)
    assert data["field"] == "select.life" or data["error"].startswith("select: life")


def test_comparison_is_one_analysis_per_bearing_at_the_same_point(client):
    r = client.post("/api/catalogue/compare", json={"designations": ["6209", "6309"], "point": POINT})
    assert r.status_code == 200, r.text
    columns = r.json()["bearings"]
    assert [c["designation"] for c in columns] == ["6209", "6309"]
    for c in columns:
        a = bk.analyze(
            c["designation"], load={"F_x": "5 kN"}, speed="3000 rpm", temperature="70 degC",
            lubricant="ISO_VG68", contamination=0.5,
        )  # fmt: skip
        case = a.to_dict()["cases"][0]
        system = case["rating"]["system"]
        assert c["L10h_iso281_h"] == system["L10h_iso281_h"] and c["L10h_iso16281_h"] == system["L10h_h"]
        assert c["Lnm_iso281_h"] == system["Lnm_iso281_h"] and c["Lnmr_h"] == system["Lnmr_h"]
        assert c["static_safety"] == system["static_safety"]
        assert c["friction_torque_Nm"] == case["friction"]["total_Nm"]
        assert c["k_radial_N_per_m"] == case["stiffness_SI"][0][0]
        assert c["limiting_speed_rad_s"] == case["limits"]["limiting_speed_rad_s"]
        assert c["catalogue"]["designation"] == c["designation"]
    # the bigger bearing of the same bore lives longer under the same load (C 53 kN against 31.5 kN)
    assert columns[1]["L10h_iso281_h"] > columns[0]["L10h_iso281_h"]
    # a compared bearing is kept: the bearing page opens it with the same numbers (same request, same id)
    page = client.post(
        "/api/analyze", json={"source": {"kind": "designation", "name": "6209"}, **POINT}
    ).json()
    assert page["id"] == columns[0]["id"]


@pytest.mark.parametrize(
    ("body", "status", "field"),
    [
        ({"designations": ["6209", "6xx9"], "point": POINT}, 400, "compare.1"),
        ({"designations": ["6209"], "point": {**POINT, "loads": {"F_x": "5 kg"}}}, 400, "compare.load.F_x"),
        ({"designations": ["6209", "6209"], "point": POINT}, 400, "compare"),
        ({"designations": ["6205", "6206", "6207", "6208", "6209"], "point": POINT}, 422, "source"),
    ],
)
def test_comparison_errors_name_the_bearing_or_the_field(client, body, status, field):
    data = error_of(client.post("/api/catalogue/compare", json=body), status)
    assert data["field"] == field


# ------------------------------------------------------------------------------------------ systems
def _system(client, system, name, **extra):
    return client.post(
        "/api/system/analyze", json={"system": system, "source": {"kind": "example", "name": name}, **extra}
    )


def test_the_shaft_example_gives_the_cli_numbers_and_its_figures(client):
    r = _system(client, "shaft", "shaft_countershaft.toml")
    assert r.status_code == 200, r.text
    out = r.json()
    ref = cli_json("shaft", str(EXAMPLES / "shaft_countershaft.toml"))
    for case, ref_case in zip(out["analysis"]["cases"], ref["cases"], strict=True):
        for b, rb in zip(case["bearings"], ref_case["bearings"], strict=True):
            assert b["reaction_on_shaft"] == rb["reaction_on_shaft"]
            assert b["summary"]["L10h_h"] == rb["summary"]["L10h_h"]
        assert case["rating"]["system"] == ref_case["rating"]["system"]
    assert out["layout"] is None and len(out["figures"]) == len(ref["cases"])
    png = client.get(out["figures"][1])
    assert png.status_code == 200 and png.content.startswith(b"\x89PNG")
    assert client.get(f"/api/figure/system/{out['id']}/case-9.png").status_code == 404
    assert client.get("/api/figure/system/0123456789abcdef/case-0.png").status_code == 404
    # the example's text comes back for the editor, and edited text is solved as sent
    text = client.post(
        "/api/system/open",
        json={"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}},
    ).json()["text"]
    assert text == (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8")
    edited = text.replace(
        'input_gear = "250 N*m", output_pinion = "-250 N*m"', 'input_gear = "0 N*m", output_pinion = "0 N*m"'
    )
    r = client.post(
        "/api/system/analyze",
        json={"system": "shaft", "source": {"kind": "upload", "name": "edited.toml", "text": edited}},
    )
    assert r.status_code == 200, r.text
    first = r.json()["analysis"]["cases"][0]["bearings"]
    # no torque: the bearings carry only the weight of the shaft and the gears (gravity -y); in x only the
    # pair of forces from the balls' cross stiffness k_xy (equal and opposite, ~1e-6 of the weight)
    weight = sum(abs(b["reaction_on_shaft"]["F_y_N"]) for b in first)
    assert all(abs(b["reaction_on_shaft"]["F_x_N"]) < 1e-5 * weight for b in first)
    assert abs(sum(b["reaction_on_shaft"]["F_x_N"] for b in first)) < 1e-9 * weight
    shaft_mass = 7850.0 * np.pi / 4 * (0.045**2 * 0.05 + 0.055**2 * 0.2)  # sections of the file
    assert weight == pytest.approx(9.80665 * (shaft_mass + 4.5 + 0.8), rel=1e-6)


def test_the_drivetrain_example_gives_the_cli_numbers(client):
    r = _system(client, "drivetrain", "planetary_stage.toml")
    assert r.status_code == 200, r.text
    out = r.json()
    ref = cli_json("system", str(EXAMPLES / "planetary_stage.toml"))
    for case, ref_case in zip(out["analysis"]["cases"], ref["cases"], strict=True):
        assert case["power"] == ref_case["power"] and case["system"] == ref_case["system"]
        assert [b["summary"] for b in case["bearings"]] == [b["summary"] for b in ref_case["bearings"]]
    layout = client.get(out["layout"])
    assert layout.status_code == 200 and layout.content.startswith(b"\x89PNG")


@pytest.mark.parametrize(
    ("system", "text", "start"),
    [
        (
            "shaft",
            '[shaft]\n[[shaft.sections]]\nlength = "100 mm"\nouter_diameter = "40 mm"\n[[shaft.bearings]]\n'
            'name = "A"\nfile = "../../../etc/passwd"\nposition = "10 mm"\n[[load_cases]]\nname = "a"\n',
            "x.toml: shaft.bearings[0].file ('../../../etc/passwd') must name an example bearing file",
        ),
        (
            "drivetrain",
            (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8"),
            "x.toml: shafts: missing; a drivetrain file has [shafts]; it looks like a shaft file",
        ),
        ("shaft", "[shaft\n", "x.toml: not valid TOML"),
    ],
)
def test_system_files_are_read_as_data_and_name_no_other_file(client, system, text, start):
    r = client.post(
        "/api/system/analyze",
        json={"system": system, "source": {"kind": "upload", "name": "x.toml", "text": text}},
    )
    assert error_of(r, 400)["error"].startswith(start)


def test_system_examples_are_names_from_the_list(client):
    names = client.get("/api/systems").json()["examples"]
    assert names == {
        "shaft": ["shaft_countershaft.toml", "shaft_spindle.toml"],
        "drivetrain": ["gearbox_two_stage.toml", "planetary_stage.toml"],
    }
    r = _system(client, "shaft", "../pyproject.toml")
    assert error_of(r, 400)["error"].startswith(
        "example ('../pyproject.toml') is not one of the shaft examples"
    )


# ------------------------------------------------------------------------------------------ duty cycles
DUTY = {"kind": "example", "name": "dgbb_6209_duty_cycle.toml"}
BINS = [
    {"name": "low", "values": {"F_x": "3 kN", "speed": "3000 rpm", "temperature": "70 degC"},
     "fraction": "0.6"},
    {"name": "high", "values": {"F_x": "7 kN", "F_z": "1 kN", "speed": "1500 rpm", "temperature": "80 degC"},
     "fraction": "0.4"},
]  # fmt: skip


def test_duty_cycle_is_the_pipelines_and_miner_as_written(client):
    r = client.post("/api/duty", json={"base": {"source": DUTY, "contamination": "0.5"}, "bins": BINS})
    assert r.status_code == 200, r.text
    d = r.json()["duty_cycle"]
    assert [b["bin"] for b in d["bins"]] == ["low", "high"]
    # Palmgren–Miner by hand: revolution shares U_i = t_i n_i / Σ t_j n_j, L = 1 / Σ (U_i / L_i)
    t, n = np.array([0.6, 0.4]), np.array([3000.0, 1500.0])
    share = t * n / np.sum(t * n)
    lives = np.array([b["L10r_rev"] for b in d["bins"]])
    assert [b["revolution_fraction"] for b in d["bins"]] == pytest.approx(share, rel=1e-12)
    assert d["L10r_rev"] == pytest.approx(1.0 / np.sum(share / lives), rel=1e-12)
    damage = share / lives / np.sum(share / lives)
    assert [b["damage_share"] for b in d["bins"]] == pytest.approx(damage, rel=1e-12)
    # ISO 281 (listed first) combined the same way from its own bin lives
    iso = np.array([b["L10_iso281_rev"] for b in d["bins"]])
    assert d["headline"]["method"] == "ISO 281"
    assert d["L10_iso281_rev"] == pytest.approx(1.0 / np.sum(share / iso), rel=1e-12)
    iso_damage = share / iso / np.sum(share / iso)
    assert [b["damage_share_iso281"] for b in d["bins"]] == pytest.approx(iso_damage, rel=1e-12)
    # the same bins written into a file and rated by the pipeline
    text = (EXAMPLES / "dgbb_6209_duty_cycle.toml").read_text(encoding="utf-8")
    head = text[: text.index("[[duty_cycle]]")]
    tail = text[text.index("[solver]") :]
    bins = (
        '[[duty_cycle]]\nname = "low"\nF_x = "3 kN"\nspeed = "3000 rpm"\ntemperature = "70 degC"\n'
        "time_fraction = 0.6\n\n"
        '[[duty_cycle]]\nname = "high"\nF_x = "7 kN"\nF_z = "1 kN"\nspeed = "1500 rpm"\n'
        'temperature = "80 degC"\ntime_fraction = 0.4\n\n'
    )
    a = bk.analyze(bk.io.loader.loads(head + bins + tail, "duty.toml"), contamination=0.5)
    ref = a.duty_cycle.to_dict()
    assert d["L10r_rev"] == ref["L10r_rev"] and d["Lnmr_rev"] == ref["Lnmr_rev"]


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({0: {"values": {"F_x": "3 kg"}}}, "duty.0.F_x"),
        ({1: {"fraction": "a half"}}, "duty.1.fraction"),
        ({1: {"fraction": "0.7"}}, "duty"),
    ],
)
def test_duty_cycle_errors_name_the_cell(client, change, field):
    bins = [{**b, **change.get(i, {})} for i, b in enumerate(BINS)]
    data = error_of(client.post("/api/duty", json={"base": {"source": DUTY}, "bins": bins}), 400)
    assert data["field"] == field


def test_opening_a_file_gives_its_duty_cycle_bins(client):
    o = client.post("/api/open", json={"source": DUTY}).json()
    assert [b["name"] for b in o["duty_cycle"]] == ["cruise", "climb", "peak", "idle"]
    assert o["duty_cycle"][1]["F_z"] == "0.8 kN" and o["duty_cycle"][1]["fraction"] == "0.25"
    assert o["duty_fraction"] == "time"


# ------------------------------------------------------------------------------------------ studies
BASE = {"source": {"kind": "example", "name": "dgbb_6209.toml"}, "speed": "3000 rpm", "lubricant": "ISO_VG68"}
STUDY = {
    "subject": "bearing",
    "bearing": BASE,
    "design": "factorial",
    "factors": [
        {"path": "geometry.clearance_radial", "start": "0 um", "stop": "40 um", "n": 5},
        {"path": "load_cases.page.F_x", "start": "1 kN", "stop": "10 kN", "n": 10},
    ],
    "outputs": ["L10r_rev", "max_load_N"],
}


def _wait(client, key: str, states=("done", "failed", "stopped"), seconds: float = 300.0) -> dict:
    deadline = time.monotonic() + seconds
    while True:
        job = client.get(f"/api/study/{key}").json()
        if job["state"] in states:
            return job
        assert time.monotonic() < deadline, job
        time.sleep(0.2)


def test_study_paths_are_those_of_the_page_bearing(client):
    out = client.post("/api/study/paths", json={"subject": "bearing", "bearing": BASE}).json()
    paths = {p["path"]: p for p in out["paths"]}
    assert paths["geometry.clearance_radial"]["unit"] == "m"
    assert paths["load_cases.page.F_x"]["kind"] == "case"
    assert {"L10r_rev", "max_load_N", "friction_torque_Nm"} <= {o["name"] for o in out["outputs"]}
    shaft = {"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}}
    out = client.post("/api/study/paths", json={"subject": "shaft", "system": shaft}).json()
    paths = {p["path"]: p for p in out["paths"]}
    assert paths["bearing"]["choices"] == ["A", "B"] and "file" not in paths
    assert "system_L10h_h" in [o["name"] for o in out["outputs"]]


@pytest.mark.parametrize(
    ("change", "field", "start"),
    [
        ({"factors": [{"path": "geometry.clearence", "start": "1 um", "stop": "2 um"}]}, "study.factor.0",
         "study.factors[0].path ('geometry.clearence') is not a factor of this bearing"),
        ({"factors": [{"path": "load_cases.page.F_x", "start": "1 kg", "stop": "2 kN"}]}, "study.factor.0",
         "study.factors[0].from"),
        ({"outputs": ["L10r_yr"]}, "study.outputs", "study.outputs ('L10r_yr') is not an output"),
        ({"factors": [{"path": "load_cases.page.F_x", "start": "1 kN", "stop": "2 kN", "n": 50},
                      {"path": "geometry.clearance_radial", "start": "0 um", "stop": "40 um", "n": 50}]},
         "study", "study: 2500 cases is above the app's budget of 2000"),
        ({"subject": "shaft"}, "study", "study: no shaft open"),
    ],
)  # fmt: skip
def test_a_refused_study_is_one_line_and_starts_nothing(client, change, field, start):
    data = error_of(client.post("/api/study", json={**STUDY, **change}), 400)
    assert data["field"] == field and data["error"].startswith(start), data


def test_study_runs_in_the_background_stops_resumes_and_equals_the_cli(client, tmp_path):
    from typer.testing import CliRunner

    from bearingkit.cli import app

    r = client.post("/api/study", json=STUDY)
    assert r.status_code == 200, r.text
    job = r.json()
    key = job["id"]
    assert job["cases"] == 50 and job["state"] == "running"
    # its files are in the server's temporary folder, under the name the server made
    root = client.app.state.store.root.resolve()
    folder = client.app.state.workbench.jobs.get(key).folder.resolve()
    assert folder == root / "studies" / key and {"study.toml", "bearing.toml"} <= {
        p.name for p in folder.iterdir()
    }
    # the server answers while the study runs (its own process), and refuses a second study
    t0 = time.perf_counter()
    assert client.get("/api/meta").status_code == 200
    assert time.perf_counter() - t0 < 5.0
    assert error_of(client.post("/api/study", json=STUDY), 409)["error"].startswith("a study is running")
    stopped = client.post(f"/api/study/{key}/stop").json()
    stopped = _wait(client, key)
    assert stopped["state"] == "stopped" and stopped["fraction"] < 1.0, stopped
    assert error_of(client.get(f"/api/study/{key}/results"), 400)["error"].endswith(
        "no results yet (stopped)"
    )
    resumed = client.post(f"/api/study/{key}/resume").json()
    assert resumed["state"] == "running" and resumed["runs"] == 2
    done = _wait(client, key)
    assert done["state"] == "done" and done["fraction"] == 1.0 and done["cases_done"] == 50, done
    res = client.get(f"/api/study/{key}/results").json()
    assert res["total_rows"] == 50 and res["summary"]["reused"] == done["chunks"] - res["summary"]["computed"]
    assert {"plot_1.png", "plot_2.png", "main_effects.png", "range.png"} <= set(res["figures"])
    png = client.get(f"/api/study/{key}/figure/plot_1.png")
    assert png.status_code == 200 and png.content.startswith(b"\x89PNG")
    assert client.get(f"/api/study/{key}/figure/..%2Fstudy.toml").status_code == 404
    assert client.get(f"/api/study/{key}/figure/results.csv").status_code == 404
    # the downloaded folder runs with the command line: the same numbers
    z = client.get(f"/api/study/{key}.zip")
    assert z.status_code == 200 and z.headers["content-type"] == "application/zip"
    zipfile.ZipFile(io.BytesIO(z.content)).extractall(tmp_path)
    folder = tmp_path / f"study-{key}"
    assert {"study.toml", "bearing.toml", "out"} <= {p.name for p in folder.iterdir()}
    import pandas as pd

    cli = CliRunner().invoke(app, ["study", str(folder / "study.toml"), "--out", str(tmp_path / "cli")])
    assert cli.exit_code == 0, cli.stderr
    ours = pd.DataFrame(res["rows"], columns=res["columns"])
    theirs = pd.read_csv(tmp_path / "cli" / "results.csv")
    for col in ("L10r_rev", "max_load_N", "load_cases.page.F_x", "geometry.clearance_radial"):
        assert np.array_equal(ours[col].to_numpy(float), theirs[col].to_numpy(float)), col


def test_an_optimisation_draws_its_pareto_front(client):
    body = {
        "subject": "bearing",
        "bearing": {**BASE, "temperature": "70 degC"},
        "design": "optimize",
        "population": 6,
        "generations": 2,
        "factors": [
            {"path": "geometry.clearance_radial", "start": "0 um", "stop": "40 um"},
            {"path": "lubricant.nu_40", "start": "20 mm^2/s", "stop": "200 mm^2/s"},
        ],
        "objectives": [
            {"output": "L10r_h", "sense": "max"},
            {"output": "friction_torque_Nm", "sense": "min"},
        ],
    }
    r = client.post("/api/study", json=body)
    assert r.status_code == 200, r.text
    assert r.json()["cases"] == 12
    done = _wait(client, r.json()["id"])
    assert done["state"] == "done", done
    res = client.get(f"/api/study/{done['id']}/results").json()
    assert res["figures"] == ["pareto.png"]
    front = res["tables"]["pareto"]
    life = np.array([row[front["columns"].index("L10r_h")] for row in front["rows"]])
    torque = np.array([row[front["columns"].index("friction_torque_Nm")] for row in front["rows"]])
    # no point of the front is dominated by another (longer life AND less friction), checked here
    for i in range(len(life)):
        better = (life >= life[i]) & (torque <= torque[i]) & ((life > life[i]) | (torque < torque[i]))
        assert not better.any(), i
    # and every evaluated design off the front is dominated by a point of it
    cases = np.array(
        [[row[res["columns"].index(c)] for c in ("L10r_h", "friction_torque_Nm")] for row in res["rows"]]
    )
    for a, b in cases:
        on = np.any(np.isclose(life, a, rtol=1e-12) & np.isclose(torque, b, rtol=1e-12))
        assert on or np.any((life >= a) & (torque <= b))


def test_a_shaft_study_is_written_with_the_bearing_files_it_names(client):
    from bearingkit.app.workbench.studies import StudyRequest, study_files

    shaft = {"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}}
    body = {
        "subject": "shaft",
        "system": shaft,
        "factors": [
            {"path": "load_scale", "start": "0.5", "stop": "1.5", "n": 3},
            {"path": "designation", "levels": ["6209", "6309"]},
        ],
        "outputs": ["system_L10h_h"],
    }
    data = error_of(client.post("/api/study", json=body), 400)
    assert data["field"] == "study.factor.1" and "add it, with one level to fix it (A, B)" in data["error"]
    body["factors"].append({"path": "bearing", "levels": ["A"]})
    made = study_files(StudyRequest.model_validate(body))
    assert set(made.files) == {"study.toml", "shaft.toml", "dgbb_6209.toml", "crb_nu209.toml"}
    assert made.files["shaft.toml"] == (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8")
    assert made.n_cases == 6 and 'evaluator = "shaft"' in made.files["study.toml"]


@pytest.mark.slow
def test_a_shaft_study_runs_as_the_cli_runs_it(client, tmp_path):
    shaft = {"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}}
    body = {
        "subject": "shaft",
        "system": shaft,
        "factors": [{"path": "load_scale", "levels": ["1.0", "1.5"]}],
        "outputs": ["system_L10h_h", "max_bearing_radial_load_N"],
    }
    r = client.post("/api/study", json=body)
    assert r.status_code == 200, r.text
    done = _wait(client, r.json()["id"])
    assert done["state"] == "done", done
    res = client.get(f"/api/study/{done['id']}/results").json()
    import pandas as pd

    from bearingkit.studies.generic.shaft import SHAFT

    ref = SHAFT(
        pd.DataFrame({"file": [str(EXAMPLES / "shaft_countershaft.toml")] * 2, "load_scale": [1.0, 1.5]})
    )
    got = [row[res["columns"].index("system_L10h_h")] for row in res["rows"]]
    # the study's child runs one solver thread, this process all cores: equal to the last bits of the solve
    assert got == pytest.approx(list(ref["system_L10h_h"]), rel=1e-10)


def test_unknown_study_is_404_and_ids_are_not_paths(client):
    assert client.get("/api/study/0123456789abcdef").status_code == 404
    assert client.get("/api/study/..%2F..%2Fetc").status_code == 404
    assert client.post("/api/study/0123456789abcdef/resume").status_code == 404


# ------------------------------------------------------------------------------------------ guards
#: Every POST route of the workbench with a body it would accept (the same guards as the bearing page's).
WORKBENCH_POSTS = {
    "/api/catalogue/search": {"kind": "deep_groove"},
    "/api/catalogue/select": {"radial": "5 kN", "speed": "3000 rpm", "life": "20000 h", "count": 1},
    "/api/catalogue/compare": {"designations": ["6209"]},
    "/api/system/open": {"system": "shaft", "source": {"kind": "example", "name": "shaft_countershaft.toml"}},
    "/api/system/analyze": {
        "system": "shaft",
        "source": {"kind": "example", "name": "shaft_countershaft.toml"},
    },
    "/api/study/paths": {"subject": "bearing", "bearing": BASE},
    "/api/study": STUDY,
    "/api/duty": {"base": BASE, "bins": [{"values": {"F_x": "3 kN"}, "fraction": "1"}]},
}


@pytest.mark.parametrize("path", sorted(WORKBENCH_POSTS))
def test_every_workbench_route_has_the_pages_guards(client, path):
    from bearingkit.app.api import MAX_REQUEST_BYTES

    jobs = client.app.state.workbench.jobs._jobs
    before = set(jobs)
    body = json.dumps(WORKBENCH_POSTS[path]).encode()
    # DNS rebinding: a foreign Host header is refused before the route runs
    r = client.post(path, content=body, headers={"host": "evil.example", "content-type": "application/json"})
    assert r.status_code == 400
    # a cross-site form can post text/plain without a preflight (CSRF): the JSON in it is not read
    data = error_of(client.post(path, content=body, headers={"content-type": "text/plain"}), 422)
    assert data["field"] == "source"
    # a body above the cap, declared: 413 before it is read
    big = body[:-1] + b', "x": "' + b"x" * MAX_REQUEST_BYTES + b'"}'
    assert error_of(client.post(path, content=big, headers={"content-type": "application/json"}), 413)
    assert set(jobs) == before  # nothing of the above started a study


def test_a_study_without_the_studies_extra_is_one_line_and_starts_nothing(client, monkeypatch):
    import sys

    before = dict(client.app.state.workbench.jobs._jobs)
    monkeypatch.setitem(sys.modules, "pymoo", None)  # as if `pip install bearingkit[app]` only
    data = error_of(client.post("/api/study", json=STUDY), 400)
    assert data["error"].startswith("a study of the web app needs the [studies] extra"), data
    assert data["field"] == "study" and client.app.state.workbench.jobs._jobs == before


def test_the_study_child_runs_under_the_apps_bounds(tmp_path, monkeypatch):
    import subprocess

    from bearingkit.app.workbench import jobs as jobs_module
    from bearingkit.budget import MAX_WORK_ENV

    seen = {}

    class Finished:  # a child that ended at once, and what it was started with
        pid = -1

        def __init__(self, command, **kwargs):
            seen.update(kwargs, command=command)

        def wait(self, timeout=None):
            return 0

        def poll(self):
            return 0

    monkeypatch.setattr(subprocess, "Popen", Finished)
    monkeypatch.delenv(MAX_WORK_ENV, raising=False)
    jobs = jobs_module.Jobs(lambda: tmp_path, max_seconds=321.0)
    job = jobs.start({"study.toml": "# a study\n"}, 1, "factorial", "bearing", ["s0"], ["x"])
    assert seen["cwd"] == job.folder and job.folder.parent == tmp_path / "studies"
    assert seen["command"][1:] == ["-m", "bearingkit.studies", "study.toml", "--out", "out", "--no-progress"]
    # the study's work estimate may take one run of the app (a page cannot set the variable) …
    assert seen["env"][MAX_WORK_ENV] == "321" and seen["env"]["BEARINGKIT_THREADS"] == "1"
    # … unless the server was started with a limit of its own
    monkeypatch.setenv(MAX_WORK_ENV, "50")
    deadline = time.monotonic() + 10
    while jobs.get(job.id).state == "running":
        assert time.monotonic() < deadline
        time.sleep(0.02)
    jobs.start({"study.toml": "# a study\n"}, 1, "factorial", "bearing", ["s0"], ["x"])
    assert seen["env"][MAX_WORK_ENV] == "50"
