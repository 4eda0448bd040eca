"""ISO 76 / ISO 281 factors of the bearing kinds the shipped tables leave out: self-aligning ball f0 and
f_c, and the equivalent-load factors of four-point, self-aligning, spherical roller, crossed roller
and needle bearings.

SI units (m, N, Pa, rad); f0 in MPa (N/mm²) and f_c in ISO 281's N–mm units, as the standards write them.

**f0 of self-aligning ball bearings**: ISO 76 Table 1 column 2 (:func:`f0_self_aligning_ball_table`, the
table from memory) for catalogue ratings, checked against its definition (:func:`f0_self_aligning_ball`):

**f0 from its definition.** ISO 76 defines C0 as the load that produces the limit contact stress
(4200 MPa ball, 4600 MPa self-aligning ball) at the most heavily loaded contact, with the radial load
distribution Q_max = 5 F_r/(i Z cos α) (Stribeck's 5). Hence f0 = Q0/(5 D_w²) with Q0 the Hertz load of
the more stressed raceway contact at the limit stress: :func:`f0_from_contact_stress`. With steel
(E' = 2.28e11 Pa) and f_i = 0.52, f_o = 0.53 it reproduces ISO 76 Table 1, column "radial and angular
contact groove ball bearings", to 0.3-0.8 % over γ = 0.05 … 0.40 (tested); applied to the self-aligning
geometry (outer raceway a sphere, f_o = (1 + γ)/(2γ)) at 4600 MPa it follows the self-aligning column
within 3 % (the column's one decimal is up to 2.5 % of its values).

**f_c of self-aligning ball bearings** (ISO 281 Table 2, column 3, not shipped): the tabulated radial
column 1 times the ratio of the ISO/TR 1281-1 (Lundberg–Palmgren) closed form for the two geometries,
whose constant and γ terms cancel in the ratio (the conformity terms remain): [derived, not checked
against the printed column].

References: ISO 76:2006 clause 6.1, Table 1; ISO 281:2007 clause 5.1, Table 2, Table 3 (X, Y, e);
ISO/TR 1281-1:2021 (closed forms); Lundberg & Palmgren (1947); Harris & Kotzalas (2007) ch. 8.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.physics import tables
from bearingkit.physics.life import iso76, iso281, iso281_load

#: Stribeck's factor of ISO 76's radial ball ratings: Q_max = 5 F_r / (i Z cos α) (ISO/TR 10657).
STRIBECK_FACTOR = 5.0
#: Reduced modulus of steel on steel used by ISO 76's stress criterion [Pa] (E = 207.9 GPa, ν = 0.3).
E_REDUCED_STEEL = 2.28e11
#: Inner groove conformity assumed by ISO 281 / ISO 76 for self-aligning ball bearings [-] (the usual
#: 0.53; the outer raceway is the sphere).
SELF_ALIGNING_CONFORMITY_INNER = 0.53
#: Inner/outer conformities behind ISO 281 Table 2 column 1 (ISO 281:2007 5.1.1).
RADIAL_CONFORMITIES = (0.52, 0.53)
_MM = 1.0e-3
_F0_SELF_ALIGNING = "iso76_f0_self_aligning_ball.csv"


def sphere_conformity(gamma):
    """Outer "conformity" R_o/D_w of a spherical outer raceway [-]: (1 + γ)/(2γ).

    Parameters
    ----------
    gamma : array_like
        γ = D_w cos α / d_m [-] (R_o = d_m/(2 cos α) + D_w/2, Harris & Kotzalas 2007 ch. 1).
    """
    g = np.asarray(gamma, float)
    return (1.0 + g) / (2.0 * g)


def f0_from_contact_stress(gamma, conformity_inner, conformity_outer, p_limit):
    """ISO 76 factor f0 [MPa] from the contact-stress definition of C0.

    .. math:: f_0 = \\frac{Q_0}{5 D_w^2},\\qquad p_{max}(Q_0) = p_{limit}\\ \\text{(more stressed raceway)}

    Parameters
    ----------
    gamma : array_like
        γ = D_w cos α / d_m [-], > 0.
    conformity_inner, conformity_outer : array_like
        r/D_w of the raceways [-], > 0.5.
    p_limit : float
        Limit contact stress [Pa] (4.2e9 ball, 4.6e9 self-aligning ball).

    Returns
    -------
    numpy.ndarray
        f0 [MPa].
    """
    from bearingkit.physics.contact import hertz

    checks.positive("gamma", gamma)
    checks.positive("p_limit", p_limit, "Pa")
    g = np.asarray(gamma, float)
    d = _MM  # 1 mm ball: Q0 [N] / (5 · 1 mm²) is f0 in N/mm²
    loads = []
    for side, f in (("inner", conformity_inner), ("outer", conformity_outer)):
        sr, fr = hertz.ball_raceway_curvature(d, d / g, 0.0, np.asarray(f, float) * d, side)
        p_unit = hertz.point_contact(np.ones_like(g), sr, fr, E_REDUCED_STEEL).max_pressure
        loads.append((p_limit / p_unit) ** 3)
    return np.minimum(*loads) / STRIBECK_FACTOR


def f0_self_aligning_ball_table(gamma):
    """f0 [MPa] of self-aligning ball bearings, ISO 76:2006 Table 1 column 2 (linear interpolation).

    The column ships as ``data/iso76_f0_self_aligning_ball.csv`` [from memory: no stored copy could be
    found]; :func:`f0_self_aligning_ball` (the stress definition) follows it within 3 %, which is the
    check of the remembered values. The catalogue ratings (:mod:`bearingkit.catalogue.iso_ratings`) use
    this table, as ISO 76 prescribes for bearings of conventional design.

    Parameters
    ----------
    gamma : array_like
        γ = D_w cos α / d_m [-], 0 … 0.40 (outside: InputError).
    """
    t = _F0_SELF_ALIGNING
    return tables.interp_strict("gamma", gamma, tables.column(t, "gamma"), tables.column(t, "f0"))


def f0_self_aligning_ball(gamma, conformity_inner=SELF_ALIGNING_CONFORMITY_INNER):
    """f0 [MPa] of self-aligning ball bearings from ISO 76's stress definition (4600 MPa, the outer
    raceway the sphere) for the row's own inner conformity: the engine's row rating uses it; at ISO's
    conformity it follows the table (:func:`f0_self_aligning_ball_table`) within 3 %.

    Parameters
    ----------
    gamma : array_like
        γ = D_w cos α / d_m [-], > 0.
    conformity_inner : float
        Inner groove r/D_w [-].
    """
    limit = iso76.CONTACT_LIMITS["self_aligning_ball"][0]
    return f0_from_contact_stress(gamma, conformity_inner, sphere_conformity(gamma), limit)


def _lp_ball_fc(gamma, fi, fe):
    """Lundberg–Palmgren / ISO/TR 1281-1 ball f_c closed form, up to a constant factor [from memory]."""
    g = np.asarray(gamma, float)
    t = 1.04 * ((1 - g) / (1 + g)) ** 1.72 * (fi * (2 * fe - 1) / (fe * (2 * fi - 1))) ** 0.41
    return (
        g**0.3
        * (1 - g) ** 1.39
        / (1 + g) ** (1 / 3)
        * (2 * fi / (2 * fi - 1)) ** 0.41
        * (1 + t ** (10 / 3)) ** -0.3
    )


def fc_self_aligning_ball(gamma, conformity_inner=SELF_ALIGNING_CONFORMITY_INNER):
    """f_c [-] (ISO 281 N–mm units) of self-aligning ball bearings: column 1 × the closed-form ratio.

    .. math:: f_c = f_{c,1}(\\gamma)\\,\\frac{F(\\gamma, f_i, (1+\\gamma)/2\\gamma)}{F(\\gamma, 0.52, 0.53)}

    F the ISO/TR 1281-1 form (module docstring). γ within ISO 281 Table 2 (0.01 … 0.40).

    Parameters
    ----------
    gamma : array_like
        γ = D_w cos α / d_m [-].
    conformity_inner : float
        Inner groove r/D_w [-].
    """
    g = np.asarray(gamma, float)
    ratio = _lp_ball_fc(g, conformity_inner, sphere_conformity(g)) / _lp_ball_fc(g, *RADIAL_CONFORMITIES)
    return iso281.fc_radial_ball(g) * ratio


#: ISO equivalent-load laws per bearing kind: (ISO 281 P model, ISO 76 P0 model, rows i). Four-point
#: contact ball bearings take the double-row angular contact factors (ISO 281 Table 3 / ISO 76 Table 2,
#: the values the makers print for QJ bearings, e.g. e = 0.95, Y = 0.66/1.07, Y0 = 0.58 at 35°); spherical
#: roller and crossed roller bearings the double-row radial roller laws (e = 1.5 tan α; X, Y = 1, 0.45 cot α
#: and 0.67, 0.67 cot α; Y0 = 0.44 cot α) — crossed rollers have no ISO entry, the double-row law is
#: assumed; needle bearings P = F_r.
KIND_LOAD_LAWS = {
    "four_point": ("angular_contact_ball", "angular_contact_ball", 2),
    "self_aligning_ball": ("self_aligning_ball", "self_aligning_ball", 2),
    "spherical_roller": ("radial_roller", "radial_roller", 2),
    "crossed_roller": ("radial_roller", "radial_roller", 2),
    "needle": ("radial_roller", "radial_roller", 1),
}


def equivalent_loads(kind, load_radial, load_axial, contact_angle):
    """ISO 281 dynamic and ISO 76 static equivalent loads (P, P0) [N] of a bearing of ``kind``.

    Parameters
    ----------
    kind : str
        A key of :data:`KIND_LOAD_LAWS`.
    load_radial, load_axial : array_like
        F_r, F_a [N], ≥ 0 (the whole bearing).
    contact_angle : float
        Nominal contact angle α [rad] (0 for needles).

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        P and P0 [N].
    """
    checks.one_of("kind", kind, KIND_LOAD_LAWS)
    p_law, p0_law, rows = KIND_LOAD_LAWS[kind]
    alpha = abs(float(contact_angle))
    p = iso281_load.equivalent_dynamic_load(load_radial, load_axial, p_law, alpha, n_rows=rows)
    p0 = iso76.equivalent_static_load(load_radial, load_axial, p0_law, alpha, n_rows=rows)
    return p, p0
