"""The makers' designation suffixes: what each code means and which field of a designation it sets.

A suffix is matched greedily (longest code first) inside each token of the text after the basic
designation; tokens are separated by ``-``, ``/`` or spaces (``6308-2RS1/C3``, ``7014 CD/P4ADBB``,
``B7014-C-T-P4S-UL``, ``7014CTYNDBLP4``). Every code names the field it sets:

- ``seal`` — shields and seals (Z, 2Z, ZZ: shields; RS, 2RS1, 2RSH, RSR, LLU, DDU: contact seals;
  RZ, 2RZ, RSL, LLB, VV: non-contact / low-friction seals), with their kind and the number of sides;
- ``snap_ring`` — N, NR, ZNR (snap-ring groove, ring);
- ``clearance`` — radial internal clearance C1 … C5, CN (ISO 5753-1 groups);
- ``tolerance`` — P0/PN, P6, P6X, P5, P4, P4A, P4S, PA9A, P2, SP, UP (ISO 492 classes and the makers'
  precision classes);
- ``cage`` — J, J1, J2, M, MA, MB, ML, P, Y, F, T, TN, TN9, TNH, TVH, TVP, TVP2, TYN, TR …;
- ``arrangement`` — matched sets DB (back-to-back), DF (face-to-face), DT (tandem), followed in the
  arrangement context by a preload class letter (SKF A/B/C/D, NSK EL/L/M/H: ``DBB``, ``DBL``);
- ``matching`` — bearings for universal matching: SKF CA/CB/CC (axial clearance) and GA/GB/GC (preload),
  FAG UA/UO/UL/UM/UH and the pair forms DUL/DUM/DUH, NSK SU;
- ``design`` — internal design codes (E, EC, ECP, ECJ, ECM, ECML, EA, C, CC, CA, CAM, CD, E1, J2, Q, X,
  XJ, B of steep tapered bearings, E4/W33 lubrication groove, N2 QJ slots …);
- ``bore`` — K (taper 1:12), K30 (1:30);
- ``other`` — greases, heat stabilisation, coatings, running accuracy (GJN, WT, HT, LT, MT33, S0, S1,
  VL0241, C083 …).

Preload classes of the makers, mapped onto bearingkit's four classes (:data:`PRELOAD_CLASSES`): SKF
super-precision sets A extra light, B light, C moderate, D heavy; SKF universally matchable GA/GB/GC
light/moderate/heavy; FAG UL/UM/UH light/medium/heavy; NSK EL/L/M/H extra light/light/medium/heavy.
The code letters are the makers' (SKF says its preload values are "not standardized and are listed in
the product table", skf.com, super-precision bearings, bearing preload); the SKF and FAG letter meanings
are taken from the makers' catalogues as remembered [from memory], not from a stored copy; NSK's are in
NSK E1102e Table 7.6 (A56–A57). The forces of the classes are NSK's (:mod:`.pairs`), onto which the
other makers' letters map by name only.

A token that is not in the vocabulary is kept and named in a note; a token of an enumerated kind with
a value that does not exist (clearance ``C7``, tolerance ``P3``, seal ``2RX``) is refused with the
nearest valid spellings (:func:`wrong_token`).
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass

#: bearingkit's preload classes, lightest first (a maker's class maps onto one of them).
PRELOAD_CLASSES = ("extra_light", "light", "medium", "heavy")


@dataclass(frozen=True)
class Code:
    """One suffix code.

    Attributes
    ----------
    field : str
        The designation field it sets (module docstring).
    meaning : str
        What it means (shown in notes).
    value : str or None
        The normalised value for fields with one (seal kind, preload class, arrangement …).
    """

    field: str
    meaning: str
    value: str | None = None


def _seals() -> dict[str, Code]:
    shields = ("Z", "Z1", "2Z", "ZZ", "2Z1")
    contact = ("RS", "RS1", "RSH", "RSR", "2RS", "2RS1", "2RSH", "2RSR", "LLU", "LU", "DDU", "DU", "2HRS")
    low_friction = ("RZ", "2RZ", "RSL", "2RSL", "LLB", "LB", "LLH", "LH", "VV", "DD")
    out = {}
    for code in shields:
        out[code] = Code("seal", "shield", "shield")
    for code in contact:
        out[code] = Code("seal", "contact seal", "contact_seal")
    for code in low_friction:
        out[code] = Code("seal", "non-contact (low-friction) seal", "low_friction_seal")
    return out


#: Codes every family knows (the families' own codes follow in :data:`FAMILY_CODES`).
COMMON: dict[str, Code] = {
    **_seals(),
    "N": Code("snap_ring", "snap-ring groove in the outer ring"),
    "NR": Code("snap_ring", "snap-ring groove with snap ring"),
    "ZNR": Code("snap_ring", "shield and snap ring"),
    "2ZNR": Code("snap_ring", "two shields and snap ring"),
    **{
        c: Code("clearance", f"radial internal clearance {c}", c)
        for c in ("C1", "C2", "CN", "C3", "C4", "C5")
    },
    **{
        c: Code("tolerance", f"tolerance class {c}", c)
        for c in ("P0", "PN", "P6", "P6X", "P5", "P4", "P4A", "P4S", "PA9A", "PA9", "P2", "SP", "UP", "HG")
    },
    **{
        c: Code("cage", m)
        for c, m in (
            ("J", "pressed steel cage"),
            ("J1", "pressed steel cage"),
            ("J2", "pressed steel cage"),
            ("M", "machined brass cage"),
            ("MA", "machined brass cage, outer-ring centred"),
            ("MB", "machined brass cage, inner-ring centred"),
            ("ML", "machined brass window cage"),
            ("MP", "machined brass window cage"),
            ("P", "glass-fibre polyamide cage"),
            ("PH", "PEEK cage"),
            ("Y", "pressed brass cage"),
            ("F", "machined steel cage"),
            ("T", "phenolic (textile) cage"),
            ("TN", "polyamide cage"),
            ("TN9", "glass-fibre polyamide cage"),
            ("TNH", "glass-fibre PEEK cage"),
            ("TNHA", "glass-fibre PEEK cage, outer-ring centred"),
            ("TVH", "glass-fibre polyamide cage"),
            ("TVP", "glass-fibre polyamide cage"),
            ("TVP2", "glass-fibre polyamide cage"),
            ("TVPB", "glass-fibre polyamide cage"),
            ("TYN", "polyamide cage (NSK)"),
            ("TR", "phenolic cage (NSK)"),
            ("W", "pressed steel cage (NSK)"),
            ("V", "full complement (no cage)"),
        )
    },
    "K": Code("bore", "tapered bore 1:12", "K"),
    "K30": Code("bore", "tapered bore 1:30", "K30"),
    **{
        c: Code("other", m)
        for c, m in (
            ("GJN", "polyurea grease"),
            ("WT", "grease for wide temperature range"),
            ("HT", "high-temperature grease"),
            ("LT", "low-temperature grease"),
            ("MT33", "grease"),
            ("MT47", "grease"),
            ("S0", "heat stabilised to 150 °C"),
            ("S1", "heat stabilised to 200 °C"),
            ("S2", "heat stabilised to 250 °C"),
            ("VL0241", "electrically insulating coating (INSOCOAT)"),
            ("VL2071", "electrically insulating coating (INSOCOAT)"),
            ("HC5", "ceramic (silicon nitride) balls: not modelled, the mechanics takes steel balls"),
            ("C08", "running accuracy P5"),
            ("C083", "running accuracy P5, clearance C3"),
            ("C084", "running accuracy P5, clearance C4"),
            ("XL", "X-life (FAG)"),
            ("CM", "NSK electric-motor clearance (narrower than CN)"),
        )
    },
}


def _arrangements() -> dict[str, Code]:
    out = {
        a: Code("arrangement", m, a)
        for a, m in (("DB", "back-to-back pair"), ("DF", "face-to-face pair"), ("DT", "tandem pair"))
    }
    return out


#: Preload letters read right after an arrangement code (``DBB``, ``DFA``, ``DBL``): SKF A/B/C/D,
#: NSK EL/L/M/H (module docstring) [from memory].
ARRANGEMENT_PRELOAD: dict[str, Code] = {
    "A": Code("preload", "SKF preload class A (extra light)", "extra_light"),
    "B": Code("preload", "SKF preload class B (light)", "light"),
    "C": Code("preload", "SKF preload class C (moderate)", "medium"),
    "D": Code("preload", "SKF preload class D (heavy)", "heavy"),
    "EL": Code("preload", "NSK preload EL (extra light)", "extra_light"),
    "L": Code("preload", "NSK preload L (light)", "light"),
    "M": Code("preload", "NSK preload M (medium)", "medium"),
    "H": Code("preload", "NSK preload H (heavy)", "heavy"),
}

#: Codes of angular contact ball bearings (single row, spindle series 70/72/73/718/719).
ANGULAR: dict[str, Code] = {
    **_arrangements(),
    "CA": Code("matching", "universally matchable, axial clearance smaller than normal (SKF)", "universal"),
    "CB": Code("matching", "universally matchable, normal axial clearance (SKF)", "universal"),
    "CC": Code("matching", "universally matchable, axial clearance larger than normal (SKF)", "universal"),
    "GA": Code("preload", "universally matchable, light preload in a DB/DF pair (SKF GA)", "light"),
    "GB": Code("preload", "universally matchable, moderate preload in a DB/DF pair (SKF GB)", "medium"),
    "GC": Code("preload", "universally matchable, heavy preload in a DB/DF pair (SKF GC)", "heavy"),
    "UA": Code("matching", "universal, small axial clearance (FAG UA)", "universal"),
    "UO": Code("matching", "universal, zero axial clearance (FAG UO)", "universal"),
    "U": Code("matching", "universally matchable (FAG)", "universal"),
    "UL": Code("preload", "universal, light preload (FAG UL)", "light"),
    "UM": Code("preload", "universal, medium preload (FAG UM)", "medium"),
    "UH": Code("preload", "universal, heavy preload (FAG UH)", "heavy"),
    "DUL": Code("preload", "universal pair, light preload (FAG DUL)", "light"),
    "DUM": Code("preload", "universal pair, medium preload (FAG DUM)", "medium"),
    "DUH": Code("preload", "universal pair, heavy preload (FAG DUH)", "heavy"),
    "SU": Code("matching", "single universal (NSK SU)", "universal"),
    "E": Code("design", "optimised internal design (E)"),
    "D": Code("design", "super-precision D design (SKF)"),
    "BE": Code("design", "40 deg, optimised internal design"),
    "HC": Code("other", "hybrid, ceramic balls: not modelled, the mechanics takes steel balls"),
}
#: Codes of tapered roller bearings.
TAPERED: dict[str, Code] = {
    **_arrangements(),
    "Q": Code("design", "optimised contact geometry and surface finish (SKF Q)"),
    "X": Code("design", "boundary dimensions to ISO 355 (X)"),
    "XJ": Code("design", "boundary dimensions to ISO 355, pressed steel cage"),
    "B": Code("design", "steeper contact angle design (B)"),
    "BJ2": Code("design", "steeper contact angle design, pressed steel cage"),
    "CL7C": Code("other", "SKF special running accuracy and preload (CL7C)"),
    "CL7A": Code("other", "SKF special running accuracy (CL7A)"),
    "VA606": Code("other", "SKF railway / special execution (VA606)"),
    "HR": Code("design", "NSK high-capacity design"),
}
#: Codes of cylindrical roller bearings.
CYLINDRICAL: dict[str, Code] = {
    "E": Code("design", "high-capacity E design"),
    "EC": Code("design", "high-capacity EC design"),
    "ECP": Code("design", "high-capacity EC design, glass-fibre polyamide cage"),
    "ECJ": Code("design", "high-capacity EC design, pressed steel cage"),
    "ECM": Code("design", "high-capacity EC design, machined brass cage"),
    "ECML": Code("design", "high-capacity EC design, machined brass window cage"),
    "EW": Code("design", "NSK E design, pressed steel cage"),
    "ET": Code("design", "NSK E design, polyamide cage"),
    "EM": Code("design", "NSK E design, machined brass cage"),
    "NA": Code("other", "clearance group for non-interchangeable rings"),
}
#: Codes of spherical roller bearings.
SPHERICAL: dict[str, Code] = {
    **{
        c: Code("design", f"{c} internal design")
        for c in ("E", "E1", "EA", "EJ", "EM", "EMA", "C", "CC", "CA", "CAM", "CD", "CJ", "MB")
    },
    "E4": Code("design", "lubrication groove and holes (NSK E4)"),
    "W33": Code("design", "lubrication groove and holes (W33)"),
    "W20": Code("design", "lubrication holes (W20)"),
    "W26": Code("design", "lubrication holes (W26)"),
    "VA405": Code("other", "vibratory application execution (VA405)"),
    "VA406": Code("other", "vibratory application execution (VA406)"),
}
#: Codes of the other families (self-aligning ball, four-point, double-row, needle, thrust, deep groove).
OTHER_FAMILIES: dict[str, Code] = {
    "E": Code("design", "optimised internal design (E)"),
    "N2": Code("design", "two locating slots in the outer ring"),
    "A": Code("design", "without filling slots (A)"),
    "W64": Code("other", "solid oil"),
    "ETN9": Code("design", "E design, glass-fibre polyamide cage"),
}

#: Family → its codes (COMMON and the family's own; the family's win on a clash: CC is a spherical
#: roller design but a matching code of angular contact bearings).
FAMILY_CODES = {
    "angular_contact_ball": {**COMMON, **ANGULAR},
    "tapered_roller": {**COMMON, **TAPERED},
    "cylindrical_roller": {**COMMON, **CYLINDRICAL},
    "spherical_roller": {**COMMON, **SPHERICAL},
}


def codes_of(family: str) -> dict[str, Code]:
    """The suffix vocabulary of ``family``."""
    return FAMILY_CODES.get(family, {**COMMON, **OTHER_FAMILIES})


#: Enumerated kinds whose wrong values are refused (:func:`wrong_token`): pattern, field, valid values.
_ENUMERATED = (
    (re.compile(r"^C\d+$"), "clearance class", ("C1", "C2", "CN", "C3", "C4", "C5", "C08", "C083", "C084")),
    (re.compile(r"^P\d\w*$"), "tolerance class", ("P0", "P6", "P6X", "P5", "P4", "P4A", "P4S", "P2")),
    (
        re.compile(r"^2?(RS|RZ)\w*$|^2[A-Z]{1,3}$"),
        "seal or shield",
        ("2RS", "2RS1", "2RSH", "2RSR", "2RZ", "2RSL", "2Z", "RS", "RS1", "RZ", "Z"),
    ),
)


def wrong_token(token: str) -> tuple[str, list[str]] | None:
    """(kind, nearest valid spellings) when ``token`` has the form of an enumerated suffix kind
    (clearance ``C7``, tolerance ``P3``, seal ``2RX``) but no such code exists; None otherwise."""
    for pattern, kind, valid in _ENUMERATED:
        if pattern.match(token):
            return kind, difflib.get_close_matches(token, valid, n=3, cutoff=0.0)
    return None


def split(rest: str, codes: dict[str, Code]) -> list[tuple[str, Code | None]]:
    """Tokens of ``rest`` cut into codes of ``codes``: (code, Code) pairs; what no code matches comes back
    as (text, None), from the first character no segmentation explains to the end of the token.

    Each token (separated by ``-``, ``/`` or spaces) is cut into the codes that leave the fewest characters
    unexplained, then the fewest pieces (``DBMP4`` is DB + M + P4, ``ECBP`` is E + CB + P). A preload
    letter (:data:`ARRANGEMENT_PRELOAD`) is a code only right after an arrangement code.
    """
    out: list[tuple[str, Code | None]] = []
    for token in re.split(r"[\s/\-]+", rest):
        if token:
            out.extend(_segment(token, codes))
    return out


def _segment(token: str, codes: dict[str, Code]) -> list[tuple[str, Code | None]]:
    """Best cut of one token (see :func:`split`): dynamic programming from the end of the token."""
    n = len(token)
    # best[(pos, after_arrangement)] = (unexplained characters, pieces, cut)
    best: dict[tuple[int, bool], tuple[int, int, list]] = {(n, False): (0, 0, []), (n, True): (0, 0, [])}
    for pos in range(n - 1, -1, -1):
        for after in (False, True):
            options = [(n - pos, 1, [(token[pos:], None)])]
            table = ([ARRANGEMENT_PRELOAD] if after else []) + [codes]  # a tie: the preload reading
            for vocab in table:
                for key, code in vocab.items():
                    if token.startswith(key, pos):
                        u, k, cut = best[(pos + len(key), code.field == "arrangement")]
                        options.append((u, k + 1, [(key, code), *cut]))
            best[(pos, after)] = min(options, key=lambda o: (o[0], o[1]))
    return best[(0, False)][2]
