"""Interference fits and thermal expansion of rings, shafts and housings (thick-cylinder Lamé theory).

SI units: m, Pa, 1/K, K. Pure, vectorised functions.

A thick cylinder a ≤ r ≤ b (plane stress, open ends) under an internal pressure p_a and an external
pressure p_b displaces radially by (Lamé; Timoshenko & Goodier 1951 §28)

.. math::
    u(r) = \\frac{1}{E}\\left[(1-\\nu)\\,\\frac{p_a a^2 - p_b b^2}{b^2 - a^2}\\,r
           + (1+\\nu)\\,\\frac{(p_a - p_b)\\,a^2 b^2}{(b^2 - a^2)\\,r}\\right].

Two cylinders pressed together on the diameter d with a diametral interference Δ share the contact
pressure

.. math::
    p = \\frac{\\Delta}{d\\left[\\dfrac{1}{E_o}\\left(\\dfrac{d_o^2 + d^2}{d_o^2 - d^2} + \\nu_o\\right)
        + \\dfrac{1}{E_i}\\left(\\dfrac{d^2 + d_i^2}{d^2 - d_i^2} - \\nu_i\\right)\\right]}

(inner body: bore d_i, 0 for a solid shaft; outer body: outside diameter d_o, ∞ for a housing much
larger than the ring), the classical shrink-fit formula (Shigley's Mechanical Engineering Design,
§3-16; Harris & Kotzalas 2007, Essential Concepts, ch. 2 on fitting practice use the same Lamé
solution). For an inner ring pressed on a shaft the raceway (the ring's outside diameter d_r)
grows by 2u(d_r/2) = 2 p d² d_r / [E (d_r² − d²)]; an outer ring pressed into a housing shrinks at its
raceway D_r by 2 p D² D_r / [E (D² − D_r²)]. For the same material and a solid shaft the first is
Δ·d/d_r, the well-known rule.

Thermal expansion of a diameter: Δd = α d (T − T_ref).

References: Timoshenko S., Goodier J.N. (1951) Theory of Elasticity, 2nd ed., §28 (thick cylinder);
Budynas R.G., Nisbett J.K. (2011) Shigley's Mechanical Engineering Design, 9th ed., §3-16 (press and
shrink fits); Harris T.A., Kotzalas M.N. (2007) Essential Concepts of Bearing Technology, ch. 2.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references

references.add(
    "timoshenko1951",
    "Timoshenko S., Goodier J.N. (1951) Theory of Elasticity, 2nd ed., McGraw-Hill, §28 (thick cylinder).",
)
references.add(
    "shigley2011",
    "Budynas R.G., Nisbett J.K. (2011) Shigley's Mechanical Engineering Design, 9th ed., McGraw-Hill, "
    "§3-16 (press and shrink fits).",
)


def lame_radial_displacement(
    radius, inner_radius, outer_radius, inner_pressure, outer_pressure, youngs_modulus, poisson_ratio
):
    """Radial displacement of a thick cylinder under internal and external pressure (plane stress).

    .. math::
        u(r) = \\frac{1}{E}\\left[(1-\\nu)\\frac{p_a a^2 - p_b b^2}{b^2-a^2}\\,r
               + (1+\\nu)\\frac{(p_a-p_b)a^2b^2}{(b^2-a^2)\\,r}\\right]

    Parameters
    ----------
    radius : array_like [m]
        r, in [a, b].
    inner_radius, outer_radius : array_like [m]
        a ≥ 0 and b > a.
    inner_pressure, outer_pressure : array_like [Pa]
        p_a on the bore, p_b on the outside (compressive positive).
    youngs_modulus : array_like [Pa]
        E, > 0.
    poisson_ratio : array_like [-]
        ν.

    Returns
    -------
    ndarray [m]
        u(r), positive outward.

    References
    ----------
    Timoshenko & Goodier (1951) §28.
    """
    checks.non_negative("inner_radius", inner_radius, "m")
    checks.greater("outer_radius", outer_radius, "inner_radius", inner_radius, "m")
    checks.positive("youngs_modulus", youngs_modulus, "Pa")
    a2 = np.asarray(inner_radius, dtype=float) ** 2
    b2 = np.asarray(outer_radius, dtype=float) ** 2
    r = np.asarray(radius, dtype=float)
    pa, pb = np.asarray(inner_pressure, dtype=float), np.asarray(outer_pressure, dtype=float)
    nu = np.asarray(poisson_ratio, dtype=float)
    e = np.asarray(youngs_modulus, dtype=float)
    return (
        (1 - nu) * (pa * a2 - pb * b2) / (b2 - a2) * r + (1 + nu) * (pa - pb) * a2 * b2 / ((b2 - a2) * r)
    ) / e


def fit_pressure(
    interference,
    diameter,
    inner_bore,
    outer_diameter,
    youngs_modulus_inner,
    poisson_ratio_inner,
    youngs_modulus_outer,
    poisson_ratio_outer,
):
    """Contact pressure of two cylinders pressed together with a diametral interference.

    .. math::
        p = \\frac{\\Delta}{d\\left[\\frac{1}{E_o}\\left(\\frac{d_o^2+d^2}{d_o^2-d^2}+\\nu_o\\right)
            + \\frac{1}{E_i}\\left(\\frac{d^2+d_i^2}{d^2-d_i^2}-\\nu_i\\right)\\right]}

    Parameters
    ----------
    interference : array_like [m]
        Diametral interference Δ; ≤ 0 (a clearance fit) gives p = 0.
    diameter : array_like [m]
        Fit diameter d, > 0.
    inner_bore : array_like [m]
        Bore d_i of the inner body (0: solid shaft), < d.
    outer_diameter : array_like [m]
        Outside diameter d_o of the outer body, > d; ``np.inf`` for a body much larger than d.
    youngs_modulus_inner, poisson_ratio_inner : array_like [Pa], [-]
        E_i, ν_i of the inner body (shaft, or a bearing's outer ring in its housing).
    youngs_modulus_outer, poisson_ratio_outer : array_like [Pa], [-]
        E_o, ν_o of the outer body (inner ring on its shaft, or the housing).

    Returns
    -------
    ndarray [Pa]

    References
    ----------
    Shigley (Budynas & Nisbett 2011) §3-16, eq. (3-56); Timoshenko & Goodier (1951) §28.
    """
    checks.positive("diameter", diameter, "m")
    checks.non_negative("inner_bore", inner_bore, "m")
    checks.greater("diameter", diameter, "inner_bore", inner_bore, "m")
    do = np.asarray(outer_diameter, dtype=float)
    if np.any(np.isnan(do)) or np.any(do <= np.asarray(diameter, dtype=float)):
        raise checks.InputError(
            f"outer_diameter ({np.min(do):.6g} m) must exceed diameter ({np.max(diameter):.6g} m), or be inf"
        )
    d = np.asarray(diameter, dtype=float)
    di2 = np.asarray(inner_bore, dtype=float) ** 2
    with np.errstate(invalid="ignore"):
        outer_term = np.where(np.isinf(do), 1.0, (do**2 + d**2) / (do**2 - d**2))
    c_o = (outer_term + np.asarray(poisson_ratio_outer, dtype=float)) / np.asarray(
        youngs_modulus_outer, dtype=float
    )
    c_i = ((d**2 + di2) / (d**2 - di2) - np.asarray(poisson_ratio_inner, dtype=float)) / np.asarray(
        youngs_modulus_inner, dtype=float
    )
    return np.maximum(np.asarray(interference, dtype=float), 0.0) / (d * (c_o + c_i))


def ring_expansion(pressure, bore, outside_diameter, youngs_modulus):
    """Growth of a ring's outside diameter when its bore is pressed with ``pressure`` (inner ring on a shaft).

    .. math:: \\Delta d_r = 2u(d_r/2) = \\frac{2\\,p\\,d^2\\,d_r}{E\\,(d_r^2 - d^2)}

    Parameters
    ----------
    pressure : array_like [Pa]
        Fit pressure p on the bore.
    bore : array_like [m]
        Bore d.
    outside_diameter : array_like [m]
        The ring's outside (raceway) diameter d_r > d.
    youngs_modulus : array_like [Pa]
        E of the ring.

    Returns
    -------
    ndarray [m]
        Diametral growth (≥ 0 for p ≥ 0).

    References
    ----------
    Timoshenko & Goodier (1951) §28 (u at r = b with p_b = 0; independent of ν).
    """
    checks.greater("outside_diameter", outside_diameter, "bore", bore, "m")
    d, dr = np.asarray(bore, dtype=float), np.asarray(outside_diameter, dtype=float)
    return (
        2.0
        * np.asarray(pressure, dtype=float)
        * d**2
        * dr
        / (np.asarray(youngs_modulus, dtype=float) * (dr**2 - d**2))
    )


def ring_contraction(pressure, bore, outside_diameter, youngs_modulus):
    """Shrink of a ring's bore when its outside is pressed with ``pressure`` (outer ring in a housing).

    .. math:: \\Delta D_r = -2u(D_r/2) = \\frac{2\\,p\\,D^2\\,D_r}{E\\,(D^2 - D_r^2)}

    Parameters
    ----------
    pressure : array_like [Pa]
        Fit pressure p on the outside diameter.
    bore : array_like [m]
        The ring's bore (raceway) diameter D_r.
    outside_diameter : array_like [m]
        Outside diameter D > D_r.
    youngs_modulus : array_like [Pa]
        E of the ring.

    Returns
    -------
    ndarray [m]
        Diametral shrink of the bore (≥ 0 for p ≥ 0).

    References
    ----------
    Timoshenko & Goodier (1951) §28 (u at r = a with p_a = 0; independent of ν).
    """
    checks.greater("outside_diameter", outside_diameter, "bore", bore, "m")
    dr, big = np.asarray(bore, dtype=float), np.asarray(outside_diameter, dtype=float)
    return (
        2.0
        * np.asarray(pressure, dtype=float)
        * big**2
        * dr
        / (np.asarray(youngs_modulus, dtype=float) * (big**2 - dr**2))
    )


def thermal_growth(diameter, thermal_expansion, temperature_rise):
    """Thermal growth of a diameter.

    .. math:: \\Delta d = \\alpha\\,d\\,\\Delta T

    Parameters
    ----------
    diameter : array_like [m]
        d.
    thermal_expansion : array_like [1/K]
        Linear expansion coefficient α.
    temperature_rise : array_like [K]
        T − T_ref.

    Returns
    -------
    ndarray [m]

    References
    ----------
    Timoshenko & Goodier (1951) ch. 13 (free thermal expansion of a uniformly heated body).
    """
    checks.finite("temperature_rise", temperature_rise, "K")
    return (
        np.asarray(diameter, dtype=float)
        * np.asarray(thermal_expansion, dtype=float)
        * np.asarray(temperature_rise, dtype=float)
    )
