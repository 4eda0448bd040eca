"""Print the accuracy table of docs/catalogue.md: ISO 281 C / ISO 76 C0 of the estimated geometry
against the published ratings, per family and series, over every tabulated size.

Usage: ``python scripts/catalogue_accuracy.py [--sizes]`` (``--sizes`` adds one line per size).
Error = estimate / catalogue - 1. Needle bearings without inner ring (RNA, twins of the NA rows with the
same published ratings) are left out; angular contact series are split by contact-angle suffix,
spherical roller thrust series by design (E or standard).
"""

from __future__ import annotations

import re
import sys

import numpy as np

from bearingkit.catalogue import FAMILIES, basis, entries, estimate, ratings

NAMES = {
    "deep_groove_ball": "deep groove ball",
    "angular_contact_ball": "angular contact ball",
    "double_row_angular_contact_ball": "double row angular contact ball",
    "four_point_contact_ball": "four-point contact ball (axial)",
    "self_aligning_ball": "self-aligning ball",
    "cylindrical_roller": "cylindrical roller",
    "double_row_cylindrical_roller": "double-row cylindrical roller",
    "tapered_roller": "tapered roller",
    "thrust_ball": "thrust ball",
    "thrust_cylindrical_roller": "thrust cylindrical roller",
    "spherical_roller": "spherical roller",
    "spherical_roller_thrust": "spherical roller thrust (axial)",
    "needle_roller": "needle roller",
}


def _series(e) -> str:
    if e.family == "angular_contact_ball":
        return e.series + re.sub(r"^\d+", "", e.designation)
    if e.family == "spherical_roller_thrust":  # NSK's E design and the standard one have their own rules
        return e.series + (" E" if e.extra.get("design") == "E" else "")
    return e.series


def _source(e) -> str:
    if e.source.upper().startswith("SKF"):
        return "SKF 6000"
    if e.source.startswith("NTN-ULTAGE"):
        return "NTN ULTAGE"
    if e.source.startswith("AKE-"):
        return "AKE CSKGB072009"
    if e.source.startswith("KRW-"):
        return "KRW 2006"
    if e.source.startswith("ZVL-"):
        return "ZVL Bearing Catalogue"
    return "KOYO B2001" if e.source.startswith("KOYO-B2001") else "NSK E1102"


def groups():
    """{(family, series, source): [(designation, C_est, C_cat, C0_est, C0_cat)]} in table order."""
    out: dict = {}
    for fam in FAMILIES:
        for e in entries(fam).values():
            if e.C is None or e.extra.get("inner_ring") == "no":
                continue
            c, c0 = ratings(estimate(e))
            out.setdefault((fam, _series(e), _source(e)), []).append((e.designation, c, e.C, c0, e.C0))
    return out


def _stats(err):
    err = np.asarray(err)
    return (
        f"{100 * err.mean():+.1f}%",
        f"{100 * err.min():+.0f}% … {100 * err.max():+.0f}%",
        f"{100 * np.mean(np.abs(err) <= 0.10):.0f}%",
    )


def main(argv: list[str]) -> None:
    print(
        "| family | series | source | sizes | C: mean error | C: range | C: within 10 % "
        "| C0: mean error | C0: range | C0: within 10 % |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    table = groups()
    for (fam, series, src), rows in table.items():
        ec = [r[1] / r[2] - 1 for r in rows]
        e0 = [r[3] / r[4] - 1 for r in rows]
        print(
            f"| {NAMES[fam]} | {series} | {src} | {len(rows)} | " + " | ".join(_stats(ec) + _stats(e0)) + " |"
        )
    if "--sizes" in argv:
        for (fam, series, _), rows in table.items():
            for name, c, cc, c0, cc0 in rows:
                print(
                    f"{fam:32s} {series:5s} {name:10s} C {c / 1e3:8.1f} / {cc / 1e3:8.1f} kN "
                    f"{100 * (c / cc - 1):+6.1f}%  C0 {c0 / 1e3:8.1f} / {cc0 / 1e3:8.1f} kN "
                    f"{100 * (c0 / cc0 - 1):+6.1f}%  ({basis(fam)})"
                )


if __name__ == "__main__":
    main(sys.argv[1:])
