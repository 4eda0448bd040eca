"""Operating clearance: a 6209 on a k5 shaft with a 20 K inner–outer temperature difference, by hand."""

import numpy as np
import pytest

from bearingkit.analysis.clearance import FitConditions, Temperatures, operating_clearance
from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.bearings.standard import deep_groove_ball
from bearingkit.errors import InputError
from bearingkit.materials import get_material

D_W, D_M, BORE, OD, P0 = 12.7e-3, 65e-3, 45e-3, 85e-3, 15e-6


def _model(clearance=P0):
    return deep_groove_ball(
        n_elements=9, element_diameter=D_W, pitch_diameter=D_M, clearance_radial=clearance
    )


def test_6209_k5_20K_hand_calculation():
    ring = get_material("AISI52100")  # the shaft: structural steel, the default (E 210 GPa, α 12e-6)
    chain = operating_clearance(
        _model(),
        BORE,
        OD,
        ring,
        FitConditions(shaft_tolerance="k5", housing_tolerance="H7"),
        Temperatures(inner_ring=60.0, outer_ring=40.0),
    )
    # --- by hand -------------------------------------------------------------------------------
    e_r, nu_r, a_r = ring.youngs_modulus, ring.poisson_ratio, 11.9e-6
    e_s, nu_s, a_s = 210e9, 0.3, 12.0e-6
    # k5 at 45 mm: +13/+2 µm (IT5 = 11, ei = +2); bore, Normal class: 0/−12 µm → mean interference 13.5 µm.
    interference_20 = (13 + 2) / 2 * 1e-6 - (0 - 12) / 2 * 1e-6
    # At 60 °C the shaft and the ring both grow; the interference changes by d (α_s − α_r) ΔT.
    interference_60 = interference_20 + BORE * (a_s - a_r) * 40.0
    d_r = D_M - D_W  # inner raceway diameter 52.3 mm

    def expansion(delta):  # Lamé: ring (bore d, outside d_r) on a solid shaft, then u at the raceway
        p = delta / (BORE * ((d_r**2 + BORE**2) / (d_r**2 - BORE**2) + nu_r) / e_r + BORE * (1 - nu_s) / e_s)
        return 2 * p * BORE**2 * d_r / (e_r * (d_r**2 - BORE**2))

    mounted = P0 - expansion(interference_20)  # H7 housing: 25 µm mean clearance fit, no contraction
    # Rings at 60 and 40 °C, balls at 50 °C: ΔP = α[D_o ΔT_o − d_i ΔT_i − 2 D_w ΔT_b].
    thermal_rings = a_r * ((D_M + D_W) * 20.0 - d_r * 40.0 - 2 * D_W * 30.0)
    operating = P0 - expansion(interference_60) + thermal_rings
    # ---------------------------------------------------------------------------------------------
    row = chain.rows[0]
    assert chain.fit_inner[row][0] == pytest.approx(expansion(interference_20), rel=1e-12)
    assert chain.fit_outer[row][0] == 0.0
    assert chain.mounted[row][0] == pytest.approx(mounted, rel=1e-12)
    assert chain.operating[row][0] == pytest.approx(operating, rel=1e-12)
    assert chain.thermal[row][0] == pytest.approx(operating - mounted, rel=1e-12)
    # The numbers: 11.6 µm of the 15 µm go to the fit, and 20 K more on the inner ring take the rest.
    assert chain.mounted[row][0] == pytest.approx(3.37e-6, abs=0.05e-6)
    assert chain.operating[row][0] < 0.0
    assert any("clearance is lost" in w for w in chain.warnings)


def test_operating_clearance_feeds_the_solve():
    """The chain's radial raceway shift gives the same solution as a bearing built with that clearance."""
    chain = operating_clearance(
        _model(),
        BORE,
        OD,
        get_material("AISI52100"),
        FitConditions(shaft_tolerance="m6"),
        Temperatures(inner_ring=np.array([20.0, 45.0]), outer_ring=np.array([20.0, 35.0])),
    )
    load = np.array([[5000.0, 0, 0, 0, 0], [5000.0, 0, 0, 0, 0]])
    free = [True, True, False, False, False]
    res = solve(_model(), load, free=free, raceway_offsets=chain.offsets(_model(), 2))
    for c in range(2):
        ref = solve(_model(chain.operating["balls"][c]), load[c], free=free)
        np.testing.assert_allclose(res.displacement[c], ref.displacement[0], rtol=1e-9, atol=1e-15)


def test_hollow_shaft_and_loose_housing_at_temperature():
    ring = get_material("AISI52100")
    solid = operating_clearance(_model(), BORE, OD, ring, FitConditions(shaft_tolerance="k5"), Temperatures())
    hollow = operating_clearance(
        _model(), BORE, OD, ring, FitConditions(shaft_tolerance="k5", shaft_bore=0.03), Temperatures()
    )
    assert hollow.fit_inner["balls"][0] < solid.fit_inner["balls"][0]  # a hollow shaft yields more
    # An aluminium housing with an N7 fit loosens when warm: the interference at 80 °C is smaller.
    alu = FitConditions(housing_tolerance="N7", housing_material=get_material("aluminium_alloy"))
    cold = operating_clearance(_model(), BORE, OD, ring, alu, Temperatures())
    warm = operating_clearance(_model(), BORE, OD, ring, alu, Temperatures(80.0, 80.0))
    assert warm.interference_outer[0] < cold.interference_outer[0]


def test_bad_fit_code_is_an_input_error():
    with pytest.raises(InputError, match="tolerance field"):
        operating_clearance(
            _model(), BORE, OD, get_material("GCr15"), FitConditions(shaft_tolerance="k55"), Temperatures()
        )
