"""REXS couplings between shafts (io/rexs/couplings.py): a rigid coupling of two coaxial shafts end to end
is read as one shaft.

The test model is the two-stage gearbox of examples/gearbox_two_stage.rexs with its input shaft (0–160 mm)
cut at 140 mm into two shafts — the stub (its last section and the NU 208 at 150 mm) placed at its own
u = 0 — joined by a coupling of 10²⁰ N/m and N·mm/rad: it must solve to the uncut gearbox (1e-9).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from bearingkit.errors import InputError
from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import load_drivetrain_file

GEARBOX = Path(__file__).resolve().parents[2] / "examples" / "gearbox_two_stage.rexs"


def _attr(parent, key, unit, text):
    el = ET.SubElement(parent, "attribute", {"id": key, "unit": unit})
    el.text = text
    return el


def _relation(root, rid, kind, refs):
    rel = ET.SubElement(root.find("relations"), "relation", {"id": str(rid), "type": kind})
    for cid, role in refs:
        ET.SubElement(rel, "ref", {"id": str(cid), "role": role})


def _cut(tmp_path, stiffness="1e+20", overlap=False) -> Path:
    tree = ET.parse(GEARBOX)
    root = tree.getroot()
    comps = {int(c.get("id")): c for c in root.find("components")}
    stub = ET.SubElement(root.find("components"), "component", {"id": "11", "name": "stub", "type": "shaft"})
    array = ET.SubElement(_attr(stub, "support_vector", "mm", None), "array")
    for value in ("0", "0", "140"):  # its u = 0 at the input shaft's 140 mm (u along z)
        ET.SubElement(array, "c").text = value
    coupling = ET.SubElement(
        root.find("components"), "component", {"id": "12", "name": "cut", "type": "coupling"}
    )
    _attr(coupling, "u_coordinate_on_shaft_inner_side", "mm", "140")
    _attr(coupling, "u_coordinate_on_shaft_outer_side", "mm", "10" if overlap else "0")
    for key, unit in (
        ("radial_stiffness", "N / m"),
        ("axial_stiffness", "N / m"),
        ("bending_stiffness", "N mm / rad"),
    ):
        _attr(coupling, key, unit, stiffness)
    # the last section and the NU 208 move onto the stub, in its own coordinates
    for rel in root.iter("relation"):
        refs = {r.get("role"): r for r in rel.findall("ref")}
        if rel.get("type") == "assembly" and refs["part"].get("id") == "102":
            refs["assembly"].set("id", "11")
        if (
            rel.get("type") == "side"
            and refs.get("assembly") is not None
            and refs["assembly"].get("id") == "41"
        ):
            refs["inner_part"].set("id", "11")
    section = comps[102].find("attribute[@id='u_coordinate_on_shaft']")
    section.text = "0"
    bearing = comps[41].find("attribute[@id='u_coordinate_on_shaft_inner_side']")
    bearing.text = "10"
    _relation(root, 900, "assembly", [(1, "assembly"), (11, "part")])
    _relation(root, 901, "reference", [(11, "origin"), (90, "referenced")])
    _relation(root, 902, "side", [(12, "assembly"), (10, "inner_part"), (11, "outer_part")])
    path = tmp_path / "cut.rexs"
    tree.write(path, encoding="utf-8", xml_declaration=True)
    return path


def test_two_shafts_joined_by_a_rigid_coupling_solve_as_one(tmp_path, assert_same_loads):
    path = _cut(tmp_path)
    data = read_rexs(path)
    shafts = {s["name"]: s for s in data["shafts"]}
    assert "stub" not in shafts  # read into the input shaft
    assert any("joins shafts" in n and "stub" in n for n in data[REXS_NOTES])
    whole = DrivetrainAnalysis(load_drivetrain_file(GEARBOX)).to_dict()
    cut = DrivetrainAnalysis(load_drivetrain_file(path)).to_dict()
    assert_same_loads(whole["cases"], cut["cases"])


@pytest.mark.parametrize(
    ("kwargs", "needle"), [({"stiffness": "1e+06"}, "flexible coupling"), ({"overlap": True}, "overlap")]
)
def test_a_flexible_or_overlapping_coupling_is_one_line(tmp_path, kwargs, needle):
    with pytest.raises(InputError) as err:
        read_rexs(_cut(tmp_path, **kwargs))
    assert needle in str(err.value) and "\n" not in str(err.value)
