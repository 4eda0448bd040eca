"""Public REXS models written by other tools (examples/rexs/SOURCES.md): read, and solved where we can.

* ``FVA-Industriegetriebe_2stufig_1-4.rexs``: the FVA two-stage industrial gearbox, REXS 1.4, written by
  Bearinx 12 (Schaeffler's REXSapi test models). Three shafts, the input and output shafts coaxial (a
  needle cage K 50x58x25 between them, a concept bearing), the countershaft on two tapered roller bearings
  33016 given as concept bearings that carry axial load one way each, the output shaft on 33014/33012,
  four load cases with time fractions.
* ``SEW_3-stage_cylindrical_gearbox_1.0.rexs``: a three-stage SEW gearbox, REXS 1.0, FVA Workbench 5.0
  (FVA's rexs-api-java test models); no load spectrum, catalogue designations in a ``name`` attribute.
* ``FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj``: a planetary stage, REXS 1.1 JSON: read as a stage and
  solved (tests/systems/test_rexs_planetary.py); here its results model read back.

No tool's results travel with these files, so the checks are the ones that hold whatever the tool: the
speeds and torques of the tooth counts, the power balance, and the one-way concept bearings.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import drivetrain_from_dict, load_drivetrain_file

PUBLIC = Path(__file__).resolve().parents[2] / "examples" / "rexs"
FVA = PUBLIC / "FVA-Industriegetriebe_2stufig_1-4.rexs"
SEW = PUBLIC / "SEW_3-stage_cylindrical_gearbox_1.0.rexs"
PLANETARY = PUBLIC / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj"


@pytest.fixture(scope="module")
def fva():
    return DrivetrainAnalysis(load_drivetrain_file(FVA)).to_dict()


def test_the_fva_gearbox_solves_every_load_case_with_the_speeds_and_torques_of_its_teeth(fva):
    # tooth counts of the file: 27/51 (m_n 4.5 mm), 23/34 (m_n 6.5 mm); input torques 567, 345, 456, … N·m
    ratio = (51 / 27) * (34 / 23)
    assert len(fva["cases"]) == 4 and all(c["converged"] for c in fva["cases"])
    for case in fva["cases"]:
        w = case["power"]["speeds_rad_s"]
        assert w["Shaft [25]"] == pytest.approx(-w["Shaft [6]"] * 27 / 51, rel=1e-12)
        assert w["Shaft [42]"] == pytest.approx(w["Shaft [6]"] / ratio, rel=1e-12)
        t_in = case["meshes"][0]["on_a"]["torque_Nm"]
        assert case["held_torque_Nm"] == pytest.approx(t_in * ratio, rel=1e-9)
        p = case["power"]
        assert p["input_W"] == pytest.approx(-t_in * w["Shaft [6]"], rel=1e-9)
        assert p["output_W"] + p["loss_W"] == pytest.approx(p["input_W"], rel=1e-9)
        assert 0 < p["loss_W"] < 0.01 * p["input_W"]


def test_the_fva_countershaft_s_one_way_bearings_carry_its_axial_load_on_one_side(fva):
    """The two 33016 of the countershaft are concept bearings with axial_force_absorption 'negative' (at
    u = 20 mm) and 'positive' (at u = 250 mm): 'negative' supports an axial force on the shaft along −u,
    pushing it back along +z, 'positive' pushes along −z (as FVA Workbench's solution of this gearbox has
    it, test_rexs_fva_workbench.py): a shaft held between them (X arrangement). Each only pushes; in these
    cases the gear forces stretch the shaft between them, so both push and share the net axial mesh
    force (at FVA Workbench's operating point they would pull, and one carries none: the other test)."""
    for case in fva["cases"]:
        meshes = {m["name"]: m for m in case["meshes"]}
        # the countershaft is gear b of the first stage and gear a of the second
        net = (
            meshes["Cylindrical stage [24]"]["on_b"]["axial_N"]
            + meshes["Cylindrical stage [41]"]["on_a"]["axial_N"]
        )
        bearings = {b["name"]: b for b in case["bearings"]}
        neg = bearings["not a catalogue bearing: 33016 (Rolling bearing [35])"]["reaction_on_inner_body"][
            "F_z_N"
        ]
        pos = bearings["not a catalogue bearing: 33016 (Rolling bearing [60])"]["reaction_on_inner_body"][
            "F_z_N"
        ]
        assert net < 0  # every load case pushes the countershaft along -z
        assert neg > 0.0 > pos  # each pushes its own way, neither pulls
        assert neg + pos == pytest.approx(-net, rel=1e-9)


def test_the_fva_import_keeps_what_the_file_says():
    data = read_rexs(FVA)
    notes = data.pop(REXS_NOTES, [])
    shafts = {s["name"]: s for s in data["shafts"]}
    assert sorted(shafts) == ["Shaft [25]", "Shaft [42]", "Shaft [6]"]
    cage = next(b for b in shafts["Shaft [6]"]["bearings"] if "K 50x58x25" in b["name"])
    assert cage["outer"] == "Shaft [42]" and cage["axial"] == "floating"  # shaft in shaft, radial only
    counter = {b["name"]: b["stiffness"] for b in shafts["Shaft [25]"]["bearings"]}
    assert sorted(k["axial_direction"] for k in counter.values()) == ["+z", "-z"]
    assert [c["time_fraction"] for c in data["load_cases"]] == pytest.approx(
        [0.2, 0.3, 0.35, 0.15]
    )  # the file: 20, 30, 35, 15 %
    assert notes == []  # the tapered bearings' one-way absorption is their orientation: nothing to say
    designations = sorted(b.get("designation", "") for s in data["shafts"] for b in s["bearings"])
    assert designations == ["", "", "", "33012", "33014", "6210-2Z"]


def test_the_sew_gearbox_reads_its_rexs_1_0_spelling():
    """REXS 1.0: the degree sign as a unit, the designation in a ``name`` attribute, no load spectrum."""
    data = read_rexs(SEW)
    notes = data.pop(REXS_NOTES)
    inp = drivetrain_from_dict(data, str(SEW), base=PUBLIC)
    dt = inp.drivetrain
    assert [s.name for s in dt.shafts] == ["ANW [4]", "RW3 [5]", "RW5 [36]", "ABW [54]"]
    assert len(dt.meshes) == 3 and len(dt.bearings) == 9
    names = [b["designation"] for s in data["shafts"] for b in s["bearings"]]
    assert names == [
        "6305-2Z",
        "6205",
        "6202",
        "6202",
        "6302",
        "NUP204-E-XL-TVP2",
        "6303-C",
        "6207",
        "6308-2Z",
    ]
    case = data["load_cases"][0]
    assert case["torques"] == {"ANW [4]": "4.724562306435156 N*m"} and case["speed"] == {
        "ANW [4]": "1400.0 rpm"
    }
    assert any("no load_spectrum" in n for n in notes)
    # the cross-located 6202 pair and 6302/6303: one-way absorption on deep groove bearings is said
    one_way = [n for n in notes if "seat's one-sided shoulder is not modelled" in n]
    assert len(one_way) == 4
    assert inp.loads["given_speeds"]["ANW [4]"][0] == pytest.approx(1400 * np.pi / 30, rel=1e-12)
    assert inp.loads["torques"]["ANW [4]"][0] == pytest.approx(4.724562306435156, rel=1e-15)


def test_the_sew_gearbox_solves_though_its_input_shaft_winds_up_far():
    """Three stages of 105.8 : 1 amplify the output's deflections at the input: its rotation about its
    axis is ~0.3 rad at 4.72 N·m. The Newton neither caps nor watches that rotation (a drivetrain's wind-up
    is no bearing deflection): before, it walked there one capped step at a time and was stopped as
    "displacement diverged"."""
    from typer.testing import CliRunner

    from bearingkit.cli.commands import app

    da = DrivetrainAnalysis(load_drivetrain_file(SEW))
    res = da.result
    assert res.converged.tolist() == [True]
    ratio = (67 / 23) * (76 / 13) * (87 / 14)
    # three external meshes: the output turns against the input, its held torque has the input's sign
    assert float(res.held_torque()[0]) == pytest.approx(4.724562306435156 * ratio, rel=1e-9)
    blk = res.assembly.blocks["ANW [4]"]
    wind_up = abs(float(res.unknowns[0, blk.theta_z]))
    limit = da.input.options.divergence_limit * min(law.deflection_scale for law in res.laws)
    assert wind_up * da.drivetrain.char_length > limit  # what the old test called divergence
    out = CliRunner().invoke(app, ["system", str(SEW), "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    power = data["cases"][0]["power"]
    # no lubricant in the file: no bearing friction, so the losses and the output are unknown (null)
    assert power["loss_W"] is None and power["output_W"] is None
    assert power["output_lossless_W"] == pytest.approx(power["input_W"], rel=1e-9)
    # the import's notes reach the JSON (the CLI and report print the same notes list)
    # 4 one-way deep groove, 1 spectrum, 1 the FAG ratings the lives use
    assert sum(n.startswith("REXS import: ") for n in data["notes"]) == 6
    rated = [n for n in data["notes"] if "the lives use the file's ratings" in n]
    assert len(rated) == 1 and "Lager NUP204E [50] (C 32.5 kN, C0 24.7 kN)" in rated[0]


def test_the_fva_import_has_nothing_to_note(fva):
    """Its one-way bearings are tapered (their orientation says it) or concept bearings (modelled)."""
    assert not any("REXS import" in n for n in fva["notes"])


def test_mutated_public_models_load_or_are_refused_in_one_line(tmp_path, escape_of):
    """60 mutants of the two XML models (a dropped attribute, a bad number, a foreign unit, a short vector,
    a removed or retyped component, a dangling or non-integer relation reference): each loads, or is
    refused with one InputError line; nothing else escapes (27 of 300 mutants raised KeyError or ValueError
    before the reader checked references and numbers)."""
    import random
    import xml.etree.ElementTree as ET

    rng = random.Random(20261129)
    escaped = []
    for i in range(60):
        source = rng.choice([FVA, SEW])
        tree = ET.parse(source)
        root = tree.getroot()
        attribute = rng.choice(list(root.iter("attribute")))
        kind = rng.choice(["drop", "text", "unit", "vector", "component", "relation", "role"])
        if kind == "drop":
            next(p for p in root.iter() if attribute in list(p)).remove(attribute)
        elif kind == "text":
            attribute.text = rng.choice(["abc", "-1", "1e400", "", "nan", "1,5"])
            for child in list(attribute):
                attribute.remove(child)
        elif kind == "unit":
            attribute.set("unit", rng.choice(["foo", "mm", "N", "", "kN"]))
        elif kind == "vector":
            array = attribute.find("array")
            if array is not None and len(array):
                array.remove(array[0])
            else:
                attribute.text = "1"
        elif kind == "component":
            components = root.find("components")
            component = rng.choice(list(components))
            if rng.random() < 0.5:
                components.remove(component)
            else:
                component.set("type", rng.choice(["shaft", "cylindrical_gear", "concept_bearing", "foo"]))
        elif kind == "role":  # a role renamed, or a reference dropped: the relation misses one it needs
            relation = rng.choice(list(root.find("relations")))
            ref = rng.choice(list(relation))
            if rng.random() < 0.5:
                ref.set("role", rng.choice(["part", "inner_part", "x"]))
            else:
                relation.remove(ref)
        else:
            relation = rng.choice(list(root.find("relations")))
            rng.choice(list(relation)).set("id", rng.choice(["9999", "x", "-1"]))
        path = tmp_path / f"mutant{i}.rexs"
        tree.write(path, encoding="utf-8", xml_declaration=True)
        if (escape := escape_of(path)) is not None:
            escaped.append((i, kind, *escape))
    assert escaped == []


@pytest.mark.parametrize("model", [FVA, SEW, PLANETARY], ids=["fva", "sew", "planetary"])
def test_the_results_model_written_reads_again_to_the_same_results(model, tmp_path):
    """`--rexs` writes the source model plus the results: its load cases keep their inputs (speeds, torques,
    forces, time shares), so the file written solves again to the same bearing loads (before, its load
    spectrum held the results only and read back as an unloaded gearbox)."""
    from bearingkit.io.rexs.export import write_rexs_results

    first = DrivetrainAnalysis(load_drivetrain_file(model)).to_dict()
    path = write_rexs_results(first, tmp_path / "results.rexsj", source=model)
    again = DrivetrainAnalysis(load_drivetrain_file(path)).to_dict()
    assert len(again["cases"]) == len(first["cases"])
    for a, b in zip(first["cases"], again["cases"], strict=True):
        assert b["converged"] and b["held_torque_Nm"] == pytest.approx(a["held_torque_Nm"], rel=1e-12)
        for x, y in zip(a["bearings"], b["bearings"], strict=True):
            scale = max(abs(x["radial_load_N"]), abs(x["axial_load_N"]), 1.0)
            assert y["radial_load_N"] == pytest.approx(x["radial_load_N"], abs=1e-9 * scale)
            assert y["axial_load_N"] == pytest.approx(x["axial_load_N"], abs=1e-9 * scale)


def test_an_input_given_by_its_power_is_the_torque_p_over_omega(tmp_path):
    """FVA Workbench writes an input's power beside (or instead of) its torque: with the torques of the
    FVA gearbox's four cases replaced by P = T ω [kW] at the case's input speed, the import reads the same
    torques (1e-12); a power on a shaft whose speed the case does not give is one line."""
    import xml.etree.ElementTree as ET

    tree = ET.parse(FVA)
    for case in tree.getroot().iter("load_case"):
        speed = next(float(a.text) for a in case.iter("attribute") if a.get("id") == "rotational_speed")
        for a in case.iter("attribute"):
            if a.get("id") == "torque_around_u_axis":
                a.set("id", "power")
                a.set("unit", "kW")
                a.text = repr(float(a.text) * speed * 2 * np.pi / 60 / 1e3)
    path = tmp_path / "power.rexs"
    tree.write(path, encoding="utf-8", xml_declaration=True)
    by_power = read_rexs(path)["load_cases"]
    by_torque = read_rexs(FVA)["load_cases"]
    for a, b in zip(by_torque, by_power, strict=True):
        (shaft, torque), (shaft_b, text) = *a["torques"].items(), *b["torques"].items()
        assert shaft == shaft_b
        assert float(text.split()[0]) == pytest.approx(float(torque.split()[0]), rel=1e-12)
    for case in tree.getroot().iter("load_case"):  # no speed in the cases: no ω to divide by
        for comp in case.findall("component"):
            for a in [a for a in comp.findall("attribute") if a.get("id") == "rotational_speed"]:
                comp.remove(a)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    with pytest.raises(InputError) as err:
        read_rexs(path)
    assert "rotational_speed" in str(err.value) and "\n" not in str(err.value)


def test_a_dynamic_rating_alone_rates_the_lives_and_is_named(tmp_path):
    """A bearing giving only its dynamic rating (no static one) is rated with that C; its C0 stays
    bearingkit's, and the note says no C0 was given."""
    text = SEW.read_text(encoding="utf-8")
    changed = text.replace('<attribute id="static_capacity" unit="kN">24.7</attribute>', "", 1)
    assert changed != text
    path = tmp_path / "c_only.rexs"
    path.write_text(changed, encoding="utf-8")
    data = read_rexs(path)
    bearing = next(b for s in data["shafts"] for b in s["bearings"] if "NUP204E" in b["name"])
    assert bearing["ratings"] == {"C": "32.5 kN"}
    assert any("Lager NUP204E [50] (C 32.5 kN, no C0 given)" in n for n in data[REXS_NOTES])
