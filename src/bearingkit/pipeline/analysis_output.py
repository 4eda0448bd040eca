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

    def statics_dict(self) -> dict:
        """The load distribution of every case (``bearingkit analyze --json``), with its warnings."""
        from bearingkit.io.export import case_dict

        b, res = self.input, self.statics
        cases = []
        from bearingkit.pipeline.operating_output import row_speed_dicts

        preload = self.preload
        for i in range(self.n_cases):
            d = case_dict(b, res, i)
            for row, state in zip(d["rows"], res.rows, strict=True):
                row.update(row_speed_dicts(state, i))
                if preload is not None:
                    row["preload_N"] = preload[row["name"]]
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
            cases.append(d)
        # the DOFs the statics were solved with (the default fixed tilt of a single row included)
        free_used = self.setup.free
        free = [n for n, f in zip(("u_x", "u_y", "u_z", "theta_x", "theta_y"), free_used, strict=True) if f]
        return {**self._header(), "free_dofs": free, "cases": cases, "notes": self.notes}

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
                        "torque_Nm": float(friction.total[i]),
                        "power_loss_W": float(friction.power_loss[i]),
                    }
            if self.lubrication is not None:
                d["lubrication"] = self.lubrication.to_dict(i)
            d["warnings"] = list(dict.fromkeys([*self.warnings[i], *d.get("warnings", [])]))
            cases.append(d)
        out = {**self._header(), "cases": cases, "notes": self.notes}
        if self.duty_cycle is not None:
            out["duty_cycle"] = self.duty_cycle.to_dict()
        return out

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
            cases.append(d)
        return {**self._header(), "friction_model": outcome.model, "cases": cases, "notes": self.notes}

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

    def to_pandas(self):
        """One line per case: operating point, displacement, per-row max load and pressure, lives, torque."""
        import pandas as pd

        res = self.statics
        cols: dict[str, object] = {"case": self.case_names}
        cols["speed_rad_s"] = self.operating.speed
        cols["temperature_C"] = self.operating.temperature
        cols["temperature_found"] = np.full(self.n_cases, self.thermal is not None)
        for k, name in enumerate(("u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad")):
            cols[name] = res.displacement[:, k]
        cols["converged"] = np.asarray(res.converged, bool)
        for row in res.rows:
            cols[f"{row.name}_max_load_N"] = row.max_load
            cols[f"{row.name}_max_pressure_Pa"] = row.max_pressure.max(axis=-1)
            cols[f"{row.name}_loaded_count"] = row.loaded_count
        if self.rating is not None:
            cols["L10r_rev"] = np.ma.filled(self.rating.life.astype(float), np.nan)
            cols["static_safety"] = np.ma.filled(self.rating.static_safety.astype(float), np.nan)
        if self.friction is not None:
            cols["friction_torque_Nm"] = self.friction.total
            cols["power_loss_W"] = self.friction.power_loss
        cols["warnings"] = [len(w) for w in self.warnings]
        return pd.DataFrame(cols)
