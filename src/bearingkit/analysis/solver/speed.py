"""Speed in the statics: rows at speed (centrifugal force, gyroscopic moment), batched like loads.

SI units (rad/s, kg/m³). :func:`model_at_speed` returns a bearing model whose rows' solver kernels
include the inertia of their rolling elements at the given ring speeds, per load case:

- ball rows: :class:`~bearingkit.rows.ball.speed.BallSpeedKernel` (per-ball equilibrium with the
  centrifugal force and the gyroscopic moment under outer- or inner-raceway control; inner and
  outer contact angles part);
- radial cylindrical rows: :class:`~bearingkit.rows.cylindrical.speed.CylindricalSpeedKernel`
  (per-roller equilibrium with the centrifugal force; thrust rows are unaffected);
- tapered rows: their own centrifugal model (``TaperedRow.speed``, one value or one per case);
- other kinds (threaded, rows registered later): unchanged; :func:`speed_notes` says so.

Row kinds register their speed kernel with :func:`register_speed_kernel` (a spherical-roller row
plugs in its factory ``(row, OperatingSpeed) -> kernel`` there). When every speed is zero the model
is returned unchanged, so the zero-speed path is the existing one, bit for bit.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.physics.dynamics.ball_kinematics import RACEWAY_CONTROLS

#: Default density of the rolling elements [kg/m³] (GCr15, bearingkit.materials).
DEFAULT_ELEMENT_DENSITY = 7810.0


@dataclass(frozen=True)
class OperatingSpeed:
    """Ring speeds per load case and the inertia data of the rolling elements.

    Parameters
    ----------
    speed_inner : float or array (C,) [rad/s]
        Inner-ring speed about the bearing axis.
    speed_outer : float or array (C,) [rad/s]
        Outer-ring speed (default 0).
    element_density : float [kg/m³]
        Density of the balls or rollers (default :data:`DEFAULT_ELEMENT_DENSITY`).
    raceway_control : {"outer", "inner"}
        Ball spin-axis hypothesis (:mod:`bearingkit.physics.dynamics.ball_kinematics`).
    """

    speed_inner: object = 0.0
    speed_outer: object = 0.0
    element_density: float = DEFAULT_ELEMENT_DENSITY
    raceway_control: str = "outer"

    def __post_init__(self):
        checks.finite("speed_inner", self.speed_inner, "rad/s")
        checks.finite("speed_outer", self.speed_outer, "rad/s")
        checks.positive("element_density", self.element_density, "kg/m^3")
        checks.one_of("raceway_control", self.raceway_control, RACEWAY_CONTROLS)

    @property
    def inner(self) -> np.ndarray:
        """Inner-ring speed as a (C,) or (1,) array [rad/s]."""
        return np.atleast_1d(np.asarray(self.speed_inner, dtype=float))

    @property
    def outer(self) -> np.ndarray:
        """Outer-ring speed as a (C,) or (1,) array [rad/s]."""
        return np.atleast_1d(np.asarray(self.speed_outer, dtype=float))

    @property
    def moving(self) -> bool:
        """Whether any case has a ring turning."""
        return bool(np.any(self.inner != 0.0) or np.any(self.outer != 0.0))


def as_speed(speed) -> OperatingSpeed:
    """An :class:`OperatingSpeed` from itself or from inner-ring speeds [rad/s] (scalar or (C,))."""
    return speed if isinstance(speed, OperatingSpeed) else OperatingSpeed(speed_inner=speed)


def _ball(row, speed: OperatingSpeed):
    from bearingkit.rows.ball.speed import BallSpeedKernel

    return BallSpeedKernel(row, speed.inner, speed.outer, speed.element_density, speed.raceway_control)


def _cylindrical(row, speed: OperatingSpeed):
    if row.direction != 0:  # thrust rows: F_c is perpendicular to the contact normals
        return row.kernel()
    from bearingkit.rows.cylindrical.speed import CylindricalSpeedKernel

    return CylindricalSpeedKernel(row, speed.inner, speed.outer, speed.element_density)


def _tapered(row, speed: OperatingSpeed):
    """The row at its relative ring speed: one value when every case shares it (the row constant, as
    before), else one per case (each case's rollers at its own centrifugal force)."""
    relative = speed.inner - speed.outer
    if np.all(relative == relative[0]):
        return dataclasses.replace(row, speed=float(relative[0])).kernel()
    return dataclasses.replace(row, speed=relative).kernel()


#: Row kind → factory ``(row, OperatingSpeed) -> kernel`` of the row at speed.
SPEED_KERNELS: dict[str, Callable] = {"ball": _ball, "cylindrical": _cylindrical, "tapered": _tapered}


def register_speed_kernel(kind: str, factory: Callable) -> None:
    """Register the kernel factory of a row kind at speed (e.g. spherical rollers)."""
    SPEED_KERNELS[kind] = factory


@dataclass(frozen=True)
class ModelAtSpeed(BearingModel):
    """A :class:`BearingModel` whose kernels include the rolling elements' inertia at ``speed``."""

    speed: OperatingSpeed = field(default_factory=OperatingSpeed)

    @cached_property
    def kernels(self) -> tuple:
        out = []
        for row in self.rows:
            factory = SPEED_KERNELS.get(row.kind)
            out.append(row.kernel() if factory is None else factory(row, self.speed))
        return tuple(out)


def model_at_speed(model: BearingModel, speed) -> BearingModel:
    """``model`` with its rows at ``speed`` (an OperatingSpeed or inner-ring speeds [rad/s]).

    Returns ``model`` itself when no ring turns (the zero-speed solve is unchanged).
    """
    speed = as_speed(speed)
    if not speed.moving:
        return model
    base = model.base if isinstance(model, ModelAtSpeed) else model
    fields = {f.name: getattr(base, f.name) for f in dataclasses.fields(BearingModel)}
    out = ModelAtSpeed(**fields, speed=speed)
    object.__setattr__(out, "base", base)
    return out


def check_case_count(model: BearingModel, n_cases: int) -> None:
    """Raise InputError when the speeds of ``model`` (a :class:`ModelAtSpeed`) are neither one value nor
    one per load case."""
    if not isinstance(model, ModelAtSpeed):
        return
    for ring, values in (("inner", model.speed.inner), ("outer", model.speed.outer)):
        if values.size not in (1, n_cases):
            raise InputError(
                f"speed ({ring} ring): {values.size} values for {n_cases} load cases; give one speed or "
                "one per load case"
            )


def speed_notes(model: BearingModel) -> list[str]:
    """What the speed model leaves out for this bearing (rows without a speed kernel)."""
    if not isinstance(model, ModelAtSpeed):
        return []
    return [
        f"row {r.name!r} ({r.kind}): speed effects on the contact loads are not modelled"
        for r in model.rows
        if r.kind not in SPEED_KERNELS
    ]


def flag_beyond_model(result) -> None:
    """Mark cases the speed model cannot hold as not converged, with the reason (in place).

    A loaded ball whose inner or outer contact angle reaches
    :data:`~bearingkit.rows.ball.speed.ANGLE_LIMIT`, or whose own equilibrium did not converge, has
    been pushed by its centrifugal force past the raceway geometry (it rides over the raceway's
    crown): the equilibrium the solver found is not a bearing's.
    """
    if not isinstance(result.model, ModelAtSpeed):
        return
    from bearingkit.rows.ball.speed import ANGLE_LIMIT, beyond_model

    for row, state in zip(result.model.rows, result.rows, strict=True):
        if row.kind != "ball":
            continue
        bad = beyond_model(state, row.contact_angle) & result.converged
        if not bad.any():
            continue
        ex = state.extras
        for c in np.flatnonzero(bad):
            worst = float(np.degrees(np.abs(ex["contact_angle_inner"][c]).max()))
            rpm = float((result.model.speed.inner * 30.0 / np.pi)[c % result.model.speed.inner.size])
            result.converged[c] = False
            result.reason[c] = (
                f"speed {rpm:.6g} r/min is above what the high-speed ball model holds: in row "
                f"{state.name!r} a loaded ball's contact angle reaches {worst:.1f} deg: the centrifugal "
                "force has pushed it over the raceway (angular rows: limit "
                f"{np.degrees(ANGLE_LIMIT):.1f} deg); reduce the speed or add axial load"
            )


#: Why a case that did not converge at speed did: the same load converges at rest (:func:`explain_at_rest`).
AT_REST_REASON = (
    "at {rpm} r/min the elements' centrifugal force and gyroscopic moment outweigh the load: the same load "
    "converges at rest (a load below the bearing's minimum load at this speed, or a speed past its limiting "
    "speed); give more load (axial load for angular-contact and tapered rows) or check the speed"
)


def explain_at_rest(base_model: BearingModel, result, load, free, options, displacement, solve) -> None:
    """Re-solve at rest the cases that did not converge at speed; where they converge there, the speed is
    the cause, not the load (the solver's own reason said "the load exceeds what the contacts carry" for
    a light load on a large tapered bearing at 1000 r/min); a case stopped by its budget keeps that
    reason with the cause after it. Changes ``result.reason`` in place; only on the failure path, so a
    converged run pays nothing. ``solve`` is :func:`bearingkit.analysis.solver.quasistatic.solve`, passed
    in by it (this module sits below it).
    """
    failed = np.flatnonzero(~result.converged)
    if failed.size == 0 or not isinstance(result.model, ModelAtSpeed):
        return
    disp = displacement
    if displacement is not None and np.ndim(displacement) == 2:
        disp = np.asarray(displacement)[failed]
    rest = solve(base_model, np.asarray(load)[failed], free=free, displacement=disp, options=options)
    inner = np.atleast_1d(result.model.speed.inner) * 30.0 / np.pi
    for i, c in enumerate(failed):
        if rest.converged[i]:
            why = AT_REST_REASON.format(rpm=f"{float(inner[c % inner.size]):.6g}")
            old = result.reason[c] or ""
            # a stop by the case's budget stays said (what stopped it, how to give more); the cause follows
            result.reason[c] = f"{old}; {why}" if "budget" in old else why
