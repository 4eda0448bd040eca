"""A solved drivetrain: every bearing a pipeline Analysis, the system lives, the power flow.

SI units (m, N, rad/s, W, h). The drivetrain solve (:mod:`bearingkit.systems.drivetrain.solver`) gives
each bearing the displacement q of its inner ring against its outer ring; as for one shaft
(:mod:`bearingkit.systems.shaft.shaft_analysis`), a
:class:`~bearingkit.systems.shaft.shaft_analysis.SeatInput`
hands that state to the one orchestration (``bearingkit.pipeline.analyze``): element loads, pressures,
friction and power loss, lubrication, ISO 76 / ISO 281 / ISO/TS 16281 ratings and lives, warnings.

Ring speeds. Every shaft's speed follows from the given ones through the gear ratios
(:func:`bearingkit.systems.drivetrain.power_flow.speeds`). A bearing's rings turn with their bodies; the
speeds are
taken relative to its frame: the housing, or a planet bearing's carrier (its load turns with the
carrier: the outer ring, in the planet, is the one that rotates relative to the load; the carrier's
centrifugal field on the planet bearings is not modelled). The pipeline rates each bearing at the
relative speed of its rings with the ring that turns relative to the load as ``rotating``.

System lives. Bearings of a drivetrain turn at different speeds, so the lives are combined in hours:
L_sys = (Σ_i L_i^(−e))^(−1/e) over the rows of every bearing (ISO 281:2007 slopes e = 10/9 balls,
9/8 rollers; the mixed case solves Σ (L_sys/L_i)^e_i = 1,
:func:`bearingkit.analysis.rating.assembly.system_life`),
once from the ISO/TS 16281 lives of the rows and once from the ISO 281 basic lives of the bearings. A
duty cycle (``time_fraction`` per load case) combines the cases by Palmgren–Miner,
L = 1 / Σ_c (f_c / L_c), for every bearing and for the system.
"""

from __future__ import annotations

import importlib

import numpy as np

from bearingkit.analysis.rating.assembly import HOUR, system_life
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.pipeline import analyze
from bearingkit.pipeline.thermal.balance import at_heat_balance, heat_balance_wanted
from bearingkit.systems.drivetrain import power_flow
from bearingkit.systems.drivetrain.model import HOUSING
from bearingkit.systems.drivetrain.solver import law_for, solve
from bearingkit.systems.shaft.shaft_analysis import SeatInput

#: Renderers of a DrivetrainAnalysis by format, registered by the report layer on import.
DRIVETRAIN_RENDERERS: dict = {}
_RENDERER_MODULES = {"html": "bearingkit.report.systems.drivetrain_html"}


def _miner(lives: np.ndarray, fractions: np.ndarray) -> float | None:
    """Palmgren–Miner life of a duty cycle: 1 / Σ f_c / L_c (None where a loaded case has none)."""
    lives = np.asarray(lives, float)
    used = fractions > 0
    if not np.all(np.isfinite(lives[used])) or np.any(lives[used] <= 0):
        return None
    return float(1.0 / np.sum(fractions[used] / lives[used]))


class DrivetrainAnalysis:
    """A solved drivetrain file with every bearing's Analysis, the system lives and the power flow.

    Parameters
    ----------
    drivetrain_input : DrivetrainInput
    friction_model, contamination, reliability, thermal
        As :class:`~bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis` (``thermal``: each bearing's
        temperature by its own heat balance; the meshes keep the load cases' temperature).
    """

    def __init__(
        self,
        drivetrain_input,
        *,
        friction_model="components",
        contamination=None,
        reliability=0.9,
        thermal=None,
    ):
        self.input = drivetrain_input
        self.friction_model = friction_model
        self.contamination = contamination
        self.reliability = reliability
        self.thermal = thermal

    @property
    def heat_balance(self) -> bool:
        """True when each bearing's temperature is found by its heat balance (``--heat``, ``[thermal]``)."""
        return heat_balance_wanted(self.thermal, self.input)

    @property
    def drivetrain(self):
        return self.input.drivetrain

    @property
    def n_cases(self) -> int:
        return self.input.loads["n_cases"]

    @property
    def case_names(self) -> list[str]:
        return list(self.input.loads["names"])

    @cached_property
    def omega(self) -> dict | None:
        """Speed (C,) [rad/s] of every shaft (None when the load cases give no speed)."""
        given = self.input.loads["given_speeds"]
        return power_flow.speeds(self.drivetrain, given) if given else None

    def _body_speed(self, body: str | None) -> np.ndarray:
        if body is None or body == HOUSING or self.omega is None:
            return np.zeros(self.n_cases)
        return np.asarray(self.omega[body], float)

    def ring_speeds(self, name: str) -> tuple[np.ndarray, np.ndarray] | None:
        """(inner, outer) ring speeds (C,) [rad/s] about +z relative to the bearing's frame."""
        if self.omega is None:
            return None
        b = self.drivetrain.bearing(name)
        frame = self._body_speed(b.frame_body)
        return self._body_speed(b.inner.body) - frame, self._body_speed(b.outer.body) - frame

    def rotating_ring(self, name: str) -> str:
        """The ring that turns relative to the load: the outer one of a planet bearing, else the faster."""
        b = self.drivetrain.bearing(name)
        if b.frame_body is not None:
            return "outer"
        speeds = self.ring_speeds(name)
        if speeds is None:
            return "inner"
        return "outer" if np.abs(speeds[1]).max() > np.abs(speeds[0]).max() else "inner"

    @cached_property
    def laws(self) -> list:
        out = []
        for b in self.drivetrain.bearings:
            speeds = self.ring_speeds(b.name)
            out.append(b.seat.law if speeds is None else law_for(b, *speeds))
        return out

    @cached_property
    def result(self):
        """The :class:`~bearingkit.systems.drivetrain.result.DrivetrainResult` (one batched Newton)."""
        return solve(self.drivetrain, self.input.loads, self.laws, self.input.options)

    def _seat_input(self, b) -> SeatInput:
        res, loads = self.result, self.input.loads
        source = b.seat.source
        speeds = self.ring_speeds(b.name)
        speed = None
        if speeds is not None:
            t = b.seat.transform[2, 2]
            rel = speeds[0] - speeds[1]  # inner relative to outer about +z
            speed = t * (rel if self.rotating_ring(b.name) == "inner" else -rel)
        return SeatInput(
            model=b.seat.bearing,
            load=res.bearing_load(b.name),
            free=np.zeros(5, bool),
            lubricant=getattr(source, "lubricant", None) or self.input.lubricant,
            source=f"{self.input.source} (bearing {b.name})",
            material=getattr(source, "material", None),
            displacement=res.relative_displacement(b.name),
            case_names=tuple(loads["names"]),
            speeds=speed,
            temperatures=loads["temperature"],
            system_state=(res.converged, res.iterations, res.residual_norm, res.reason),
            bearing_input=source,
            lubrication=self.input.lubrication,
            solved_model=res.model(b.name),
            thermal=getattr(self.input, "thermal", None),
        )

    @cached_property
    def bearings(self) -> dict:
        """Name → pipeline :class:`~bearingkit.pipeline.Analysis` of every bearing with rows."""
        out = {}
        for b in self.drivetrain.bearings:
            if not isinstance(b.seat.bearing, BearingModel):
                continue
            seat_input = self._seat_input(b)
            try:
                out[b.name] = analyze(
                    seat_input,
                    friction_model=self.friction_model,
                    contamination=self.contamination,
                    reliability=self.reliability,
                    rotating=self.rotating_ring(b.name),
                    thermal=False,  # the balance of every bearing at once, below
                )
            except InputError as exc:
                text = str(exc)
                raise InputError(
                    text if text.startswith(seat_input.source) else f"{seat_input.source}: {text}"
                ) from None
        return at_heat_balance(out, self.input.source, self.thermal) if self.heat_balance and out else out

    # -- lives ------------------------------------------------------------------------------------
    def bearing_lives(self, name: str) -> dict:
        """Per case (C,) [h]: ISO/TS 16281 L10h and ISO 281 L10h of one bearing (nan where none)."""
        a = self.bearings[name]
        out = {"L10h_h": np.full(self.n_cases, np.nan), "L10h_iso281_h": np.full(self.n_cases, np.nan)}
        if a.rating is None:
            return out
        for c in range(self.n_cases):
            sysd = a.rating.to_dict(c)["system"]
            unloaded = all(np.asarray(r.loaded_count)[c] == 0 for r in a.rating.rows)
            for key, src in (("L10h_h", "L10h_h"), ("L10h_iso281_h", "L10h_iso281_h")):
                v = sysd.get(src)
                out[key][c] = np.inf if unloaded else (np.nan if v is None else float(v))
        return out

    @cached_property
    def system_lives(self) -> dict:
        """System L10h (C,) [h] from the ISO/TS 16281 row lives and the ISO 281 lives (module docstring)."""
        n = self.n_cases
        ts, ts_slopes, iso, iso_slopes = [], [], [], []
        for name, a in self.bearings.items():
            if a.rating is None:
                continue
            speeds = np.abs(np.asarray(a.operating.speed, float))
            hours = np.where(speeds > 0, 1.0, np.nan)
            for row in a.rating.rows:
                life = np.ma.filled(np.ma.asarray(row.life, float), np.nan)
                unloaded = np.asarray(row.loaded_count) == 0
                ts.append(
                    np.where(unloaded, np.inf, life / np.maximum(speeds, 1e-300) * 2 * np.pi / HOUR * hours)
                )
                ts_slopes.append(row.weibull_slope)
            iso.append(self.bearing_lives(name)["L10h_iso281_h"])
            iso_slopes.append(a.rating.rows[0].weibull_slope)
        if not ts:
            return {"L10h_h": np.full(n, np.nan), "L10h_iso281_h": np.full(n, np.nan)}

        def combine(lives, slopes):
            lives = np.array(lives)
            bad = ~np.isfinite(lives) & ~np.isinf(lives)
            lives = np.where(np.isnan(lives), np.inf, lives)
            out = system_life(lives, np.array(slopes))
            return np.where(bad.any(axis=0) | ~self.result.converged, np.nan, out)

        return {"L10h_h": combine(ts, ts_slopes), "L10h_iso281_h": combine(iso, iso_slopes)}

    def duty_cycle(self) -> dict | None:
        """Palmgren–Miner lives [h] of every bearing and of the system over the cases' time fractions."""
        f = self.input.loads["time_fraction"]
        if f is None:
            return None
        out = {"bearings": {}, "system": {}}
        for name in self.bearings:
            lives = self.bearing_lives(name)
            out["bearings"][name] = {k: _miner(v, f) for k, v in lives.items()}
        out["system"] = {k: _miner(v, f) for k, v in self.system_lives.items()}
        return out

    # -- power ------------------------------------------------------------------------------------
    @cached_property
    def power(self) -> dict | None:
        """Power flow per case (C,) [W]: input, bearing and mesh losses, output, efficiency."""
        if self.omega is None:
            return None
        loads, res = self.input.loads, self.result
        p_in = np.zeros(self.n_cases)
        for shaft, torque in loads["torques"].items():
            p_in += np.asarray(torque, float) * self.omega[shaft]
        bearing_loss = {}
        for name, a in self.bearings.items():
            f = a.friction
            bearing_loss[name] = (
                np.full(self.n_cases, np.nan) if f is None else np.asarray(f.power_loss, float)
            )
        meshes = power_flow.mesh_losses(res, self.omega)
        losses = sum(bearing_loss.values(), np.zeros(self.n_cases)) + sum(
            (m["loss_W"] for m in meshes.values()), np.zeros(self.n_cases)
        )
        held = self.drivetrain.held
        lossless_out = -res.held_torque() * self.omega[held]
        p_out = p_in - losses
        return {
            "input_W": p_in,
            "output_lossless_W": lossless_out,
            "bearing_loss_W": bearing_loss,
            "mesh": meshes,
            "loss_W": losses,
            "output_W": p_out,
            "efficiency": np.where(p_in != 0, p_out / np.where(p_in != 0, p_in, 1.0), np.nan),
            "speeds_rad_s": {k: np.asarray(v, float) for k, v in self.omega.items()},
        }

    # -- warnings ---------------------------------------------------------------------------------
    @cached_property
    def warnings(self) -> list[list[str]]:
        res, out = self.result, []
        separated = res.separated_meshes()
        for c in range(self.n_cases):
            notes = []
            if not res.converged[c]:
                notes.append(f"drivetrain did not converge: {res.reason[c] or 'no reason given'}")
            for m in separated[c]:
                notes.append(
                    f"mesh {m}: the teeth would pull (contact lost); backlash and tooth separation are not "
                    "modelled"
                )
            for name, a in self.bearings.items():
                for w in a.warnings[c]:
                    if res.converged[c] or "did not converge" not in w:
                        notes.append(f"{name}: {w}")
            out.append(list(dict.fromkeys(notes)))
        return out

    @property
    def notes(self) -> list[str]:
        out = list(self.input.warnings)
        for b in self.drivetrain.bearings:
            if b.name not in self.bearings:
                out.append(f"{b.name}: a linear stiffness: no rows, so no pressures, lives or friction")
        if any(b.frame_body for b in self.drivetrain.bearings):
            out.append(
                "planet bearings: rated at the planet's speed relative to the carrier, outer ring rotating; "
                "the carrier's centrifugal field on their elements is not modelled"
            )
        if not any(m.friction is not None for m in self.drivetrain.meshes):
            out.append("meshes: no mesh friction given (friction = μ_mz): the losses are the bearings' only")
        if self.heat_balance:
            out.append(
                "heat balance: each bearing's temperature is found by its own balance at the load the "
                "drivetrain gives it (the solution does not depend on the temperature); the load cases' "
                "temperatures, if any, are replaced for the bearings (the meshes keep them)"
            )
        for name, a in self.bearings.items():
            out += [f"{name}: {n}" for n in a.notes]
            iso_note = a.rating.iso281.note if a.rating is not None else None
            if iso_note:  # why a bearing has no ISO 281 life, or how it got one (below Table 3)
                out.append(f"{name}: ISO 281: {iso_note}")
        return list(dict.fromkeys(out))

    def to_dict(self) -> dict:
        """Everything a face shows, JSON-ready (SI, units in keys)."""
        from bearingkit.systems.drivetrain.output import analysis_dict

        return analysis_dict(self)

    def report(self, path, **options):
        """Write the HTML report of the drivetrain to ``path``; returns the path."""
        if "html" not in DRIVETRAIN_RENDERERS:
            importlib.import_module(_RENDERER_MODULES["html"])
        return DRIVETRAIN_RENDERERS["html"](self, path, **options)
