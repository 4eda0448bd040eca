"""REXS import (docs/drivetrains.md): the two-stage gearbox written as a REXS 1.4 model from the
specification (examples/gearbox_two_stage.rexs) solves to the same results as the TOML file; the
results go back into a REXS JSON model; unsupported parts are one-line refusals."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io.rexs.reader import read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import load_drivetrain_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def both():
    return (
        DrivetrainAnalysis(load_drivetrain_file(EXAMPLES / "gearbox_two_stage.toml")),
        DrivetrainAnalysis(load_drivetrain_file(EXAMPLES / "gearbox_two_stage.rexs")),
    )


def test_rexs_model_solves_to_the_toml_result(both):
    toml, rexs = both
    assert rexs.drivetrain.held == "output" and rexs.case_names == [
        "load case 1",
        "load case 2",
        "load case 3",
    ]
    np.testing.assert_allclose(rexs.input.loads["time_fraction"], [0.6, 0.1, 0.3], rtol=1e-12)
    for b in toml.drivetrain.bearings:
        ref = toml.result.reaction(b.name)
        np.testing.assert_allclose(rexs.result.reaction(b.name), ref, rtol=0, atol=1e-9 * np.abs(ref).max())
        for key in ("L10h_h", "L10h_iso281_h"):
            np.testing.assert_allclose(
                rexs.bearing_lives(b.name)[key], toml.bearing_lives(b.name)[key], rtol=1e-9
            )
    for m in toml.drivetrain.meshes:
        np.testing.assert_allclose(rexs.result.mesh_force(m.name), toml.result.mesh_force(m.name), rtol=1e-9)
    np.testing.assert_allclose(rexs.system_lives["L10h_h"], toml.system_lives["L10h_h"], rtol=1e-9)
    # REXS has no mesh friction: the REXS model's losses are the bearings' (the same as the TOML's)
    bearing_loss = sum(toml.power["bearing_loss_W"].values())
    np.testing.assert_allclose(rexs.power["loss_W"], bearing_loss, rtol=1e-9)


def test_results_go_back_into_a_rexs_json_model(both, tmp_path):
    from bearingkit.io.rexs.export import write_rexs_results

    _, rexs = both
    path = write_rexs_results(
        rexs.to_dict(), tmp_path / "out.rexsj", source=EXAMPLES / "gearbox_two_stage.rexs"
    )
    model = json.loads(Path(path).read_text(encoding="utf-8-sig"))["model"]
    assert model["version"] == "1.4"
    bearing_ids = {
        c["name"]: c["id"]
        for c in model["components"]
        if c["type"] == "rolling_bearing_with_catalog_geometry"
    }
    assert bearing_ids["input_A"] == 40  # the source model's component ids are kept
    case = model["load_spectrum"]["load_cases"][0]
    comp = next(c for c in case["components"] if c["id"] == 40)
    attrs = {a["id"]: a for a in comp["attributes"]}
    life = rexs.bearing_lives("input_A")["L10h_h"][0]
    assert attrs["custom_bearingkit_l10h_iso_ts_16281"]["floating_point"] == pytest.approx(life, rel=1e-12)
    q = rexs.result.relative_displacement("input_A")[0]
    assert attrs["axial_deflection"]["floating_point"] == pytest.approx(q[2] * 1e6, rel=1e-12)
    assert attrs["axial_deflection"]["unit"] == "mum"


@pytest.mark.parametrize(
    ("edit", "needle"),
    [
        (
            lambda s: s.replace(  # no rows, no bearing_type, no designation: nothing to build it from
                'type="rolling_bearing_with_catalog_geometry">',
                'type="rolling_bearing_with_detailed_geometry">',
                1,
            ).replace('<attribute id="catalogue_designation" unit="">6208</attribute>', "", 1),
            "detailed geometry",
        ),
        (
            lambda s: s.replace("<c>0</c><c>0</c><c>1</c></array>", "<c>1</c><c>0</c><c>0</c></array>", 3)[
                ::1
            ],
            "not parallel",
        ),
        (
            lambda s: s.replace(
                'id="outer_diameter_end" unit="mm">48', 'id="outer_diameter_end" unit="mm">50'
            ),
            "conical",
        ),
        (lambda s: s.replace('version="1.4"', 'version="2.0"'), "REXS version"),
    ],
)
def test_unsupported_parts_are_one_line_refusals(tmp_path, edit, needle):
    text = (EXAMPLES / "gearbox_two_stage.rexs").read_text(encoding="utf-8")
    changed = edit(text)
    assert changed != text
    path = tmp_path / "bad.rexs"
    path.write_text(changed, encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_rexs(path)
    assert needle in str(err.value) and "\n" not in str(err.value)


def test_the_json_syntax_reads_as_the_xml(tmp_path):
    """The same model in REXS JSON (1.5 syntax: typed attribute values) builds the same drivetrain."""
    from bearingkit.io.rexs.reader import parse
    from bearingkit.systems.drivetrain.input import drivetrain_from_dict

    m = parse(EXAMPLES / "gearbox_two_stage.rexs")

    def attrs(a):
        out = []
        for key, (value, unit) in a.items():
            if isinstance(value, bool):
                out.append({"id": key, "boolean": value})
            elif isinstance(value, list):
                out.append({"id": key, "unit": unit, "floating_point_array": value})
            elif key == "catalogue_designation" or not value.replace(".", "").replace("-", "").isdigit():
                out.append({"id": key, "unit": unit, "string": value})
            else:
                out.append({"id": key, "unit": unit, "floating_point": float(value)})
        return out

    model = {
        "version": m["version"],
        "applicationId": "test",
        "applicationVersion": "1",
        "date": "2026-11-27T21:00:00+00:00",
        "relations": [
            {"id": k, "type": r["type"], "refs": [{"id": i, "role": role} for i, role in r["refs"]]}
            for k, r in enumerate(m["relations"])
        ],
        "components": [
            {"id": i, "name": c["name"], "type": c["type"], "attributes": attrs(c["attrs"])}
            for i, c in m["components"].items()
        ],
        "load_spectrum": {
            "id": 1,
            "load_cases": [
                {
                    "id": lc["id"],
                    "components": [{"id": i, "attributes": attrs(a)} for i, a in lc["components"].items()],
                }
                for lc in m["load_cases"]
            ],
        },
    }
    path = tmp_path / "gearbox.rexsj"
    path.write_text(json.dumps({"model": model}), encoding="utf-8")
    a = drivetrain_from_dict(read_rexs(path), "json", base=EXAMPLES).drivetrain
    b = drivetrain_from_dict(read_rexs(EXAMPLES / "gearbox_two_stage.rexs"), "xml", base=EXAMPLES).drivetrain
    assert [s.centre for s in a.shafts] == [s.centre for s in b.shafts]
    assert [(x.name, x.inner.position, x.seat.bearing.name) for x in a.bearings] == [
        (x.name, x.inner.position, x.seat.bearing.name) for x in b.bearings
    ]
    assert [(m.name, m.pair.a.teeth, m.pair.b.teeth, m.pair.a.helix_angle) for m in a.meshes] == [
        (m.name, m.pair.a.teeth, m.pair.b.teeth, m.pair.a.helix_angle) for m in b.meshes
    ]


def test_one_direction_bearings_face_the_way_axial_force_absorption_says(tmp_path):
    """A tapered row takes axial force one way: ``axial_force_absorption`` ``positive`` (an axial force on
    the shaft along +u) reads as orientation +z, ``negative`` as -z; the input shaft on two tapered rows
    facing each other then carries the helical thrust both ways (every case converges), the rows swapped
    reverse both orientations."""
    text = (EXAMPLES / "gearbox_two_stage.rexs").read_text(encoding="utf-8")
    middle = '</attribute>\n      <attribute id="radial_force_absorption" unit="">true</attribute>\n      '
    a_old = '">both_directions' + middle + '<attribute id="catalogue_designation" unit="">6208<'
    b_old = '">no_direction' + middle + '<attribute id="catalogue_designation" unit="">NU 208<'
    assert text.count(a_old) == 1 and text.count(b_old) == 1
    orientations = []
    for first, second in (("negative", "positive"), ("positive", "negative")):
        edited = text.replace(a_old, a_old.replace("both_directions", first).replace("6208", "30208"))
        edited = edited.replace(b_old, b_old.replace("no_direction", second).replace("NU 208", "30208"))
        path = tmp_path / f"{first}.rexs"
        path.write_text(edited, encoding="utf-8")
        data = read_rexs(path)
        shaft = next(s for s in data["shafts"] if any(b["name"] == "input_A" for b in s["bearings"]))
        by_name = {b["name"]: b for b in shaft["bearings"]}
        orientations.append((by_name["input_A"]["orientation"], by_name["input_B"]["orientation"]))
        assert by_name["input_A"]["axial"] == by_name["input_B"]["axial"] == "locating"
    assert orientations == [("-z", "+z"), ("+z", "-z")]
    res = DrivetrainAnalysis(load_drivetrain_file(tmp_path / "negative.rexs")).result
    assert res.converged.all()


def test_the_export_types_the_values_an_xml_model_gave_as_text(tmp_path):
    """XML gives every value as text; the JSON written types them: a number with a unit is a
    floating_point, a tooth count an integer, a designation (no unit) stays a string."""
    import json

    from bearingkit.io.rexs.export import write_rexs_results
    from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
    from bearingkit.systems.drivetrain.input import load_drivetrain_file

    source = EXAMPLES / "gearbox_two_stage.rexs"
    data = DrivetrainAnalysis(load_drivetrain_file(source)).to_dict()
    model = json.loads(
        write_rexs_results(data, tmp_path / "out.rexsj", source=source).read_text(encoding="utf-8-sig")
    )["model"]
    attrs = {(c["id"], a["id"]): a for c in model["components"] for a in c["attributes"]}
    kinds = {key: next(k for k in a if k not in ("id", "unit")) for key, a in attrs.items()}
    assert (
        kinds[(40, "catalogue_designation")] == "string"
        and attrs[(40, "catalogue_designation")]["string"] == "6208"
    )
    assert kinds[(40, "u_coordinate_on_shaft_inner_side")] == "floating_point"
    assert attrs[(40, "u_coordinate_on_shaft_inner_side")]["floating_point"] == 10.0
    teeth = [a for (cid, key), a in attrs.items() if key == "number_of_teeth"]
    assert teeth and all(isinstance(a.get("integer"), int) for a in teeth)
