"""Seed 004 studies: Table 4/5 sweeps (trends), Table 3 ordering, Table 6 data."""

import numpy as np
import pytest

from bearingkit.analysis.ptrb_friction import ptrb_objectives
from bearingkit.studies import seed004 as s

# Table 5 directions (sign of M(high) − M(low)) that bearingkit reproduces / does not (7 of 10 with
# Harris's viscous rolling resistance; n_teeth under axial load joined with it).
REPRODUCED = [
    ("roller_contact_radius", "axial", +1),
    ("roller_contact_radius", "radial", +1),
    ("n_elements", "axial", -1),
    ("n_elements", "radial", -1),
    ("contact_angle", "radial", +1),
    ("n_teeth", "axial", +1),
    ("n_teeth", "radial", -1),
]
NOT_REPRODUCED = [
    ("contact_angle", "axial", +1),
    ("roller_pitch_diameter", "axial", +1),
    ("roller_pitch_diameter", "radial", +1),
]


def _direction(parameter, case):
    """Sign of M(high) − M(low) over the §5 range (endpoints: with Z the radial share of the roller
    under the load alternates between odd and even Z, so only the endpoints are compared)."""
    _, _, lo, hi = s.SWEEP_PARAMETERS[parameter]
    m = s.table5_sweep(parameter, [lo, hi])[f"M_{case}_Nm"].to_numpy()
    return np.sign(np.diff(m)), m


@pytest.mark.parametrize("parameter,case,sign", REPRODUCED)
def test_table5_trends(parameter, case, sign):
    steps, _ = _direction(parameter, case)
    assert np.all(steps == sign)


@pytest.mark.parametrize("parameter,case,sign", NOT_REPRODUCED)
def test_table5_trends_not_reproduced_are_opposite(parameter, case, sign):
    """Known deviation (stated in bearingkit.validation.seed004_friction): the power-balance torque
    moves against the paper's direction here. Pinned so a model change that flips it is noticed."""
    steps, _ = _direction(parameter, case)
    assert np.all(steps == -sign)


@pytest.mark.parametrize("parameter", list(s.SWEEP_PARAMETERS))
def test_table4_ratings_increase_with_every_parameter(parameter):
    df = s.table4_sweep(parameter)
    for col in ("C0a_N", "C0r_N", "Ca_N", "Cr_N"):
        assert np.all(np.diff(df[col].to_numpy()) > 0), col


def test_table3_orderings_stated_by_the_paper():
    df = s.table3_comparison().set_index(["bearing", "direction"])
    p_ax = df.loc[("PTRB prototype", "axial")]
    p_ra = df.loc[("PTRB prototype", "radial")]

    def row(prefix):
        return df[df.index.get_level_values(0).str.startswith(prefix)].iloc[0]

    for col0, col in (("C0_catalogue_N", "C_catalogue_N"), ("C0_iso_N", "C_iso_N")):
        # (1) axial-only bearings: Ca above the single thrust ball, below the roller thrust; C0a below all
        assert p_ax[col] > row("single-direction thrust ball")[col]
        assert p_ax[col] < row("cylindrical roller thrust")[col]
        for name in ("single-direction thrust", "double-direction thrust", "cylindrical roller thrust"):
            assert p_ax[col0] < row(name)[col0]
        # (2) radial-only bearings: Cr and C0r above deep groove and cylindrical roller
        for name in ("deep-groove", "cylindrical roller (SKF NU"):
            assert p_ra[col] > row(name)[col] and p_ra[col0] > row(name)[col0]
        # (3) angular contact ball bearings: C above both; C0 (the larger of C0a, C0r) above both
        for name in ("single-row angular", "double-row angular"):
            assert p_ra[col] > row(name)[col] and max(p_ax[col0], p_ra[col0]) > row(name)[col0]
        # (4) tapered roller bearings are above the PTRB
        for name in ("single-row tapered roller (SKF 30206", "single-row tapered roller (SKF 33206"):
            assert row(name)[col] > p_ra[col] and row(name)[col0] > p_ra[col0]


def test_table3_iso_recomputation_is_close_to_the_catalogue():
    df = s.table3_comparison()
    std = df[df.bearing != "PTRB prototype"]
    r = np.concatenate([std.C_iso_N / std.C_catalogue_N, std.C0_iso_N / std.C0_catalogue_N])
    assert np.all((r > 0.6) & (r < 1.35))


def test_table6_data_and_nearest_solution():
    assert set(s.TABLE6) == set(s.TABLE6_OBJECTIVES)
    for k, x in s.TABLE6.items():
        if k != "prototype":
            # the threads fit in the 18 mm width (Table 6 does NOT hold n·P = 12 mm: xa2 has 10.45 mm)
            assert 10.0 < x["n"] * x["P_mm"] <= 18.0
    pts = [s.TABLE6[k] for k in ("xa1", "xa2")]
    o = ptrb_objectives(
        np.radians([p["alpha_deg"] for p in pts]),
        [p["n"] for p in pts],
        [p["R_rr_mm"] * 1e-3 for p in pts],
        [p["d_R_mm"] * 1e-3 for p in pts],
        "axial",
    )
    near = s.nearest_table6(o, "axial")
    assert list(near.point) == ["xa1", "xa2"]
    # xa2 is nearest to itself; the optimum has about twice the prototype's ratings (§6)
    assert near.loc[near.point == "xa2", "index"].item() == 1
    assert o["C0a"][0] > 2.0 * 38.36e3 and o["Ca"][0] > 2.0 * 33.20e3


def test_table6_mu_at_the_published_designs():
    """μ of the friction model at the published optimum designs (20 kN, 4000 rpm): the axial points
    within 12 %, the radial ones within 35 % (α acts too strongly under radial load, see Table 5)."""
    t = s.table6_at_published_designs().set_index("point")
    assert np.all(np.abs(t["mu_a_err"]) < 0.12)
    assert np.all(np.abs(t["mu_r_err"]) < 0.35)
    # the prototype's own μ (Table 6: 2.3e-3 and 3.0e-3) is close
    assert t.loc["prototype", "mu_a"] == pytest.approx(2.3e-3, rel=0.03)
    assert t.loc["prototype", "mu_r"] == pytest.approx(3.0e-3, rel=0.08)
    # the §6 orderings the paper draws from Table 6: xa1 costs more axial friction than xa2, and so on
    assert t.loc["xa1", "mu_a"] > t.loc["xa2", "mu_a"]
    assert t.loc["xr1", "mu_r"] > t.loc["xr2", "mu_r"]
