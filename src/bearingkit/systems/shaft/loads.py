"""Loads on a shaft: point forces and moments, line loads, gear meshes, masses under gravity.

SI units (m, N, N·m, N/m, kg, m/s², rad, rad/s). Every load value carries a leading case axis
(C, or 1 when shared by every case), so one :class:`ShaftLoads` describes a batch of load cases.
Generalised loads on the shaft are (F_x, F_y, F_z, M_x, M_y) at a position z on the shaft axis, the
order of the node DOFs (:mod:`bearingkit.systems.shaft.beam`).

Gear mesh (spur or helical, parallel axes; Shigley's Mechanical Engineering Design ch. 13, "force
analysis — helical gearing"): with the torque T the mesh applies to the shaft about +z and the
pitch diameter d,

    F_t = 2 T / d,   F_r = |F_t| tan α_n / cos β,   F_a = F_t tan β,

acting at the pitch point, at azimuth φ (``mesh_angle``, from +x towards +y) and radius d/2. On the
gear: tangential F_t e_t (e_t = (−sin φ, cos φ, 0), so (d/2) e_r × F_t e_t = T ẑ), radial −F_r e_r
(towards the gear's centre), axial F_a ẑ. The axial force at the lever d/2 bends the shaft:
M = (d/2) e_r × F_a ẑ = (d/2) F_a (sin φ, −cos φ). The helix angle is signed: its sign and the sign of
T set the direction of the thrust (flip ``helix_angle`` to flip it).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

#: Standard acceleration of gravity g_n [m/s²] (3rd CGPM 1901, exact by definition).
STANDARD_GRAVITY = 9.80665
#: Unit vectors of the axis names accepted for the direction of gravity.
AXES = {
    "+x": (1.0, 0.0, 0.0),
    "-x": (-1.0, 0.0, 0.0),
    "+y": (0.0, 1.0, 0.0),
    "-y": (0.0, -1.0, 0.0),
    "+z": (0.0, 0.0, 1.0),
    "-z": (0.0, 0.0, -1.0),
}


def _cases(name: str, value, width: int | None = None) -> np.ndarray:
    """A load value as (C|1, width) (or (C|1,) when width is None), finite."""
    a = np.asarray(value, dtype=float)
    if width is None:
        a = a.reshape(-1)
    else:
        a = a.reshape(-1, width) if a.ndim <= 1 else a
        if a.ndim != 2 or a.shape[1] != width:
            raise InputError(f"{name} (shape {np.shape(value)}) must have {width} components per case")
    checks.finite(name, a)
    return a


@dataclass(frozen=True)
class PointLoad:
    """A force and moment on the shaft axis at ``position``.

    Parameters
    ----------
    position : float [m]
    load : array_like (5,) or (C, 5) [N, N, N, N·m, N·m]
        (F_x, F_y, F_z, M_x, M_y).
    name : str
    """

    position: float
    load: np.ndarray
    name: str = "force"

    def __post_init__(self):
        checks.finite("position", self.position, "m")
        object.__setattr__(self, "load", _cases(f"{self.name}.load", self.load, 5))


@dataclass(frozen=True)
class LineLoad:
    """A uniform load per length between ``start`` and ``end``.

    Parameters
    ----------
    start, end : float [m]
    load : array_like (3,) or (C, 3) [N/m]
        (q_x, q_y, q_z).
    name : str
    """

    start: float
    end: float
    load: np.ndarray
    name: str = "line load"

    def __post_init__(self):
        checks.finite("start", self.start, "m")
        checks.greater("end", self.end, "start", self.start, "m")
        object.__setattr__(self, "load", _cases(f"{self.name}.load", self.load, 3))


@dataclass(frozen=True)
class Gear:
    """A spur or helical gear (or a pulley with ``pressure_angle`` 0) fixed on the shaft.

    Parameters
    ----------
    name : str
    position : float [m]
        Axial position of the mid-face on the shaft.
    pitch_diameter : float [m]
        Operating pitch diameter d.
    pressure_angle : float [rad]
        Normal pressure angle α_n (20° standard, ISO 53).
    helix_angle : float [rad]
        Helix angle β, signed (module docstring); 0 for a spur gear.
    mesh_angle : float [rad]
        Azimuth φ of the pitch point, from +x towards +y.
    mass : float [kg]
        Mass carried into the weight when gravity is on (0: not counted).
    """

    name: str
    position: float
    pitch_diameter: float
    pressure_angle: float = np.deg2rad(20.0)
    helix_angle: float = 0.0
    mesh_angle: float = 0.0
    mass: float = 0.0

    def __post_init__(self):
        checks.finite("position", self.position, "m")
        checks.positive("pitch_diameter", self.pitch_diameter, "m")
        checks.in_range("pressure_angle", self.pressure_angle, 0.0, np.pi / 2, "rad", closed=False)
        checks.in_range("helix_angle", self.helix_angle, -np.pi / 2, np.pi / 2, "rad", closed=False)
        checks.finite("mesh_angle", self.mesh_angle, "rad")
        checks.non_negative("mass", self.mass, "kg")

    def load(self, torque) -> np.ndarray:
        """Mesh load (C, 5) [N, N, N, N·m, N·m] on the shaft axis for mesh torques T (C,) [N·m]."""
        t = np.asarray(torque, dtype=float).reshape(-1)
        ft = 2.0 * t / self.pitch_diameter
        fr = np.abs(ft) * np.tan(self.pressure_angle) / np.cos(self.helix_angle)
        fa = ft * np.tan(self.helix_angle)
        c, s = np.cos(self.mesh_angle), np.sin(self.mesh_angle)
        r = self.pitch_diameter / 2.0
        return np.stack([-fr * c - ft * s, -fr * s + ft * c, fa, r * fa * s, -r * fa * c], axis=-1)


@dataclass(frozen=True)
class PointMass:
    """A lumped mass on the shaft (a coupling, a disc) that gravity loads. [kg] at [m]."""

    position: float
    mass: float
    name: str = "mass"

    def __post_init__(self):
        checks.finite("position", self.position, "m")
        checks.positive("mass", self.mass, "kg")


@dataclass(frozen=True)
class ShaftLoads:
    """The load cases of a shaft (leading case axis C everywhere).

    Parameters
    ----------
    names : tuple of str
        One name per case; fixes C.
    forces : tuple of PointLoad
    line_loads : tuple of LineLoad
    gear_torques : dict gear name → array (C,) [N·m]
        Torque each gear mesh applies to the shaft about +z (:class:`Gear`).
    gravity : array (3,) or None [m/s²]
        Acceleration of gravity in shaft axes; loads the shaft, the gears' and the point masses.
    speed : array (C,) or None [rad/s]
        Shaft speed (the inner rings rotate with it); lives in hours and friction need it.
    temperature : array (C,) or None [°C]
    """

    names: tuple
    forces: tuple = ()
    line_loads: tuple = ()
    gear_torques: dict = field(default_factory=dict)
    gravity: np.ndarray | None = None
    speed: np.ndarray | None = None
    temperature: np.ndarray | None = None

    def __post_init__(self):
        if not self.names:
            raise InputError("load_cases (none): give at least one load case")
        if len(set(self.names)) != len(self.names):
            raise InputError(f"load_cases names ({list(self.names)}) must be unique")
        n = len(self.names)
        for item in (*self.forces, *self.line_loads):
            if item.load.shape[0] not in (1, n):
                raise InputError(
                    f"{item.name}.load has {item.load.shape[0]} cases; expected 1 or {n} (one per load case)"
                )
        for gear, torque in self.gear_torques.items():
            t = _cases(f"gears.{gear}", torque)
            if t.shape[0] not in (1, n):
                raise InputError(f"gears.{gear} torque has {t.shape[0]} cases; expected 1 or {n}")
        if self.gravity is not None:
            g = np.asarray(self.gravity, dtype=float)
            if g.shape != (3,):
                raise InputError(f"gravity (shape {g.shape}) must be a 3-vector [m/s²]")
            checks.finite("gravity", g, "m/s^2")
        for name in ("speed", "temperature"):
            v = getattr(self, name)
            if v is not None:
                v = np.broadcast_to(_cases(name, v), (n,)).copy()
                object.__setattr__(self, name, v)

    @property
    def n_cases(self) -> int:
        return len(self.names)

    def take(self, cases) -> ShaftLoads:
        """The load cases ``cases`` (indices) only."""
        idx = np.asarray(cases, dtype=int)

        def pick(a):
            a = np.asarray(a)
            return a if a.shape[0] == 1 else a[idx]

        return ShaftLoads(
            names=tuple(self.names[i] for i in idx),
            forces=tuple(PointLoad(f.position, pick(f.load), f.name) for f in self.forces),
            line_loads=tuple(LineLoad(q.start, q.end, pick(q.load), q.name) for q in self.line_loads),
            gear_torques={k: pick(np.reshape(v, -1)) for k, v in self.gear_torques.items()},
            gravity=self.gravity,
            speed=None if self.speed is None else self.speed[idx],
            temperature=None if self.temperature is None else self.temperature[idx],
        )
