"""REXS bearings with detailed geometry (``rolling_bearing_with_detailed_geometry`` with its
``rolling_bearing_row`` and ``rolling_element`` parts), written from the REXS attribute database.

No public model with rows and elements was found (the one public detailed bearing seen, an FVA needle
cage K 45x52x18, gives boundary dimensions and ratings only), so the test models are the two-stage
gearbox of examples/gearbox_two_stage.rexs with its 6208 and NU 208 given by their geometry instead of
their designations: the geometry of bearingkit's own estimate of those designations, written as REXS rows
and elements. Read back, it must solve to the designation model's reactions and lives (1e-9): the
attribute mapping (pitch diameter, count, diameters, groove radii as conformities, clearance, length)
carries every number the statics use.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from bearingkit.catalogue import parse, tables
from bearingkit.catalogue.resolve import resolve
from bearingkit.errors import InputError
from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import load_drivetrain_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GEARBOX = EXAMPLES / "gearbox_two_stage.rexs"


def _attribute(parent, key, unit, value):
    el = ET.SubElement(parent, "attribute", {"id": key, "unit": unit})
    el.text = str(value)


def _relation(
    root, rid, owner, part, hints=("rolling_bearing_with_detailed_geometry", "rolling_bearing_row")
):
    rel = ET.SubElement(root.find("relations"), "relation", {"id": str(rid), "type": "assembly"})
    ET.SubElement(rel, "ref", {"hint": hints[0], "id": str(owner), "role": "assembly"})
    ET.SubElement(rel, "ref", {"hint": hints[1], "id": str(part), "role": "part"})


def _detailed(tmp_path, kinds=None, drop=None, ratings=False, source=GEARBOX) -> Path:
    """The two-stage gearbox with input_A (6208) and input_B (NU 208) as detailed-geometry bearings (or
    ``kinds``: component name → (designation, REXS bearing_type) of ``source``)."""
    tree = ET.parse(source)
    root = tree.getroot()
    comps = root.find("components")
    kinds = kinds or {
        "input_A": ("6208", "radial_grooved_ball_bearing"),
        "input_B": ("NU 208", "radial_roller_bearing"),
    }
    next_id = 900
    for comp in list(comps):
        if comp.get("name") not in kinds:
            continue
        designation, kind = kinds[comp.get("name")]
        g = resolve(designation).geometry
        comp.set("type", "rolling_bearing_with_detailed_geometry")
        for el in [
            a for a in comp.findall("attribute") if a.get("id") in ("catalogue_designation", "bearing_type")
        ]:
            comp.remove(el)
        _attribute(comp, "bearing_type", "", kind)
        _attribute(comp, "inner_diameter", "mm", g["bore"] * 1e3)
        _attribute(comp, "outer_diameter", "mm", g["outer_diameter"] * 1e3)
        _attribute(comp, "number_of_bearing_rows", "", 1)
        if "clearance_radial" in g:
            _attribute(comp, "radial_bearing_clearance", "mum", g["clearance_radial"] * 1e6)
        if ratings:  # the catalogue's own C and C0 of the designation, as a maker's file would give them
            des = parse(designation)
            entry = tables.entries(des.family)[des.base]
            _attribute(comp, "radial_dynamic_load_rating", "kN", entry.C / 1e3)
            _attribute(comp, "radial_static_load_rating", "kN", entry.C0 / 1e3)
        row = ET.SubElement(
            comps, "component", {"id": str(next_id), "name": "row", "type": "rolling_bearing_row"}
        )
        _attribute(row, "number_of_rolling_elements", "", g["n_elements"])
        _attribute(row, "reference_diameter", "mm", g["pitch_diameter"] * 1e3)
        _attribute(row, "pressure_angle", "deg", math.degrees(g.get("contact_angle_outer", 0.0)))
        element = ET.SubElement(
            comps, "component", {"id": str(next_id + 1), "name": "element", "type": "rolling_element"}
        )
        if "small_diameter" in g:  # a tapered roller: its mean diameter, length and half cone angle
            _attribute(
                element,
                "diameter_of_rolling_element",
                "mm",
                (g["small_diameter"] + g["large_diameter"]) * 5e2,
            )
            _attribute(element, "roller_angle", "deg", math.degrees(g["roller_angle"]))
        else:
            _attribute(element, "diameter_of_rolling_element", "mm", g["element_diameter"] * 1e3)
        if "conformity_inner" in g:
            for side in ("inner", "outer"):
                _attribute(
                    row,
                    f"raceway_radius_of_{side}_ring",
                    "mm",
                    g[f"conformity_{side}"] * g["element_diameter"] * 1e3,
                )
        else:
            _attribute(element, "length_of_rolling_element", "mm", g["effective_length"] * 1e3)
        _relation(root, next_id, comp.get("id"), next_id)
        _relation(root, next_id + 1, next_id, next_id + 1, ("rolling_bearing_row", "rolling_element"))
        next_id += 2
    if drop is not None:
        for comp in comps:
            for el in [a for a in comp.findall("attribute") if a.get("id") == drop]:
                comp.remove(el)
    path = tmp_path / "detailed.rexs"
    tree.write(path, encoding="utf-8", xml_declaration=True)
    return path


def test_bearings_given_by_rows_and_elements_read_as_bearing_files(tmp_path):
    data = read_rexs(_detailed(tmp_path))
    notes = data.pop(REXS_NOTES, [])
    bearings = {b["name"]: b for s in data["shafts"] for b in s["bearings"]}
    ball, roller = bearings["input_A"]["bearing"], bearings["input_B"]["bearing"]
    assert (ball["bearing"]["type"], roller["bearing"]["type"]) == ("deep_groove_ball", "cylindrical_roller")
    assert ball["geometry"]["n_elements"] == 8 and ball["geometry"]["conformity_outer"] == pytest.approx(
        0.53, rel=1e-12
    )
    assert roller["geometry"]["profile"] == {"name": "iso16281"}  # no crowning radius in the file
    assert not any("file's ratings" in n for n in notes)  # none given: the geometry is rated


def test_the_detailed_gearbox_solves_to_the_designation_gearbox(tmp_path, assert_same_loads):
    """Same statics to 1e-9. The lives differ as the ratings do, and only so: a designation is rated with
    the catalogue's published C (docs/catalogue.md), a bearing given by its geometry with the ISO 281 C
    of that geometry; so L(designation)/L(geometry) = (C_cat/C_geometry)^p, p = 10/3 for the NU 208's
    ISO 281 life (P = F_r, radial only) and 4 and 3 for the ISO/TS 16281 lives of roller and ball rows."""
    by_name = DrivetrainAnalysis(load_drivetrain_file(GEARBOX)).to_dict()
    by_geometry = DrivetrainAnalysis(load_drivetrain_file(_detailed(tmp_path))).to_dict()
    ratio = {}
    for text in ("6208", "NU 208"):
        des = parse(text)
        ratio[text] = tables.entries(des.family)[des.base].C / resolve(text).C
    assert_same_loads(by_name["cases"], by_geometry["cases"])
    for a, b in zip(by_name["cases"], by_geometry["cases"], strict=True):
        for x, y in zip(a["bearings"], b["bearings"], strict=True):
            assert y["summary"]["static_safety"] == pytest.approx(x["summary"]["static_safety"], rel=1e-9)
            lives = {k: x["summary"][k] / y["summary"][k] for k in ("L10h_h", "L10h_iso281_h")}
            if x["name"] == "input_B":
                assert lives["L10h_iso281_h"] == pytest.approx(ratio["NU 208"] ** (10 / 3), rel=1e-9)
                assert lives["L10h_h"] == pytest.approx(ratio["NU 208"] ** 4, rel=1e-9)
            elif x["name"] == "input_A":
                assert lives["L10h_h"] == pytest.approx(ratio["6208"] ** 3, rel=1e-9)
            else:  # the other bearings are the same designations in both models
                assert lives == pytest.approx({"L10h_h": 1.0, "L10h_iso281_h": 1.0}, rel=1e-9)


def test_a_crowning_radius_is_a_full_crown(tmp_path):
    path = _detailed(tmp_path)
    tree = ET.parse(path)
    element = next(
        c
        for c in tree.getroot().iter("component")
        if any(a.get("id") == "length_of_rolling_element" for a in c)  # the NU 208's roller
    )
    _attribute(element, "roller_crowning_radius", "mm", 500.0)
    tree.write(path, encoding="utf-8", xml_declaration=True)
    data = read_rexs(path)
    roller = next(b for s in data["shafts"] for b in s["bearings"] if b["name"] == "input_B")["bearing"]
    assert roller["geometry"]["profile"] == {"name": "full_crown", "crown_radius": "500.0 mm"}


def test_a_kind_not_read_from_geometry_falls_back_to_its_designation_or_is_refused(tmp_path):
    path = _detailed(tmp_path, kinds={"input_B": ("NU 208", "radial_spherical_roller_bearing")})
    with pytest.raises(InputError) as err:
        read_rexs(path)
    line = str(err.value)
    assert "\n" not in line and "radial_spherical_roller_bearing" in line and "designation" in line
    tree = ET.parse(path)
    comp = next(c for c in tree.getroot().iter("component") if c.get("name") == "input_B")
    _attribute(comp, "catalogue_designation", "", "NU 208")
    tree.write(path, encoding="utf-8", xml_declaration=True)
    data = read_rexs(path)
    bearing = next(b for s in data["shafts"] for b in s["bearings"] if b["name"] == "input_B")
    assert bearing["designation"] == "NU 208"
    assert any("read by its designation" in n for n in data[REXS_NOTES])


def test_a_row_without_its_groove_radius_is_refused_in_one_line(tmp_path):
    with pytest.raises(InputError) as err:
        read_rexs(_detailed(tmp_path, drop="raceway_radius_of_outer_ring"))
    line = str(err.value)
    assert "\n" not in line and "raceway_radius_of_outer_ring" in line and "input_A" in line


def test_with_the_catalogue_s_ratings_in_the_file_the_lives_are_the_designation_s(tmp_path):
    """A detailed bearing whose file gives radial_dynamic/static_load_rating is rated with them, as a
    designation is with its catalogue's: with the catalogue's own C and C0 written in, the geometry model's
    lives equal the designation model's (1e-9), and one note names the ratings used."""
    path = _detailed(tmp_path, ratings=True)
    notes = read_rexs(path)[REXS_NOTES]
    assert sum("the lives use the file's ratings" in n for n in notes) == 1
    assert any("input_B (C 55.5 kN, C0 55.5 kN)" in n for n in notes)
    by_name = DrivetrainAnalysis(load_drivetrain_file(GEARBOX)).to_dict()
    by_geometry = DrivetrainAnalysis(load_drivetrain_file(path)).to_dict()
    for a, b in zip(by_name["cases"], by_geometry["cases"], strict=True):
        for x, y in zip(a["bearings"], b["bearings"], strict=True):
            for key in ("L10h_h", "L10h_iso281_h"):
                assert y["summary"][key] == pytest.approx(x["summary"][key], rel=1e-9)


def test_tapered_rows_read_from_geometry_solve_to_their_designations(tmp_path, assert_same_loads):
    """The public FVA two-stage gearbox's 33014 and 33012 (one-way tapered rows facing each other on the
    output shaft) written as rows and elements of bearingkit's estimate (mean roller diameter, effective
    length, cup angle, half cone angle): same statics as the designations (1e-9), and the rows face the
    same way (their axial_force_absorption)."""
    fva = EXAMPLES / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs"
    names = {"33014 (Rolling bearing [90])": "33014", "33012 (Rolling bearing [49])": "33012"}
    kinds = {k: (v, "radial_tapered_roller_bearing") for k, v in names.items()}
    path = _detailed(tmp_path, kinds=kinds, source=fva)
    data = read_rexs(path)
    tapered = [b for s in data["shafts"] for b in s["bearings"] if b["name"] in names]
    assert [b["bearing"]["bearing"]["type"] for b in tapered] == ["tapered_roller", "tapered_roller"]
    assert sorted(b["orientation"] for b in tapered) == ["+z", "-z"]
    by_name = DrivetrainAnalysis(load_drivetrain_file(fva)).to_dict()
    by_geometry = DrivetrainAnalysis(load_drivetrain_file(path)).to_dict()
    assert_same_loads(by_name["cases"], by_geometry["cases"])
