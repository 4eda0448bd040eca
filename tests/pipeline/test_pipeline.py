"""The analysis pipeline: one orchestration, parts computed lazily and once, the same numbers as the parts."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.analysis.friction.components import OperatingPoint, friction_torque
from bearingkit.analysis.rating.assembly import rate
from bearingkit.analysis.solver import quasistatic
from bearingkit.errors import InputError
from bearingkit.io.export import to_json
from bearingkit.io.loader import load_file
from bearingkit.pipeline import FRICTION_MODELS, ModelInput, analyze, register_friction_model

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DGBB = EXAMPLES / "dgbb_6209.toml"
RPM = np.pi / 30.0


def test_top_level_analyze_is_the_pipeline():
    assert bk.analyze is analyze
    with pytest.raises(AttributeError):
        _ = bk.no_such_name


def test_parts_equal_the_engine_called_directly():
    """At a speed whose inertia is negligible the statics are the plain solve; rating and friction equal
    the analysis functions called on it."""
    a = analyze(DGBB, load={"F_x": "5 kN", "F_z": "1 kN"}, speed="10 rpm", lubricant="ISO_VG68")
    bearing = load_file(DGBB).with_cases(list(a.input.cases))
    res = bearing.solve()
    np.testing.assert_array_equal(a.statics.displacement, res.displacement)
    assert any("speed effects negligible" in n for n in a.notes)
    direct = rate(res, speed=10 * RPM)
    np.testing.assert_array_equal(np.ma.getdata(a.rating.life), np.ma.getdata(direct.life))
    fr = friction_torque(res, OperatingPoint(speed_inner=10 * RPM, lubricant="ISO_VG68", temperature=25.0))
    components = a.friction_by("components")
    np.testing.assert_allclose(components.total, fr.total, rtol=1e-14)
    np.testing.assert_allclose(components.power_loss, fr.total * 10 * RPM, rtol=1e-14)


def test_each_part_is_computed_once(monkeypatch):
    calls = []
    real = quasistatic.solve

    def counting(*args, **kwargs):
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(quasistatic, "solve", counting)
    a = analyze(DGBB, speed="1000 rpm", lubricant="ISO_VG68")
    assert calls == []  # nothing computed until asked
    _ = a.statics, a.rating, a.friction, a.warnings, a.to_dict(), a.statics_dict(), a.rating_dict()
    assert len(calls) == 1


def test_per_case_speeds_and_temperatures():
    a = analyze(DGBB, speed=np.array([100.0, 200.0]), temperature=[40.0, 60.0], lubricant="ISO_VG68")
    np.testing.assert_array_equal(a.operating.speed, [100.0, 200.0])
    np.testing.assert_array_equal(a.operating.temperature, [40.0, 60.0])
    one = analyze(DGBB, cases=["radial_4kN"], speed=200.0, temperature=60.0, lubricant="ISO_VG68")
    assert a.friction.total[1] == pytest.approx(one.friction.total[0], rel=1e-14)
    with pytest.raises(InputError, match=r"speed \(3 values\) must give one value per load case \(2\)"):
        analyze(DGBB, speed=[1.0, 2.0, 3.0])


def test_a_model_built_in_code_runs_through_the_same_pipeline():
    bearing = load_file(DGBB)
    load = bearing.load_matrix()
    model_input = ModelInput(bearing.model, load, free=bearing.free, material=bearing.material)
    a = analyze(model_input, speed=500.0, lubricant="ISO_VG68")
    b = analyze(DGBB, speed=500.0, lubricant="ISO_VG68")
    np.testing.assert_array_equal(a.statics.displacement, b.statics.displacement)
    # the file is a catalogue bearing (SKF by default); the model built in code is not: same components
    assert (a.friction.model, b.friction.model) == ("components", "skf")
    np.testing.assert_array_equal(a.friction.total, b.friction_by("components").total)
    assert a.case_names == ["case 0", "case 1"]
    with pytest.raises(InputError, match=r"load \(shape \(2, 4\)\) must be \(cases, 5\)"):
        ModelInput(bearing.model, np.zeros((2, 4)))


def test_friction_models_are_a_registry():
    a = analyze(DGBB, speed="1500 rpm", lubricant="ISO_VG68")
    totals = {m: a.friction_by(m).total[0] for m in ("components", "skf", "palmgren")}
    assert all(t > 0 for t in totals.values())
    with pytest.raises(InputError, match="friction model"):
        a.friction_by("nope")

    def constant(analysis):
        out = FRICTION_MODELS["skf"](analysis)
        out.model = "constant"
        return out

    try:
        register_friction_model("constant", constant)
        assert analyze(DGBB, speed=1.0, lubricant="ISO_VG68", friction_model="constant").friction.model == (
            "constant"
        )
    finally:
        FRICTION_MODELS.pop("constant")


def test_missing_lubricant_is_a_note_not_a_crash():
    a = analyze(DGBB)
    assert a.friction is None
    assert any("lubricant" in n for n in a.notes)
    with pytest.raises(InputError, match="lubricant"):
        a.friction_by("components")


def test_to_dict_is_strict_json_with_units_in_keys(tmp_path):
    a = analyze(DGBB, speed="1000 rpm", lubricant="ISO_VG68", contamination=0.5, temperature="60 degC")
    d = json.loads(to_json(a.to_dict()))
    case = d["cases"][0]
    assert {"operating", "rating", "friction", "warnings", "rows"} <= set(case)
    assert case["friction"]["power_loss_W"] > 0 and case["operating"]["speed_rad_s"] == pytest.approx(
        1000 * RPM
    )
    assert case["rating"]["system"]["Lnmr_rev"] is not None  # a_ISO with e_C, lubricant, T and speed
    frame = a.to_pandas()
    assert list(frame["case"]) == a.case_names and "L10r_rev" in frame and "power_loss_W" in frame
    path = a.report(tmp_path / "a" / "r.html")
    assert path.exists() and "bearingkit report" in path.read_text(encoding="utf-8")


def test_designations_are_inputs():
    a = analyze("6205", load={"Fr": "2 kN"})
    assert a.input.spec.bearing.designation == "6205"
    assert a.statics.converged.all()
