"""Which life comes first, and why ISO/TS 16281 differs from ISO 281 for this bearing and case.

SI units: loads in N, lives in revolutions, lengths in m. For a bearing ISO 281 rates (one row, or two
equal rows: :mod:`bearingkit.analysis.rating.iso281`) the headline life is ISO 281's — the catalogue
method, what SKF's calculators and the commercial tools print first — and the ISO/TS 16281:2008 life from
the load distribution stands beside it with one line saying what the difference comes from. Where ISO 281
has no equivalent load (slewing rings, crossed roller, composites, threaded rows) the headline is the TS's.

The line is computed from the case. L10r / L10 splits into two factors:

- the method: the TS life of the ideal distribution under ISO 281's P (zero clearance, no tilt, the
  Stribeck load zone, evenly loaded rollers). For balls that is ISO 281's (C/P)^3 (the TS's constants are
  ISO 281's at ε = 0.5), factor 1. For rollers it is (C/(λν P))^4: the Lundberg–Palmgren line-contact
  exponent 4 where ISO 281 uses 10/3, and the λν (0.83 radial, 0.73 thrust) that ISO 281 builds into C
  divided out (ISO/TS 16281:2008 eq. (47)-(57)), factor λν^-4 (C/P)^(2/3) — 2.1 at P = C, 9.8 at C/P = 10;
- the load distribution the TS resolves and ISO 281 takes as nominal, L10r / L_ideal, with the causes
  present in the case named: operating clearance, tilt or moment, combined or axial load (ISO 281's X, Y),
  a held axial displacement, the roller profile and edge-stress factor, else the discrete elements and the
  operating contact angle.
"""

from __future__ import annotations

import numpy as np

from bearingkit.physics.life import iso16281

__all__ = ["HEADLINE_METHODS", "S0_SAME", "compare", "headline", "static_safety_difference"]

#: Headline life by availability: ISO 281 when it rates the bearing, else ISO/TS 16281.
HEADLINE_METHODS = ("ISO 281", "ISO/TS 16281")
#: Life exponents of the ideal TS distribution: balls (C/P)^3, rollers (C/(λν P))^4.
_IDEAL_EXPONENT = {"ball": 3.0, "roller": 4.0}
#: ISO 281 life exponents p.
_ISO_EXPONENT = {"ball": 3.0, "roller": 10.0 / 3.0}
#: Loaded share of a row's elements below which its load zone is called narrow [-] (wording only; the
#: ε = 0.5 zone of ISO 281's nominal case loads about half).
NARROW_ZONE = 0.25
#: Tilt [rad] below which a case counts as untilted (the solver's round-off of a symmetric case).
TILT_ROUND_OFF = 1e-12
#: Relative amount below which a load component counts as absent [-].
_ABSENT = 1e-9


def _causes(result, rows, case: int, free) -> list[str]:
    """What in this case makes the TS's distribution differ from ISO 281's nominal one."""
    load = np.asarray(result.load[case], float)
    fr, fa = float(np.hypot(load[0], load[1])), abs(float(load[2]))
    scale = max(fr, fa, 1.0)
    out = []
    clearance = max(float(np.max(getattr(r, "clearance", 0.0))) for r in result.model.rows)
    if clearance > 0.0:
        out.append(f"clearance {clearance * 1e6:.3g} µm")
    tilt = float(np.hypot(*np.asarray(result.displacement[case, 3:5], float)))
    moment = float(np.hypot(load[3], load[4])) if free[3] or free[4] else 0.0
    if moment > 0.0:
        out.append(f"moment {moment:.3g} N·m")
    elif tilt > TILT_ROUND_OFF:
        out.append(f"tilt {tilt * 1e3:.3g} mrad")
    if not free[2] and fa > _ABSENT * scale:
        out.append("the axial reaction of the held u_z")
    elif fr > _ABSENT * scale and fa > _ABSENT * scale:
        out.append("combined load (ISO 281's X, Y)")
    elif fa > _ABSENT * scale and rows[0].bearing_type in ("deep_groove_ball", "angular_contact_ball"):
        out.append("axial load (ISO 281's Y)")
    if len(rows) == 1:
        z = int(np.max(result.model.rows[0].n_elements))
        k = int(rows[0].loaded_count[case])
        if 0 < k < NARROW_ZONE * z:
            out.append(f"a narrow load zone ({k} of {z} elements loaded)")
    kinds = {r.kind for r in result.model.rows}
    if "spherical_roller" in kinds:
        out.append("the roller/raceway osculation")
    elif any(getattr(r, "n_slices", 1) > 1 for r in result.model.rows):
        out.append("the roller profile and edge-stress factor")
    return out or ["discrete elements, operating contact angle"]


def compare(result, rows, life, iso, free) -> list:
    """Per case a dict comparing the system L10r [rev] with ISO 281's L10 (module docstring), or None when
    either life is missing.

    Parameters
    ----------
    result : QuasiStaticResult
        The solved cases (their loads, displacements and rows).
    rows : list of RowRating
    life : MaskedArray (C,) [rev]
        System L10r.
    iso : Iso281Life or None
    free : array_like (5,) of bool
        DOFs the cases were solved with.

    Returns
    -------
    list of dict or None
        ``ratio`` L10r/L10, ``method_factor``, ``distribution_factor``, ``causes`` (list of str), ``text``.
    """
    n = len(life)
    if iso is None or iso.load_rating is None or not rows:
        return [None] * n
    element = rows[0].element
    thrust = rows[0].bearing_type.startswith("thrust")
    lam = iso16281.LAMBDA_NU["thrust" if thrust else "radial"]
    free = np.asarray(free, bool)
    out = []
    for c in range(n):
        if np.ma.getmaskarray(life)[c] or np.ma.getmaskarray(iso.life)[c]:
            out.append(None)
            continue
        l10r, l10 = float(life[c]), float(iso.life[c])
        c_over_p = iso.load_rating / float(iso.load[c])
        if element == "roller":
            method = lam ** -_IDEAL_EXPONENT[element] * c_over_p ** (
                _IDEAL_EXPONENT[element] - _ISO_EXPONENT[element]
            )
        else:
            method = 1.0
        ratio = l10r / l10
        dist = ratio / method
        causes = _causes(result, rows, c, free)
        text = f"ISO/TS 16281 L10r = {ratio:.3g} × ISO 281 L10"
        if element == "roller":
            text += (
                f": ×{method:.3g} from the TS's line-contact life exponent 4 (ISO 281: 10/3) with "
                f"λν = {lam:g} divided out of C (λν⁻⁴ (C/P)^(2/3), C/P = {c_over_p:.3g}), ×{dist:.3g} "
                f"from the load distribution it resolves ({', '.join(causes)})"
            )
        else:
            text += f", from the load distribution the TS resolves ({', '.join(causes)})"
        out.append(
            {
                "ratio": ratio,
                "method_factor": method,
                "distribution_factor": dist,
                "causes": causes,
                "text": text,
            }
        )
    return out


def headline(system: dict) -> dict:
    """The life shown first for a case's ``system`` dict: ISO 281's when it rates the bearing, else the TS's.

    Returns ``{"method", "L10_rev", "L10h_h", "Lnm_rev", "Lnmh_h", "why"}`` (None where not computed).
    """
    if system.get("L10_iso281_rev") is not None:
        return {
            "method": HEADLINE_METHODS[0],
            "L10_rev": system["L10_iso281_rev"],
            "L10h_h": system.get("L10h_iso281_h"),
            "Lnm_rev": system.get("Lnm_iso281_rev"),
            "Lnmh_h": system.get("Lnm_iso281_h"),
            "why": "ISO 281 basic rating life, as catalogues and calculators give it; ISO/TS 16281 from the "
            "load distribution beside it (life_difference says why they differ)",
        }
    note = system.get("iso281_note") or "ISO 281 has no equivalent load for this bearing"
    return {
        "method": HEADLINE_METHODS[1],
        "L10_rev": system.get("L10r_rev"),
        "L10h_h": system.get("L10h_h"),
        "Lnm_rev": system.get("Lnmr_rev"),
        "Lnmh_h": system.get("Lnmr_h"),
        "why": f"ISO/TS 16281 reference rating life from the load distribution ({note})",
    }


#: Two static safeties within this relative difference [-] are the same for the report (no line).
S0_SAME = 0.05


def static_safety_difference(s0_iso76, s0_rows) -> str | None:
    """The line saying why ISO 76's s0 = C0/P0 and the rows' s0 from p_max differ, and which governs;
    None when either is missing or they agree within :data:`S0_SAME`.

    ISO 76:2006 clause 10 rates the bearing by C0/P0: its C0 assumes the static load distribution of the
    nominal bearing under P0. The rows' s0 = (p_limit / p_max)^n (ISO 76's limit contact pressures, n = 3
    for point and 2 for line contact) reads the largest contact pressure of the load distribution solved:
    clearance, tilt, the roller profile and edge stress, the operating contact angle. Both check the same
    permanent deformation (about 1e-4 of the element diameter); the smaller governs.
    """
    if s0_iso76 is None or s0_rows is None or not (s0_iso76 > 0 and s0_rows > 0):
        return None
    if abs(s0_rows / s0_iso76 - 1.0) <= S0_SAME:
        return None
    lower = "the rows' s0 from p_max" if s0_rows < s0_iso76 else "ISO 76's s0 = C0/P0"
    return (
        f"ISO 76 s0 = C0/P0 = {s0_iso76:.4g} (the catalogue method: its C0 assumes the nominal load "
        f"distribution under P0) and the rows' s0 = {s0_rows:.4g} from the largest contact pressure of the "
        "load distribution solved (clearance, tilt, roller profile and edge stress) check the same "
        f"permanent deformation; the smaller, {lower}, governs"
    )
