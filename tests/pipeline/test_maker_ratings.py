"""A maker's ratings for the lives: ``[bearing] rating_C`` / ``rating_C0`` (and ``ratings`` of a shaft or
drivetrain bearing), the geometry kept.

ISO 281 rates a bearing with its C: L10 = (C/P)^p, p = 3 balls, 10/3 rollers, so with the same load the
life scales as (C_maker/C)^p. bearingkit starts ISO/TS 16281's raceway ratings from the same C (as for a
catalogue's published C), so that life scales as the rows' life exponent: 3 for ball rows, 4 for line
contact. The statics (pressures, the rows' static safety) do not depend on the rating; ISO 76's
s0 = C0/P0 does, linearly.
"""

from __future__ import annotations

import pytest

import bearingkit as bk
from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict


def _system(header: dict, geometry: dict | None = None) -> dict:
    data = {
        "bearing": header,
        "load_cases": [{"name": "radial", "F_x": "8 kN", "speed": "1500 rpm"}],
        "lubricant": {"name": "ISO_VG68"},
    }
    if geometry is not None:
        data["geometry"] = geometry
    case = bk.analyze(from_dict(data, "ratings.toml")).rating_dict()["cases"][0]
    return case["system"]


def test_a_maker_s_ratings_replace_the_catalogue_s_for_a_designation():
    base = _system({"designation": "NU 208"})
    maker = _system({"designation": "NU 208", "rating_C": "70 kN", "rating_C0": "66 kN"})
    assert base["C_iso281_N"] == 55500.0 and maker["C_iso281_N"] == 70000.0  # NSK E-design row: 55.5 kN
    assert (base["C_source"], maker["C_source"], maker["C0_source"]) == ("catalogue", "rating_C", "rating_C0")
    ratio = 70.0 / 55.5
    assert maker["L10h_iso281_h"] / base["L10h_iso281_h"] == pytest.approx(ratio ** (10 / 3), rel=1e-9)
    assert maker["L10h_h"] / base["L10h_h"] == pytest.approx(ratio**4, rel=1e-9)
    assert maker["s0_iso76"] / base["s0_iso76"] == pytest.approx(66.0 / 55.5, rel=1e-12)
    assert maker["static_safety"] == pytest.approx(base["static_safety"], rel=1e-12)  # geometry kept


def test_a_maker_s_rating_rates_a_bearing_given_by_its_geometry():
    geometry = {
        "bore": "45 mm",
        "outer_diameter": "85 mm",
        "n_elements": 9,
        "element_diameter": "12.7 mm",
        "pitch_diameter": "65 mm",
        "conformity_inner": 0.52,
        "conformity_outer": 0.52,
    }
    own = _system({"type": "deep_groove_ball"}, geometry)
    maker = _system({"type": "deep_groove_ball", "rating_C": "35 kN"}, geometry)
    assert maker["C_iso281_N"] == 35000.0 and own["C_iso281_N"] != 35000.0
    assert (own["C_source"], maker["C_source"]) == ("computed", "rating_C")
    ratio = 35000.0 / own["C_iso281_N"]
    assert maker["L10h_iso281_h"] / own["L10h_iso281_h"] == pytest.approx(ratio**3, rel=1e-9)
    assert maker["L10h_h"] / own["L10h_h"] == pytest.approx(ratio**3, rel=1e-9)


@pytest.mark.parametrize(
    ("header", "needle"),
    [
        ({"designation": "6208", "C": "30 kN", "rating_C": "32 kN"}, "give one of them"),
        ({"designation": "6208", "rating_C0": "20 kN"}, "give it with rating_C"),
    ],
)
def test_contradicting_ratings_are_one_line(header, needle):
    with pytest.raises(InputError) as err:
        from_dict({"bearing": header}, "ratings.toml")
    assert needle in str(err.value) and "\n" not in str(err.value)


def test_a_drivetrain_bearing_s_ratings_reach_its_lives():
    """``ratings`` of a shaft or drivetrain bearing go into its bearing's [bearing] rating_C/rating_C0:
    the two-stage gearbox's NU 208 (input_B, radial only) rated at 70 kN lives (70/55.5)^(10/3) as long
    (ISO 281), the rest unchanged; ratings on a stiffness are one line."""
    import copy
    from pathlib import Path

    from bearingkit.io.reading import load_toml
    from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
    from bearingkit.systems.drivetrain.input import drivetrain_from_dict

    path = Path(__file__).resolve().parents[2] / "examples" / "gearbox_two_stage.toml"
    data = load_toml(path)
    rated = copy.deepcopy(data)
    bearing = next(b for s in rated["shafts"] for b in s["bearings"] if b["name"] == "input_B")
    bearing["ratings"] = {"C": "70 kN"}
    lives = []
    for d in (data, rated):
        res = DrivetrainAnalysis(drivetrain_from_dict(d, str(path), base=path.parent))
        lives.append({n: res.bearing_lives(n)["L10h_iso281_h"][0] for n in res.bearings})
    for name, life in lives[0].items():
        expected = (70.0 / 55.5) ** (10 / 3) if name == "input_B" else 1.0
        assert lives[1][name] / life == pytest.approx(expected, rel=1e-9)
    bearing.pop("designation")
    bearing["stiffness"] = {"radial": "1e9 N/m"}
    with pytest.raises(InputError) as err:
        drivetrain_from_dict(rated, str(path), base=path.parent)
    assert "ratings" in str(err.value) and "\n" not in str(err.value)


def test_a_four_point_row_s_maker_rating_is_radial_and_keeps_the_radial_c0():
    """QJ rows print axial ratings (NSK's C_a, C_0a); bearingkit rates on the radial basis (C_r = 1.07 C_a,
    C_0r = 0.58 C_0a): rating_C is a radial C, and without rating_C0 the catalogue's C0 enters on the same
    radial basis (not its axial figure, which would make s0 1.7x too high)."""
    base = _system({"designation": "QJ 208"})
    maker = _system({"designation": "QJ 208", "rating_C": f"{base['C_iso281_N'] * 1.1} N"})
    assert maker["C0_iso76_N"] == pytest.approx(base["C0_iso76_N"], rel=1e-12)
    assert (maker["C_source"], maker["C0_source"]) == (
        "rating_C",
        "catalogue",
    )  # C0 not given: the catalogue's
    assert maker["s0_iso76"] == pytest.approx(base["s0_iso76"], rel=1e-12)
    assert maker["L10h_iso281_h"] / base["L10h_iso281_h"] == pytest.approx(1.1**3, rel=1e-9)
