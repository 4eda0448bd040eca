"""The public FVA planetary stage (examples/rexs/FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj, REXS 1.1
JSON by FVA Workbench 5.5) read as a planetary stage and solved.

The stage: sun z_s = 17 on its own shaft, three planets z_p = 22 on pins of a two-plate carrier, ring
z_r = 61 held in the casing, m_n = 4 mm, α_n = 20°, spur, no profile shift, 1591.55 N·m (250 kW at
1500 rpm) into the sun, the carrier the output; every bearing a rigid concept bearing. No tool's results
travel with the file, so the checks are the closed forms of such a stage (rigid supports, equal
planets, no gravity): each planet's bearings carry F = T_s / (N r_w,s) together twice over (the sun's and
the ring's tangential forces push the planet the same way; their radial parts cancel), r_w,s =
a_w z_s / (z_s + z_p); the carrier turns at n_s z_s / (z_s + z_r) and holds T_s (1 + z_r / z_s); and the
same stage written by hand as a drivetrain TOML (beside the REXS file) solves to the same loads.
"""

from __future__ import annotations

import copy
import json
import random
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import drivetrain_from_dict, load_drivetrain_file
from bearingkit.systems.drivetrain.model import HOUSING

PUBLIC = Path(__file__).resolve().parents[2] / "examples" / "rexs"
PLANETARY = PUBLIC / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj"
TWIN = PUBLIC / "FVA_Planetary_stage_as_drivetrain.toml"
T_SUN = 1591.5494309189535  # N·m, the file's torque_around_u_axis on the sun shaft
Z_S, Z_P, Z_R, N_PLANETS, A_W = 17, 22, 61, 3, 0.078  # the file's teeth, planets, centre distance [m]


def _solve(data):
    return DrivetrainAnalysis(drivetrain_from_dict(data, str(PLANETARY), base=PUBLIC))


def test_the_stage_reads_as_a_sun_three_planets_a_held_ring_and_a_carrier():
    data = read_rexs(PLANETARY)
    notes = data.pop(REXS_NOTES)
    (stage,) = data["planetary"]
    assert (stage["sun"], stage["carrier"], stage["planets"]) == ("Sonnenrad [53]", "Steg 1 [4]", 3)
    assert (stage["planet"]["teeth"], stage["ring_teeth"]) == (Z_P, Z_R)
    assert (
        stage["first_planet_angle"] == "0.0 deg"
    )  # stages at 0°, 120°, 240° about −u: planets at 0, 240, 120
    # the planet bearings sit ±12.5 mm from the planet's mid-plane, in the planet and on the pin alike
    assert [b["position"] for b in stage["planet_bearings"]] == ["-12.5 mm", "12.5 mm"]
    # placed by the couplings (pin 4 mm ↔ plate 4 mm, carrier 96 mm ↔ plate 4 mm) and the meshes
    assert stage["carrier_position"] == "125.0 mm"
    shafts = {s["name"]: s for s in data["shafts"]}
    assert sorted(shafts) == ["Sonnenwelle [34]", "Steg 1 [4]"]  # planets, pins, ring, web: the stage's
    assert (
        shafts["Steg 1 [4]"]["axial_offset"] == "-100.0 mm"
        and shafts["Sonnenwelle [34]"]["axial_offset"] == "0.0 mm"
    )
    ends = [
        float(s["start"].split()[0]) + float(s["length"].split()[0]) for s in shafts["Steg 1 [4]"]["sections"]
    ]
    assert ends == [100.0, 150.0, 158.0]  # the carrier shaft, the web (Shaft [260]), the far side plate
    assert data["drivetrain"] == {"name": "Gear unit [1]", "held": "Steg 1 [4]", "gravity": "+x"}
    said = " ".join(notes)
    for words in ("is_engaged false", "Steg 2 [6]", "extended to", "read as rigid", "no load_spectrum"):
        assert words in said


def test_the_stage_solves_to_the_closed_form_without_gravity():
    data = read_rexs(PLANETARY)
    data.pop(REXS_NOTES)
    data["drivetrain"].pop("gravity")
    da = _solve(data)
    case = da.to_dict()["cases"][0]
    assert case["converged"]
    r_ws = A_W * Z_S / (Z_S + Z_P)  # 34 mm
    f_t = T_SUN / (N_PLANETS * r_ws)  # 15 603.43 N
    planet = [b for b in case["bearings"] if ".planet" in b["name"]]
    assert len(planet) == 6
    for b in planet:  # each of a planet's two bearings takes one F_t: 2 F_t per planet
        assert b["radial_load_N"] == pytest.approx(f_t, rel=1e-9)
    for b in case["bearings"]:
        if ".planet" not in b["name"]:  # the sun and carrier float between balanced planets
            assert b["radial_load_N"] < 1e-6 * f_t
    assert case["held_torque_Nm"] == pytest.approx(-T_SUN * (1 + Z_R / Z_S), rel=1e-9)
    omega = da.omega
    n_sun = 1500.0 * 2 * np.pi / 60
    assert omega["Steg 1 [4]"] == pytest.approx(n_sun * Z_S / (Z_S + Z_R), rel=1e-12)
    n_c = n_sun * Z_S / (Z_S + Z_R)
    for k in (1, 2, 3):  # ω_p = ω_c − (ω_s − ω_c) z_s / z_p
        assert omega[f"Planetenstufe [9].planet{k}"] == pytest.approx(
            n_c - (n_sun - n_c) * Z_S / Z_P, rel=1e-12
        )


def test_with_the_file_s_gravity_the_housing_carries_the_stage_s_weight():
    """Gravity along +v (the file's direction_vector_gravity) is bearingkit's +x: the casing's bearings and
    the held ring push back −x with the weight of every body (sections × steel density, 92.2 N)."""
    da = DrivetrainAnalysis(load_drivetrain_file(PLANETARY))
    res = da.result
    assert res.equilibrium_residual()[0] < 1e-9
    dt = res.drivetrain
    force = np.zeros(3)
    for b in dt.bearings:
        if b.outer.body == HOUSING:
            force += res.reaction(b.name)[0, :3]
    for m in dt.meshes:
        if m.b[0] == HOUSING:  # the ring gear held in the casing, on each planet
            force += res.mesh_vector(m.name, "a")[0]
    weight = sum(
        7850.0 * np.pi / 4 * (s.outer_diameter**2 - s.inner_diameter**2) * (s.end - s.start) * 9.80665
        for shaft in dt.shafts
        for s in shaft.shaft.sections
    )
    assert weight == pytest.approx(92.2, abs=0.05)
    assert force == pytest.approx([-weight, 0.0, 0.0], abs=1e-9 * weight)


def test_the_stage_written_as_a_drivetrain_toml_solves_to_the_same_loads():
    from_rexs = DrivetrainAnalysis(load_drivetrain_file(PLANETARY)).to_dict()["cases"][0]
    from_toml = DrivetrainAnalysis(load_drivetrain_file(TWIN)).to_dict()["cases"][0]
    assert [b["name"] for b in from_rexs["bearings"]] == [b["name"] for b in from_toml["bearings"]]
    scale = max(b["radial_load_N"] for b in from_rexs["bearings"])
    for a, b in zip(from_rexs["bearings"], from_toml["bearings"], strict=True):
        assert b["radial_load_N"] == pytest.approx(a["radial_load_N"], abs=1e-9 * scale)
        assert b["axial_load_N"] == pytest.approx(a["axial_load_N"], abs=1e-9 * scale)
    assert from_toml["held_torque_Nm"] == pytest.approx(from_rexs["held_torque_Nm"], rel=1e-12)


def _model():
    return json.loads(PLANETARY.read_text(encoding="utf-8-sig"))


def _component(model, cid):
    return next(c for c in model["model"]["components"] if c["id"] == cid)


def _attribute(component, key):
    return next(a for a in component["attributes"] if a["id"] == key)


def _refused(model, tmp_path) -> str:
    path = tmp_path / "bad.rexsj"
    path.write_text(json.dumps(model), encoding="utf-8")
    with pytest.raises(InputError) as err:
        read_rexs(path)
    line = str(err.value)
    assert "\n" not in line
    return line


def test_a_planet_unlike_the_others_is_refused_in_one_line(tmp_path):
    model = _model()
    _attribute(_component(model, 248), "number_of_teeth")["floating_point"] = 23.0
    assert "planets differ" in _refused(model, tmp_path)


def test_a_planet_of_another_module_is_refused_in_one_line(tmp_path):
    model = _model()
    for cid in (247, 248, 249):
        _attribute(_component(model, cid), "normal_module")["floating_point"] = 5.0
    assert "mismatched modules" in _refused(model, tmp_path)


def test_a_ring_turning_in_bearings_is_refused_in_one_line(tmp_path):
    model = _model()
    _component(model, 65)["type"] = "concept_bearing"  # the ring shaft's coupling to the casing → a bearing
    line = _refused(model, tmp_path)
    assert "Hohlradwelle [62]" in line and "[[planetary]] ring" in line


def test_a_load_on_a_planet_is_refused_in_one_line(tmp_path):
    model = _model()
    model["model"]["components"].append(
        {"id": 900, "type": "external_load", "name": "on a planet", "attributes": []}
    )
    model["model"]["relations"].append(
        {
            "id": 900,
            "type": "assembly",
            "refs": [{"id": 229, "role": "assembly"}, {"id": 900, "role": "part"}],
        }
    )
    line = _refused(model, tmp_path)
    assert "external_load 900" in line and "planet" in line


def test_mutated_planetary_models_load_or_are_refused_in_one_line(tmp_path, escape_of):
    """40 mutants of the JSON model (a dropped or retyped attribute value, a foreign unit, a removed or
    retyped component, a removed relation, a relation pointing elsewhere, a role renamed or a reference
    dropped): each builds a drivetrain or is refused with one InputError line (before the readers checked
    them: a missing tooth count, a sun retyped, and every relation missing a role raised KeyError)."""
    rng = random.Random(20261129)
    base = _model()
    escaped = []
    for i in range(60):
        model = copy.deepcopy(base)
        m = model["model"]
        kind = rng.choice(["drop", "value", "unit", "component", "relation", "ref", "type", "role", "unref"])
        if kind in ("drop", "value", "unit"):
            c = rng.choice([c for c in m["components"] if c.get("attributes")])
            a = rng.choice(c["attributes"])
            if kind == "drop":
                c["attributes"].remove(a)
            elif kind == "value":
                key = next(k for k in a if k not in ("id", "unit"))
                a[key] = rng.choice(["abc", -1, 1e300, None, True, False, [1, 2], 0, 7])
            else:
                a["unit"] = rng.choice(["foo", "mm", "N", "", "kN", "deg"])
        elif kind == "component":
            m["components"].remove(rng.choice(m["components"]))
        elif kind == "relation":
            m["relations"].remove(rng.choice(m["relations"]))
        elif kind == "ref":
            rng.choice(rng.choice(m["relations"])["refs"])["id"] = rng.choice(m["components"])["id"]
        elif kind == "role":  # a role renamed: the relation misses one it needs
            rng.choice(rng.choice(m["relations"])["refs"])["role"] = rng.choice(["part", "inner_part", "x"])
        elif kind == "unref":  # a reference dropped
            relation = rng.choice(m["relations"])
            relation["refs"].remove(rng.choice(relation["refs"]))
        else:
            rng.choice(m["components"])["type"] = rng.choice(
                ["shaft", "coupling", "concept_bearing", "side_plate", "cylindrical_gear", "ring_gear"]
            )
        path = tmp_path / f"mutant{i}.rexsj"
        path.write_text(json.dumps(model), encoding="utf-8")
        if (escape := escape_of(path)) is not None:
            escaped.append((i, kind, *escape))
    assert escaped == []


def test_the_results_model_puts_each_planet_bearing_s_results_on_its_own_rexs_component(tmp_path):
    """REXS has one component per planet bearing (FVA names the copies "… @ angle"); bearingkit's stage
    names them per planet: the export writes each result on the component of its planet, none new."""
    from bearingkit.io.rexs.export import write_rexs_results

    data = DrivetrainAnalysis(load_drivetrain_file(PLANETARY)).to_dict()
    path = write_rexs_results(data, tmp_path / "results.rexsj", source=PLANETARY)
    model = json.loads(path.read_text(encoding="utf-8-sig"))["model"]
    assert len(model["components"]) == len(_model()["model"]["components"])  # no component added
    (case,) = model["load_spectrum"]["load_cases"]
    force = {
        c["id"]: _attribute(c, "custom_bearingkit_radial_force")["floating_point"]
        for c in case["components"]
        if any(a["id"] == "custom_bearingkit_radial_force" for a in c["attributes"])
    }
    # planets at 0°, 120°, 240° (about +u) are REXS planets 229, 231, 230: bearings 232/244, 234/246, 233/245
    by_name = {b["name"]: b["radial_load_N"] for b in data["cases"][0]["bearings"]}
    for k, (first, second) in enumerate(((232, 244), (234, 246), (233, 245)), start=1):
        assert force[first] == by_name[f"Planetenstufe [9].planet{k}.Planetenlager [44]"]
        assert force[second] == by_name[f"Planetenstufe [9].planet{k}.Planetenlager [45]"]
    assert len(force) == 10  # six planet bearings, two sun and two carrier bearings


@pytest.mark.parametrize("name", ["gearbox_two_stage.rexs", "rexs/SEW_3-stage_cylindrical_gearbox_1.0.rexs"])
def test_bodies_with_support_vectors_keep_their_place_along_the_shaft_axis(name):
    """The placement seeds every body with a support_vector with its component along the shafts' axis
    (u = z in the two-stage gearbox, not the vector's first component), and meshes of ordinary stages,
    whose mid-planes may differ, place nothing: neither model is refused, every shaft keeps support · u."""
    from bearingkit.io.rexs.parse import parse
    from bearingkit.io.rexs.parts import vector_mm
    from bearingkit.io.rexs.planetary import axial_offsets, shaft_axis

    path = PUBLIC.parent / name
    m = parse(path)
    shafts = [i for i, c in m["components"].items() if c["type"] == "shaft"]
    offsets = axial_offsets(m, str(path), shafts[0], mesh_gears=set())
    u = shaft_axis(m, str(path), shafts[0])
    for i in shafts:
        assert offsets[i] == pytest.approx(
            float(vector_mm(m["components"][i]["attrs"], "support_vector", "") @ u)
        )
