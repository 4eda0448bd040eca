"""The output of an :class:`~bearingkit.pipeline.analysis.Analysis`: JSON-ready dicts and a table.

SI values, units in keys. :class:`AnalysisOutput` holds what every face prints or exports: the dict of
each command (``statics_dict`` for ``bearingkit analyze --json``, ``rating_dict``, ``friction_dict``,
``friction_comparison``, ``heat_dict``), everything at once (``to_dict``) and one line per case
(``to_pandas``). :class:`~bearingkit.pipeline.analysis.Analysis` inherits it.

It is apart from :mod:`bearingkit.pipeline.analysis` because it only lays out parts computed there
(``statics``, ``rating``, ``friction_by``, ``warnings``, ``notes`` …); the orchestration (what is
computed, when, once) stays in one place and the layout for the faces in another.
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError

__all__ = ["AnalysisOutput"]


class AnalysisOutput:
    """JSON-ready dicts and the pandas table of an Analysis (a mixin: it reads the Analysis's parts)."""

    def _header(self) -> dict:
        b = self.input
        return {
            "file": b.source,
            "bearing_type": b.bearing_type,
            "bearing_name": b.model.name,
            "source": b.spec.bearing.source,
        }

    def statics_dict(self, subsurface=None) -> dict:
        """The load distribution of every case (``bearingkit analyze --json``), with its warnings.

        ``subsurface`` (a :class:`~bearingkit.analysis.subsurface.SubsurfaceResult`, ``analyze
        --subsurface``) adds ``rows[].subsurface`` (profiles against depth, maxima, the case check) and, for
        ball rows, ``rows[].truncation``, and the settings as ``subsurface``.
        """
        from bearingkit.io.export import case_dict

        b, res = self.input, self.statics
        cases = []
        from bearingkit.pipeline.operating_output import rest_speed_dicts, row_speed_dicts

        preload = self.preload
        for i in range(self.n_cases):
            d = case_dict(b, res, i)
            for row, state in zip(d["rows"], res.rows, strict=True):
                row.update(row_speed_dicts(state, i))
                row.update(rest_speed_dicts(row))  # the same keys at every speed
                if preload is not None:
                    row["preload_N"] = preload[row["name"]]
                if subsurface is not None:
                    self._add_subsurface(row, subsurface, i)
            if self.clearance is not None:
                d["clearance"] = self.clearance.to_dict(i)
            if self.flexible is not None:
                d["flexible"] = self.flexible.to_dict(i) | {"case": d["case"]}
                if hasattr(self.flexible, "rigid"):  # a [structure]: what the flexibility changes
                    from bearingkit.pipeline.structure import change

                    d["flexible"]["change"] = change(self, i)
            if self.thermal is not None:
                d["thermal"] = self.thermal.to_dict(i)
            d["warnings"] = self.warnings[i]
            d["limits"] = None if self.limits is None else self.limits.to_dict(i)
            cases.append(d)
        # the DOFs the statics were solved with (the default fixed tilt of a single row included)
        free_used = self.setup.free
        free = [n for n, f in zip(("u_x", "u_y", "u_z", "theta_x", "theta_y"), free_used, strict=True) if f]
        out = {**self._header(), "free_dofs": free, "cases": cases, "notes": self.notes}
        if subsurface is not None:
            out["subsurface"] = subsurface.settings_dict()
        return out

    def _add_subsurface(self, row: dict, subsurface, case: int) -> None:
        """``row['subsurface']`` (and ``row['truncation']`` of a ball row) for one case."""
        try:
            row["subsurface"] = subsurface.row(row["name"]).to_dict(case)
        except KeyError:  # a row the check does not cover (threaded)
            row["subsurface"] = None
        if self.rating is not None:
            t = self.truncation.row_dict(row["name"], case)
            if t is not None:
                row["truncation"] = t

    def rating_dict(self) -> dict:
        """Ratings and lives of every case (``bearingkit rating --json``) and of the duty cycle, when the
        input has one; InputError when not rateable."""
        if self.n_cases == 0 and self.duty_cycle is not None:  # a file may give only its load spectrum
            cycle = self.duty_cycle.to_dict()
            return {**self._header(), "cases": [], "notes": cycle["notes"], "duty_cycle": cycle}
        if self.rating is None:
            raise InputError(f"{self.input.source}: {self._rating[1]}")
        cases = []
        for i, c in enumerate(self.input.cases):
            d = {"case": c.name, **self.rating.to_dict(i)}
            if self.thermal is not None:
                d["thermal"] = self.thermal.to_dict(i)
                friction = self.friction
                if friction is not None:
                    d["friction"] = {
                        "model": friction.model,
                        "model_why": friction.why,
                        "torque_Nm": float(friction.total[i]),
                        "power_loss_W": float(friction.power_loss[i]),
                    }
            self._add_truncation(d, i)
            if self.lubrication is not None:
                d["lubrication"] = self.lubrication.to_dict(i)
            d["limits"] = None if self.limits is None else self.limits.to_dict(i)
            d["warnings"] = list(dict.fromkeys([*self.warnings[i], *d.get("warnings", [])]))
            cases.append(d)
        out = {**self._header(), "cases": cases, "notes": self.notes}
        if self.duty_cycle is not None:
            out["duty_cycle"] = self.duty_cycle.to_dict()
        return out

    def _add_truncation(self, rating_case: dict, case: int) -> None:
        """``rows[].truncation`` of the rating rows truncated in this case (numbers beside the warning)."""
        for row in rating_case["rows"]:
            t = self.truncation.row_dict(row["name"], case)
            if t is not None and t["truncated"]:
                row["truncation"] = t

    def friction_dict(self, model: str | None = None) -> dict:
        """Friction of every case by ``model`` (``bearingkit friction --json``)."""
        outcome = self.friction_by(model)
        cases = []
        for i, d in enumerate(outcome.case_dicts):
            d = dict(d)
            d["friction"] = {**d["friction"], "power_loss_W": float(outcome.power_loss[i])}
            if self.thermal is not None:
                d["thermal"] = self.thermal.to_dict(i)
            d["warnings"] = self.warnings[i]
            d["limits"] = None if self.limits is None else self.limits.to_dict(i)
            cases.append(d)
        return {
            **self._header(),
            "friction_model": outcome.model,
            "friction_model_why": outcome.why,
            "cases": cases,
            "notes": self.notes,
        }

    def friction_comparison(self) -> dict:
        """Every friction model that applies, side by side, with when each applies
        (:func:`bearingkit.pipeline.friction.extra.compare`)."""
        from bearingkit.pipeline.friction.extra import compare

        return {**self._header(), **compare(self), "notes_run": self.notes}

    def heat_dict(self, model: str | None = None) -> dict:
        """Heat balance (operating temperature) and the model's thermal reference speed (ISO 15312
        method), JSON-ready (:mod:`bearingkit.pipeline.thermal.reference`; the balance of
        :mod:`bearingkit.pipeline.thermal.balance`, the analysis's own when it found its temperature)."""
        from bearingkit.pipeline.thermal import reference as thermal

        model = model or self.friction_model
        if self.thermal is not None and self.thermal.model == model:
            balance = thermal.HeatBalance.of(self.thermal)
        else:
            balance = self._in_file(thermal.heat_balance, self, model)
        try:
            n_ref = self._in_file(
                thermal.thermal_reference_speed, self, "skf" if model == "components" else model
            )
            why = None
        except InputError as exc:
            n_ref, why = None, str(exc)
        return {
            **self._header(),
            "thermal_reference_speed_rad_s": None if n_ref is None or np.isnan(n_ref) else float(n_ref),
            "thermal_reference_speed_note": why,
            "cases": [{"case": c, **balance.to_dict(i)} for i, c in enumerate(self.case_names)],
        }

    def to_dict(self) -> dict:
        """Everything computed for every case, JSON-ready (SI values, units in keys)."""
        out = self.statics_dict()
        for i, d in enumerate(out["cases"]):
            d["operating"] = self.operating.to_dict(i)
            d["operating"]["temperature_found"] = self.thermal is not None
            if self.rating is not None:
                d["rating"] = self.rating.to_dict(i)
                self._add_truncation(d["rating"], i)
            if self.lubrication is not None:
                d["lubrication"] = self.lubrication.to_dict(i)
            friction = self.friction
            if friction is not None:
                d["friction"] = {
                    **friction.case_dicts[i]["friction"],
                    "power_loss_W": float(friction.power_loss[i]),
                }
        if self.load_diagram is not None:
            out["load_diagram"] = self.load_diagram.to_dict()
        if self.operating.lubricant is not None:  # what the lubricant analysed is (docs/lubricants.md)
            out["lubricant"] = self.operating.lubricant.to_dict()
        out["notes"] = self.notes
        out["references"] = self.references
        return out

    def __repr__(self) -> str:
        names = ", ".join(repr(n) for n in self.case_names[:3]) + (" …" if self.n_cases > 3 else "")
        plural = "case" if self.n_cases == 1 else "cases"
        source = str(self.input.source)
        return f"<Analysis of {self.input.model.name!r} from {source!r}: {self.n_cases} {plural} {names}>"

    def _repr_html_(self) -> str:
        """The notebook view (:mod:`bearingkit.display`): one line per case with loads, the largest
        element load and pressure, L10h by ISO 281 and ISO/TS 16281 and s0, then every warning."""
        from bearingkit.display import html_table, number

        try:
            res = self.statics
            rating = self.rating
            rows, warnings = [], []
            for i, name in enumerate(self.case_names):
                load = res.load[i]
                system = rating.to_dict(i)["system"] if rating is not None else {}
                speed = self.operating.speed[i]
                rows.append(
                    [
                        name,
                        "yes" if res.converged[i] else "NO",
                        number(speed, 30 / np.pi) if speed else "0",
                        number(np.hypot(load[0], load[1]), 1e-3),
                        number(load[2], 1e-3),
                        number(np.hypot(load[3], load[4])),
                        number(max(float(r.max_load[i]) for r in res.rows)),
                        number(max(float(np.max(r.max_pressure[i])) for r in res.rows), 1e-6),
                        number(system.get("L10h_iso281_h"), digits=4),
                        number(system.get("L10h_h"), digits=4),
                        number(system.get("s0_iso76"), digits=3),
                        number(system.get("static_safety"), digits=3),
                    ]
                )
                warnings += [f"{name}: {w}" for w in self.warnings[i]]
            columns = ["case", "converged", "n [r/min]", "F_r [kN]", "F_a [kN]", "M [N·m]", "Q_max [N]",
                       "p_max [MPa]", "L10h ISO 281 [h]", "L10h ISO/TS 16281 [h]", "s0 ISO 76",
                       "s0"]  # fmt: skip
            notes = list(self.notes)
            if rating is None:
                notes.insert(0, f"no ratings: {self._rating[1]}")
            title = f"{self.input.model.name} ({self.input.source})"
            return html_table(title, columns, rows, warnings=warnings, notes=notes)
        except Exception as exc:  # a notebook cell must show something, and say what went wrong
            from html import escape

            return f"<div class='bearingkit'><b>{escape(repr(self))}</b><br>error: {escape(str(exc))}</div>"

    def to_pandas(self):
        """One line per case with every headline quantity (SI, units in the column names).

        Operating point, displacement, convergence; per row the largest element load, contact pressure,
        loaded elements and operating clearance (the fits' chain where the file has fits, else the
        model's); both lives — ISO 281 (``L10_iso281_rev``, ``L10h_iso281_h``, ``Lnm_iso281_rev``,
        ``Lnm_iso281_h``, ``a_ISO_iso281``) and ISO/TS 16281 (``L10r_rev``, ``L10r_h``, ``Lnmr_rev``,
        ``Lnmr_h``, ``a_ISO``) —, κ (the smallest over the rows), s0, p_max, the friction torque and power
        with the model's name, the stiffness diagonal, the speed and load limits with their flags and the
        number of warnings. A value a part cannot give (no speed, no lubricant, no rating) is NaN.
        """
        import pandas as pd

        res, n = self.statics, self.n_cases
        nan = np.full(n, np.nan)
        cols: dict[str, object] = {"case": self.case_names}
        cols["speed_rad_s"] = self.operating.speed
        cols["temperature_C"] = self.operating.temperature
        cols["temperature_found"] = np.full(self.n_cases, self.thermal is not None)
        for k, name in enumerate(("u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad")):
            cols[name] = res.displacement[:, k]
        cols["converged"] = np.asarray(res.converged, bool)
        clearance = self.clearance
        for row, model_row in zip(res.rows, res.model.rows, strict=True):
            cols[f"{row.name}_max_load_N"] = row.max_load
            cols[f"{row.name}_max_pressure_Pa"] = row.max_pressure.max(axis=-1)
            cols[f"{row.name}_loaded_count"] = row.loaded_count
            if clearance is not None and row.name in clearance.operating:
                cols[f"{row.name}_operating_clearance_m"] = np.broadcast_to(
                    clearance.operating[row.name], (n,)
                )
            elif getattr(model_row, "clearance", None) is not None:
                cols[f"{row.name}_operating_clearance_m"] = np.broadcast_to(np.max(model_row.clearance), (n,))
        cols["p_max_Pa"] = np.max([r.max_pressure.max(axis=-1) for r in res.rows], axis=0)
        cols.update(_life_columns(self, nan))
        cols.update(_friction_columns(self, nan))
        for k, name in enumerate(DIAGONAL_NAMES):
            cols[name] = res.stiffness[:, k, k]
        cols.update(_limit_columns(self, nan))
        cols["warnings"] = [len(w) for w in self.warnings]
        return pd.DataFrame(cols)


#: Column names of the stiffness diagonal in :meth:`AnalysisOutput.to_pandas` (the studies' names).
DIAGONAL_NAMES = (
    "k_xx_N_per_m",
    "k_yy_N_per_m",
    "k_zz_N_per_m",
    "k_thx_thx_Nm_per_rad",
    "k_thy_thy_Nm_per_rad",
)
#: ``to_pandas`` column → key of the rating's ``system`` dict (lives of both methods).
_SYSTEM_LIVES = {
    "L10_iso281_rev": "L10_iso281_rev",
    "L10h_iso281_h": "L10h_iso281_h",
    "Lnm_iso281_rev": "Lnm_iso281_rev",
    "Lnm_iso281_h": "Lnm_iso281_h",
    "a_ISO_iso281": "a_ISO_iso281",
    "L10r_rev": "L10r_rev",
    "L10r_h": "L10h_h",
    "Lnmr_rev": "Lnmr_rev",
    "Lnmr_h": "Lnmr_h",
    "static_safety": "static_safety",
}


def _number(value) -> float:
    return np.nan if value is None else float(value)


def _life_columns(a, nan) -> dict:
    """Lives of both methods, a_ISO, κ and s0 per case (NaN where not rated)."""
    out = {name: nan.copy() for name in _SYSTEM_LIVES}
    out["a_ISO"], out["kappa"] = nan.copy(), nan.copy()
    if a.rating is not None:
        for i in range(a.n_cases):
            d = a.rating.to_dict(i)
            for name, key in _SYSTEM_LIVES.items():
                out[name][i] = _number(d["system"].get(key))
            a_iso = [r.get("a_ISO") for r in d["rows"] if r.get("a_ISO") is not None]
            out["a_ISO"][i] = min(a_iso) if a_iso else np.nan
    lub = a.lubrication
    if lub is not None and lub.result.kappa:
        out["kappa"] = np.min([np.asarray(v, float) for v in lub.result.kappa.values()], axis=0)
    return out


def _friction_columns(a, nan) -> dict:
    f = a.friction
    if f is None:  # not computed (the notes say why): the model it would be
        from bearingkit.pipeline.friction.choice import AUTO, choose

        model = choose(a)[0] if a.friction_model == AUTO else a.friction_model
        return {"friction_model": [model] * a.n_cases, "friction_torque_Nm": nan, "power_loss_W": nan}
    return {
        "friction_model": [f.model] * a.n_cases,
        "friction_torque_Nm": np.asarray(f.total, float),
        "power_loss_W": np.asarray(f.power_loss, float),
    }


def _limit_columns(a, nan) -> dict:
    lim = a.limits
    names = ("above_limiting_speed", "above_reference_speed", "seal_lip_speed_exceeded", "below_minimum_load")
    if lim is None:
        out = {"limiting_speed_rad_s": nan, "minimum_load_N": nan}
        out.update({k: [False] * a.n_cases for k in names})
        return out
    flags = [lim.flags(i) for i in range(a.n_cases)]
    out = {
        "limiting_speed_rad_s": np.full(a.n_cases, lim.limiting_speed),
        "minimum_load_N": nan if lim.minimum_load is None else lim.minimum_load,
    }
    out.update({k: [f[k] for f in flags] for k in names})
    return out
