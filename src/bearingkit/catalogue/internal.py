"""Internal-geometry estimate of standard bearings from their boundary dimensions. SI units.

Catalogues print d, D, B (T) and the load ratings, not the internal geometry the mechanics needs.
Each family has one rule set (:data:`RULES`) turning the boundary dimensions into element count Z,
element diameter D_w (D_we), effective length L_we, pitch diameter d_m, conformities or crowning and
contact angle; :func:`estimate` applies it and returns an :class:`Estimate` (SI) with a note saying how.

The rules are the bearing-design rules of the textbooks, with their constants in one table:

- pitch diameter d_m = (d + D)/2 (Harris & Kotzalas 2006, *Essential Concepts*, ch. 2 [M]); for
  cylindrical roller bearings with a published roller inscribed diameter F_w, d_m = F_w + D_we;
- element diameter D_w = k_w (D − d) (deep groove series: k_w ≈ 0.3, the rule quoted in the brief;
  other families: the per-family constant of :data:`RULES`);
- ball count of Conrad-assembled deep groove bearings from the assembly (fill) angle of Harris
  (2006, ch. 2 [M]): φ = 2(Z − 1) D_w/d_m ≤ φ_max. φ_max = 189° is a CALIBRATION on one size, the
  6309: the smallest limit that gives its estimated 17.05 mm balls (0.31 (D − d)) the eighth ball its
  published C and C0 imply (2·7·17.05/72.5 rad = 188.6°, rounded up); every other size is a
  prediction (docs/catalogue.md). The 6205 with its 9 balls of 7.938 mm on d_m = 39.04 mm reaches
  186.4°, and the ball size and count NSK's C and C0 imply (ISO 281 and ISO 76 inverted) give fill angles
  of 179–198° over the 62 and 63 series (median 189°) [M: Harris's rule]; the same rule per
  row for the double-row angular contact series 32/33 (no filling slots; NSK's C and C0 together imply
  that count, tests/catalogue/test_estimate.py);
- other rows: the cage pitch, Z = floor(π d_m / (s D_w)) with a pitch ratio s > 1 (cage bars between
  the elements), s per family in :data:`RULES`;
- conformities f_i = 0.52, f_o = 0.53 (radial, angular contact), 0.54 (thrust) (Harris 2006 ch. 2:
  0.515–0.52 inner, 0.52–0.53 outer [M]);
- tapered rows: cup angle from the catalogue's e, α_o = atan(e/1.5) (ISO 281 cl. 7.2: e = 1.5 tan α);
  roller half angle ε = 1.5° [M] (seed 001's 32008 has 1.50°), cone angle α_i = α_o − 2ε;
- angular contact: the nominal angle of the designation suffix (B 40°, AC 25°, A 30°, C 15°);
  four-point 35° (NSK E1102 B68 prints the load-centre spacing a0 = 0.700 d_m = d_m tan 35°; SKF 6000
  p. 452: "contact angle 35°"); double-row 32/33 as printed by the source (NSK e = 0.68 → 25°);
- self-aligning ball and spherical roller rows: α = atan(e/1.5) from the e the catalogue prints per
  bearing (ISO 281 Table 3 and cl. 7.2: e = 1.5 tan α for both kinds);
- spherical roller: two rows of barrel rollers, D_we = k_w (D − d), L_we = k_L B/2 per row, d_m = (d + D)/2,
  k_w and k_L per design (NSK's EA or the standard one, :data:`SPHERICAL_RULES`);
- spherical roller thrust: one row, α = atan 1.2 from the equivalent load NSK prints (ISO 281 8.2:
  X = tan α), D_we = k_w T and L_we = k_L T per design (NSK's E design or the standard one), Z from the
  cage pitch, d_m = (d + D)/2 (:data:`SPHERICAL_THRUST_RULES`);
- needle roller: d_m = F_w + D_w with the published roller inscribed diameter F_w, D_w = k_w (D − F_w)/2
  (the needle takes a share of the outer-ring section), L_we = k_L C (C the ring width);

The family constants k_w, s and the length ratios are not given by the design texts for every
family; where they are chosen here they are chosen once, in :data:`RULES`, and docs/catalogue.md lists
the computed ISO 281 C and ISO 76 C0 against the catalogue for every tabulated size (the tests check
them within 10 %).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from bearingkit.catalogue.tables import Entry
from bearingkit.errors import InputError
from bearingkit.physics.life.iso281_load import E_TAN_FACTOR
from bearingkit.physics.life.kinds import SELF_ALIGNING_CONFORMITY_INNER

DEG = math.pi / 180.0

#: Harris's Conrad assembly angle limit φ_max [rad]: calibrated on the 6309 (module docstring); valid for
#: the Conrad-assembled deep groove and double-row angular contact rows of the tables.
CONRAD_FILL_ANGLE = 189.0 * DEG
#: Roller end allowance [m]: the effective length L_we of ISO 281/76 excludes the roller end chamfers,
#: which do not scale with the bearing. CALIBRATED on the 32008 X: the ISO 76 C0 of seed 001's published
#: roller (Z = 23, D_we = 6.49 mm, L = 13.66 mm, α 14.2°) is 8.2 % above NSK's 71.0 kN, i.e. NSK rates
#: an effective length 13.66/1.082 = 12.62 mm, 1.0 mm shorter. Subtracted from the length rule of
#: tapered and cylindrical rollers (L_we = k_L B − this); valid for bores 10–100 mm of the tables.
ROLLER_END_ALLOWANCE = 1.0e-3
#: Nominal contact angles of the angular contact suffixes [rad] (NSK E1102 B50 note 2; SKF AC = 25°).
CONTACT_ANGLES = {"B": 40.0 * DEG, "AC": 25.0 * DEG, "A": 30.0 * DEG, "C": 15.0 * DEG}
#: Four-point contact (QJ) nominal contact angle [rad] (NSK E1102 B68 load-centre spacing a0 = d_m tan 35°;
#: SKF General Catalogue 6000 p. 452).
FOUR_POINT_ANGLE = 35.0 * DEG
#: Tapered roller half angle ε [rad] [M] (seed 001 Table 1, 32008: ε = 0.0262 rad).
TAPER_HALF_ANGLE = 1.5 * DEG
#: Relative margin that keeps self-aligning balls strictly on their side of the centre plane (the engine's
#: row check is strict); a numerical margin, not a design value.
CENTRE_PLANE_MARGIN = 1e-3
#: Self-aligning ball rows without a published e: the two rows fill the ring width, B = D_w + d_m tan α,
#: with the ball D_w = this · (D − d). CHOSEN over the 42 sizes 1200–1220, 2200–2220, whose published e
#: it gives within ±15 % (mean |error| 6 %, tests/catalogue/test_series_new.py); used only for rows the
#: source prints no e for (13, 23).
SELF_ALIGNING_E_BALL_SHARE = 0.25
#: Cage pitch ratio s = π d_m / (Z D_w) of angular contact and four-point rows with MACHINED cages (brass,
#: phenolic): thicker cage bars than a pressed steel cage's (RULES). The median of the geometry NSK's C and
#: C0 imply over the 72xxC sizes (machined brass by NSK E1102 B48 Table 1), the calibration set; 73, QJ
#: and the pressed steel pitch's other series are predictions (docs/catalogue.md).
MACHINED_CAGE_PITCH = 1.227
#: Largest bore codes with a pressed steel cage per angular contact series (NSK E1102 B48 Table 1: 70A
#: 7000–7018, 72A/B 7200–7222, 73A/B 7300–7320; 70C, 72C, 79A5/C machined brass throughout).
PRESSED_STEEL_CAGE_UP_TO = {"70": 18, "72": 22, "73": 20}
#: Spherical roller thrust bearings (292, 293, 294): tan α of every size. NSK E1102 B225-B229 print one
#: dynamic equivalent load for all, P = 1.2 F_r + F_a, which is ISO 281 8.2's P = tan α F_r + F_a of a
#: thrust roller bearing at tan α = 1.2 (α = 50.2°); the static P0 = 2.8 F_r + F_a (ISO 76: 2.3 tan α =
#: 2.76) and the limit F_r/F_a ≤ 0.55 (ISO 281: F_a/F_r > e = 1.5 tan α = 1.8) agree with it.
SPHERICAL_THRUST_TAN = 1.2
#: Groove conformities r/D_w (Harris 2006 ch. 2 [M]).
CONFORMITY_INNER = 0.52
CONFORMITY_OUTER = 0.53
CONFORMITY_THRUST = 0.54


@dataclass(frozen=True)
class Rule:
    """Design-rule constants of one family (all dimensionless).

    Attributes
    ----------
    k_w : float
        Element diameter D_w = k_w (D − d) (thrust: k_w · T, the height).
    pitch : float
        Cage pitch ratio s: Z = floor(π d_m / (s D_w)); 0 = Conrad fill-angle rule.
    length : float
        Effective roller length L_we = length · (width measure of the family); 0 for balls.
    rows : int
        Rows of elements.
    k_b : float
        Width cap of radial rows: D_w ≤ k_b · B / rows (narrow series such as 160 and 618).
    """

    k_w: float
    pitch: float = 0.0
    length: float = 0.0
    rows: int = 1
    k_b: float = 0.65
    wall: float = 0.0


#: Spherical roller thrust rollers by design (the ``design`` column: ``E`` NSK's E design, ``""`` the
#: standard one): D_we = k_w T, L_we = length · T (T the height), Z from the cage pitch of the radial
#: spherical rule (1.15, not chosen here). CALIBRATED: k_w and length are the medians of the geometry
#: NSK's C_a and C_0a imply (ISO 281 eq. (11) and ISO 76 eq. (7) solved for D_we and L_we at the α above,
#: d_m = (d + D)/2, Z = π d_m/(1.15 D_we)) over the 294 series: its 14 E sizes (29412 E-29432 E) for the E
#: rule, its 19 standard sizes (29434-294/500) for the other; 293 and 292 are predictions
#: (docs/catalogue.md).
SPHERICAL_THRUST_RULES = {
    "E": Rule(k_w=0.445, pitch=1.15, length=0.580),
    "": Rule(k_w=0.368, pitch=1.15, length=0.518),
}
#: Radial spherical roller bearings by design (the ``design`` column: ``EA`` NSK's high-capacity design,
#: ``""`` every other: CA, CD, C, BCA): D_we = k_w (D − d), L_we = length · B/2 per row, Z per row from the
#: cage pitch 1.15 (chosen before, by C over the 222/223 tables). CALIBRATED: k_w and length are the
#: medians of the geometry NSK's C and C0 imply (ISO 281 eq. (9) and ISO 76 eq. (7) solved for D_we and
#: L_we at the printed e's α, d_m = (d + D)/2, Z = π d_m/(1.15 D_we)): over the 230 series (41 sizes, NSK
#: E1102 B182-B200: 31 CA, 9 CD, 1 C) for the standard rule (0.2470, 0.7162), over the 16 EA sizes of the
#: 222 series (22208-22226 EA, B180-B186) for the EA rule (0.2607, 0.7528). The other series and 223 EA and
#: 213 EA are predictions (docs/catalogue.md). Before issue 33's third part: one rule, 0.24 and 0.80 chosen
#: by C alone, which put C0 +8…+11 % above NSK's in the 222 and 230-241 series (mean per series).
SPHERICAL_RULES = {
    "EA": Rule(k_w=0.261, pitch=1.15, length=0.753, rows=2),
    "": Rule(k_w=0.247, pitch=1.15, length=0.716, rows=2),
}
#: The one place where the rule constants live (module docstring: where they come from).
RULES: dict[str, Rule] = {
    "deep_groove_ball": Rule(k_w=0.31, k_b=0.70),
    # D_w and the pitch of a pressed steel cage: the medians of the geometry NSK's C and C0 imply over the
    # 72 series (calibration set, docs/catalogue.md); machined cages: MACHINED_CAGE_PITCH (cage_type)
    "angular_contact_ball": Rule(k_w=0.317, pitch=1.145, k_b=0.80),
    # no filling slots: each row Conrad-assembled like a deep groove row, the deep groove ball rule with
    # the angular contact width cap per row (docs/catalogue.md: NSK's C and C0 together imply it)
    "double_row_angular_contact_ball": Rule(k_w=0.31, rows=2, k_b=0.80),
    # QJ: the angular contact rule unchanged, machined brass cages (nothing chosen for four-point bearings)
    "four_point_contact_ball": Rule(k_w=0.317, pitch=1.145, k_b=0.80),
    # ball size mostly set by the width and centre-plane limits (estimate()); pitch = angular contact's
    # pitch CALIBRATED on the 1205 (docs/catalogue.md): at the angular contact 1.20 its count sits on the
    # boundary (π d_m/(s D_w) = 14.03 balls per row); 1.205 gives the 13 its published C0 implies
    "self_aligning_ball": Rule(k_w=0.30, pitch=1.205, rows=2),
    # length ratio re-chosen by C over the table with the roller end allowance (0.60 B before it)
    "cylindrical_roller": Rule(k_w=0.27, pitch=1.15, length=0.63),
    "tapered_roller": Rule(k_w=0.23, pitch=1.14, length=0.72),
    "thrust_ball": Rule(k_w=0.70, pitch=1.05, k_b=0.36),
    "thrust_cylindrical_roller": Rule(k_w=0.42, pitch=1.40, length=0.45),
    # by design: SPHERICAL_RULES (estimate() picks the row's)
    "spherical_roller": SPHERICAL_RULES[""],
    # by design: SPHERICAL_THRUST_RULES (estimate() picks the row's)
    "spherical_roller_thrust": SPHERICAL_THRUST_RULES["E"],
    # NN30 (diameter series 0): the roller of the NU10 rule (same diameter series) and the single-row
    # length ratio on each half of the width; nothing chosen (no stored catalogue rates NN30)
    "double_row_cylindrical_roller": Rule(k_w=0.22, pitch=1.15, length=0.63, rows=2),
    # needle pitch and length ratio from NSK's cage & needle assemblies with published D_w (docs), the
    # needle share of the section k_w chosen by C over the NA table
    "needle_roller": Rule(k_w=0.65, pitch=1.80, length=0.80),
}
#: The light angular contact sections' rule (SERIES_RULES: 70 and 719): the ball of NSK's 70 C, the family's
#: pitches and width cap (the calibration is described where the rule is used).
LIGHT_ANGULAR_CONTACT_RULE = Rule(k_w=0.295, pitch=1.145, k_b=0.80)
#: Series whose proportions differ from their family's (light, narrow sections).
SERIES_RULES: dict[tuple[str, str], Rule] = {
    # chosen by C over the NU10 table with the roller end allowance (0.20, 0.38 B before it)
    ("cylindrical_roller", "10"): Rule(k_w=0.22, pitch=1.15, length=0.42),
    # NU19: the light-section rule of NU10 (the 19 sections are as wide for their height, B ≈ 0.5 (D − d));
    # nothing chosen for it (KRW's 2006 NU19 ratings, rated later, are the E design's: docs, Known deviations)
    ("cylindrical_roller", "19"): Rule(k_w=0.22, pitch=1.15, length=0.42),
    # heavy series 64: the section is deep for its width (B ≈ 0.38 (D - d)), so the width cap decides;
    # 0.80 B is the angular contact rule's cap (chosen over the 64 table: C -3 % median, see the docs)
    ("deep_groove_ball", "64"): Rule(k_w=0.31, k_b=0.80),
    # thin section 618 (B = 5, 7, 10 mm steps): the ball is set by the width, not the section; the ball
    # size and count NSK's C and C0 imply (ISO 281 and ISO 76 solved for D_w, Z) give D_w = 0.48-0.56 B
    # (stock balls: 3/32 in = 2.381 mm at B = 5, 3.5 mm at B = 7); 0.55 B chosen by C over the 618 table
    # (median C -1 %, it was +14 % with the 0.70 B cap), C0 follows (docs/catalogue.md)
    ("deep_groove_ball", "618"): Rule(k_w=0.31, k_b=0.55),
    # light angular contact sections (ISO diameter series 0 and 9: the spindle series 70 and 719): the ball
    # CALIBRATED on NSK's 70 C (23 sizes, machined brass, B50-B56): the median of the ball NSK's C and C0
    # imply there, 0.2952 (D - d) (their cage pitch: 1.227, the machined pitch of the 72 C set); the cage
    # pitches are the angular contact rule's. 70 A/AC/B (NSK, NTN, KOYO) and 719 C/AC are predictions.
    # Diameter series 8 (718) keeps the family rule: AKE's two 71822 rows imply 0.313-0.317 (D - d).
    ("angular_contact_ball", "70"): LIGHT_ANGULAR_CONTACT_RULE,
    ("angular_contact_ball", "719"): LIGHT_ANGULAR_CONTACT_RULE,
}


@dataclass(frozen=True)
class Estimate:
    """Estimated internal geometry of one catalogue bearing (SI).

    Attributes
    ----------
    entry : Entry
        The catalogue row (boundary dimensions, published ratings).
    n_elements : int
        Elements per row Z.
    element_diameter : float [m]
        D_w (balls) or mean D_we (rollers).
    pitch_diameter : float [m]
        d_m.
    contact_angle : float [rad]
        Nominal contact angle α (tapered: cup angle α_o).
    effective_length : float or None [m]
        L_we of rollers.
    rows : int
    extra : dict
        Family-specific values (SI): conformities, cone angle, roller small/large diameters, row spacing.
    notes : tuple of str
        How the geometry was obtained (every face shows them).
    """

    entry: Entry
    n_elements: int
    element_diameter: float
    pitch_diameter: float
    contact_angle: float
    effective_length: float | None = None
    rows: int = 1
    extra: dict = field(default_factory=dict)
    notes: tuple = ()


def _pitch_count(d_m: float, d_w: float, pitch: float) -> int:
    return math.floor(math.pi * d_m / (pitch * d_w))


def _conrad_count(d_m: float, d_w: float) -> int:
    """Largest Z with Harris's assembly angle 2(Z − 1) D_w/d_m ≤ φ_max."""
    return math.floor(CONRAD_FILL_ANGLE * d_m / (2.0 * d_w)) + 1


def fill_angle(n_elements: int, element_diameter: float, pitch_diameter: float) -> float:
    """Harris's Conrad assembly angle φ = 2(Z − 1) D_w/d_m [rad] (Harris & Kotzalas 2006, ch. 2) [M]."""
    return 2.0 * (n_elements - 1) * element_diameter / pitch_diameter


def estimate(entry: Entry, contact_angle: float | None = None) -> Estimate:
    """Internal geometry of ``entry`` by the rules of :data:`RULES` (module docstring).

    Parameters
    ----------
    entry : Entry
        A catalogue row.
    contact_angle : float, optional [rad]
        Overrides the family's nominal angle (angular contact: from the suffix).
    """
    fam = entry.family
    rule = SERIES_RULES.get((fam, entry.series), RULES[fam])
    d, big_d, width = entry.bore, entry.outer_diameter, entry.width
    d_m = 0.5 * (d + big_d)
    notes = [
        f"internal geometry ESTIMATED from the boundary dimensions of {entry.designation} ({entry.source})"
    ]
    extra: dict = {}
    length = None
    if fam == "thrust_ball":
        d_w = min(rule.k_w * width, rule.k_b * (big_d - d))
        z = _pitch_count(d_m, d_w, rule.pitch)
        alpha = 0.5 * math.pi
        extra["conformity"] = CONFORMITY_THRUST
        notes.append(
            f"D_w = min({rule.k_w} T, {rule.k_b} (D - d)), Z from cage pitch {rule.pitch} D_w, "
            "d_m = (d + D)/2"
        )
    elif fam == "thrust_cylindrical_roller":
        d_w = rule.k_w * width
        length = rule.length * 0.5 * (big_d - d)
        z = _pitch_count(d_m, d_w, rule.pitch)
        alpha = 0.5 * math.pi
        notes.append(
            f"D_we = {rule.k_w} T, L_we = {rule.length} (D - d)/2, Z from cage pitch {rule.pitch} D_we, "
            "d_m = (d + D)/2"
        )
    elif fam == "spherical_roller_thrust":
        design = entry.extra.get("design", "")
        rule = SPHERICAL_THRUST_RULES.get(design, SPHERICAL_THRUST_RULES[""])
        d_w, length = rule.k_w * width, rule.length * width
        z = _pitch_count(d_m, d_w, rule.pitch)
        alpha = math.atan(SPHERICAL_THRUST_TAN) if contact_angle is None else contact_angle
        notes.append(
            f"one row ({'NSK E design' if design == 'E' else 'standard design'}): D_we = {rule.k_w} T, "
            f"L_we = {rule.length} T, Z from cage pitch {rule.pitch} D_we, d_m = (d + D)/2, "
            f"alpha = atan({SPHERICAL_THRUST_TAN}) from the printed P = {SPHERICAL_THRUST_TAN} F_r + F_a "
            "(ISO 281 8.2: X = tan alpha)"
        )
    elif fam == "spherical_roller":
        design = "EA" if entry.extra.get("design") == "EA" else ""
        rule = SPHERICAL_RULES[design]
        length = rule.length * 0.5 * width
        d_w = rule.k_w * (big_d - d)
        z = _pitch_count(d_m, d_w, rule.pitch)
        if contact_angle is None and not entry.extra.get("e"):
            alpha = spherical_angle_filling_width(entry, d_w, length, d_m)
            how = (
                f"alpha = {math.degrees(alpha):.1f} deg ESTIMATED (the source prints no e): the rows fill "
                "the width, each roller end at the ring face less the chamfer"
            )
            half_reach = 0.5 * (length * math.cos(alpha) + d_w * math.sin(alpha))
            if 0.5 * d_m * math.tan(alpha) - half_reach <= CENTRE_PLANE_MARGIN * d_w:
                # a narrow section (213): the rollers would cross the centre plane; the two rows then span
                # the width between the centre plane and the faces, each roller shortened to fit
                z_c = 0.5 * (0.5 * width - entry.chamfer)
                alpha = math.atan(2.0 * z_c / d_m)
                length = (2.0 * z_c * (1.0 - CENTRE_PLANE_MARGIN) - d_w * math.sin(alpha)) / math.cos(alpha)
                how += (
                    "; the rows meet at the centre plane (narrow section): alpha = "
                    f"{math.degrees(alpha):.1f} deg, L_we = {length * 1e3:.3g} mm"
                )
        else:
            alpha = _nominal_angle(entry, contact_angle)
            if contact_angle is not None:
                how = f"alpha = {math.degrees(alpha):.1f} deg (given)"
            else:
                how = f"alpha = atan(e/1.5) from the published e = {entry.extra['e']}"
            # the two rows cannot overlap: at a shallow printed e in a narrow section (213 EA) the rule's
            # roller would reach across the centre plane, so it is held to the largest diameter that stays
            # on its side (its inner end 0.5 d_m tan α − (L_we cos α + D_we sin α)/2 ≥ margin · D_we). Only
            # for the printed e and only a trim (at least half the rule's roller): a given angle is the
            # user's, and a row that crosses by more is not one this rule describes.
            d_fit = (0.5 * d_m * math.tan(alpha) - 0.5 * length * math.cos(alpha)) / (
                0.5 * math.sin(alpha) + CENTRE_PLANE_MARGIN
            )
            if contact_angle is None and 0.5 * d_w <= d_fit < d_w:
                d_w = d_fit
                z = _pitch_count(d_m, d_w, rule.pitch)
                how += f"; D_we held to {d_w * 1e3:.3g} mm (the row stays on its side of the centre plane)"
        extra["row_offset"] = 0.5 * d_m * math.tan(alpha)
        notes.append(
            f"two rows ({'NSK EA design' if design else 'standard design'}): D_we = {rule.k_w} (D - d), "
            f"L_we = {rule.length} B/2, Z per row from cage pitch "
            f"{rule.pitch} D_we, d_m = (d + D)/2, {how}"
        )
    elif fam == "needle_roller":
        f_w = entry.number("F_w_mm", 1e-3)
        d_w = rule.k_w * 0.5 * (big_d - f_w)
        d_m = f_w + d_w
        length = rule.length * width
        z = _pitch_count(d_m, d_w, rule.pitch)
        alpha = 0.0
        extra["inner_ring"] = entry.extra.get("inner_ring") != "no"
        notes.append(
            f"D_w = {rule.k_w} (D - F_w)/2, d_m = F_w + D_w with the published F_w, L_we = {rule.length} C, "
            f"Z from cage pitch {rule.pitch} D_w"
        )
    else:
        if fam == "self_aligning_ball":
            # the rows sit on the sphere at ±α: ball centres at z = ±(d_m/2) tan α, so a ball stays within
            # the ring width when D_w ≤ B − d_m tan α and on its side of the centre plane (the engine's
            # rows.self_aligning refuses balls crossing it) when D_w < d_m tan α: the geometry's own limits
            spread = d_m * math.tan(_nominal_angle(entry, contact_angle))
            cap = min(width - spread, spread * (1.0 - CENTRE_PLANE_MARGIN))
            cap_text = "min(B - d_m tan(alpha), d_m tan(alpha))"
        else:
            cap, cap_text = rule.k_b * width / rule.rows, f"{rule.k_b} B/{rule.rows}"
        d_w = min(rule.k_w * (big_d - d) - rule.wall, cap)
        if rule.k_w * (big_d - d) - rule.wall > d_w:
            notes.append(f"D_w capped at {cap_text} by the width")
        if rule.pitch == 0.0:
            # Conrad-assembled rows (deep groove; double row 32/33 without filling slots, one row at a time)
            z = _conrad_count(d_m, d_w)
            alpha = _nominal_angle(entry, contact_angle)
            per_row = " per row" if rule.rows > 1 else ""
            notes.append(
                f"D_w = {rule.k_w} (D - d), d_m = (d + D)/2, Z{per_row} = largest "
                f"with Conrad fill angle 2(Z-1) D_w/d_m <= {math.degrees(CONRAD_FILL_ANGLE):.0f} deg (Harris)"
            )
        else:
            if fam == "cylindrical_roller":
                f_w = entry.number("F_w_mm", 1e-3)
                if f_w is not None:
                    d_m = f_w + d_w
                    notes.append("d_m = F_w + D_we with the published roller inscribed diameter F_w")
                length = rule.length * width - ROLLER_END_ALLOWANCE
            elif fam == "double_row_cylindrical_roller":
                length = rule.length * width / rule.rows - ROLLER_END_ALLOWANCE
                extra["row_spacing"] = width / rule.rows
            elif fam == "tapered_roller":
                length = rule.length * width - ROLLER_END_ALLOWANCE
            pitch, cage = rule.pitch, ""
            if fam in ("angular_contact_ball", "four_point_contact_ball"):
                cage = cage_type(entry)
                pitch = rule.pitch if cage == "pressed steel" else MACHINED_CAGE_PITCH
                cage = f" ({cage} cage)"
            z = _pitch_count(d_m, d_w, pitch)
            alpha = _nominal_angle(entry, contact_angle)
            what = "D_we" if length is not None else "D_w"
            parts = [f"{what} = {rule.k_w} (D - d)", f"Z from cage pitch {pitch} {what}{cage}"]
            if "F_w" not in notes[-1]:
                parts.append("d_m = (d + D)/2")
            if length:
                what = {"tapered_roller": "B (cone width)", "double_row_cylindrical_roller": "B/2 per row"}
                what = what.get(fam, "B")
                parts.append(f"L_we = {rule.length} {what} - {ROLLER_END_ALLOWANCE * 1e3:g} mm (roller ends)")
            notes.append(", ".join(parts))
    if fam in (
        "deep_groove_ball",
        "angular_contact_ball",
        "double_row_angular_contact_ball",
        "four_point_contact_ball",
    ):
        extra.update(conformity_inner=CONFORMITY_INNER, conformity_outer=CONFORMITY_OUTER)
    if fam == "self_aligning_ball":
        # ISO 281/76 assume this inner conformity for self-aligning ball bearings (physics.life.kinds);
        # the outer raceway is the sphere through the ball centres
        extra["conformity_inner"] = SELF_ALIGNING_CONFORMITY_INNER
        source_e = (
            f"the published e = {entry.extra['e']}"
            if entry.extra.get("e")
            else f"e = {1.5 * math.tan(alpha):.2f} ESTIMATED (the source prints none): the rows fill the "
            f"width, B = {SELF_ALIGNING_E_BALL_SHARE} (D - d) + d_m tan(alpha)"
        )
        notes.append(
            f"alpha = atan(e/1.5) from {source_e}, inner conformity "
            f"{SELF_ALIGNING_CONFORMITY_INNER}, outer raceway a sphere"
        )
    if fam == "tapered_roller":
        half = TAPER_HALF_ANGLE
        extra.update(
            contact_angle_inner=alpha - 2.0 * half,
            roller_angle=half,
            small_diameter=d_w - length * math.tan(half),
            large_diameter=d_w + length * math.tan(half),
        )
        notes.append(
            f"cup angle atan(e/1.5) from the published e = {entry.extra['e']}, roller half angle "
            f"{math.degrees(half):.1f} deg, cone angle = cup angle - 2 x half angle"
        )
    if fam == "double_row_angular_contact_ball":
        extra["row_spacing"] = 0.5 * width
        notes.append("modelled as an angular contact pair DB with the rows B/2 apart")
    if fam == "double_row_cylindrical_roller":
        notes.append("two equal rows of rollers on shared rings, B/2 apart")
    if z < 3:
        raise InputError(
            f"{entry.designation}: estimated element count ({z}) below 3; the rules do not apply"
        )
    return Estimate(
        entry=entry,
        n_elements=z,
        element_diameter=d_w,
        pitch_diameter=d_m,
        contact_angle=alpha,
        effective_length=length,
        rows=rule.rows,
        extra=extra,
        notes=tuple(n for n in notes if n),
    )


def cage_type(entry: Entry) -> str:
    """``"pressed steel"`` or ``"machined"`` cage of an angular contact or four-point catalogue row.

    NSK E1102 B48 Table 1: 70A up to 7018, 72A/B up to 7222, 73A/B up to 7320 have pressed steel cages, the
    larger sizes and every 15° (C) and 79 row machined brass ones. The spindle series (C, AC; 718, 719)
    and four-point bearings (SKF QJ … MA, NSK QJ) take machined cages.
    """
    if entry.family == "four_point_contact_ball":
        return "machined"
    code = entry.designation[len(entry.series) : len(entry.series) + 2]
    angle = entry.designation[len(entry.series) + 2 :]
    limit = PRESSED_STEEL_CAGE_UP_TO.get(entry.series)
    if angle in ("A", "B") and limit is not None and code.isdigit() and int(code) <= limit:
        return "pressed steel"
    return "machined"


def _nominal_angle(entry: Entry, override: float | None) -> float:
    if override is not None:
        return override
    fam = entry.family
    if fam == "angular_contact_ball":
        return float(entry.extra["contact_angle_deg"]) * DEG
    if fam == "double_row_angular_contact_ball":
        return float(entry.extra["contact_angle_deg"]) * DEG
    if fam == "four_point_contact_ball":
        return FOUR_POINT_ANGLE
    if fam == "self_aligning_ball" and not entry.extra.get("e"):
        # no printed e (series 13, 23): the two rows fill the width, B = D_w + d_m tan α
        d_m = 0.5 * (entry.bore + entry.outer_diameter)
        ball = SELF_ALIGNING_E_BALL_SHARE * (entry.outer_diameter - entry.bore)
        return math.atan((entry.width - ball) / d_m)
    if fam in ("tapered_roller", "self_aligning_ball", "spherical_roller"):
        # ISO 281:2007 Table 3 (self-aligning ball) and 7.2 (radial roller): e = 1.5 tan α
        return math.atan(float(entry.extra["e"]) / E_TAN_FACTOR)
    return 0.0


def spherical_angle_filling_width(entry: Entry, d_we: float, l_we: float, d_m: float) -> float:
    """Contact angle α [rad] of spherical roller rows that fill the ring width (no printed e).

    A row's roller centre sits at z = (d_m/2) tan α and its end reaches z + (L_we cos α + D_we sin α)/2
    (:func:`axial_margin`); the rows are set as wide as the rings allow: that reach equals B/2 less the
    chamfer r_s min (the ring face's own edge). Geometry only: with the rule's rollers, over the 59 sizes
    of the 222/223 tables (whose e is printed) it gives e = 1.5 tan α −3 % on average (−10…+3 %,
    tests/catalogue/test_series_new.py).
    """
    target = 0.5 * entry.width - entry.chamfer
    lo, hi = 0.0, 0.5 * math.pi * 0.9
    for _ in range(80):  # bisection: the reach grows with α over (0, 81°)
        mid = 0.5 * (lo + hi)
        reach = 0.5 * d_m * math.tan(mid) + 0.5 * (l_we * math.cos(mid) + d_we * math.sin(mid))
        lo, hi = (mid, hi) if reach < target else (lo, mid)
    return 0.5 * (lo + hi)


def with_element_diameter(est: Estimate, element_diameter: float, note: str) -> Estimate:
    """A copy with another D_w (roller end diameters follow), the count kept."""
    extra = dict(est.extra)
    if "small_diameter" in extra:
        shift = element_diameter - est.element_diameter
        extra["small_diameter"] += shift
        extra["large_diameter"] += shift
    return replace(est, element_diameter=element_diameter, extra=extra, notes=(*est.notes, note))


def envelope_margins(est: Estimate) -> np.ndarray:
    """(inner, outer) radial gaps [m] between the elements and bore/outside diameter (> 0 = fits).

    Needle rows without inner ring are measured against F_w (their ``bore``); spherical rollers with
    their axes inclined by α: radial half extent (D_we cos α + L_we sin α)/2.
    """
    e = est.entry
    if est.entry.family in ("thrust_ball",):
        half = 0.5 * est.element_diameter
    elif est.entry.family == "thrust_cylindrical_roller":
        half = 0.5 * est.effective_length
    elif est.entry.family in ("spherical_roller", "spherical_roller_thrust"):
        a = est.contact_angle
        half = 0.5 * (est.element_diameter * math.cos(a) + est.effective_length * math.sin(a))
    else:
        half = 0.5 * est.extra.get("large_diameter", est.element_diameter)
    r = 0.5 * est.pitch_diameter
    return np.array([r - half - 0.5 * e.bore, 0.5 * e.outer_diameter - (r + half)])


def axial_margin(est: Estimate) -> float:
    """Axial gap [m] between the outer end of a spherical roller row and the ring face (> 0 = fits).

    A row's roller centre sits at z = (d_m/2) tan α (on the line from the bearing centre at angle α);
    the roller reaches z + (L_we cos α + D_we sin α)/2, which must stay within B/2.
    """
    a = est.contact_angle
    reach = est.extra["row_offset"] + 0.5 * (
        est.effective_length * math.cos(a) + est.element_diameter * math.sin(a)
    )
    return 0.5 * est.entry.width - reach
