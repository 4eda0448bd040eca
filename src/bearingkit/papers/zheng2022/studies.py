"""Seed 004 (Zheng et al. 2022, PTRB) studies: Table 4/5 single-factor sweeps, Table 3 comparison,
Table 6 optimum points. SI inside (N, m, rad, N·m); DataFrame columns carry their unit.

Table 3 puts the prototype beside catalogue bearings of a similar envelope (SKF, NSK). bearingkit
recomputes their C and C0 with its ISO 76 / ISO 281 modules from an internal geometry that is NOT in
the paper: :data:`STANDARD_BEARINGS` states, for each row, the catalogue designation bearingkit takes it
to be and the assumed ball/roller size, number and contact angle (typical of that series; not
manufacturer data). Computed ratings of such a reconstruction carry ±15 % uncertainty; the catalogue
values of Table 3 are kept beside them.

References: ``zheng2022``, ``iso76``, ``iso281``.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from bearingkit.analysis.friction.threaded import RPM, ptrb_friction
from bearingkit.bearings.ptrb import ptrb_prototype, ptrb_ratings
from bearingkit.errors import InputError
from bearingkit.papers.zheng2022.design import design_geometry
from bearingkit.physics.life import iso76, iso281

__all__ = [
    "STANDARD_BEARINGS",
    "SWEEP_PARAMETERS",
    "TABLE6",
    "TABLE6_OBJECTIVES",
    "TABLE6_ROLLER_COUNT",
    "nearest_table6",
    "table3_comparison",
    "table4_sweep",
    "table5_sweep",
    "table6_at_published_designs",
]

MM = 1.0e-3
KN = 1.0e3
#: Table 4/5 structural parameters → (display unit, SI factor, low, high) (§5 ranges).
SWEEP_PARAMETERS = {
    "contact_angle": ("deg", np.pi / 180.0, 30.0, 60.0),
    "n_teeth": ("1", 1.0, 8, 16),
    "roller_contact_radius": ("mm", MM, 4.5, 7.5),
    "roller_pitch_diameter": ("mm", MM, 4.8, 7.2),
    "n_elements": ("1", 1.0, 7, 11),
}

#: Table 6: design variables of the published optimum points (P [mm], d_R [mm], R_rr [mm], α [deg], n).
TABLE6 = {
    "xa1": {"P_mm": 0.83, "d_R_mm": 6.96, "R_rr_mm": 6.64, "alpha_deg": 53.5, "n": 15},
    "xa2": {"P_mm": 0.95, "d_R_mm": 5.92, "R_rr_mm": 4.51, "alpha_deg": 47.6, "n": 11},
    "xr1": {"P_mm": 0.83, "d_R_mm": 7.06, "R_rr_mm": 7.50, "alpha_deg": 52.5, "n": 15},
    "xr2": {"P_mm": 0.92, "d_R_mm": 6.37, "R_rr_mm": 4.54, "alpha_deg": 39.3, "n": 13},
    "prototype": {"P_mm": 1.2, "d_R_mm": 6.0, "R_rr_mm": 5.1, "alpha_deg": 45.0, "n": 10},
}
#: Number of rollers Z at each Table 6 point. NOT printed: §5 (5) and §6 say "the maximum number of
#: threaded rollers was always taken", set by the installation method (Zheng et al. 2020/2021, rule not
#: given), and the roller set shares the fixed D_pw, so fewer rollers fit as d_R grows. Inferred from
#: Table 6 itself, one integer per point: C_r (eq. 12) contains no calibrated coefficient, and at the
#: published xa1 design it is reproduced to 0.1 % with Z = 10 (6.6 % high with 11), after which C_0r
#: (eq. 5, f_rmax ∝ 1/Z) follows to −0.9 % without any change. xr1 has the larger d_R (7.06 mm), so it
#: cannot take more rollers than xa1 (6.96 mm): Z = 10 (its C_0r then +1.3 %). d_R ≤ 6.37 mm keeps the
#: prototype's 11 (xa2, xr2: C_r within 0.2 %, C_0r within 3.5 %).
TABLE6_ROLLER_COUNT = {"xa1": 10, "xa2": 11, "xr1": 10, "xr2": 11, "prototype": 11}
#: Table 6: published performance of those points (kN, μ in units of 1e-3 as printed).
TABLE6_OBJECTIVES = {
    "xa1": {"C0a_kN": 97.4, "Ca_kN": 78.9, "mu_a_1e3": 2.4, "C0r_kN": 40.4, "Cr_kN": 59.0, "mu_r_1e3": 3.6},
    "xa2": {"C0a_kN": 40.9, "Ca_kN": 37.1, "mu_a_1e3": 2.1, "C0r_kN": 20.0, "Cr_kN": 31.1, "mu_r_1e3": 3.0},
    "xr1": {"C0a_kN": 96.1, "Ca_kN": 75.7, "mu_a_1e3": 2.5, "C0r_kN": 44.8, "Cr_kN": 53.4, "mu_r_1e3": 3.1},
    "xr2": {"C0a_kN": 38.4, "Ca_kN": 33.3, "mu_a_1e3": 2.1, "C0r_kN": 24.5, "Cr_kN": 35.6, "mu_r_1e3": 2.6},
    "prototype": {
        "C0a_kN": 38.36,
        "Ca_kN": 33.20,
        "mu_a_1e3": 2.3,
        "C0r_kN": 19.93,
        "Cr_kN": 30.26,
        "mu_r_1e3": 3.0,
    },
}


def _values(parameter, values):
    if parameter not in SWEEP_PARAMETERS:
        raise InputError(f"parameter ({parameter!r}) must be one of {', '.join(SWEEP_PARAMETERS)}")
    unit, factor, lo, hi = SWEEP_PARAMETERS[parameter]
    vals = np.linspace(lo, hi, 5) if values is None else np.atleast_1d(np.asarray(values, float))
    return unit, factor, vals


def _geometry(parameter, value_si):
    if parameter in ("n_teeth", "n_elements"):
        value_si = round(value_si)
    return design_geometry(**{parameter: value_si})


def table4_sweep(parameter: str, values=None) -> pd.DataFrame:
    """Ratings C0a, C0r, Ca, Cr [N] over one structural parameter (Zheng et al. 2022, Table 4).

    Parameters
    ----------
    parameter : str
        Key of :data:`SWEEP_PARAMETERS`.
    values : array_like or None
        Values in the display unit of the parameter (deg, mm or count); None: 5 points over the §5 range.
    """
    unit, factor, vals = _values(parameter, values)
    rows = []
    for v in vals:
        r = ptrb_ratings(_geometry(parameter, v * factor))
        rows.append(
            {
                f"{parameter}_{unit}": v,
                "C0a_N": r.static_axial,
                "C0r_N": r.static_radial,
                "Ca_N": r.dynamic_axial,
                "Cr_N": r.dynamic_radial,
            }
        )
    return pd.DataFrame(rows)


def table5_sweep(parameter: str, values=None, load=20.0 * KN, speed=4000.0 * RPM, **friction_kwargs):
    """Friction torque M_PTRBa, M_PTRBr [N·m] over one structural parameter (Table 5: 20 kN, 4000 rpm).

    Parameters
    ----------
    parameter : str
        Key of :data:`SWEEP_PARAMETERS`.
    values : array_like or None
        Display-unit values (None: 5 points over the §5 range).
    load : float
        F_a = F_r [N].
    speed : float
        ω [rad/s].
    **friction_kwargs
        Passed to :func:`bearingkit.analysis.friction.threaded.ptrb_friction`.
    """
    unit, factor, vals = _values(parameter, values)
    rows = []
    for v in vals:
        g = _geometry(parameter, v * factor)
        ax = ptrb_friction(g, load, speed, "axial", **friction_kwargs)
        ra = ptrb_friction(g, load, speed, "radial", **friction_kwargs)
        rows.append(
            {
                f"{parameter}_{unit}": v,
                "M_axial_Nm": float(ax.torque),
                "M_radial_Nm": float(ra.torque),
                "mu_axial": float(ax.friction_coefficient),
                "mu_radial": float(ra.friction_coefficient),
            }
        )
    return pd.DataFrame(rows)


#: Table 3 rows: catalogue values (kN) + the internal geometry bearingkit ASSUMES for each.
#: kind: ISO formula family; D_w [mm], D_pw [mm] = (d + D)/2, Z, α [deg], rows i, L_we [mm] (rollers).
STANDARD_BEARINGS = {
    "single-row angular contact ball (NSK 7206, 62×30×16)": dict(
        kind="angular_contact_ball", dw=9.525, dpw=46.0, z=14, alpha=30.0, i=1, c0r=14.80, cr=22.50
    ),
    "double-row angular contact ball (NSK 5206, 55×30×26)": dict(
        kind="angular_contact_ball", dw=7.144, dpw=42.5, z=13, alpha=30.0, i=2, c0r=20.50, cr=24.60
    ),
    "deep-groove ball (SKF 6206, 62×30×16)": dict(
        kind="deep_groove_ball", dw=9.525, dpw=46.0, z=9, alpha=0.0, i=1, c0r=12.90, cr=23.40
    ),
    "single-direction thrust ball (SKF 51206, 52×30×16)": dict(
        kind="thrust_ball", dw=7.938, dpw=41.0, z=14, alpha=90.0, i=1, c0a=51.00, ca=25.50
    ),
    "double-direction thrust ball (SKF 52306 class, 62×30×34)": dict(
        kind="thrust_ball", dw=9.525, dpw=47.0, z=12, alpha=90.0, i=1, c0a=73.50, ca=35.10
    ),
    "single-row tapered roller (SKF 30206, 62×30×17.25)": dict(
        kind="tapered_roller", dw=7.5, dpw=46.0, z=17, alpha=14.0, i=1, lwe=12.0, c0r=44.00, cr=50.00
    ),
    "single-row tapered roller (SKF 33206, 62×30×25; Table 3: H0 34.5)": dict(
        kind="tapered_roller", dw=7.6, dpw=46.0, z=18, alpha=14.0, i=1, lwe=19.0, c0r=88.00, cr=85.70
    ),
    "cylindrical roller (SKF NU1006, 55×30×13)": dict(
        kind="cylindrical_roller", dw=5.5, dpw=42.5, z=15, alpha=0.0, i=1, lwe=6.0, c0r=17.30, cr=17.90
    ),
    "cylindrical roller thrust (SKF 81206, 52×30×16)": dict(
        kind="thrust_cylindrical_roller",
        dw=6.0,
        dpw=41.0,
        z=19,
        alpha=90.0,
        i=1,
        lwe=6.0,
        c0a=134.0,
        ca=50.00,
    ),
}


#: f_c of a cylindrical roller thrust bearing (α = 90°) at γ = D_we/D_pw ≈ 0.12 [ISO 281 units]
#: (used for the 81206 row, γ = 0.146, where f_c ≈ 190: its C is ~4 % low):
#: ISO 281:2007 Table 9 (not shipped by bearingkit), value from memory [M] (0.10: 175.7, 0.12: 183.0,
#: 0.14: 189.4) — verify against the standard.
FC_THRUST_ROLLER_90_AT_012 = 183.0


def _standard_ratings(spec: dict) -> tuple[float, float]:
    dw, dpw, z, i = spec["dw"] * MM, spec["dpw"] * MM, spec["z"], spec["i"]
    alpha = np.radians(spec["alpha"])
    kind = spec["kind"]
    if kind.endswith("_ball"):
        thrust = kind == "thrust_ball"
        c0 = iso76.static_rating_ball(dw, dpw, alpha, z, i, kind="thrust" if thrust else "radial")
        c = iso281.dynamic_rating_ball(dw, dpw, alpha, z, i, bearing_type=kind)
    else:
        lwe = spec["lwe"] * MM
        thrust = kind.startswith("thrust_")
        c0 = iso76.static_rating_roller(dw, lwe, dpw, alpha, z, i, kind="thrust" if thrust else "radial")
        fc = FC_THRUST_ROLLER_90_AT_012 if kind == "thrust_cylindrical_roller" else None
        c = iso281.dynamic_rating_roller(dw, lwe, dpw, alpha, z, i, bearing_type=kind, fc=fc)
    return float(c0), float(c)


def table3_comparison() -> pd.DataFrame:
    """The prototype beside the Table 3 bearings: catalogue and ISO-recomputed C0, C [N].

    Columns: ``bearing``, ``direction`` (axial/radial), ``C0_catalogue_N``, ``C_catalogue_N``,
    ``C0_iso_N``, ``C_iso_N`` (the PTRB rows carry bearingkit's PTRB ratings in the ``_iso`` columns).
    """
    r = ptrb_ratings(ptrb_prototype())
    rows = [
        dict(
            bearing="PTRB prototype",
            direction="axial",
            C0_catalogue_N=38.36 * KN,
            C_catalogue_N=33.20 * KN,
            C0_iso_N=r.static_axial,
            C_iso_N=r.dynamic_axial,
        ),
        dict(
            bearing="PTRB prototype",
            direction="radial",
            C0_catalogue_N=19.93 * KN,
            C_catalogue_N=30.26 * KN,
            C0_iso_N=r.static_radial,
            C_iso_N=r.dynamic_radial,
        ),
    ]
    for name, spec in STANDARD_BEARINGS.items():
        c0, c = _standard_ratings(spec)
        axial = spec["kind"].startswith("thrust")
        key0, key = ("c0a", "ca") if axial else ("c0r", "cr")
        rows.append(
            dict(
                bearing=name,
                direction="axial" if axial else "radial",
                C0_catalogue_N=spec[key0] * KN,
                C_catalogue_N=spec[key] * KN,
                C0_iso_N=c0,
                C_iso_N=c,
            )
        )
    return pd.DataFrame(rows)


def nearest_table6(objectives: dict, case: str = "axial") -> pd.DataFrame:
    """Distance of each Table 6 point to the nearest solution of a computed front.

    Parameters
    ----------
    objectives : dict
        Arrays ``C0`` [N], ``C`` [N], ``mu`` [1] of a population (e.g. a pymoo front evaluated with
        :func:`bearingkit.papers.zheng2022.design.ptrb_objectives`).
    case : {"axial", "radial"}

    Returns
    -------
    pandas.DataFrame
        One row per Table 6 point of that case: its published objectives, the nearest solution's
        index and objectives, and the relative distance (objectives scaled by the published values).
    """
    suffix = "a" if case == "axial" else "r"
    pts = {k: v for k, v in TABLE6_OBJECTIVES.items() if k.startswith(f"x{suffix}")}
    c0 = np.asarray(objectives["C0"], float)
    c = np.asarray(objectives["C"], float)
    mu = np.asarray(objectives["mu"], float)
    rows = []
    for name, pub in pts.items():
        ref = np.array(
            [pub[f"C0{suffix}_kN"] * KN, pub[f"C{suffix}_kN"] * KN, pub[f"mu_{suffix}_1e3"] * 1e-3]
        )
        d = np.sqrt((((np.stack([c0, c, mu], axis=-1) - ref) / ref) ** 2).sum(axis=-1))
        j = int(np.argmin(d))
        rows.append(
            dict(
                point=name,
                C0_pub_N=ref[0],
                C_pub_N=ref[1],
                mu_pub=ref[2],
                index=j,
                C0_N=c0[j],
                C_N=c[j],
                mu=mu[j],
                distance=float(d[j]),
            )
        )
    return pd.DataFrame(rows)


def table6_at_published_designs(parameters=None, roller_count=None) -> pd.DataFrame:
    """Table 6 recomputed at the PUBLISHED design variables of each point (no optimiser involved).

    The rating and friction models' own check of §6: α, n, R_rr, d_R of xa1, xa2, xr1, xr2 and the
    prototype (D_pw and n·P = 12 mm held, as :func:`bearingkit.papers.zheng2022.design.ptrb_objectives`),
    at the §6 operating point (20 kN, 4000 rpm), with Z rollers from ``roller_count`` (point → Z;
    None: :data:`TABLE6_ROLLER_COUNT`; an int: that Z everywhere). Columns: ``point``, ``n_elements``,
    computed ``C0a_N, Ca_N, mu_a, C0r_N, Cr_N, mu_r``, the published values (``*_pub``) and relative
    errors (``*_err``). ``parameters``: a
    :class:`~bearingkit.analysis.friction.threaded.PTRBFrictionParameters` (None: the defaults).
    """
    from bearingkit.papers.zheng2022.design import ptrb_objectives

    if roller_count is None:
        roller_count = TABLE6_ROLLER_COUNT
    if isinstance(roller_count, int | np.integer):
        roller_count = dict.fromkeys(TABLE6, int(roller_count))
    names = list(TABLE6)
    x = [TABLE6[k] for k in names]
    design = (
        np.radians([p["alpha_deg"] for p in x]),
        np.array([p["n"] for p in x], float),
        np.array([p["R_rr_mm"] * MM for p in x]),
        np.array([p["d_R_mm"] * MM for p in x]),
    )
    z = np.array([roller_count[k] for k in names])
    res = {"axial": {}, "radial": {}}
    for zk in np.unique(z):  # the roller count is a scalar of ptrb_objectives: one call per count
        sel = z == zk
        for case in res:
            o = ptrb_objectives(
                *(d[sel] for d in design), case=case, parameters=parameters, n_elements=int(zk)
            )
            for key, val in o.items():
                res[case].setdefault(key, np.empty(len(names), np.asarray(val).dtype))[sel] = val
    ax, ra = res["axial"], res["radial"]
    out = pd.DataFrame({"point": names, "n_elements": z})
    cols = {
        "C0a_N": (ax["C0a"], "C0a_kN", KN),
        "Ca_N": (ax["Ca"], "Ca_kN", KN),
        "mu_a": (ax["mu"], "mu_a_1e3", 1e-3),
        "C0r_N": (ra["C0r"], "C0r_kN", KN),
        "Cr_N": (ra["Cr"], "Cr_kN", KN),
        "mu_r": (ra["mu"], "mu_r_1e3", 1e-3),
    }
    for col, (val, key, factor) in cols.items():
        pub = np.array([TABLE6_OBJECTIVES[k][key] * factor for k in names])
        out[col], out[f"{col}_pub"], out[f"{col}_err"] = val, pub, val / pub - 1.0
    return out
