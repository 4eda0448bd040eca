"""The bearing-type registry of the input format: ``bearing.type`` → a builder of a ``BearingModel``.

Each builder maps a validated ``[geometry]`` (a dict, SI) and a material to a
:class:`~bearingkit.analysis.solver.model.BearingModel` through :mod:`bearingkit.bearings`. The keys of
:data:`BUILDERS` equal those of :data:`bearingkit.io.schema.GEOMETRY_MODELS`; the simpler kinds
(four-point, slewing, spherical, self-aligning, needle) come from :mod:`bearingkit.io.build.kinds`, a new
type from :func:`register_bearing_type`. The loader (:mod:`bearingkit.io.loader`) calls them.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np
from pydantic import BaseModel

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.build import kinds


def _profile(geometry: dict, diameter: float | None = None):
    from bearingkit.physics.contact.profiles import make_profile

    spec = geometry.get("profile")
    if spec is None:
        return None
    params = {k: v for k, v in spec.items() if k != "name" and v is not None}
    d = geometry["element_diameter"] if diameter is None else diameter
    return make_profile(spec["name"], geometry["effective_length"], d, **params)


def _standard(builder_name: str, renames: dict | None = None):
    def build(geometry: dict, material, name: str) -> BearingModel:
        from bearingkit.bearings import standard

        skip = ("bore", "outer_diameter", *schema.SHOULDER_FIELDS)  # not builder arguments
        kwargs = {k: v for k, v in geometry.items() if v is not None and k not in skip}
        for old, new in (renames or {}).items():
            if old in kwargs:
                kwargs[new] = kwargs.pop(old)
        if "profile" in kwargs:
            kwargs["profile"] = _profile(geometry)
        if name:
            kwargs["name"] = name
        return getattr(standard, builder_name)(material=material, **kwargs)

    return build


def _turntable(builder_name: str):
    def build(geometry: dict, material, name: str) -> BearingModel:
        from bearingkit.bearings import turntable
        from bearingkit.physics.contact.profiles import PROFILES, SEED000_CROWNING

        crowning = geometry.get("crowning")
        if crowning is not None and crowning not in SEED000_CROWNING and crowning not in PROFILES:
            raise InputError(
                f"crowning ({crowning!r}) must be a seed-000 letter ({', '.join(SEED000_CROWNING)}) or a "
                f"profile name ({', '.join(PROFILES)})"
            )
        overrides = {k: v for k, v in geometry.items() if v is not None}
        if builder_name == "yrt_turntable":
            overrides = {k: v for k, v in overrides.items() if k not in ("bore", "outer_diameter")}
        model = getattr(turntable, builder_name)(material=material, **overrides)
        return dataclasses.replace(model, name=name) if name else model

    return build


def _diameter_deviation(geometry: dict):
    """ΔD per roller (Z,) [m] from a list (SI already) or a generator spec; None when not given."""
    from bearingkit.physics.deviations import gaussian_deviations, seed001_series

    spec = geometry.get("diameter_deviation")
    if spec is None:
        return None
    if isinstance(spec, (list, tuple)):
        return np.asarray(spec, dtype=float)
    if spec.get("series") is not None:
        dev = seed001_series(spec["series"])
        if dev.shape[0] != geometry["n_elements"]:
            raise InputError(
                f"diameter_deviation (series {spec['series']}, {dev.shape[0]} rollers) must match "
                f"n_elements ({geometry['n_elements']})"
            )
        return dev
    return gaussian_deviations(
        geometry["n_elements"], spec["magnitude"], 1, spec["arrangement"], spec["seed"]
    )[0]


def _tapered(geometry: dict, material, name: str) -> BearingModel:
    """Tapered roller bearing: :class:`~bearingkit.rows.tapered.row.TaperedRow`, single or a DB/DF pair."""
    from bearingkit.bearings.common import e_reduced_of
    from bearingkit.bearings.tapered import tapered_pair
    from bearingkit.rows.tapered.row import TaperedRow

    skip = ("bore", "outer_diameter", "arrangement", "row_spacing", "diameter_deviation", "profile")
    kwargs = {k: v for k, v in geometry.items() if v is not None and k not in skip}
    kwargs.update(
        e_reduced=e_reduced_of(material),
        density=material.density,
        diameter_deviation=_diameter_deviation(geometry),
    )
    if geometry.get("profile") is not None:
        mean_diameter = 0.5 * (geometry["small_diameter"] + geometry["large_diameter"])
        kwargs["profile"] = _profile(geometry, diameter=mean_diameter)
    if geometry["arrangement"] == "single":
        row = TaperedRow(**kwargs, name="tapered")
        refs = ("liu2022", "kunert1961")
        return BearingModel((row,), name=name or "tapered roller bearing", references=refs)
    return tapered_pair(
        spacing=geometry["row_spacing"],
        arrangement=geometry["arrangement"],
        name=name or f"tapered roller pair {geometry['arrangement']}",
        **kwargs,
    )


def _ptrb(geometry: dict, material, name: str) -> BearingModel:
    """Planetary thread roller bearing (seed 004): one :class:`~bearingkit.rows.threaded.row.ThreadedRow`."""
    from bearingkit.bearings.ptrb import ptrb_model
    from bearingkit.rows.threaded.geometry import PTRBGeometry

    renames = {"bore": "bore_diameter", "outer_diameter": "outside_diameter"}
    kwargs = {renames.get(k, k): v for k, v in geometry.items() if v is not None and k != "clearance"}
    g = PTRBGeometry(**kwargs, youngs_modulus=material.youngs_modulus, poisson_ratio=material.poisson_ratio)
    return ptrb_model(g, clearance=geometry.get("clearance") or 0.0, name=name or "PTRB")


def _ball_column(geometry: dict, material, name: str) -> BearingModel:
    """Seed-002 ball–column composite bearing (:func:`bearingkit.bearings.ball_column.ball_column`)."""
    from bearingkit.bearings.ball_column import BallColumnGeometry, RingOptions, ball_column

    fields = {k: v for k, v in geometry.items() if v is not None and k != "ring"}
    if "support_positions" in fields:
        fields["support_positions"] = tuple(fields["support_positions"])
    ring = RingOptions(**{k: v for k, v in (geometry.get("ring") or {}).items() if v is not None})
    model = ball_column(BallColumnGeometry(**fields), material=material, ring=ring)
    return dataclasses.replace(model, name=name) if name else model


#: Bearing type → builder. Keys equal :data:`bearingkit.io.schema.GEOMETRY_MODELS`'s.
BUILDERS: dict[str, Callable[[dict, object, str], BearingModel]] = {
    "composite_turntable": _turntable("composite_turntable"),
    "yrt_turntable": _turntable("yrt_turntable"),
    "deep_groove_ball": _standard("deep_groove_ball"),
    "angular_contact_ball": _standard("angular_contact_ball"),
    "angular_contact_pair": _standard("angular_contact_pair", {"clearance_axial": "axial_clearance"}),
    "thrust_ball": _standard("thrust_ball"),
    "cylindrical_roller": _standard("cylindrical_roller"),
    "cylindrical_roller_thrust": _standard("cylindrical_roller_thrust"),
    "tapered_roller": _tapered,
    "ptrb": _ptrb,
    "ball_column": _ball_column,
}
kinds.register(BUILDERS, schema.GEOMETRY_MODELS)  # four-point, slewing, spherical, self-aligning, needle
assert set(BUILDERS) == set(schema.GEOMETRY_MODELS)


def register_bearing_type(name: str, geometry_model: type[BaseModel], builder: Callable) -> None:
    """Add a bearing type to the input format.

    Parameters
    ----------
    name : str
        The ``bearing.type`` value.
    geometry_model : pydantic model
        Validates ``[geometry]`` (use the annotated types of :mod:`bearingkit.io.schema`, e.g.
        ``schema.PositiveLength``, so values arrive in SI); unknown fields must be forbidden.
    builder : callable
        ``builder(geometry: dict (SI), material, name: str) -> BearingModel``.
    """
    if name in BUILDERS:
        raise InputError(f"bearing type ({name!r}) is already registered")
    schema.GEOMETRY_MODELS[name] = geometry_model
    BUILDERS[name] = builder
