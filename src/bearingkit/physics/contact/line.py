"""Hertz line contact: load–deflection laws of roller contacts, slices, half-width and pressure.

All quantities are SI: lengths in m, loads in N, moduli and pressures in Pa. Every function is a
pure, vectorised numpy function that broadcasts over its arguments. ``e_reduced`` is Hamrock's
E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2] (see :mod:`bearingkit.physics.contact.hertz`).

References: ``kunert1961``/``palmgren1959`` (line-contact deflection), ``iso16281`` (slice stiffness),
``harris2007`` (ch. 6, line contact half-width and pressure).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.checks import scalar_or_array as _out

__all__ = [
    "LINE_EXPONENT",
    "LINE_LAWS",
    "REFERENCE_KEYS",
    "LineContact",
    "line_contact",
    "line_deflection",
    "line_pressure_factor",
    "line_stiffness",
    "slice_grid",
]

#: Keys of :data:`bearingkit.references.REFERENCES` this module implements.
REFERENCE_KEYS = ("kunert1961", "palmgren1959", "iso16281", "harris2007")

#: Kunert (1961) / Palmgren (1959) line-contact deflection constant in
#: delta = C * eta^0.9 * Q^0.9 / l^0.8 with eta = 2/E' [dimensionless: the law is dimensionally
#: consistent in SI, eta^0.9 Q^0.9 / l^0.8 has unit m]. For steel (E = 206 GPa, nu = 0.3) it reproduces
#: Palmgren's delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N) for ONE roller–raceway contact. Valid for
#: uncrowned rollers with l >> contact half-width (Harris & Kotzalas 2007, ch. 6; Palmgren 1959).
KUNERT_COEFF = 1.36
KUNERT_LOAD_EXP = 0.9  # exponent of load (and of eta) in the Kunert law [1]
KUNERT_LENGTH_EXP = 0.8  # exponent of the length in the Kunert law [1]

#: ISO/TS 16281:2008 roller (both contacts together) stiffness c_L = C * L_we^(8/9) with
#: C = 35948 N/mm^(10/9) and L_we in mm, for steel rollers and rings. Converted to SI below.
ISO16281_LINE_COEFF_MM = 35948.0  # [N/mm^(10/9) per mm^(8/9)], ISO/TS 16281:2008 (roller slice model)
#: Assumed steel E' behind ISO16281_LINE_COEFF_MM [Pa]: E = 210 GPa, nu = 0.3 on both bodies
#: (E' = E/(1-nu^2)). The standard gives the constant for steel only; bearingkit scales it by
#: e_reduced / ISO16281_STEEL_E_REDUCED for other materials (an assumption, documented).
ISO16281_STEEL_E_REDUCED = 210.0e9 / (1.0 - 0.3**2)

#: Load-deflection exponent of line contact, Q ~ delta^(10/9) (= 1/KUNERT_LOAD_EXP) [1].
LINE_EXPONENT = 10.0 / 9.0


# ---------------------------------------------------------------------------------------------
# Line contact
# ---------------------------------------------------------------------------------------------


def _kunert_stiffness(effective_length, e_reduced):
    eta = 2.0 / np.asarray(e_reduced, float)  # elastic_compliance [1/Pa]
    coeff = KUNERT_COEFF * eta**KUNERT_LOAD_EXP  # delta = coeff * Q^0.9 * l^-0.8
    length = np.asarray(effective_length, float)
    return coeff ** (-1.0 / KUNERT_LOAD_EXP) * length ** (KUNERT_LENGTH_EXP / KUNERT_LOAD_EXP)


#: SI form of the ISO constant: Q[N] = C_mm (1e3 L)^(8/9) (1e3 delta)^(10/9) = C_mm 1e6 L^(8/9) delta^(10/9).
_MM_PER_M = 1.0e3
_ISO16281_LINE_COEFF_SI = ISO16281_LINE_COEFF_MM * _MM_PER_M ** (8.0 / 9.0 + LINE_EXPONENT)
#: Two equal contacts in series with n = 10/9: c_pair = 2^(-10/9) c_one  =>  c_one = 2^(10/9) c_pair.
_TWO_CONTACTS_FACTOR = 2.0**LINE_EXPONENT


def _iso16281_stiffness(effective_length, e_reduced):
    length = np.asarray(effective_length, float)
    scale = np.asarray(e_reduced, float) / ISO16281_STEEL_E_REDUCED
    return _TWO_CONTACTS_FACTOR * _ISO16281_LINE_COEFF_SI * length ** (8.0 / 9.0) * scale


#: Line-contact load–deflection laws Q = c_l delta^(10/9) for ONE contact of length l:
#: "kunert": Kunert (1961)/Palmgren (1959), delta = 1.36 eta^0.9 Q^0.9 / l^0.8, eta = 2/E'.
#: "iso16281": ISO/TS 16281:2008 c_L = 35948 L_we^(8/9) N/mm^(10/9) (whole steel roller, two
#: contacts) converted to one contact (x 2^(10/9)) and to SI, scaled by E'/E'_steel.
LINE_LAWS: dict[str, Callable] = {"kunert": _kunert_stiffness, "iso16281": _iso16281_stiffness}


def line_stiffness(effective_length, e_reduced, law="kunert"):
    """Load–deflection constant c_l of ONE line contact of length l, Q = c_l delta^(10/9).

    Parameters
    ----------
    effective_length : array_like
        Effective contact length l [m], > 0.
    e_reduced : array_like
        E' [Pa], > 0.
    law : {"kunert", "iso16281"}
        Key of :data:`LINE_LAWS`.

    Returns
    -------
    stiffness_line : ndarray
        c_l [N/m^(10/9)]. A slice of width w carries ``c_l * w / l``.

    Notes
    -----
    Kunert/Palmgren, with :math:`\\eta = 2/E'`:

    .. math:: \\delta = 1.36\\,\\eta^{0.9} Q^{0.9} l^{-0.8}
              \\;\\Rightarrow\\; c_l = (1.36\\,\\eta^{0.9})^{-10/9}\\, l^{8/9}

    (Kunert 1961; Palmgren 1959; Harris & Kotzalas 2007, ch. 6: 3.84e-5 mm for steel.)
    ISO/TS 16281:2008 (slice stiffness of the roller), for the roller's two equal contacts in series:

    .. math:: c_l = 2^{10/9}\\cdot 35948\\,[\\mathrm{N/mm^{10/9}}]\\; L_{we}^{8/9}\\cdot
              \\frac{E'}{E'_{steel}},\\quad E'_{steel} = 210\\,\\mathrm{GPa}/(1-0.3^2)

    The E' scaling (linear, as in the Kunert law) and E'_steel are bearingkit's assumptions.
    """
    fn = LINE_LAWS[checks.one_of("law", law, LINE_LAWS)]
    checks.positive("effective_length", effective_length, "m")
    checks.positive("e_reduced", e_reduced, "Pa")
    return _out(fn(effective_length, e_reduced))


def line_deflection(load, effective_length, e_reduced, law="kunert"):
    """Approach delta [m] of ONE line contact under load Q [N] (>= 0): delta = (Q/c_l)^(9/10).

    Parameters
    ----------
    load : array_like
        Q [N], >= 0.
    effective_length : array_like
        l [m], > 0.
    e_reduced : array_like
        E' [Pa], > 0.
    law : {"kunert", "iso16281"}
        Key of :data:`LINE_LAWS`.

    Notes
    -----
    .. math:: \\delta = (Q / c_l)^{9/10}

    with c_l from :func:`line_stiffness` (same references).
    """
    checks.non_negative("load", load, "N")
    c_l = line_stiffness(effective_length, e_reduced, law)
    return _out((np.asarray(load, float) / c_l) ** (1.0 / LINE_EXPONENT))


def slice_grid(effective_length, n_slices):
    """Centres and width of ``n_slices`` equal slices along a roller.

    Parameters
    ----------
    effective_length : array_like
        l [m], > 0.
    n_slices : int
        Number of slices n_s >= 1.

    Returns
    -------
    positions : ndarray
        Slice centres x_k measured from the roller middle [m], shape ``(..., n_slices)``.
    width : ndarray
        Slice width w = l / n_s [m], shape of ``effective_length``.

    Notes
    -----
    .. math:: w = l/n_s,\\qquad x_k = -\\frac{l}{2} + \\Big(k + \\frac12\\Big) w,\\quad k = 0 \\dots n_s - 1

    ISO/TS 16281:2008, clause 6 (slicing of the roller contact).
    """
    checks.positive("effective_length", effective_length, "m")
    n = checks.integer("n_slices", n_slices, 1)
    length = np.asarray(effective_length, float)
    width = length / n
    k = np.arange(n, dtype=float) + 0.5
    positions = -0.5 * length[..., None] + k * width[..., None]
    return positions, _out(width)


class LineContact(NamedTuple):
    """Hertz line-contact result (SI)."""

    half_width: np.ndarray  #: b, semi-width of the contact strip [m]
    max_pressure: np.ndarray  #: p_max [Pa]


def line_pressure_factor(effective_length, radius_x, e_reduced):
    """Factor c of the Hertz line-contact maximum pressure p_max = c √Q [Pa/√N].

    Parameters
    ----------
    effective_length : array_like
        l [m], > 0 (not checked: callers pass validated geometry).
    radius_x : array_like
        Effective radius R_x in the rolling direction [m], > 0.
    e_reduced : array_like
        E' [Pa], > 0.

    Notes
    -----
    .. math:: c = \\sqrt{\\frac{E'}{2\\pi\\,l\\,R_x}}

    so that p_max = √(Q E′/(2π l R_x)) as in :func:`line_contact`; taking √Q once and scaling it per
    raceway is what the per-slice post-processing of a batch needs. Johnson (1985), Contact
    Mechanics, section 4.2 with E* = E'/2.
    """
    return np.sqrt(
        np.asarray(e_reduced, float)
        / (2.0 * np.pi * np.asarray(effective_length, float) * np.asarray(radius_x, float))
    )


def line_contact(load, effective_length, radius_x, e_reduced) -> LineContact:
    """Hertz line contact (two parallel cylinders): half-width and maximum pressure.

    Parameters
    ----------
    load : array_like
        Q [N], >= 0, spread uniformly over the length.
    effective_length : array_like
        l [m], > 0.
    radius_x : array_like
        Effective radius R_x = (1/R_1 + 1/R_2)^-1 in the rolling direction [m], > 0.
    e_reduced : array_like
        E' [Pa], > 0.

    Returns
    -------
    LineContact
        ``half_width`` b [m], ``max_pressure`` p_max [Pa].

    Notes
    -----
    .. math:: b = \\sqrt{\\frac{8 Q R_x}{\\pi l E'}},\\qquad p_{max} = \\frac{2Q}{\\pi b l}
              = \\sqrt{\\frac{Q E'}{2\\pi l R_x}}

    Johnson (1985), Contact Mechanics, section 4.2 with E* = E'/2; Harris & Kotzalas (2007), ch. 6.
    """
    checks.non_negative("load", load, "N")
    checks.positive("effective_length", effective_length, "m")
    checks.positive("radius_x", radius_x, "m")
    checks.positive("e_reduced", e_reduced, "Pa")
    q = np.asarray(load, float) / np.asarray(effective_length, float)
    r = np.asarray(radius_x, float)
    e_r = np.asarray(e_reduced, float)
    b = np.sqrt(8.0 * q * r / (np.pi * e_r))
    p_max = np.sqrt(np.asarray(load, float)) * line_pressure_factor(effective_length, r, e_r)
    b, p_max = np.broadcast_arrays(b, p_max)
    return LineContact(_out(b), _out(p_max))
