"""Parse bearing designations as the makers print them: ``"6308-2RS1/C3"``, ``"7014 CD/P4ADBB"``,
``"B7014-C-T-P4S-UL"``, ``"7209 BECBP"``, ``"32008 X/Q"``, ``"NU 208 ECP"``, ``"22208 E"``, ``"6205-2Z/C3"``.

A designation is an optional prefix (FAG spindle ``B``, hybrid ``HCB``, SKF sealed ``S``, stainless
``W``, energy-efficient ``E2.``, NSK ``HR``), a *basic designation* (type and dimension series, bore code)
and suffixes. Bore codes: 00 = 10 mm, 01 = 12, 02 = 15, 03 = 17, from 04 on the code × 5, and ``/dd``
= dd mm (``302/22``, ``NA49/22``) (ISO 15 cl. 7 and every catalogue's designation system). Needle
roller bearings: ``NA`` with inner ring, ``RNA`` without (the shaft is the raceway). Angular contact
bearings carry their contact angle right after the bore code: C 15°, AC (SKF, NTN), A5 (NSK) and E (FAG,
after prefix B) 25°, A 30°, B 40°; SKF's super-precision CD/ACD, CE/ACE are 15°/25° of the D and E designs.

The suffixes (:mod:`.suffixes`) fill the fields of :class:`Designation`: seal or shield, snap ring,
clearance class, tolerance class, cage, pair arrangement DB/DF/DT, universal matching, preload class,
internal design, tapered bore. The clearance class, the contact angle, the pair arrangement (with its
preload class) and a tapered bore change the mechanics; the others are kept as notes. A suffix bearingkit
does not know is kept and named in a note; a wrong one of an enumerated kind (``C7``, ``P3``, ``2RX``)
raises :class:`~bearingkit.errors.InputError` with the nearest valid spellings, as does a designation
that is not in the tables (with the nearest designations of the table).
"""

from __future__ import annotations

import difflib
import heapq
import re
from dataclasses import dataclass, field

from bearingkit.catalogue import suffixes as sx
from bearingkit.catalogue import tables
from bearingkit.errors import InputError

#: Longest designation text looked at (a longer one is refused: no catalogue designation is that long).
MAX_LENGTH = 60
#: Basic designation patterns, tried in order: (family, regex with groups series, bore code, rest).
_PATTERNS: tuple[tuple[str, re.Pattern], ...] = (
    ("four_point_contact_ball", re.compile(r"^(QJ\s?[23])(\d\d)(.*)$")),
    ("needle_roller", re.compile(r"^(R?NA\s?4[89])(\d\d|/\d\d)(.*)$")),
    ("double_row_cylindrical_roller", re.compile(r"^(NN\s?(?:30|49))(\d\d)(.*)$")),
    ("cylindrical_roller", re.compile(r"^(?:NUP|NU|NJ|N)\s?(10|19|22|23|2|3)(\d\d|/\d+)(.*)$")),
    ("thrust_cylindrical_roller", re.compile(r"^(81[12])(\d\d)(.*)$")),
    ("thrust_ball", re.compile(r"^(51[123])(\d\d)(.*)$")),
    ("spherical_roller_thrust", re.compile(r"^(29[234])(\d\d|/\d+)(.*)$")),
    ("tapered_roller", re.compile(r"^(30[23]|313|32[0239]|33[012])(\d\d|/\d\d)(.*)$")),
    ("deep_groove_ball", re.compile(r"^(61[89]|160)(\d\d|/\d+)(.*)$")),
    ("angular_contact_ball", re.compile(r"^(71[89]|7[0239])(\d\d)(.*)$")),
    ("double_row_angular_contact_ball", re.compile(r"^(3[23])(\d\d)(.*)$")),
    # spherical 2xxyy before self-aligning 22yy/23yy: "22208", "23120" are spherical roller bearings, "2208",
    # "2312" not; bores from 500 mm as "/dd" ("230/600", "239/1000")
    ("spherical_roller", re.compile(r"^(213|22[23]|23[0129]|24[01])(\d\d|/\d+)(.*)$")),
    ("self_aligning_ball", re.compile(r"^(1[23]|2[23])(\d\d)(.*)$")),
    ("deep_groove_ball", re.compile(r"^(6[0234])(\d\d|/\d+)(.*)$")),
)
#: Prefixes before the basic designation: code → (the series it may precede (regex), meaning).
PREFIXES = {
    "HCB": (r"7", "FAG hybrid spindle bearing (ceramic balls)"),
    "B": (r"7", "FAG spindle bearing"),
    "S": (r"7", "SKF sealed super-precision bearing"),
    "W": (r"6", "SKF stainless steel"),
    "E2.": (r"6", "SKF energy-efficient"),
    "HR": (r"3", "NSK high-capacity tapered roller bearing"),
}
#: Prefixes whose balls are ceramic (the mechanics here takes steel balls: a note says so).
CERAMIC_PREFIXES = ("HCB",)
#: Angle codes of angular contact bearings → (table suffix, design note or "").
ANGLE_CODES = {
    "ACD": ("AC", "SKF super-precision D design"),
    "ACE": ("AC", "SKF high-speed E design"),
    "AC": ("AC", ""),
    "A5": ("AC", "NSK 25 deg"),
    "A": ("A", ""),
    "CD": ("C", "SKF super-precision D design"),
    "CE": ("C", "SKF high-speed E design"),
    "C": ("C", ""),
    "B": ("B", ""),
}
#: Contact angle suffixes the tables hold (the error message lists them).
TABLE_ANGLES = {"B": "40°", "AC": "25°", "A": "30°", "C": "15°"}
#: Makers' spellings of an ISO dimension series: printed series → (ISO series, whose spelling). NSK
#: writes the ISO 719 angular contact series as 79 (NSK E1102 A54 Table 7.5: series 79 = type 7, width series
#: 1, diameter series 9; SKF prints the same bearing as 71914 CD).
SERIES_ALIASES = {"angular_contact_ball": {"79": ("719", "NSK")}}
#: Families whose rows may be paired from the designation (DB/DF/DT), with the arrangements allowed.
PAIRABLE = {"angular_contact_ball": ("DB", "DF", "DT"), "tapered_roller": ("DB", "DF")}
_SHOWN = 40


def bore_from_code(code: str) -> float:
    """Bore d [mm] of a bore code (00 → 10, 01 → 12, 02 → 15, 03 → 17, else × 5; ``/22`` → 22 mm)."""
    if code.startswith("/"):
        return float(code[1:])
    return {"00": 10.0, "01": 12.0, "02": 15.0, "03": 17.0}.get(code, 5.0 * int(code))


@dataclass(frozen=True)
class Designation:
    """A parsed designation.

    Attributes
    ----------
    text : str
        As given.
    family : str
        Key of :data:`bearingkit.catalogue.tables.FAMILIES`.
    base : str
        Base designation of the catalogue table (``"6205"``, ``"7206B"``, ``"NU206E"``, ``"32206"``).
    clearance_class : str or None
        ``"C1"`` … ``"C5"`` or ``"CN"`` when given.
    suffixes : tuple of str
        The recognised suffix codes other than the clearance class, in order.
    prefix : str or None
        ``"B"``, ``"HCB"``, ``"S"``, ``"W"``, ``"E2."``, ``"HR"`` (:data:`PREFIXES`).
    series, bore_code : str
        Dimension series and bore code as printed (``"62"``, ``"05"``).
    contact_angle_code : str or None
        Angular contact: the angle code as printed (``"CD"``, ``"AC"``, ``"A5"``, ``"B"``).
    seal : str or None
        Seal or shield code (``"2RS1"``, ``"2Z"``); ``seal_kind`` ``"shield"``, ``"contact_seal"`` or
        ``"low_friction_seal"``; ``seal_sides`` 1 or 2 (0 without).
    tolerance_class, cage : str or None
        As printed (``"P4A"``, ``"TN9"``).
    arrangement : str or None
        ``"DB"``, ``"DF"``, ``"DT"`` of a matched pair.
    matching : str or None
        ``"universal"`` for a bearing for universal matching.
    preload_class : str or None
        One of :data:`bearingkit.catalogue.suffixes.PRELOAD_CLASSES`; ``preload_code`` the maker's code.
    design : tuple of str
        Internal design codes (``E``, ``ECP``, ``J2``, ``Q`` …).
    tapered_bore : str or None
        ``"K"`` (1:12) or ``"K30"`` (1:30).
    unknown : tuple of str
        Tokens bearingkit does not know (kept; named in :attr:`notes`).
    notes : tuple of str
        What each code was read as and what is not modelled.
    """

    text: str
    family: str
    base: str
    clearance_class: str | None
    suffixes: tuple
    prefix: str | None = None
    series: str = ""
    bore_code: str = ""
    contact_angle_code: str | None = None
    seal: str | None = None
    seal_kind: str | None = None
    seal_sides: int = 0
    tolerance_class: str | None = None
    cage: str | None = None
    arrangement: str | None = None
    matching: str | None = None
    preload_class: str | None = None
    preload_code: str | None = None
    design: tuple = ()
    tapered_bore: str | None = None
    unknown: tuple = ()
    notes: tuple = field(default_factory=tuple)

    @property
    def is_pair(self) -> bool:
        """True for a matched pair (DB, DF or DT) the resolver models as two rows."""
        return self.arrangement is not None

    def fields(self) -> dict:
        """The parsed fields as a JSON-ready dict (``bearingkit catalogue --parse``, the select output)."""
        keys = (
            "text", "family", "base", "prefix", "series", "bore_code", "contact_angle_code", "seal",
            "seal_kind", "seal_sides", "clearance_class", "tolerance_class", "cage", "arrangement",
            "matching", "preload_class", "preload_code", "design", "tapered_bore", "unknown", "notes",
        )  # fmt: skip
        return {k: list(v) if isinstance(v, tuple) else v for k in keys for v in (getattr(self, k),)}


def _shown(text: str) -> str:
    return repr(text if len(text) <= _SHOWN else text[:_SHOWN] + "…")


def nearest(text: str, n: int = 3) -> list[str]:
    """The ``n`` table designations closest to ``text`` (difflib ratio)."""
    names = [e.designation for e in tables.all_entries()]
    key = re.sub(r"[\s\-]", "", str(text).upper())[:_SHOWN]
    return close_matches(key, names, n)


def close_matches(word: str, names, n: int = 3) -> list[str]:
    """``difflib.get_close_matches(word, names, n, cutoff=0.0)``, the same list, faster.

    difflib scores every name with ``SequenceMatcher.ratio`` (a refused designation was ~10 ms against
    the ~2,800 table rows). Here a name is scored only when difflib's own upper bounds of the ratio
    (``real_quick_ratio`` ≥ ``quick_ratio`` ≥ ``ratio``, the same 2·matches/length with more matches)
    reach the ``n``-th best (score, name) so far; any name they skip ranks below all ``n`` kept ones,
    so the answer, ties included, is the one of difflib.
    """
    s = difflib.SequenceMatcher()
    s.set_seq2(word)
    best: list[tuple[float, str]] = []  # a min-heap of the n best (ratio, name)
    for x in names:
        s.set_seq1(x)
        if len(best) == n and (s.real_quick_ratio() < best[0][0] or s.quick_ratio() < best[0][0]):
            continue
        item = (s.ratio(), x)
        if len(best) < n:
            heapq.heappush(best, item)
        elif item > best[0]:
            heapq.heapreplace(best, item)
    return [x for _, x in sorted(best, reverse=True)]


def _prefix(up: str) -> tuple[str | None, str]:
    for code in sorted(PREFIXES, key=len, reverse=True):
        before = PREFIXES[code][0]
        if up.startswith(code) and re.match(before, up[len(code) :].lstrip()):
            return code, up[len(code) :].lstrip()
    return None, up


def _angle(raw: str, series: str, code: str, rest: str, prefix: str | None) -> tuple[str, str, str, str]:
    """(table angle suffix, code as printed, design note, rest) of an angular contact bearing."""
    codes = dict(ANGLE_CODES)
    if prefix in ("B", "HCB"):
        codes["E"] = ("AC", "FAG 25 deg")  # FAG spindle bearings: C 15 deg, E 25 deg
    alternatives = "|".join(sorted(codes, key=len, reverse=True))
    m = re.match(rf"^[\s\-]?({alternatives})(?![1-5N]|\d)", rest)
    if m is None:
        raise InputError(
            f"designation ({_shown(raw)}): an angular contact bearing needs its contact angle suffix "
            "C (15°), AC or A5 (25°), A (30°) or B (40°) (CD/ACD, CE/ACE for SKF super-precision), "
            f"e.g. '{series}{code} C'"
        )
    table, note = codes[m.group(1)]
    return table, m.group(1), note, rest[m.end() :]


def parse(text: str) -> Designation:
    """Parse ``text``; InputError (one line, nearest valid designations or spellings) when it names no
    bearing of the tables or carries a wrong suffix."""
    raw = str(text).strip()
    if not raw:
        raise InputError("designation ('') is empty; give one such as '6205-2RS C3'")
    if len(raw) > MAX_LENGTH:
        raise InputError(
            f"designation ({_shown(raw)}) is longer than {MAX_LENGTH} characters: not a bearing designation"
        )
    up = " ".join(raw.upper().split())
    prefix, body = _prefix(up)
    for family, pattern in _PATTERNS:
        m = pattern.match(body)
        if m is None:
            continue
        return _parse_family(raw, family, prefix, m)
    raise InputError(
        f"designation ({_shown(raw)}) is not a designation bearingkit knows (series 618, 619, 160, 60, 62, "
        "63, 64, 70, 718, 719, 72, 73, 32, 33, QJ2, QJ3, 12, 13, 22, 23, 213, 222, 223, 230, 231, 232, 239, "
        "240, 241, N/NU/NJ/NUP 10/19/2/22/3/23, NN30, NN49, NA48, NA49, RNA48, RNA49, 302, 303, 313, 320, "
        "322, 323, 329, 330, 331, 332, 511, 512, 513, 811, 812, 292, 293, 294) and no file of that "
        f"name exists; nearest: {', '.join(nearest(raw))}"
    )


def _parse_family(raw: str, family: str, prefix: str | None, m: re.Match) -> Designation:
    series, code, rest = m.group(1).replace(" ", ""), m.group(2), m.group(3)
    angle, angle_code, notes = "", None, []
    alias = SERIES_ALIASES.get(family, {}).get(series)
    if alias is not None:
        notes.append(f"series {series}: the {alias[1]} spelling of ISO series {alias[0]}")
        series = alias[0]
    if prefix is not None:
        notes.append(f"prefix {prefix}: {PREFIXES[prefix][1]}")
    if prefix in CERAMIC_PREFIXES:
        notes.append("ceramic balls are not modelled: the mechanics takes steel balls")
    if family == "angular_contact_ball":
        angle, angle_code, design_note, rest = _angle(raw, series, code, rest, prefix)
        if design_note:
            notes.append(f"{angle_code}: {design_note}")
    if family == "tapered_roller" and series == "320":
        rest = re.sub(r"^\s?X", "", rest)
        angle = "X"
    if family == "cylindrical_roller":
        angle = "" if series in ("10", "19") else "E"
        rest = re.sub(r"^\s?E(?![CWTM1])", "", rest)
    if family == "double_row_angular_contact_ball":
        rest = re.sub(r"^\s?A(?!C)", "", rest)
    pre = "NU" if family == "cylindrical_roller" else ""
    base = f"{pre}{series}{code}{angle}"
    parts = _suffix_fields(raw, family, rest)
    notes.extend(parts.pop("notes"))
    _check_in_table(raw, family, series, code, angle, base)
    return Designation(
        text=raw, family=family, base=base, prefix=prefix, series=series, bore_code=code,
        contact_angle_code=angle_code, notes=tuple(notes), **parts,
    )  # fmt: skip


def _suffix_fields(raw: str, family: str, rest: str) -> dict:
    """The suffix fields of :class:`Designation` (and its notes) from the text after the basic designation."""
    out: dict = {"design": [], "unknown": [], "suffixes": [], "notes": []}
    clearance: list[str] = []
    for token, code in sx.split(rest, sx.codes_of(family)):
        if code is None:
            whole = next((t for t in re.split(r"[\s/\-]+", rest) if token in t), token)
            wrong = sx.wrong_token(whole) or sx.wrong_token(token)
            if wrong is not None:
                kind, near = wrong
                raise InputError(
                    f"designation ({_shown(raw)}): {kind} {whole!r} does not exist; nearest valid "
                    f"spellings: {', '.join(near)}"
                )
            out["unknown"].append(token)
            continue
        if code.field == "clearance":
            clearance.append(token)
            continue
        out["suffixes"].append(token)
        _set_field(out, family, token, code)
    if len(clearance) > 1:
        raise InputError(
            f"designation ({_shown(raw)}): two clearance classes ({', '.join(clearance)}); give one"
        )
    out["clearance_class"] = clearance[0] if clearance else None
    if out["unknown"]:
        out["notes"].append(
            f"suffix {', '.join(out['unknown'])} not known to bearingkit: kept as given, no effect on the "
            "mechanics"
        )
    if out.get("arrangement") is not None and out["arrangement"] not in PAIRABLE.get(family, ()):
        allowed = PAIRABLE.get(family, ())
        what = f"only {', '.join(allowed)} pairs are modelled" if allowed else "pairs are not modelled"
        raise InputError(
            f"designation ({_shown(raw)}): arrangement {out['arrangement']} of a {family.replace('_', ' ')}: "
            f"{what}; give the pair as a bearing file (docs/input-format.md)"
        )
    if out.get("preload_class") is not None and out.get("arrangement") is None:
        out["notes"].append(
            f"preload class {out['preload_class']} applies to a set: add DB, DF or DT to model the pair "
            "(a single bearing is analysed)"
        )
    for key in ("design", "unknown", "suffixes"):
        out[key] = tuple(out[key])
    return out


def _set_field(out: dict, family: str, token: str, code: sx.Code) -> None:
    f = code.field
    if f == "seal":
        out.update(seal=token, seal_kind=code.value, seal_sides=2 if _two_sided(token) else 1)
    elif f == "tolerance":
        out["tolerance_class"] = token
        out["notes"].append(f"{token}: {code.meaning} (the mechanics takes the nominal geometry)")
    elif f == "cage":
        out["cage"] = token
    elif f == "arrangement":
        out["arrangement"] = token
    elif f == "matching":
        out["matching"] = code.value
    elif f == "preload":
        out.update(preload_class=code.value, preload_code=token)
        if token.startswith("DU"):
            out["matching"] = "universal"
            out["notes"].append(f"{token}: {code.meaning}; give DB, DF or DT for the arrangement of the pair")
    elif f == "bore":
        out["tapered_bore"] = token
    elif f == "design":
        out["design"].append(token)
    elif f == "other":
        out["notes"].append(f"{token}: {code.meaning} (no effect on the mechanics)")


def _two_sided(token: str) -> bool:
    return token.startswith("2") or token in ("ZZ", "LLU", "LLB", "LLH", "DDU", "DD", "VV")


def _check_in_table(raw: str, family: str, series: str, code: str, angle: str, base: str) -> None:
    table = tables.entries(family)
    if base in table:
        return
    bore = bore_from_code(code)
    same = sorted(
        (e for e in table.values() if e.series == series and e.designation.endswith(angle)),
        key=lambda e: abs(e.bore * 1e3 - bore),
    )
    if family == "angular_contact_ball" and not same:
        held = sorted(
            {e.designation[len(e.designation.rstrip("ABC")) :] for e in table.values() if e.series == series}
        )
        angles = ", ".join(f"{a} ({TABLE_ANGLES[a]})" for a in held if a in TABLE_ANGLES)
        raise InputError(
            f"designation ({_shown(raw)}): series {series} holds contact angles {angles}; {base} is not "
            f"in the tables; nearest: {', '.join(nearest(base))}"
        )
    near = [e.designation for e in same[:3]] or nearest(base)
    lo = min((e.bore for e in same), default=0.0) * 1e3
    hi = max((e.bore for e in same), default=0.0) * 1e3
    span = f"; the table holds bores {lo:g}–{hi:g} mm of series {series}" if same else ""
    raise InputError(
        f"designation ({_shown(raw)}): {base} (bore {bore:g} mm) is not in the catalogue tables{span}; "
        f"nearest: {', '.join(near)}"
    )
