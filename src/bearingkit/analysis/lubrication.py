"""Lubrication of a solved bearing: EHL film and Λ per contact, ν, ν1, κ per row.

SI units (m, m²/s, Pa·s, rad/s; temperatures in °C). For every loaded contact of every row:

- ball rows: Hamrock–Dowson point-contact film (central and minimum) with the contact's own load
  and operating angle (inner and outer differ at speed, :mod:`bearingkit.rows.ball.speed`), curvature
  from the groove conformity and the entrainment speed of pure rolling, u = |Ω| r_c (Ω the ring's
  speed relative to the cage, r_c the contact radius);
- radial cylindrical and tapered rows: Pan–Hamrock line-contact film with the roller's load on that
  raceway, over its effective length; thrust cylindrical rows: at the pitch radius;

and Λ = h_min/√(R_q,element² + R_q,raceway²). Per row and case: ν(T), the ISO 281 reference
viscosity ν1(n, D_pw) and κ = ν/ν1 (ISO 281:2007 eqs. 25–27). Rows without a film model here
(threaded rows) are listed in ``skipped``.

References: Hamrock B.J., Dowson D. (1977) J. Lubr. Technol. 99(2):264-275; Pan P., Hamrock B.J.
(1989) J. Tribol. 111(2):246-251; ISO 281:2007 clause 9.3.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.physics.contact import hertz
from bearingkit.physics.life import iso281_life
from bearingkit.physics.lubrication import ehl

#: Default RMS roughness of elements and raceways [m] (as the friction model,
#: bearingkit.analysis.friction.components).
ROUGHNESS_ELEMENT = 0.05e-6
ROUGHNESS_RACEWAY = 0.10e-6


@dataclass
class ContactFilms:
    """Films of one row (arrays (C, Z), 0 where the contact carries no load)."""

    row: str
    film_minimum_inner: np.ndarray
    film_minimum_outer: np.ndarray
    film_central_inner: np.ndarray
    film_central_outer: np.ndarray
    lambda_inner: np.ndarray
    lambda_outer: np.ndarray
    loaded_inner: np.ndarray
    loaded_outer: np.ndarray

    def min_lambda(self) -> np.ndarray:
        """Smallest Λ over the loaded contacts of the row (C,), inf when none is loaded."""
        li = np.where(self.loaded_inner, self.lambda_inner, np.inf).min(-1)
        lo = np.where(self.loaded_outer, self.lambda_outer, np.inf).min(-1)
        return np.minimum(li, lo)


@dataclass
class LubricationResult:
    """Films per contact and viscosity ratios per row (arrays over the C load cases).

    Attributes
    ----------
    films : list of ContactFilms
    viscosity : ndarray (C,) [m²/s]
        Kinematic viscosity ν at the operating temperature.
    reference_viscosity, kappa : dict row → ndarray (C,)
        ν1 [m²/s] and κ = ν/ν1 per row (NaN at rest).
    skipped : list of str
        Rows without a film model.
    """

    films: list
    viscosity: np.ndarray
    reference_viscosity: dict
    kappa: dict
    skipped: list = field(default_factory=list)

    def film(self, row: str) -> ContactFilms:
        for f in self.films:
            if f.row == row:
                return f
        raise KeyError(row)


def _ball(row, kernel, state, w_i, w_o, eta, alpha_p, rough):
    d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1)
    dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1)
    ex = state.extras
    out = {}
    for side, f in (("inner", row.conformity_inner), ("outer", row.conformity_outer)):
        load = ex.get(f"load_{side}", state.load)
        alpha = ex.get(f"contact_angle_{side}", state.contact_angle)
        cos_a = np.clip(np.abs(np.cos(alpha)), 0.0, 1.0)
        if "cage_speed" in ex:
            w_c = ex["cage_speed"]
        else:
            w_c = 0.5 * (w_i * (1 - d * cos_a / dm) + w_o * (1 + d * cos_a / dm))
        ring = w_i if side == "inner" else w_o
        radius = dm / 2 - d / 2 * cos_a if side == "inner" else dm / 2 + d / 2 * cos_a
        u = np.abs(ring - w_c) * radius
        f = np.asarray(f, dtype=float).reshape(-1, 1)
        srho, frho = hertz.ball_raceway_curvature(d, dm, np.arccos(cos_a), f * d, side)
        rx, ry = hertz.effective_radii(srho, frho)
        live = load > 0
        film = ehl.film_point_hamrock_dowson(
            eta, u, alpha_p, kernel.e_reduced, rx, ry, np.where(live, load, 1.0)
        )
        out[side] = (np.where(live, film.minimum, 0.0), np.where(live, film.central, 0.0), live)
    return out


def _line(row, kernel, state, w_i, w_o, eta, alpha_p):
    ex = state.extras
    out = {}
    if row.kind == "tapered":
        geo = kernel.geo
        r_i, r_o = geo.radius_inner, geo.radius_outer
        radii_x = {"inner": geo.radius_x_inner, "outer": geo.radius_x_outer}
        length = geo.length
        w_c = (w_i * r_i + w_o * r_o) / (r_i + r_o)
        speeds = {"inner": np.abs(w_i - w_c) * r_i, "outer": np.abs(w_o - w_c) * r_o}
        loads = {"inner": ex["load_inner"], "outer": ex["load_outer"]}
    else:
        d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1)
        dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1)
        length = np.asarray(row.effective_length, dtype=float).reshape(-1, 1)
        loads = {s: ex.get(f"load_{s}", state.load) for s in ("inner", "outer")}
        if row.direction == 0:
            radii_x = {"inner": d / 2 * (1 - d / dm), "outer": d / 2 * (1 + d / dm)}
            w_c = ex.get("cage_speed", 0.5 * (w_i * (1 - d / dm) + w_o * (1 + d / dm)))
            speeds = {"inner": np.abs(w_i - w_c) * (dm - d) / 2, "outer": np.abs(w_o - w_c) * (dm + d) / 2}
        else:  # thrust: rolling at the pitch radius on flat washers
            radii_x = {"inner": d / 2 + 0 * dm, "outer": d / 2 + 0 * dm}
            u = np.abs(w_i - w_o) / 2 * dm / 2
            speeds = {"inner": u, "outer": u}
    for side in ("inner", "outer"):
        load = loads[side]
        live = load > 0
        film = ehl.film_line_pan_hamrock(
            eta, speeds[side], alpha_p, kernel.e_reduced, radii_x[side], np.where(live, load, 1.0), length
        )
        out[side] = (np.where(live, film.minimum, 0.0), np.where(live, film.central, 0.0), live)
    return out


def lubrication(
    result,
    speed_inner,
    speed_outer,
    lubricant,
    temperature_C,
    roughness_element=ROUGHNESS_ELEMENT,
    roughness_raceway=ROUGHNESS_RACEWAY,
) -> LubricationResult:
    """Films and viscosity ratios of a solved bearing (module docstring).

    Parameters
    ----------
    result : QuasiStaticResult
    speed_inner, speed_outer : array (C,) [rad/s]
    lubricant : Lubricant
    temperature_C : array (C,) [°C]
        Operating temperature (InputError outside the lubricant's range).
    roughness_element, roughness_raceway : float [m]
        RMS roughness R_q.

    Returns
    -------
    LubricationResult
    """
    c = result.n_cases
    w_i = np.broadcast_to(np.asarray(speed_inner, dtype=float), (c,)).reshape(-1, 1)
    w_o = np.broadcast_to(np.asarray(speed_outer, dtype=float), (c,)).reshape(-1, 1)
    temps = np.broadcast_to(np.asarray(temperature_C, dtype=float), (c,))
    nu = np.asarray(lubricant.kinematic_viscosity(temps), dtype=float)
    eta = np.asarray(lubricant.viscosity(temps), dtype=float).reshape(-1, 1)
    alpha_p = np.asarray(lubricant.pressure_viscosity_at(temps), dtype=float).reshape(-1, 1)  # α(T) per case
    films, nu1, kappa, skipped = [], {}, {}, []
    relative = np.abs(w_i - w_o)[:, 0]
    for row, kernel, state in zip(result.model.rows, result.model.kernels, result.rows, strict=True):
        if row.kind == "ball":
            parts = _ball(row, kernel, state, w_i, w_o, eta, alpha_p, None)
        elif row.kind in ("cylindrical", "tapered"):
            parts = _line(row, kernel, state, w_i, w_o, eta, alpha_p)
        else:
            skipped.append(row.name)
            continue
        lam = {
            s: np.where(
                parts[s][2], ehl.film_parameter(parts[s][0], roughness_element, roughness_raceway), 0.0
            )
            for s in parts
        }
        films.append(
            ContactFilms(
                row.name,
                parts["inner"][0],
                parts["outer"][0],
                parts["inner"][1],
                parts["outer"][1],
                lam["inner"],
                lam["outer"],
                parts["inner"][2],
                parts["outer"][2],
            )
        )
        dm = float(np.max(row.pitch_diameter))
        moving = relative > 0
        v1 = np.full(c, np.nan)
        if moving.any():
            v1[moving] = iso281_life.reference_viscosity(relative[moving], dm)
        nu1[row.name] = v1
        kappa[row.name] = nu / v1
    return LubricationResult(films, nu, nu1, kappa, skipped)
