"""Notes and per-case warnings of an Analysis: what it tells every face, apart from what it computes."""

from __future__ import annotations

import numpy as np

__all__ = ["FREE_TILT_LIMIT", "notes", "warnings"]

#: Tilt [rad] above which a single-row bearing with free tilt DOFs and no applied moment is flagged:
#: it tilts only because the model lets it (a real one sits on a shaft); 1 µrad is far below any
#: misalignment that matters and far above the solver's round-off (~1e-16 rad).
FREE_TILT_LIMIT = 1.0e-6


def _coplanar(model) -> bool:
    """True when every row of ``model`` sits in one axial plane (a single-row bearing)."""
    positions = {round(float(np.max(getattr(r, "axial_position", 0.0))), 12) for r in model.rows}
    return len(positions) == 1


def notes(a) -> list[str]:
    """What was assumed or skipped, for every face (not per case)."""
    op, out = a.operating, []
    if a._rating[1]:
        out.append(a._rating[1])
    elif not np.all(op.abs_speed > 0):
        out.append("ratings: no speed for every case, so no lives in hours and no κ / a_ISO")
    elif op.contamination is None:
        out.append("ratings: no contamination factor e_C given, so no a_ISO and no L_nm")
    elif op.lubricant is None:
        out.append("ratings: no lubricant given, so no κ, a_ISO or L_nm")
    if a.thermal is not None:
        out.append(
            "operating temperature FOUND by the heat balance (not an input): viscosity, κ, a_ISO, "
            "friction "
            "and the operating clearance are at the found temperature of each case (its thermal block)"
        )
        out.extend(f"thermal: {n}" for n in a.thermal.notes)
    if a.rating is not None:
        out.extend(f"ratings: {n}" for n in a.rating.notes)
    out.extend(a.setup.notes)
    from bearingkit.pipeline.rating.mounting import mounting_notes

    out.extend(mounting_notes(a))
    from bearingkit.analysis.solver.speed import speed_notes

    out.extend(speed_notes(a.statics.model))
    lub = a.lubrication
    if lub is not None:
        out.extend(f"lubrication: {n}" for n in lub.notes)
    errors = a._friction_errors
    for model, why in errors.items():
        if model == "auto" and why in [w for m, w in errors.items() if m != "auto"]:
            continue  # the default's error is the chosen model's, already listed
        out.append(f"friction ({model}) not computed: {why}")
    auto = a._friction.get("auto")
    if auto is not None:
        out.append(f"friction: the {auto.model} model by default: {auto.why}")
    for outcome in a._friction.values():
        out.extend(f"friction ({outcome.model}): {n}" for n in outcome.notes)
    for sub in a._subsurface.values():
        out.extend(n for n in sub.notes if n not in out)
    factor = a.hardness.limit_factor()
    if factor != 1.0 and a.rating is not None:
        out.append(
            f"static limit: ISO 76's limit pressures × {factor:.3g} for the raceways' hardness "
            f"({a.hardness.describe()}; docs/subsurface.md)"
        )
    return list(dict.fromkeys(out))  # the default's outcome repeats the chosen model's notes


def _free_tilt(a, case: int) -> str | None:
    res, free = a.statics, a.setup.free
    if not (free[3] or free[4]) or not _coplanar(res.model) or not res.converged[case]:
        return None
    tilt = float(np.hypot(*res.displacement[case, 3:5]))
    moment = float(np.hypot(*res.load[case, 3:5]))
    if tilt > FREE_TILT_LIMIT and moment == 0.0:
        return (
            f"free tilt of a single-row bearing: it tilts {tilt * 1e3:.3g} mrad under no applied moment "
            "because theta_x, theta_y are free; a bearing on a shaft does not: fix them in [solver] "
            "free (as commercial tools do for a single bearing) or model the shaft"
        )
    return None


def warnings(a) -> list[list[str]]:
    """Per case: every doubtful finding of the parts computed for it (statics and ratings always)."""
    res = a.statics
    out = []
    rating = a.rating
    flex = a.flexible
    for c in range(a.n_cases):
        notes = []
        if not res.converged[c]:
            notes.append(
                f"did not converge: {res.reason[c] or 'no reason given'}; loads shown are not an equilibrium"
            )
        tilt = _free_tilt(a, c)
        if tilt:
            notes.append(tilt)
        if flex is not None and not flex.converged[c]:
            notes.append("the flexible-ring coupling did not converge")
        if flex is not None:
            notes.extend(getattr(flex, "warnings", []))
        if rating is not None:
            notes.extend(w for w in rating.warnings[c] if res.converged[c] or "did not converge" not in w)
        from bearingkit.pipeline.operating_output import operating_warnings
        from bearingkit.pipeline.rating.mounting import mounting_warnings

        notes.extend(mounting_warnings(a, c))
        notes.extend(operating_warnings(a, c))
        if a.limits is not None:
            notes.extend(a.limits.warnings(c))
        notes.extend(_subsurface_warnings(a, c))
        out.append(list(dict.fromkeys(notes)))
    return out


def _subsurface_warnings(a, case: int) -> list[str]:
    """Truncated contacts as numbers (ball rows, when rated) and an overloaded case or core (a
    case-hardened raceway: the check runs for every face)."""
    if not a.statics.converged[case]:
        return []
    out = []
    if a.rating is not None:
        from bearingkit.pipeline.rating.subsurface import truncation_warnings

        out.extend(truncation_warnings(a, case))
    if not a.hardness.through_hardened:
        out.extend(a.subsurface.warnings[case])
    return out
