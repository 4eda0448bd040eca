"""Planetary stages: a sun, N planets on a carrier (their bearings on the carrier's pins), a ring gear.

SI units. A ``[[planetary]]`` table of a drivetrain file becomes ordinary drivetrain parts: each
planet is a body (a short Timoshenko beam, its sections around the gear's mid-plane at local z = 0)
whose axis lies at the carrier radius a_w (the sun–planet working centre distance) and azimuth
ψ_i = ψ₀ + 2π i / N; its bearings sit with the inner ring on a pin (a rigid arm of the carrier from the
carrier's node at ``carrier_position``: r = (a_w cos ψ_i, a_w sin ψ_i, z_b)) and the outer ring in the
planet; a pin position error e_i moves the pin by e_i along the tangent (the direction of positive
carrier rotation). The sun–planet and planet–ring meshes roll relative to the carrier.

Checks (one line naming the stage): one module and pressure angle, the hands (sun and planets
opposite, planets and ring the same), the ring's tooth count (the ring–planet working centre distance
must equal the sun–planet one: z_r = z_s + 2 z_p without profile shift), the assembly condition of
equally spaced planets ((z_s + z_r)/N an integer), and a sun coaxial with the carrier.

Load sharing with a pin error, closed form (rigid central members, planets free to turn on their
pins; tests/systems/test_planetary.py derives it): each planet path is the sun and ring meshes in
series, k_eq = k_sp k_rp/(k_sp + k_rp); a tangential pin error e_i shortens both meshes by e_i cos α_wt
(cos β_b for the normal), so with the planet bearings' tangential stiffness k_b (in parallel, per
planet) the planet's mesh force is F_i = T_s/(N r_bs) + 2 k_e cos α_wt (ē − e_i) with
k_e = k_eq / (1 + 4 k_eq cos²α_wt / k_b) and ē the mean pin error.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from pydantic import Field, ValidationError

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.systems.drivetrain.gearing import CENTRE_DISTANCE_RTOL, GearGeometry, GearPair
from bearingkit.systems.drivetrain.model import (
    HOUSING,
    Attachment,
    DriveBearing,
    DriveGear,
    DriveShaft,
    Mesh,
)
from bearingkit.systems.shaft.input import BearingSpec, SectionSpec, _material, _seat, _sections
from bearingkit.systems.shaft.shaft import Shaft

#: Most planets of one stage (equal spacing; more do not fit around a sun of useful size).
MAX_PLANETS = 12


class PlanetSpec(schema.Strict):
    """``planet = {...}`` of a ``[[planetary]]`` stage: the planet gear and its body."""

    teeth: int = Field(ge=5, le=500)
    face_width: schema.PositiveLength
    profile_shift: schema.Dimensionless = 0.0
    sections: list[SectionSpec]
    material: schema.MaterialSpec | None = None
    mass: schema.quantity("mass", "non_negative") = 0.0


class PlanetarySpec(schema.Strict):
    """``[[planetary]]``: one stage (module docstring)."""

    name: str
    sun: str = Field(description="The sun gear (a gear of a shaft).")
    carrier: str = Field(description="The carrier shaft.")
    carrier_position: schema.Length = Field(description="Local z on the carrier of the planets' mid-plane.")
    planets: int = Field(ge=2, le=MAX_PLANETS)
    planet: PlanetSpec
    planet_bearings: list[BearingSpec]
    ring: str | None = Field(None, description="The ring gear (an internal gear of a shaft).")
    ring_teeth: int | None = Field(None, ge=10, le=2000, description="A ring fixed in the housing.")
    ring_profile_shift: schema.Dimensionless = 0.0
    ring_face_width: schema.PositiveLength | None = None
    first_planet_angle: schema.Angle = 0.0
    pin_errors: list[schema.Length] = Field(default_factory=list)
    mesh_stiffness: schema.quantity("stiffness", "positive") | None = None
    mesh_friction: schema.Dimensionless | None = None


def _find_gear(shafts, name: str, where: str):
    for s in shafts:
        for g in s.gears:
            if g.name == name:
                return s, g
    raise InputError(f"{where}: {name!r} is no gear of the shafts")


def _stage(i: int, raw: dict, shafts: list[DriveShaft], base: Path) -> dict:
    try:
        st = PlanetarySpec.model_validate(raw)
    except ValidationError as exc:
        from bearingkit.io.messages import one_line

        raise InputError(
            str(one_line("", exc, ("planetary", i), {"planetary": PlanetarySpec})).lstrip(": ")
        ) from None
    where = f"planetary[{i}] ({st.name})"
    by_name = {s.name: s for s in shafts}
    if st.carrier not in by_name:
        raise InputError(f"{where}.carrier ({st.carrier!r}) must be a shaft: {list(by_name)}")
    carrier = by_name[st.carrier]
    carrier.shaft.check_position(f"{where}.carrier_position", st.carrier_position)
    sun_shaft, sun = _find_gear(shafts, st.sun, f"{where}.sun")
    gs = sun.geometry
    if gs.internal:
        raise InputError(f"{where}.sun ({st.sun!r}) must be an external gear")
    if not np.allclose(sun_shaft.centre, carrier.centre, atol=1e-9):
        raise InputError(
            f"{where}: the sun's shaft {sun_shaft.name!r} is not coaxial with the carrier {carrier.name!r}"
        )
    if (st.ring is None) == (st.ring_teeth is None):
        raise InputError(
            f"{where}: give exactly one of ring (a gear of a shaft) and ring_teeth (fixed in the housing)"
        )
    planet_geo = GearGeometry(
        st.planet.teeth,
        gs.normal_module,
        gs.pressure_angle,
        -gs.helix_angle,
        st.planet.face_width,
        st.planet.profile_shift,
        False,
    )
    if st.ring is not None:
        ring_shaft, ring = _find_gear(shafts, st.ring, f"{where}.ring")
        if not ring.geometry.internal:
            raise InputError(f"{where}.ring ({st.ring!r}) must be an internal gear (internal = true)")
        if not np.allclose(ring_shaft.centre, carrier.centre, atol=1e-9):
            raise InputError(f"{where}: the ring's shaft {ring_shaft.name!r} is not coaxial with the carrier")
        ring_geo, ring_ref = ring.geometry, (ring_shaft.name, ring.name)
    else:
        ring_geo = GearGeometry(
            st.ring_teeth,
            gs.normal_module,
            gs.pressure_angle,
            -gs.helix_angle,
            st.ring_face_width or st.planet.face_width,
            st.ring_profile_shift,
            True,
        )
        ring_ref = (HOUSING, f"{st.name}.ring")
    sp = GearPair(gs, planet_geo, f"{where} sun–planet")
    pr = GearPair(planet_geo, ring_geo, f"{where} planet–ring")
    a_sp, a_pr = sp.centre_distance, pr.centre_distance
    if abs(a_sp - a_pr) > CENTRE_DISTANCE_RTOL * a_sp:
        raise InputError(
            f"{where}: mismatched tooth counts: sun {gs.teeth}, planet {planet_geo.teeth}, ring "
            f"{ring_geo.teeth} give centre distances {a_sp * 1e3:.6g} mm (sun–planet) and "
            f"{a_pr * 1e3:.6g} mm (planet–ring); without "
            f"profile shift the ring needs z_s + 2 z_p = {gs.teeth + 2 * planet_geo.teeth} teeth"
        )
    n = st.planets
    if (gs.teeth + ring_geo.teeth) % n:
        raise InputError(
            f"{where}: {n} planets cannot be equally spaced: (z_s + z_r)/N = "
            f"({gs.teeth} + {ring_geo.teeth})/{n} "
            "is not an integer"
        )
    errors = list(st.pin_errors) or [0.0] * n
    if len(errors) != n:
        raise InputError(f"{where}.pin_errors ({len(errors)} values) must give one per planet ({n})")
    material = _material(st.planet.material)
    z_plane = carrier.axial_offset + st.carrier_position
    out = {"shafts": [], "bearings": [], "meshes": [], "housing_gears": []}
    if ring_ref[0] == HOUSING:
        out["housing_gears"].append((DriveGear(ring_ref[1], 0.0, ring_geo), carrier.centre, z_plane))
    planet_names = []
    for p in range(n):
        psi = st.first_planet_angle + 2.0 * np.pi * p / n
        e_r = np.array([np.cos(psi), np.sin(psi)])
        e_t = np.array([-np.sin(psi), np.cos(psi)])
        centre = np.asarray(carrier.centre) + a_sp * e_r
        name = f"{st.name}.planet{p + 1}"
        planet_names.append(name)
        try:
            shaft = Shaft(_sections(st.planet.sections), material, True, name)
        except InputError as exc:
            raise InputError(f"{where}.planet.{exc}") from None
        gear = DriveGear(f"{name}.gear", 0.0, planet_geo, st.planet.mass)
        out["shafts"].append(DriveShaft(shaft, tuple(centre), z_plane, (gear,), ()))
        for j, b in enumerate(st.planet_bearings):
            try:
                seat = _seat(j, b.model_copy(update={"name": f"{name}.{b.name}"}), base)
            except InputError as exc:
                raise InputError(
                    f"{where}.planet_bearings[{j}] ({b.name}): {str(exc).split(': ', 1)[-1]}"
                ) from None
            arm = (a_sp * e_r[0], a_sp * e_r[1], b.position)
            inner = Attachment(carrier.name, st.carrier_position, arm, tuple(errors[p] * e_t))
            out["bearings"].append(
                DriveBearing(seat, inner, Attachment(name, b.position), frame_body=carrier.name)
            )
        out["meshes"].append(
            Mesh(
                f"{st.name}.sun-planet{p + 1}",
                (sun_shaft.name, sun.name),
                (name, gear.name),
                sp,
                st.mesh_stiffness,
                st.mesh_friction,
                carrier.name,
            )
        )
        out["meshes"].append(
            Mesh(
                f"{st.name}.planet{p + 1}-ring",
                (name, gear.name),
                ring_ref,
                pr,
                st.mesh_stiffness,
                st.mesh_friction,
                carrier.name,
            )
        )
    out["stage"] = {
        "name": st.name,
        "sun": (sun_shaft.name, sun.name),
        "ring": ring_ref,
        "carrier": carrier.name,
        "planets": tuple(planet_names),
        "carrier_radius_m": a_sp,
        "pin_errors_m": tuple(errors),
        "ratio_ring_fixed": 1.0 + ring_geo.teeth / gs.teeth,
    }
    return out


def expand_stages(specs: list, shafts: list[DriveShaft], base: Path) -> dict:
    """The planets, their bearings, the meshes and housing ring gears of every ``[[planetary]]`` stage."""
    out = {"shafts": (), "bearings": (), "meshes": (), "housing_gears": (), "stages": ()}
    for i, raw in enumerate(specs):
        if not isinstance(raw, dict):
            raise InputError(f"planetary[{i}] must be a table")
        st = _stage(i, raw, shafts, base)
        for key in ("shafts", "bearings", "meshes", "housing_gears"):
            out[key] = out[key] + tuple(st[key])
        out["stages"] = out["stages"] + (st["stage"],)
    return out
