"""Parse bearing designations such as ``"6205-2RS C3"``, ``"7206 BECBP"``, ``"NU 2206 ECP"``,
``"32206 J2"``, ``"22208 EK C3"``, ``"NA 4906"``, ``"RNA 49/22"``, ``"QJ 208 N2MA"``.

A designation is a *basic designation* (type and dimension series, bore code) followed by suffixes.
Bore codes: 00 = 10 mm, 01 = 12, 02 = 15, 03 = 17, from 04 on the code × 5, and ``/dd`` = dd mm
(``302/22``, ``NA49/22``) (ISO 15 cl. 7 and every catalogue's designation system). Needle roller
bearings: ``NA`` with inner ring, ``RNA`` without (the shaft is the raceway). Suffixes: seals and shields
(Z, 2Z, ZZ, RS, 2RS, 2RS1, RSH, 2RSH, RSL, 2RSL, RSR, 2RSR, RZ, 2RZ, LLU, LLH, LLB, DDU, DD, VV;
:mod:`bearingkit.catalogue.seals`), snap ring (N, NR), internal clearance
(C2, CN, C3, C4, C5), design and cage (E, EC, ECP, ECJ, ECM, J, J2, X, XJ, TN9, M, MA, P, CBP, …;
spherical roller E, EA, C, CC, CD, CA, CAM, E4, W33; four-point N2), tapered bore (K 1:12, K30 1:30),
tolerance (P6, P5). The clearance class, the contact-angle suffix of angular contact bearings and the
tapered bore (its clearance group) change the mechanics; the others are kept as notes. Bad designations
raise :class:`~bearingkit.errors.InputError` with the nearest designations of the table.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass

from bearingkit.catalogue import tables
from bearingkit.catalogue.seals import SEALS
from bearingkit.errors import InputError

#: Basic designation patterns, tried in order: (family, regex with groups series, bore code, rest).
_PATTERNS: tuple[tuple[str, re.Pattern], ...] = (
    ("four_point_contact_ball", re.compile(r"^(QJ\s?[23])(\d\d)(.*)$")),
    ("needle_roller", re.compile(r"^(R?NA\s?4[89])(\d\d|/\d\d)(.*)$")),
    ("cylindrical_roller", re.compile(r"^(?:NUP|NU|NJ|N)\s?(10|22|23|2|3)(\d\d)(.*)$")),
    ("thrust_cylindrical_roller", re.compile(r"^(81[12])(\d\d)(.*)$")),
    ("thrust_ball", re.compile(r"^(51[123])(\d\d)(.*)$")),
    ("tapered_roller", re.compile(r"^(30[23]|313|32[023])(\d\d|/\d\d)(.*)$")),
    ("deep_groove_ball", re.compile(r"^(61[89]|160)(\d\d)(.*)$")),
    ("angular_contact_ball", re.compile(r"^(7[23])(\d\d)(.*)$")),
    ("double_row_angular_contact_ball", re.compile(r"^(3[23])(\d\d)(.*)$")),
    # spherical 222xx/223xx before self-aligning 22xx: "22208" is a spherical roller bearing, "2208" not
    ("spherical_roller", re.compile(r"^(22[23])(\d\d)(.*)$")),
    ("self_aligning_ball", re.compile(r"^(1[2]|2[2])(\d\d)(.*)$")),
    ("deep_groove_ball", re.compile(r"^(6[0234])(\d\d)(.*)$")),
)
#: Known suffixes (longest first when matching). Clearance classes are extracted separately.
SEAL_SUFFIXES = (
    "2RSL",
    "2RS1",
    "2RSR",
    "2RSH",
    "2RS",
    "RS1",
    "RSL",
    "RSR",
    "RSH",
    "RS",
    "2RZ",
    "RZ",
    "2Z",
    "ZZ",
    "Z",
    "LLU",
    "LLB",
    "LLH",
    "DDU",
    "DD",
    "VV",
    "NR",
    "N",
)
DESIGN_SUFFIXES = (
    "ECBP",
    "ECBM",
    "ECBY",
    "BP",
    "BM",
    "BY",
    "ECP",
    "ECJ",
    "ECM",
    "ECML",
    "EC",
    "EW",
    "ET",
    "EM",
    "E",
    "XJ",
    "J2",
    "J",
    "X",
    "TN9",
    "TN",
    "MA",
    "M",
    "CBP",
    "CB",
    "BEP",
    "BE",
    "P6",
    "P5",
    "A",
    "W64",
    "HT",
    # spherical roller designs (NSK EA, C, CD, CA; SKF E, CC, CA, CAM), oil groove (NSK E4, SKF W33),
    # brass cage MB, four-point locating slots N2
    "CAM",
    "EA",
    "EJ",
    "CC",
    "CD",
    "CA",
    "E4",
    "W33",
    "MB",
    "N2",
    "C",
)
#: Tapered bore (1:12, 1:30): the bore d is the small end; noted, the estimate is the cylindrical one.
BORE_SUFFIXES = ("K30", "K")
CLEARANCE_SUFFIXES = ("C2", "CN", "C3", "C4", "C5")
ANGLE_SUFFIXES = ("AC", "A", "B", "C")
_SUFFIX_RE = re.compile(
    "|".join(
        sorted((*SEAL_SUFFIXES, *DESIGN_SUFFIXES, *BORE_SUFFIXES, *CLEARANCE_SUFFIXES), key=len, reverse=True)
    )
)


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
        ``"C2"`` … ``"C5"`` or ``"CN"`` when given.
    suffixes : tuple of str
        The other recognised suffixes (seals, cage, tolerance), kept as notes.
    """

    text: str
    family: str
    base: str
    clearance_class: str | None
    suffixes: tuple


def _split_suffixes(text: str, rest: str) -> list[str]:
    out = []
    for token in rest.replace("-", " ").replace("/", " ").split():
        pos = 0
        while pos < len(token):
            m = _SUFFIX_RE.match(token, pos)
            if m is None:
                break
            out.append(m.group(0))
            pos = m.end()
        if pos < len(token):
            bad = token
            raise InputError(
                f"designation ({text!r}): suffix {bad!r} not recognised; known suffixes: seals "
                f"{', '.join(SEAL_SUFFIXES[:10])}…, clearance {', '.join(CLEARANCE_SUFFIXES)}, design "
                f"{', '.join(DESIGN_SUFFIXES[:8])}… (e.g. '6205-2RS C3')"
            )
    return out


def seal_suffix(suffixes) -> str | None:
    """The seal or shield suffix among a designation's ``suffixes`` (``"2RS1"``, ``"ZZ"``), or None.

    Snap-ring suffixes (``N``, ``NR``) share :data:`SEAL_SUFFIXES` with the seals but close nothing; they
    are skipped. :mod:`bearingkit.catalogue.seals` says what each suffix means.
    """
    found = [s for s in suffixes if s in SEALS]
    return found[0] if found else None


def nearest(text: str, n: int = 3) -> list[str]:
    """The ``n`` table designations closest to ``text`` (difflib ratio)."""
    names = [e.designation for e in tables.all_entries()]
    key = re.sub(r"[\s\-]", "", text.upper())
    return difflib.get_close_matches(key, names, n=n, cutoff=0.0)


def parse(text: str) -> Designation:
    """Parse ``text``; InputError (one line, nearest valid designations) when it is not in the tables."""
    raw = str(text).strip()
    up = raw.upper()
    for family, pattern in _PATTERNS:
        m = pattern.match(up)
        if m is None:
            continue
        series, code, rest = m.group(1).replace(" ", ""), m.group(2), m.group(3)
        angle = ""
        if family == "angular_contact_ball":
            am = re.match(r"^\s?(AC|A|B|C)(?![2-5N])", rest)
            if am is None:
                raise InputError(
                    f"designation ({raw!r}): an angular contact bearing needs its contact angle suffix "
                    f"B (40°), AC (25°), A (30°) or C (15°), e.g. '{series}{code}B'"
                )
            angle, rest = am.group(1), rest[am.end() :]
        if family == "tapered_roller" and series == "320":
            rest = re.sub(r"^\s?X", "", rest)
            angle = "X"
        if family == "cylindrical_roller":
            angle = "" if series == "10" else "E"
            rest = re.sub(r"^\s?E(?![CWTM])", "", rest)
        if family == "double_row_angular_contact_ball":
            rest = re.sub(r"^\s?A(?!C)", "", rest)
        if family in ("four_point_contact_ball", "needle_roller"):
            series = series.replace(" ", "")
        prefix = "NU" if family == "cylindrical_roller" else ""
        base = f"{prefix}{series}{code}{angle}"
        suffixes = _split_suffixes(raw, rest)
        clearance = [s for s in suffixes if s in CLEARANCE_SUFFIXES]
        if len(clearance) > 1:
            raise InputError(
                f"designation ({raw!r}): two clearance classes ({', '.join(clearance)}); give one"
            )
        table = tables.entries(family)
        if base not in table:
            bore = bore_from_code(code)
            same = sorted(
                (e for e in table.values() if e.series == series and e.designation.endswith(angle)),
                key=lambda e: abs(e.bore * 1e3 - bore),
            )
            near = [e.designation for e in same[:3]] or nearest(base)
            lo = min((e.bore for e in same), default=0.0) * 1e3
            hi = max((e.bore for e in same), default=0.0) * 1e3
            span = f"; the table holds bores {lo:g}–{hi:g} mm of series {series}" if same else ""
            raise InputError(
                f"designation ({raw!r}): {base} (bore {bore:g} mm) is not in the catalogue tables{span}; "
                f"nearest: {', '.join(near)}"
            )
        others = tuple(s for s in suffixes if s not in CLEARANCE_SUFFIXES)
        return Designation(raw, family, base, clearance[0] if clearance else None, others)
    raise InputError(
        f"designation ({raw!r}) is not a designation bearingkit knows (series 618, 619, 160, 60, 62, 63, 64, "
        "72, 73, 32, 33, QJ2, QJ3, 12, 22, 222, 223, N/NU/NJ/NUP 10/2/22/3/23, NA48, NA49, RNA48, RNA49, "
        f"302, 303, 313, 320, 322, 323, 511, 512, 513, 811, 812); nearest: {', '.join(nearest(raw))}"
    )
