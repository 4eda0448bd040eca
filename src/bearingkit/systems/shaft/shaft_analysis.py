"""Every bearing of a solved shaft as a pipeline :class:`~bearingkit.pipeline.Analysis`, and the system.

SI units (m, N, N·m, rad, rad/s, W; temperatures in °C). The shaft solver (:mod:`bearingkit.systems.
solver`) finds each bearing's relative displacement q (inner ring against outer ring, bearing frame).
:class:`SeatInput` hands that state to the one orchestration of the library: it is a
:class:`~bearingkit.pipeline.ModelInput` whose five DOFs are all held at q, so the pipeline's statics
is one evaluation of the same row kernels at the same q (the load it reports is −f(q), the load the
shaft puts on the bearing), and friction, lubrication (κ, film), ratings (ISO 76 / ISO 281 / ISO/TS
16281, a_ISO and L_nm where a lubricant, a temperature and e_C are known) and warnings follow exactly as
for a single bearing. Nothing is orchestrated twice.

Speed effects are those of the shaft solve: the statics evaluate the bearing model the shaft was
solved with (its rows at the cases' shaft speed, :meth:`ShaftResult.model
<bearingkit.systems.shaft.result.ShaftResult.model>`), not the pipeline's own speed setup, so the loads
equal the shaft solver's reactions. What the shaft solver does not model is not added: no fits and no
preload of the bearing file's ``[operating]`` section (the shaft's ``axial_offset`` is the adjustment).

Speed: the inner rings turn with the shaft; a bearing turned end for end (``orientation = "-z"``)
sees the shaft's speed with the opposite sign about its own axis (the inertia terms depend on its
square; the sign orients friction torques). Lubricant and ``[lubrication]`` (contamination,
roughness): the bearing file's, else the shaft file's.

Temperature: the load cases', or with ``--heat`` / the shaft file's ``[thermal]`` each bearing's own,
found by its heat balance (friction heat = heat through its seats and housing + oil;
:func:`bearingkit.pipeline.thermal.balance.with_thermal_equilibria`, all bearings and cases in one batched
iteration; the sinks of the bearing file's ``[thermal]``, else of the shaft file's, else the ISO 15312
reference housing of that bearing). The shaft solve does not depend on the temperature (it models no
fits or thermal growth), so each bearing balances at the reaction the shaft gives it.
"""

from __future__ import annotations

import dataclasses
import importlib
from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.pipeline import ModelInput, analyze
from bearingkit.pipeline.thermal.balance import at_heat_balance, heat_balance_wanted
from bearingkit.systems.shaft.life import combine_ratings

__all__ = [
    "SHAFT_RENDERERS",
    "SeatInput",
    "ShaftAnalysis",
    "inputs_dict",
]

#: Renderers of a ShaftAnalysis by format, registered by the report layer on import
#: (:mod:`bearingkit.report.systems.shaft_html`); :meth:`ShaftAnalysis.report` loads it by name.
SHAFT_RENDERERS: dict = {}
_RENDERER_MODULES = {"html": "bearingkit.report.systems.shaft_html"}


@dataclass(frozen=True)
class SeatInput(ModelInput):
    """One bearing of a solved shaft as an analysis input: its seat state imposed on all five DOFs.

    Parameters (besides :class:`~bearingkit.pipeline.ModelInput`'s; ``free`` is all False)
    ----------
    displacement : ndarray (C, 5) [m, m, m, rad, rad]
        Relative displacement q of the inner ring in the bearing frame (the shaft solution).
    case_names : tuple of str
    speeds, temperatures : ndarray (C,) or None [rad/s, °C]
        Inner-ring speed about the bearing axis, operating temperature.
    system_state : tuple or None
        (converged, iterations, residual_norm, reason) of the shaft solve, carried into the statics.
    bearing_input : BearingInput or None
        The bearing file the seat came from (geometry, header, its ``[lubrication]``).
    lubrication : LubricationSpec or None
        ``[lubrication]`` (contamination, roughness) when the bearing file has none.
    solved_model : BearingModel or None
        The model the shaft solved the bearing with (rows at speed); the statics evaluate it at q.
        None: ``model``.
    thermal : ThermalSpec or None
        ``[thermal]`` (the heat sinks of the balance) when the bearing file has none.
    """

    displacement: np.ndarray = None
    case_names: tuple = ()
    speeds: np.ndarray | None = None
    temperatures: np.ndarray | None = None
    system_state: tuple | None = None
    bearing_input: object = None
    lubrication: object = None
    solved_model: object = None
    thermal: object = None

    def __post_init__(self):
        super().__post_init__()
        q = np.asarray(self.displacement, dtype=float)
        if q.shape != self.load.shape:
            raise InputError(f"displacement (shape {q.shape}) must match load (shape {self.load.shape})")
        object.__setattr__(self, "displacement", q)
        if np.any(self.free):
            raise InputError("free: a seat input holds all five DOFs at the shaft's solution")

    @cached_property
    def cases(self) -> tuple:
        from bearingkit.io.loader import LoadCase

        def at(values, i):
            return None if values is None else float(values[i])

        names = self.case_names or tuple(f"case {i}" for i in range(len(self.load)))
        return tuple(
            LoadCase(n, self.load[i], at(self.speeds, i), at(self.temperatures, i))
            for i, n in enumerate(names)
        )

    @property
    def bearing_type(self) -> str:
        if self.bearing_input is not None:
            return self.bearing_input.bearing_type
        return super().bearing_type

    @property
    def sections(self):
        """No fits or preload (the shaft solver models none), no speed setup of the pipeline (the
        statics take the shaft's model at speed, :meth:`solve`); the ``[lubrication]``."""
        from bearingkit.io.optional_sections.operating import OperatingSections, OperatingSpec

        own = getattr(self.bearing_input, "sections", None)
        lub = own.lubrication if own is not None and own.lubrication is not None else self.lubrication
        heat = own.thermal if own is not None and own.thermal is not None else self.thermal
        return OperatingSections(operating=OperatingSpec(speed_effects=False), lubrication=lub, thermal=heat)

    @property
    def spec(self):
        """ModelInput's header and (empty) free DOFs, with the bearing file's source and geometry."""
        base = super().spec
        b = self.bearing_input
        if b is None:
            return base
        header = dataclasses.replace(
            base.bearing,
            type=self.bearing_type,
            source=b.spec.bearing.source,
            # the designation and the file's ratings the lives use (pipeline.analysis._catalogue_rating)
            **{k: getattr(b.spec.bearing, k, None) for k in ("designation", "C", "rating_C", "rating_C0")},
        )
        return dataclasses.replace(base, bearing=header, geometry=dict(b.spec.geometry))

    @property
    def geometry(self):
        if self.bearing_input is None:
            return super().geometry
        return self.bearing_input.geometry

    def solve(self):
        """The statics at the imposed state: the row kernels evaluated at q (load = −f(q)); the
        convergence, iterations, residual and reason are the shaft solve's (including its beyond-the-
        speed-model flags)."""
        from bearingkit.analysis.solver.quasistatic import solve

        model = self.model if self.solved_model is None else self.solved_model
        res = solve(model, self.load, free=self.free, displacement=self.displacement, options=self.options)
        if self.system_state is None:
            return res
        converged, iterations, residual, reason = self.system_state
        return dataclasses.replace(
            res,
            converged=np.asarray(converged, bool).copy(),
            iterations=np.asarray(iterations).copy(),
            residual_norm=np.asarray(residual, float).copy(),
            reason=list(reason),
        )


def _max_or_none(values) -> float | None:
    vals = [float(v) for v in values if v is not None and np.isfinite(v)]
    return max(vals) if vals else None


class ShaftAnalysis:
    """A solved shaft file with every bearing's pipeline Analysis and the system life.

    Parameters
    ----------
    shaft_input : ShaftInput
        The loaded shaft file (:func:`bearingkit.systems.shaft.input.load_shaft_file`).
    result : ShaftResult, optional
        Its solution (default: solved here).
    friction_model : str
        A key of :data:`bearingkit.pipeline.FRICTION_MODELS` (default ``"auto"``: each bearing the model
        of its kind, :func:`bearingkit.pipeline.friction.choice.choose`).
    contamination : float or str, optional
        ISO 281 e_C (or a level name) for every bearing, replacing the files' ``[lubrication]``.
    reliability : float
        Reliability of L_nm (0.9 … 0.9995).
    thermal : bool or dict, optional
        Find each bearing's temperature by its heat balance: True, or ``[thermal]`` fields for every
        bearing (overriding the files'); None (default): when the shaft file has ``[thermal]``.
    """

    def __init__(
        self,
        shaft_input,
        result=None,
        *,
        friction_model="auto",
        contamination=None,
        reliability=0.9,
        thermal=None,
    ):
        self.input = shaft_input
        self._result = result
        self.friction_model = friction_model
        self.contamination = contamination
        self.reliability = reliability
        self.thermal = thermal

    @property
    def heat_balance(self) -> bool:
        """True when each bearing's temperature is found by its heat balance (module docstring)."""
        return heat_balance_wanted(self.thermal, self.input)

    @cached_property
    def result(self):
        """The :class:`~bearingkit.systems.shaft.result.ShaftResult` (one batched solve of every case)."""
        return self._result if self._result is not None else self.input.solve()

    @property
    def system(self):
        return self.input.system

    @property
    def case_names(self) -> list[str]:
        return list(self.input.loads.names)

    @property
    def n_cases(self) -> int:
        return len(self.input.loads.names)

    def _seat_input(self, seat) -> SeatInput:
        res, loads = self.result, self.input.loads
        source = seat.source
        lubricant = getattr(source, "lubricant", None) or self.input.lubricant
        speed = None if loads.speed is None else seat.seat_speed(loads.speed)
        return SeatInput(
            model=seat.bearing,
            load=res.bearing_load(seat.name),
            free=np.zeros(5, bool),
            lubricant=lubricant,
            source=f"{self.input.source} (bearing {seat.name})",
            material=getattr(source, "material", None),
            displacement=res.relative_displacement(seat.name),
            case_names=tuple(loads.names),
            speeds=speed,
            temperatures=loads.temperature,
            system_state=(res.converged, res.iterations, res.residual_norm, res.reason),
            bearing_input=source,
            lubrication=getattr(self.input, "lubrication", None),
            solved_model=res.model(seat.name),
            thermal=getattr(self.input, "thermal", None),
        )

    @cached_property
    def bearings(self) -> dict:
        """Name → :class:`~bearingkit.pipeline.Analysis` of every bearing with rows (not linear ones)."""
        out = {}
        for seat in self.system.bearings:
            if not isinstance(seat.bearing, BearingModel):
                continue
            seat_input = self._seat_input(seat)
            try:
                out[seat.name] = analyze(
                    seat_input,
                    friction_model=self.friction_model,
                    contamination=self.contamination,
                    reliability=self.reliability,
                    thermal=False,  # the balance of every bearing at once, below
                )
            except InputError as exc:  # one line naming the shaft file and the bearing
                text = str(exc)
                raise InputError(
                    text if text.startswith(seat_input.source) else f"{seat_input.source}: {text}"
                ) from None
        return at_heat_balance(out, self.input.source, self.thermal) if self.heat_balance and out else out

    @cached_property
    def rating(self):
        """The :class:`~bearingkit.systems.shaft.life.SystemRating`: each bearing's Analysis rating
        combined."""
        ratings = {n: a.rating for n, a in self.bearings.items() if a.rating is not None}
        speed = self.input.loads.speed
        if speed is not None and not np.all(np.asarray(speed) != 0):
            speed = None  # a standstill case has no life in hours; revolutions are still given
        out = combine_ratings(ratings, self.result.converged, None if speed is None else np.abs(speed))
        unrated = [n for n in self.bearings if n not in ratings]
        if unrated:  # a system without one of its bearings' lives has no life (not a longer one)
            out.life = np.ma.masked_all(self.n_cases)
            out.modified_life = np.ma.masked_all(self.n_cases)
            out.iso281_life = np.ma.masked_all(self.n_cases)
            out.iso281_modified_life = np.ma.masked_all(self.n_cases)
            for notes in out.warnings:
                notes.append(f"system: no system life: bearing(s) {unrated} could not be rated (see notes)")
        return out

    @cached_property
    def warnings(self) -> list[list[str]]:
        """Per case: the system's non-convergence, every bearing's warnings (``NAME: …``), the system's."""
        res, out = self.result, []
        for c in range(self.n_cases):
            notes = []
            if not res.converged[c]:
                notes.append(f"shaft system did not converge: {res.reason[c] or 'no reason given'}")
            for name, a in self.bearings.items():
                for w in a.warnings[c]:
                    if res.converged[c] or "did not converge" not in w:
                        notes.append(f"{name}: {w}")
            notes += [w for w in self.rating.warnings[c] if w.startswith("system")]
            out.append(list(dict.fromkeys(notes)))
        return out

    @property
    def notes(self) -> list[str]:
        """The shaft file's notes, and each bearing's Analysis notes (``NAME: …``)."""
        out = list(self.input.warnings)
        for seat in self.system.bearings:
            if seat.name not in self.bearings:
                out.append(f"{seat.name}: a linear stiffness: no rows, so no pressures, lives or friction")
        if self.heat_balance:
            replaced = "; the load cases' temperatures are replaced by them"
            out.append(
                "heat balance: each bearing's temperature is found by its own balance at the reaction the "
                "shaft gives it (the shaft models no fits or thermal growth, so its solution and the "
                "clearances do not depend on the temperature)"
                + (replaced if self.input.loads.temperature is not None else "")
            )
        out.append(
            "bearings: each is analysed at the state the shaft solution gives it (all five DOFs imposed), "
            "with the speed effects of the shaft solve; no fits or [operating] preload of the bearing "
            "files (the shaft models none)"
        )
        for name, a in self.bearings.items():
            out += [f"{name}: {n}" for n in a.notes]
        return list(dict.fromkeys(out))

    # ------------------------------------------------------------------------------- output
    def bearing_summary(self, name: str, case: int) -> dict:
        """The per-bearing line of the shaft table (CLI, JSON ``summary``, report), SI, units in keys."""
        res = self.result
        seat = self.system.bearing(name)
        load = res.bearing_load(name)[case]
        out = {
            "name": name,
            "position_m": seat.position,
            "reaction_on_shaft": dict(zip(_LOAD_KEYS, map(float, res.reaction(name)[case]), strict=True)),
            "seat_displacement": dict(
                zip(_DOF_KEYS, map(float, res.seat_displacement(name)[case]), strict=True)
            ),
            "misalignment_rad": float(res.misalignment(name)[case]),
            "radial_load_N": float(np.hypot(load[0], load[1])),
            "axial_load_N": float(load[2]),
            "max_pressure_Pa": None,
            "static_safety": None,
            "L10_iso281_rev": None,
            "L10h_iso281_h": None,
            "Lnm_iso281_rev": None,
            "Lnm_iso281_h": None,
            "L10r_rev": None,
            "L10h_h": None,
            "Lnmr_rev": None,
            "Lnmr_h": None,
            "kappa_min": None,
            "friction_torque_Nm": None,
            "power_loss_W": None,
            "temperature_C": None,
            "temperature_found": False,
            "warnings": len([w for w in self.warnings[case] if w.startswith(f"{name}: ")]),
        }
        a = self.bearings.get(name)
        if a is None:
            return out
        out["max_pressure_Pa"] = _max_or_none(float(np.max(r.max_pressure[case])) for r in a.statics.rows)
        if a.rating is not None:
            system = a.rating.to_dict(case)["system"]
            keys = ("static_safety", "L10r_rev", "L10h_h", "Lnmr_rev", "Lnmr_h", *_ISO281_KEYS)
            out.update({k: system.get(k) for k in keys})
        if a.lubrication is not None:
            films = a.lubrication.to_dict(case).get("rows", [])
            kappas = [r.get("kappa") for r in films]
            vals = [k for k in kappas if k is not None]
            out["kappa_min"] = min(vals) if vals else None
        temperature = a.operating.temperature
        if temperature is not None:
            out["temperature_C"] = float(np.broadcast_to(temperature, (self.n_cases,))[case])
        out["temperature_found"] = a.thermal is not None
        f = a.friction
        if f is not None:
            out["friction_torque_Nm"] = float(f.total[case])
            out["power_loss_W"] = float(f.power_loss[case])
        return out

    def bearing_dict(self, name: str, case: int) -> dict:
        """The shaft result's state of the bearing, its summary and its Analysis parts for one case."""
        d = self.result.bearing_dict(name, case)
        d["summary"] = self.bearing_summary(name, case)
        a = self.bearings.get(name)
        if a is not None:
            part = {"operating": a.operating.to_dict(case), "warnings": list(a.warnings[case])}
            if a.rating is not None:
                part["rating"] = a.rating.to_dict(case)
            if a.lubrication is not None:
                part["lubrication"] = a.lubrication.to_dict(case)
            if a.thermal is not None:
                part["thermal"] = a.thermal.to_dict(case)
            if a.friction is not None:
                part["friction"] = {
                    **a.friction.case_dicts[case]["friction"],
                    "power_loss_W": float(a.friction.power_loss[case]),
                }
            d["analysis"] = part
        return d

    def to_dict(self) -> dict:
        """Everything a face shows, JSON-ready (SI, units in keys): inputs, per case the shaft lines,
        every bearing (state, summary, Analysis parts), the system life and every warning."""
        res, rating = self.result, self.rating
        cases = []
        for c in range(self.n_cases):
            d = res.to_dict(c)
            d["bearings"] = [self.bearing_dict(b.name, c) for b in self.system.bearings]
            d["rating"] = rating.to_dict(c)
            d["friction_Nm"] = {
                b["name"]: b["summary"]["friction_torque_Nm"]
                for b in d["bearings"]
                if b["name"] in self.bearings
            }
            losses = [b["summary"]["power_loss_W"] for b in d["bearings"] if b["name"] in self.bearings]
            d["power_loss_W"] = None if any(v is None for v in losses) else float(sum(losses))
            d["warnings"] = list(self.warnings[c])
            cases.append(d)
        return {
            "file": self.input.source,
            "shaft": self.system.name,
            "friction_model": self.friction_model,
            "heat_balance": self.heat_balance,
            "inputs": inputs_dict(self.input),
            "bearings": [
                {
                    "name": b.name,
                    "bearing": getattr(b.bearing, "name", "linear bearing"),
                    "position_m": b.position,
                }
                for b in self.system.bearings
            ],
            "notes": self.notes,
            "cases": cases,
        }

    def __repr__(self) -> str:
        names = ", ".join(b.name for b in self.system.bearings)
        return f"<ShaftAnalysis of {self.system.name!r}: bearings {names}; {self.n_cases} load case(s)>"

    def _repr_html_(self) -> str:
        """The notebook view (:mod:`bearingkit.display`): per case each bearing's loads, pressure, s0,
        lives and friction, then the system life; every warning below."""
        from bearingkit.display import html_table, number

        try:
            rows, warnings = [], []
            for c, case in enumerate(self.case_names):
                for seat in self.system.bearings:
                    s = self.bearing_summary(seat.name, c)
                    rows.append([
                        case, seat.name, number(s["position_m"], 1e3), number(s["radial_load_N"], 1e-3),
                        number(s["axial_load_N"], 1e-3), number(s["misalignment_rad"], 1e3),
                        number(s["max_pressure_Pa"], 1e-6), number(s["static_safety"], digits=3),
                        number(s["L10h_iso281_h"]), number(s["Lnm_iso281_h"]),
                        number(s["L10h_h"]), number(s["Lnmr_h"]), number(s["friction_torque_Nm"]),
                        number(s["temperature_C"]) + (" found" if s["temperature_found"] else ""),
                    ])  # fmt: skip
                system = self.rating.to_dict(c)["system"]
                lives = ("L10h_iso281_h", "Lnm_iso281_h", "L10h_h", "Lnmr_h")
                rows.append([case, "system", *["—"] * 6, *(number(system[k]) for k in lives), "—", "—"])
                warnings += [f"{case}: {w}" for w in self.warnings[c]]
            columns = ["case", "bearing", "z [mm]", "F_r [kN]", "F_a [kN]", "tilt [mrad]", "p_max [MPa]",
                       "s0", "L10h ISO 281 [h]", "L_nmh ISO 281 [h]", "L10rh ISO/TS 16281 [h]",
                       "L_nmrh ISO/TS 16281 [h]", "M_friction [N·m]", "T [°C]"]  # fmt: skip
            title = f"{self.system.name} ({self.input.source})"
            from bearingkit.systems.shaft.life import SYSTEM_LIFE_DIFFERENCE

            notes = [*self.notes, f"why the two lives differ: {SYSTEM_LIFE_DIFFERENCE}"]
            return html_table(title, columns, rows, warnings=warnings, notes=notes)
        except Exception as exc:  # a notebook cell must show something, and say what went wrong
            from html import escape

            return f"<div class='bearingkit'><b>{escape(repr(self))}</b><br>error: {escape(str(exc))}</div>"

    def report(self, path, **options):
        """Write the HTML report of the shaft to ``path`` (atomic); returns the path."""
        self.input.check_work(report=True)
        if "html" not in SHAFT_RENDERERS:
            importlib.import_module(_RENDERER_MODULES["html"])  # the report layer registers itself
        return SHAFT_RENDERERS["html"](self, path, **options)


#: The bearing's ISO 281 lives in the shaft summary (first among its lives).
_ISO281_KEYS = ("L10_iso281_rev", "L10h_iso281_h", "Lnm_iso281_rev", "Lnm_iso281_h")
_LOAD_KEYS = ("F_x_N", "F_y_N", "F_z_N", "M_x_Nm", "M_y_Nm")
_DOF_KEYS = ("u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad")


def _named(keys, values) -> dict:
    return {k: float(v) for k, v in zip(keys, values, strict=True)}


def inputs_dict(inp) -> dict:
    """The shaft file as read (SI, units in keys): sections, material, bearings, gears, masses, cases."""
    system, loads = inp.system, inp.loads
    shaft = system.shaft
    mat = shaft.material
    n = loads.n_cases

    def per_case(c):
        forces = [
            {"name": f.name, "position_m": f.position, **_named(_FORCE_KEYS, f.load[c])}
            for f in loads.forces
            if np.any(f.load[c] != 0.0)
        ]
        lines = [
            {
                "name": q.name,
                "start_m": q.start,
                "end_m": q.end,
                **_named(("q_x_N_per_m", "q_y_N_per_m", "q_z_N_per_m"), q.load[c]),
            }
            for q in loads.line_loads
            if np.any(q.load[c] != 0.0)
        ]
        torques = {g: float(np.broadcast_to(t, (n,))[c]) for g, t in loads.gear_torques.items()}
        return {
            "name": loads.names[c],
            "speed_rad_s": None if loads.speed is None else float(loads.speed[c]),
            "temperature_C": None if loads.temperature is None else float(loads.temperature[c]),
            "gear_torques_Nm": torques,
            "forces": forces,
            "line_loads": lines,
        }

    return {
        "material": {
            "name": mat.name,
            "youngs_modulus_Pa": mat.youngs_modulus,
            "poisson_ratio": mat.poisson_ratio,
            "density_kg_per_m3": mat.density,
        },
        "shear_deformation": shaft.shear_deformation,
        "gravity_m_per_s2": None if loads.gravity is None else [float(g) for g in loads.gravity],
        "sections": [
            {
                "start_m": s.start,
                "end_m": s.end,
                "outer_diameter_m": s.outer_diameter,
                "inner_diameter_m": s.inner_diameter,
            }
            for s in shaft.sections
        ],
        "bearings": [
            {
                "name": b.name,
                "bearing": getattr(b.bearing, "name", "linear bearing"),
                "file": getattr(b.source, "source", None),
                "position_m": b.position,
                "orientation": b.orientation,
                "axial": b.axial,
                "axial_offset_m": b.axial_offset,
                "housing_stiffness_SI": None
                if b.housing_stiffness is None
                else [None if not np.isfinite(k) else float(k) for k in b.housing_stiffness],
            }
            for b in system.bearings
        ],
        "gears": [
            {
                "name": g.name,
                "position_m": g.position,
                "pitch_diameter_m": g.pitch_diameter,
                "pressure_angle_rad": g.pressure_angle,
                "helix_angle_rad": g.helix_angle,
                "mesh_angle_rad": g.mesh_angle,
                "mass_kg": g.mass,
            }
            for g in system.gears
        ],
        "masses": [{"name": m.name, "position_m": m.position, "mass_kg": m.mass} for m in system.masses],
        "lubricant": None if inp.lubricant is None else inp.lubricant.name,
        "thermal": None if inp.thermal is None else inp.thermal.model_dump(exclude_none=True),
        "load_cases": [per_case(c) for c in range(n)],
    }


_FORCE_KEYS = ("F_x_N", "F_y_N", "F_z_N", "M_x_Nm", "M_y_Nm")
