"""SKF and Palmgren friction of the bearing kinds of issue 17: spherical roller, self-aligning ball, needle.

Every expected value is the catalogue formula written out by hand in the catalogue's own units (N·mm, mm,
r/min, mm²/s) with the constants typed in from the sources (SKF Table 2a forms; SKF geometry constants as
transcribed publicly; Schaeffler's Palmgren factors), not read back from bearingkit's tables. Agreement to
1e-12 therefore checks the SI boundary, the table rows and the laws at once.
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.analysis.friction import engineering as ef
from bearingkit.errors import InputError
from bearingkit.physics.friction import palmgren, skf

RPM = 2.0 * np.pi / 60.0
MU_BL, MU_EHL_MINERAL, K_RS_OIL = 0.15, 0.05, 3e-8  # SKF 2018 "Friction" (verified constants)


def _skf_reductions(n, nu, d, big_d, k_z):
    dm = 0.5 * (d + big_d)
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = np.exp(-K_RS_OIL * nu * n * (d + big_d) * np.sqrt(k_z / (2.0 * (big_d - d))))
    phi_bl = np.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * MU_BL + (1.0 - phi_bl) * MU_EHL_MINERAL
    return dm, phi_ish * phi_rs, mu_sl


@pytest.mark.parametrize(
    ("fr", "fa"),
    [(60e3, 15e3), (2e3, 20e3), (200e3, 0.0), (500e3, 0.0)],  # e- and l-laws each the smaller somewhere
)
def test_skf_spherical_roller_222e_by_hand(fr, fa):
    """22220 E (d 100, D 180 mm), series 213 E / 222 E: R1..R4, S1..S4 = 1.6e-6, 5.84, 2.81e-6, 5.8,
    3.62e-3, 508, 8.8e-3, 117; K_Z = 5.5; G = min(G_e, G_l) (SKF Table 2a)."""
    n, nu, d, big_d = 1000.0, 20.0, 100.0, 180.0
    dm, phi, mu_sl = _skf_reductions(n, nu, d, big_d, 5.5)
    g_rr = min(1.6e-6 * dm**1.85 * (fr + 5.84 * fa) ** 0.54, 2.81e-6 * dm**2.3 * (fr + 5.8 * fa) ** 0.31)
    g_sl = min(
        3.62e-3 * dm**0.25 * (fr**4 + 508 * fa**4) ** (1 / 3),
        8.8e-3 * dm**0.94 * (fr**3 + 117 * fa**3) ** (1 / 3),
    )
    expected = (phi * g_rr * (nu * n) ** 0.6 + g_sl * mu_sl) * 1e-3  # N·mm → N·m
    out = skf.skf_friction_moment(
        "spherical_roller",
        bore_diameter=0.1,
        outside_diameter=0.18,
        speed=n * RPM,
        kinematic_viscosity=nu * 1e-6,
        load_radial=fr,
        load_axial=fa,
        series="222E",
    )
    assert float(out["total_Nm"]) == pytest.approx(expected, rel=1e-12)
    assert float(out["G_rr"]) == pytest.approx(g_rr, rel=1e-12)
    assert float(out["G_sl"]) == pytest.approx(g_sl, rel=1e-12)


def test_skf_spherical_roller_takes_each_branch():
    """The case table above is not vacuous: both laws switch between their e- and l-forms."""
    dm = 140.0
    rr_e = lambda fr, fa: 1.6e-6 * dm**1.85 * (fr + 5.84 * fa) ** 0.54  # noqa: E731
    rr_l = lambda fr, fa: 2.81e-6 * dm**2.3 * (fr + 5.8 * fa) ** 0.31  # noqa: E731
    sl_e = lambda fr, fa: 3.62e-3 * dm**0.25 * (fr**4 + 508 * fa**4) ** (1 / 3)  # noqa: E731
    sl_l = lambda fr, fa: 8.8e-3 * dm**0.94 * (fr**3 + 117 * fa**3) ** (1 / 3)  # noqa: E731
    assert rr_e(60e3, 15e3) < rr_l(60e3, 15e3) and rr_e(200e3, 0.0) > rr_l(200e3, 0.0)
    assert sl_e(60e3, 15e3) < sl_l(60e3, 15e3) and sl_e(500e3, 0.0) > sl_l(500e3, 0.0)


def test_skf_self_aligning_ball_series_12_by_hand():
    """1209 (d 45, D 85 mm) at 3000 r/min, series 12: R1, R2, R3 = 3.25e-7, 6.51, 2.43e-12; S1, S2, S3 =
    4.36e-3, 9.33, 2.43e-12; K_Z = 4.8; F_g = R3 d_m^3.5 n² (SKF Table 2a)."""
    n, nu, d, big_d, fr, fa = 3000.0, 30.0, 45.0, 85.0, 3000.0, 600.0
    dm, phi, mu_sl = _skf_reductions(n, nu, d, big_d, 4.8)
    fg = 2.43e-12 * dm**3.5 * n**2
    assert fg > 10.0  # the speed term is not negligible here (~48 N)
    g_rr = 3.25e-7 * dm**2 * (fr + fg + 6.51 * fa) ** 0.54
    g_sl = 4.36e-3 * dm**-0.12 * ((fr + fg) ** (4 / 3) + 9.33 * fa ** (4 / 3))
    expected = (phi * g_rr * (nu * n) ** 0.6 + g_sl * mu_sl) * 1e-3
    out = skf.skf_friction_moment(
        "self_aligning_ball",
        bore_diameter=0.045,
        outside_diameter=0.085,
        speed=n * RPM,
        kinematic_viscosity=nu * 1e-6,
        load_radial=fr,
        load_axial=fa,
        series="12",
    )
    assert float(out["total_Nm"]) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(("fa", "branch"), [(10e3, "low"), (30e3, "high")])
def test_palmgren_spherical_roller_by_hand(fa, branch):
    """f0 = 6 (oil bath), f1 = 0.0006, P1 = 1.6 F_a/e or F_r [1 + 0.6 (F_a/(e F_r))³], e = 1.5 tan α."""
    n, nu, dm, fr, alpha = 1000.0, 20.0, 140.0, 60e3, np.radians(10.0)
    e = 1.5 * np.tan(alpha)
    assert (fa / fr > e) == (branch == "high")
    p1 = 1.6 * fa / e if fa / fr > e else fr * (1 + 0.6 * (fa / (e * fr)) ** 3)
    expected = (1e-7 * 6.0 * (nu * n) ** (2 / 3) * dm**3 + 0.0006 * p1 * dm) * 1e-3
    out = palmgren.palmgren_friction_moment(
        "spherical_roller",
        pitch_diameter=dm * 1e-3,
        speed=n * RPM,
        kinematic_viscosity=nu * 1e-6,
        load_radial=fr,
        load_axial=fa,
        contact_angle=alpha,
    )
    assert float(out["total_Nm"]) == pytest.approx(expected, rel=1e-12)
    assert float(out["P1_N"]) == pytest.approx(p1, rel=1e-12)


def test_palmgren_spherical_p1_is_continuous_at_e():
    alpha = np.radians(12.0)
    e = 1.5 * np.tan(alpha)
    p1 = palmgren.P1_LAWS["spherical"]
    below, above = p1(1e4, e * 1e4 * (1 - 1e-12), alpha), p1(1e4, e * 1e4 * (1 + 1e-12), alpha)
    assert float(below) == pytest.approx(1.6e4, rel=1e-9) and float(above) == pytest.approx(1.6e4, rel=1e-9)


@pytest.mark.parametrize(("lubrication", "f0"), [("grease", 12.0), ("oil_bath", 12.0), ("oil_jet", 24.0)])
def test_palmgren_needle_by_hand(lubrication, f0):
    """f0 = 12 / 12 / 24, f1 = 0.002, P1 = F_r; both branches of M0 (ν n above and below 2000)."""
    dm, fr = 61.0, 10e3
    for n, nu in ((2000.0, 20.0), (50.0, 20.0)):
        m0 = 1e-7 * f0 * (nu * n) ** (2 / 3) * dm**3 if nu * n >= 2000 else 160e-7 * f0 * dm**3
        expected = (m0 + 0.002 * fr * dm) * 1e-3
        out = palmgren.palmgren_friction_moment(
            "needle_roller",
            pitch_diameter=dm * 1e-3,
            speed=n * RPM,
            kinematic_viscosity=nu * 1e-6,
            load_radial=fr,
            lubrication=lubrication,
        )
        assert float(out["total_Nm"]) == pytest.approx(expected, rel=1e-12)


def test_models_refuse_kinds_without_sourced_constants_in_one_line():
    with pytest.raises(InputError) as skf_exc:
        skf.skf_friction_moment(
            "needle_roller", bore_diameter=0.05, outside_diameter=0.072, speed=100.0, kinematic_viscosity=2e-5
        )
    msg = str(skf_exc.value)
    assert "\n" not in msg and "needle_roller" in msg and "no G_rr/G_sl law and no R/S constants" in msg
    with pytest.raises(InputError) as pg_exc:
        palmgren.palmgren_friction_moment(
            "self_aligning_ball", pitch_diameter=0.065, speed=100.0, kinematic_viscosity=2e-5
        )
    msg = str(pg_exc.value)
    assert "\n" not in msg and "self_aligning_ball" in msg
    assert all(k in msg for k in ("f0", "(z, y)", "P1"))  # names the missing constants
    with pytest.raises(InputError, match="palmgren model refused"):
        ef.engineering_friction_moment(
            "palmgren", "self_aligning_ball", pitch_diameter=0.065, speed=100.0, kinematic_viscosity=2e-5
        )
