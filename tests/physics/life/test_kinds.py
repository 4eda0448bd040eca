"""ISO 76 / ISO 281 factors of the bearing kinds (bearingkit.physics.life.kinds)."""

import numpy as np
import pytest

from bearingkit.physics.life import iso76, iso281, kinds

DEG = np.pi / 180


@pytest.mark.parametrize("gamma", [0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35, 0.40])
def test_f0_definition_reproduces_iso76_table1_radial_column(gamma):
    """C0 = the load of 4200 MPa at the most loaded contact with Q_max = 5 F_r/(Z cos α): with the
    ISO conformities 0.52/0.53 the derivation gives ISO 76 Table 1 (radial column, printed to 0.1 MPa)
    within 1 % — the check that licenses the same derivation for the self-aligning column."""
    f0 = kinds.f0_from_contact_stress(gamma, 0.52, 0.53, 4200e6)
    assert f0 == pytest.approx(float(iso76.f0_radial_ball(gamma)), rel=0.01)


def test_self_aligning_f0_is_the_sphere_contact_at_4600_mpa():
    g = np.array([0.05, 0.1, 0.2, 0.3])
    f0 = kinds.f0_self_aligning_ball(g)
    # the outer sphere is far less conforming than a groove: f0 well below the radial column (less than a
    # third), growing with γ (a smaller sphere per ball); at 4200 MPa it would be (42/46)^3 lower
    assert (f0 < 0.3 * iso76.f0_radial_ball(g)).all() and (np.diff(f0) > 0).all()
    low = kinds.f0_from_contact_stress(g, 0.53, kinds.sphere_conformity(g), 4200e6)
    np.testing.assert_allclose(low / f0, (4200 / 4600) ** 3, rtol=1e-12)


def test_self_aligning_fc_ratio_is_one_for_the_radial_conformities():
    """The derived column uses the column-1 table times a conformity ratio: with the radial bearing's own
    conformities the ratio is 1 (the construction, not a fit), and the sphere lowers f_c."""
    g = np.array([0.05, 0.1, 0.2, 0.3])
    same = iso281.fc_radial_ball(g) * kinds._lp_ball_fc(g, 0.52, 0.53) / kinds._lp_ball_fc(g, 0.52, 0.53)
    np.testing.assert_allclose(same, iso281.fc_radial_ball(g), rtol=1e-14)
    assert (kinds.fc_self_aligning_ball(g) < iso281.fc_radial_ball(g)).all()


def test_four_point_equivalent_loads_use_double_row_angular_factors():
    """QJ 35°: ISO 281 Table 3 double-row angular contact e = 0.95, X/Y = 1/0.66 and 0.6/1.07; ISO 76
    Table 2 Y0 = 0.58 — the values four-point catalogues print (P = F_r + 0.66 F_a …, P0 = F_r + 0.58 F_a)."""
    fr = 1000.0
    p_low, _ = kinds.equivalent_loads("four_point", fr, 0.9 * fr, 35 * DEG)
    p_high, p0_high = kinds.equivalent_loads("four_point", fr, 2.0 * fr, 35 * DEG)
    assert p_low == pytest.approx(fr + 0.66 * 0.9 * fr, rel=1e-12)
    assert p_high == pytest.approx(0.60 * fr + 1.07 * 2.0 * fr, rel=1e-12)
    assert p0_high == pytest.approx(fr + 0.58 * 2.0 * fr, rel=1e-12)


def test_spherical_roller_and_self_aligning_equivalent_loads():
    """Double-row radial roller (ISO 281 7.2: e = 1.5 tan α, Y = 0.45 cot α / X = 0.67, Y = 0.67 cot α;
    ISO 76 7.2: Y0 = 0.44 cot α) and self-aligning ball (0.42 cot α / 0.65, 0.65 cot α) laws."""
    a = 10 * DEG
    cot = 1 / np.tan(a)
    fr = 1000.0
    p, p0 = kinds.equivalent_loads("spherical_roller", fr, 0.2 * fr, a)
    assert p == pytest.approx(fr + 0.45 * cot * 0.2 * fr) and p0 == pytest.approx(fr + 0.44 * cot * 0.2 * fr)
    p, _ = kinds.equivalent_loads("spherical_roller", fr, 0.5 * fr, a)
    assert p == pytest.approx(0.67 * fr + 0.67 * cot * 0.5 * fr)
    p, _ = kinds.equivalent_loads("self_aligning_ball", fr, 0.1 * fr, a)
    assert p == pytest.approx(fr + 0.42 * cot * 0.1 * fr)
    p, p0 = kinds.equivalent_loads("needle", fr, 0.0, 0.0)
    assert p == fr and p0 == fr
