"""L10r / L10 at the reference condition for every kind (docs/ratings.md table; issue #40 item 3).

Zero clearance, no tilt, pure radial load (radial bearings; a single tapered or angular contact bearing is
then held at u_z) or centric axial load (thrust bearings), catalogue geometry estimate and C, P = 0.1 C
and 0.3 C. Independent checks: the ball ratios lie in 0.8-1.25 (the TS's ball constants are ISO 281's
load zone); a thrust ball bearing under centric load gives ISO 281 exactly (every ball carries F_a/Z);
the roller method factor is the closed form λν^-4 (C/P)^(2/3) (hand-computed below); the cylindrical and
needle ratios equal the independent TS implementation (ts16281_roller_reference.py) on the same geometry;
every roller's load distribution can only shorten its life against the ideal one (the TS profile makes
the slice loads uneven, the life exponent 9/2 > 1 and f_k >= 1), so its distribution factor is < 1.
"""

from __future__ import annotations

import numpy as np
import pytest
import ts16281_roller_reference as ref

import bearingkit as bk
from bearingkit.catalogue import resolve

#: (kind, designation, load direction)
BALLS = [
    ("deep groove", "6208", "radial"),
    ("angular contact, u_z held", "7208 B", "radial"),
    ("four-point", "QJ 208", "radial"),
    ("self-aligning", "1208", "radial"),
    ("thrust", "51208", "axial"),
]
ROLLERS = [
    ("cylindrical", "NU 208", "radial", 0.83),
    ("needle", "NA 4908", "radial", 0.83),
    ("tapered, u_z held", "30208", "radial", 0.83),
    ("tapered, pure axial", "30208", "tapered_axial", 0.83),
    ("spherical", "22208 E", "radial", 0.83),
    ("cylindrical thrust", "81212", "axial", 0.73),
]
#: λν^-4 (C/P)^(2/3) by hand: 0.83^-4 = 2.1071, 0.73^-4 = 3.5214; 10^(2/3) = 4.6416, (1/0.3)^(2/3) = 2.2314.
METHOD = {(0.83, 0.1): 9.780, (0.83, 0.3): 4.702, (0.73, 0.1): 16.34, (0.73, 0.3): 7.858}


def _analysis(designation, how, share, geometry=None):
    spec = {"bearing": {"designation": designation}, "geometry": dict(geometry or {})}
    if "clearance_radial" in resolve(designation).geometry:  # the others have zero clearance already
        spec["geometry"]["clearance_radial"] = "0 um"
    first = bk.analyze(spec, load={"F_z": "1 kN"} if how != "radial" else {"F_x": "1 kN"})
    c = first.rating.iso281.load_rating
    if how == "radial":
        load = {"F_x": f"{share * c} N"}
    elif how == "axial":
        load = {"F_z": f"{share * c} N"}
    else:  # a radial bearing under pure axial load: P = Y F_a, Y = 0.4 cot α (ISO 281 7.2)
        y = 0.4 / np.tan(float(first.input.model.rows[0].contact_angle_outer))
        load = {"F_z": f"{share * c / y} N"}
    a = bk.analyze(spec, load=load)
    assert a.statics.converged.all()
    assert float(a.rating.iso281.load[0]) == pytest.approx(share * c, rel=1e-9)
    return a, c


@pytest.mark.parametrize("share", [0.1, 0.3])
@pytest.mark.parametrize(("kind", "designation", "how"), BALLS, ids=[b[0] for b in BALLS])
def test_ball_ratios_lie_within_the_band(kind, designation, how, share):
    a, _ = _analysis(designation, how, share)
    cmp = a.rating.comparison[0]
    assert 0.8 <= cmp["ratio"] <= 1.25
    assert cmp["method_factor"] == 1.0
    if kind == "thrust":
        assert cmp["ratio"] == pytest.approx(1.0, rel=1e-9)


@pytest.mark.parametrize("share", [0.1, 0.3])
@pytest.mark.parametrize(("kind", "designation", "how", "lam"), ROLLERS, ids=[r[0] for r in ROLLERS])
def test_roller_ratio_is_the_ts_method_times_a_shortening_distribution(kind, designation, how, lam, share):
    a, _ = _analysis(designation, how, share)
    cmp = a.rating.comparison[0]
    assert cmp["method_factor"] == pytest.approx(METHOD[(lam, share)], rel=5e-4)
    assert 0.2 < cmp["distribution_factor"] < 1.0
    assert cmp["ratio"] == pytest.approx(cmp["method_factor"] * cmp["distribution_factor"], rel=1e-12)
    assert cmp["ratio"] > 1.25  # outside the band: said, with its cause, in docs/ratings.md
    assert "from the TS's line-contact life exponent 4" in a.rating.to_dict(0)["system"]["life_difference"]


@pytest.mark.parametrize("share", [0.1, 0.3])
@pytest.mark.parametrize("designation", ["NU 208", "NA 4908"])
def test_cylindrical_and_needle_ratios_equal_the_independent_implementation(designation, share):
    """The TS line law at the TS's steel (E = 210 GPa) so that both slice models are the TS's: the ratio
    equals the independent implementation within 0.1 % (its slice loads solve the same equations)."""
    steel = {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3, "density": "7850 kg/m^3"}
    c = bk.analyze(designation, load={"F_x": "1 kN"}).rating.iso281.load_rating
    spec = {
        "bearing": {"designation": designation},
        "geometry": {"clearance_radial": "0 um", "line_law": "iso16281"},
        "material": steel,
    }
    a = bk.analyze(spec, load={"F_x": f"{share * c} N"})
    row = a.input.model.rows[0]
    mm = 1e3
    geometry = dict(
        z=int(row.n_elements),
        dwe=float(row.element_diameter) * mm,
        dpw=float(row.pitch_diameter) * mm,
        n_s=int(row.n_slices),
    )
    q = ref.slice_loads(share * c, lwe=float(row.effective_length) * mm, **geometry)
    fk = ref.edge_factor(geometry["n_s"])
    life = ref.life(q, c=c, f_inner=fk, f_outer=fk, **geometry)
    expected = life / (1.0 / share) ** (10.0 / 3.0)
    assert a.rating.comparison[0]["ratio"] == pytest.approx(expected, rel=1e-3)


@pytest.mark.parametrize("share", [0.1, 0.3])
def test_spherical_roller_thrust_ratio(share):
    """29412 under centric axial load: every roller carries F_a/(Z sin α), so the distribution factor is
    the slice profile's alone: the osculation 0.98 (assumed) on rollers 1.3 D_we long puts the load on the
    roller middle (at 0.1 C on 11 of the 15 slices, peaked), below the 0.2 of the other rollers at 0.1 C."""
    a, _ = _analysis("29412", "axial", share)
    cmp = a.rating.comparison[0]
    assert cmp["method_factor"] == pytest.approx(METHOD[(0.73, share)], rel=5e-4)
    assert cmp["ratio"] == pytest.approx(cmp["method_factor"] * cmp["distribution_factor"], rel=1e-12)
    lo, hi = {0.1: (0.13, 0.15), 0.3: (0.39, 0.42)}[share]  # as measured (0.140, 0.406)
    assert lo < cmp["distribution_factor"] < hi
    loads = a.statics.rows[0].load[0]
    np.testing.assert_allclose(loads, loads.mean(), rtol=1e-12)
