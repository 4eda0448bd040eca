"""Subsurface stresses, the hardened-layer check and truncation numbers of an
:class:`~bearingkit.pipeline.analysis.Analysis` (docs/subsurface.md).

SI units. What :class:`~bearingkit.pipeline.analysis.Analysis` computes lazily for every face:

- :func:`raceway_profile`: the raceways' hardness profile (the file's ``[hardness]``, else the material's);
- :func:`subsurface_of`: :func:`bearingkit.analysis.subsurface.subsurface` on the solved statics;
- :func:`truncation_of`: the truncated ball contacts as numbers and the rating *with* truncation (the
  truncated contacts carry their re-equilibrated loads; :mod:`bearingkit.analysis.truncation`);
- :func:`truncation_warnings`: per case, one line per truncated row beside the rating's warning.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["TruncationOutcome", "raceway_profile", "subsurface_of", "truncation_of", "truncation_warnings"]


def raceway_profile(analysis):
    """The raceways' :class:`~bearingkit.hardness.HardnessProfile`."""
    given = getattr(analysis.input, "hardness", None)
    return given if given is not None else analysis.input.material.raceway_hardness


def subsurface_of(analysis, *, traction=0.0, target_safety=1.0, every_contact=False):
    """SubsurfaceResult of the analysis's statics (InputError prefixed with the file)."""
    from bearingkit.analysis.subsurface import subsurface

    return analysis._in_file(
        subsurface,
        analysis.statics,
        raceway_profile(analysis),
        float(analysis.input.material.poisson_ratio),
        traction=traction,
        target_safety=target_safety,
        every_contact=every_contact,
    )


@dataclass
class TruncationOutcome:
    """Truncated contacts of every row (None for rows without groove shoulders) and the rating with them.

    Attributes
    ----------
    rows : list of RowTruncation or None
    rating : RatingResult or None
        The rating of the solution whose truncated contacts carry Q′ = s³ Q and p_tr (None when no contact
        is truncated, or the bearing is not rated).
    """

    rows: list
    rating: object = None

    def row(self, name: str):
        for r in self.rows:
            if r is not None and r.name == name:
                return r
        return None

    def row_dict(self, name: str, case: int) -> dict | None:
        """JSON-ready truncation numbers of one row and case (None for a row without shoulders)."""
        t = self.row(name)
        if t is None:
            return None
        out = {
            "pressure_Pa": float(t.pressure[case]),
            "hertz_pressure_Pa": float(t.hertz_pressure[case]),
            "safety": float(t.safety[case]) if np.isfinite(t.safety[case]) else None,
            "truncated": bool(t.truncated[case]),
            "static_safety": None,
            "L10r_rev": None,
        }
        if self.rating is not None and t.truncated[case]:
            r = self.rating.row(name)
            out["static_safety"] = _val(r.static_safety, case)
            out["L10r_rev"] = _val(r.life, case)
        return out


def _val(a, case):
    a = np.ma.asarray(a)
    return None if np.ma.getmaskarray(a)[case] else float(np.ma.getdata(a)[case])


def truncation_of(analysis) -> TruncationOutcome:
    """Truncation numbers with the rating's shoulder heights, and the rating with truncation."""
    from bearingkit.analysis.rating.options import RatingOptions
    from bearingkit.analysis.truncation import truncated_result, truncation

    options = RatingOptions(shoulder_height=analysis._shoulder_heights())
    rows = analysis._in_file(truncation, analysis.statics, options)
    rating = None
    if analysis.rating is not None and any(t is not None and t.truncated.any() for t in rows):
        rating = analysis._rate(truncated_result(analysis.statics, rows))
    return TruncationOutcome(rows, rating)


def truncation_warnings(analysis, case: int) -> list[str]:
    """One line per truncated row: the truncated pressure, the safety, s0 and L10r with truncation."""
    out = analysis.truncation
    plain = analysis.rating
    lines = []
    for t in out.rows:
        if t is None or not t.truncated[case]:
            continue
        text = (
            f"{t.name}: truncated contact as numbers: pressure {t.pressure[case] / 1e6:.0f} MPa (Hertz "
            f"{t.hertz_pressure[case] / 1e6:.0f} MPa; ellipse cut at the edge and re-equilibrated), "
            f"track-truncation safety {t.safety[case]:.2f}"
        )
        if out.rating is not None and plain is not None:
            with_t, without = out.rating.row(t.name), plain.row(t.name)
            s0, s0p = _val(with_t.static_safety, case), _val(without.static_safety, case)
            life, lifep = _val(with_t.life, case), _val(without.life, case)
            if s0 is not None and s0p is not None:
                text += f"; with truncation s0 = {s0:.3g} ({s0p:.3g} without)"
            if life is not None and lifep is not None:
                text += f", L10r = {life:.3g} rev ({lifep:.3g} without)"
        lines.append(text)
    return lines
