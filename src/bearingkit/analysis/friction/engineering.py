"""Engineering friction models (SKF four-component, Palmgren) behind one registry, and their use on a
bearingkit bearing so that users can compare them with the physics torque of
:mod:`bearingkit.analysis.friction.components`.

SI units at the boundary: m, N, rad/s, m²/s, °C (temperature, as the lubricant API); moments in N·m,
with the unit in every result key (``total_Nm`` …). The models themselves live in
:mod:`bearingkit.physics.friction.skf` and :mod:`bearingkit.physics.friction.palmgren` (each converts
to its catalogue units inside).

Registries
----------
:data:`ENGINEERING_MODELS`
    ``"skf"`` → :func:`~bearingkit.physics.friction.skf.skf_friction_moment`,
    ``"palmgren"`` → :func:`~bearingkit.physics.friction.palmgren.palmgren_friction_moment`.
:data:`BEARING_TYPES`
    Bearing type names each model knows (``deep_groove_ball``, ``angular_contact_ball``,
    ``four_point_contact_ball``, ``cylindrical_roller``, ``tapered_roller``, ``thrust_ball``,
    ``cylindrical_roller_thrust`` …).

From a bearing model
--------------------
:func:`engineering_friction_torque` reads a single-row :class:`~bearingkit.analysis.solver.model.BearingModel`
built by :mod:`bearingkit.bearings.standard` (duck-typed: ``rows[0].kind``, ``contact_angle``,
``orientation``, ``pitch_diameter``, ``element_diameter``, ``n_elements``) and infers the type. The
catalogue models need the boundary dimensions d and D, which the builders do not store: pass them
(``bore_diameter``, ``outside_diameter``); otherwise they are **estimated** as
d, D = d_m ∓ D_w / (2·:data:`ELEMENT_TO_SECTION`) (documented assumption, flagged in the result's
``notes``). C0 for the ball-bearing laws comes from ISO 76 (:mod:`bearingkit.physics.life.iso76`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import palmgren as friction_palmgren
from bearingkit.physics.friction import skf as friction_skf
from bearingkit.physics.friction import skf_terms
from bearingkit.physics.life import iso76
from bearingkit.physics.life.iso281 import RADIAL_MAX_ANGLE

#: Registry of engineering friction models.
ENGINEERING_MODELS = {
    "skf": friction_skf.skf_friction_moment,
    "palmgren": friction_palmgren.palmgren_friction_moment,
}
#: Component names (keys without the ``_Nm`` suffix) of each model; they add up to ``total``.
MODEL_COMPONENTS = {"skf": ("rolling", "sliding", "seal", "drag"), "palmgren": ("viscous", "load")}
#: Bearing types each model covers.
BEARING_TYPES = {"skf": tuple(skf_terms.G_MODELS), "palmgren": friction_palmgren.palmgren_types()}
#: Bearing types a model refuses, with the constants no source gave (one-line refusal).
NOT_COVERED = {"skf": skf_terms.NOT_COVERED, "palmgren": friction_palmgren.NOT_COVERED}
#: Row kinds of the two-row self-aligning bearings → engineering type (the whole bearing, both rows).
_TWO_ROW_KINDS = {"spherical_roller": "spherical_roller", "self_aligning_ball": "self_aligning_ball"}
#: Element diameter over ring section width, D_w / (D − d), so that D − d ≈ D_w / ELEMENT_TO_SECTION;
#: typical of standard ball and roller bearings (6208: D_w = 12.7 mm, D − d = 40 mm → 0.32; NU 208:
#: 11/40 → 0.28). [M] estimate, used only when the boundary dimensions are not given.
ELEMENT_TO_SECTION = 0.3  # [-]
#: Citation keys used by the engineering models.
REFERENCE_KEYS = friction_skf.REFERENCE_KEYS + friction_palmgren.REFERENCE_KEYS


@dataclass(frozen=True)
class EngineeringFrictionResult:
    """Friction torque of a bearing by an engineering model (leading case axis).

    Attributes
    ----------
    model : str
        Key of :data:`ENGINEERING_MODELS`.
    bearing_type : str
        Bearing type used.
    components : dict name → ndarray [N·m]
        Breakdown (:data:`MODEL_COMPONENTS`); sums to ``total``.
    total : ndarray [N·m]
        Total friction torque.
    factors : dict
        Model factors (φ_ish, μ_sl, f0, f1, P1 …) for inspection.
    inputs : dict
        The SI inputs used (with unit-suffixed keys), including estimated d and D.
    references : tuple of str
        Citation keys.
    notes : tuple of str
        Assumptions made (estimated dimensions, unverified constants).
    """

    model: str
    bearing_type: str
    components: dict
    total: np.ndarray
    factors: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    references: tuple = ()
    notes: tuple = ()

    def to_dict(self) -> dict:
        """JSON-ready dict; torques carry ``_Nm`` in their keys."""

        def _j(v):
            a = np.asarray(v)
            return a.tolist() if a.ndim else float(a) if np.issubdtype(a.dtype, np.number) else v

        out = {"model": self.model, "bearing_type": self.bearing_type, "total_Nm": _j(self.total)}
        out.update({f"{k}_Nm": _j(v) for k, v in self.components.items()})
        out["factors"] = {k: _j(v) for k, v in self.factors.items()}
        out["inputs"] = {k: _j(v) for k, v in self.inputs.items()}
        out["references"] = list(self.references)
        out["notes"] = list(self.notes)
        return out


def _tag_notes(model: str, bearing_type: str, series: str | None) -> tuple[str, ...]:
    if model == "skf":
        c = skf_terms.series_constants(bearing_type, series)
        notes = []
        if c["tag"] == "M" or c["kz_tag"] == "M":
            notes.append(f"SKF constants of {bearing_type} series {c['series']} are [M] (not verified)")
        if series is None and len(skf_terms.series_keys(bearing_type)) > 1:
            notes.append(
                f"SKF constants of series {c['series']} used (the first of {bearing_type}'s series "
                f"{', '.join(skf_terms.series_keys(bearing_type))}; "
                "engineering_friction_torque(..., series=…) or a file's [bearing] series selects another)"
            )
        return tuple(notes)
    if bearing_type in ("spherical_roller", "needle_roller"):
        return (
            f"Palmgren f0/f1 of {bearing_type}: Schaeffler's type values via one public transcription [S1]",
        )
    return ("Palmgren f0/f1 tables are [M] (from memory of Harris & Kotzalas 2007 ch. 11, not verified)",)


def engineering_friction_moment(model: str, bearing_type: str, **kwargs) -> EngineeringFrictionResult:
    """Run an engineering friction model by name.

    Parameters
    ----------
    model : str
        Key of :data:`ENGINEERING_MODELS`.
    bearing_type : str
        One of ``BEARING_TYPES[model]``.
    **kwargs
        The model's keyword arguments (SI), see
        :func:`~bearingkit.physics.friction.skf.skf_friction_moment` and
        :func:`~bearingkit.physics.friction.palmgren.palmgren_friction_moment`.

    Returns
    -------
    EngineeringFrictionResult
    """
    checks.one_of("model", model, ENGINEERING_MODELS)
    if bearing_type in NOT_COVERED[model]:
        raise InputError(
            f"bearing_type ({bearing_type!r}): {model} model refused: {NOT_COVERED[model][bearing_type]}"
        )
    checks.one_of(f"{model} bearing_type", bearing_type, BEARING_TYPES[model])
    raw = ENGINEERING_MODELS[model](bearing_type, **kwargs)
    comps = {k: raw[f"{k}_Nm"] for k in MODEL_COMPONENTS[model]}
    factors = {k: v for k, v in raw.items() if not k.endswith("_Nm")}
    refs = friction_skf.REFERENCE_KEYS if model == "skf" else friction_palmgren.REFERENCE_KEYS
    return EngineeringFrictionResult(
        model=model,
        bearing_type=bearing_type,
        components=comps,
        total=raw["total_Nm"],
        factors=factors,
        references=refs,
        notes=_tag_notes(model, bearing_type, kwargs.get("series")),
    )


def bearing_type_of(bearing) -> str:
    """Engineering-model type name of a single-row standard bearing model (duck-typed).

    Ball row: α = 0 → ``deep_groove_ball``; 0 < α < π/2 → ``angular_contact_ball``; α = π/2 →
    ``thrust_ball``. Cylindrical row: radial → ``cylindrical_roller``; thrust → ``cylindrical_roller_thrust``.
    Four-point row → ``four_point_contact_ball``; needle row → ``needle_roller``; the two rows of a spherical
    roller or self-aligning ball bearing → ``spherical_roller`` / ``self_aligning_ball`` (the catalogue
    models describe the whole two-row bearing); one spherical roller row at |α| > 45° →
    ``spherical_roller_thrust``.
    """
    rows = getattr(bearing, "rows", None)
    kinds = {getattr(r, "kind", None) for r in rows or ()}
    one = rows[0] if rows and len(rows) == 1 else None
    if kinds == {"spherical_roller"} and one is not None and abs(float(one.contact_angle)) > RADIAL_MAX_ANGLE:
        return "spherical_roller_thrust"  # ISO 281's thrust bearing: the one row of a 292/293/294 (α ≈ 50°)
    if len(kinds) == 1 and next(iter(kinds)) in _TWO_ROW_KINDS:
        return _TWO_ROW_KINDS[next(iter(kinds))]
    if not rows or len(rows) != 1:
        n = 0 if not rows else len(rows)
        raise InputError(
            f"bearing ({getattr(bearing, 'name', bearing)!r}) has {n} rows; the engineering models take a "
            "single-row standard bearing (for pairs compute each bearing and add, as SKF does)"
        )
    row = rows[0]
    kind = getattr(row, "kind", None)
    if kind == "ball":
        alpha = abs(float(row.contact_angle))
        if np.isclose(alpha, 0.0, atol=1e-12):
            return "deep_groove_ball"
        if np.isclose(alpha, np.pi / 2, atol=1e-9):
            return "thrust_ball"
        return "angular_contact_ball"
    if kind == "cylindrical":
        return "cylindrical_roller" if row.orientation == "radial" else "cylindrical_roller_thrust"
    if kind == "four_point":  # QJ bearings: SKF Table 2a, four-point contact ball bearings
        return "four_point_contact_ball"
    if kind == "needle":
        return "needle_roller"
    raise InputError(
        f"row kind ({kind!r}) has no engineering friction model; supported: ball, cylindrical, four-point, "
        "needle (single row), spherical roller and self-aligning ball bearings"
    )


def _static_rating(row, bearing_type):
    if bearing_type == "thrust_ball":
        return iso76.static_rating_ball(
            row.element_diameter, row.pitch_diameter, np.pi / 2, row.n_elements, kind="thrust"
        )
    return iso76.static_rating_ball(
        row.element_diameter, row.pitch_diameter, abs(float(row.contact_angle)), row.n_elements
    )


def engineering_friction_torque(
    bearing,
    *,
    load_radial=0.0,
    load_axial=0.0,
    speed,
    lubricant,
    temperature,
    model: str = "skf",
    bearing_type: str | None = None,
    bore_diameter=None,
    outside_diameter=None,
    lubrication: str | None = None,
    **model_kwargs,
) -> EngineeringFrictionResult:
    """Engineering-model friction torque of a bearingkit bearing at an operating point.

    Parameters
    ----------
    bearing : BearingModel
        Single-row bearing from :mod:`bearingkit.bearings.standard`.
    load_radial, load_axial : array_like
        F_r, F_a [N] (leading case axis).
    speed : array_like
        Relative ring speed |ω_i − ω_o| [rad/s].
    lubricant : Lubricant or str
        Lubricant (a grease by its base oil), :mod:`bearingkit.lubricants`.
    temperature : array_like
        Operating temperature [°C] (sets ν).
    model : str
        ``"skf"`` or ``"palmgren"``.
    bearing_type : str or None
        Override the inferred type (e.g. ``"four_point_contact_ball"``).
    bore_diameter, outside_diameter : float or None
        Boundary dimensions d, D [m]; None = estimated from d_m and D_w (see module docstring).
    lubrication : str or None
        Lubrication method; None = ``grease`` for a grease, else ``oil_bath`` (low level: no drag).
    **model_kwargs
        Further keyword arguments of the model (series, seal, oil_level, f0 …).

    Returns
    -------
    EngineeringFrictionResult
        Compare ``total`` with :func:`bearingkit.analysis.friction.components.friction_torque` ``.total``.
    """
    checks.one_of("model", model, ENGINEERING_MODELS)
    lub = as_lubricant(lubricant)
    btype = bearing_type or bearing_type_of(bearing)
    row = bearing.rows[0]
    dm = float(row.pitch_diameter)
    notes = []
    if (bore_diameter is None) != (outside_diameter is None):
        raise InputError("bore_diameter and outside_diameter must be given together (or both left None)")
    if bore_diameter is None:
        half = 0.5 * float(row.element_diameter) / ELEMENT_TO_SECTION
        bore_diameter, outside_diameter = dm - half, dm + half
        notes.append(
            f"d and D estimated from d_m and D_w (D - d = D_w/{ELEMENT_TO_SECTION}): "
            f"d = {bore_diameter * 1e3:.4g} mm, D = {outside_diameter * 1e3:.4g} mm"
        )
    nu = lub.kinematic_viscosity(temperature)
    if lubrication is None:
        lubrication = "grease" if lub.base == "grease" else "oil_bath"
    inputs = {
        "bore_diameter_m": bore_diameter,
        "outside_diameter_m": outside_diameter,
        "pitch_diameter_m": dm,
        "load_radial_N": load_radial,
        "load_axial_N": load_axial,
        "speed_rad_s": speed,
        "kinematic_viscosity_m2_s": nu,
        "temperature_C": temperature,
    }
    kw = dict(model_kwargs)
    if btype in NOT_COVERED[model]:
        raise InputError(f"bearing_type ({btype!r}): {model} model refused: {NOT_COVERED[model][btype]}")
    if model == "skf":
        if btype == "deep_groove_ball" and "static_rating" not in kw:
            kw["static_rating"] = _static_rating(row, btype)
        if btype == "self_aligning_ball":
            kw.setdefault("n_rows", len(bearing.rows))  # ball drag counts both rows
        res = engineering_friction_moment(
            "skf",
            btype,
            bore_diameter=bore_diameter,
            outside_diameter=outside_diameter,
            speed=speed,
            kinematic_viscosity=nu,
            load_radial=load_radial,
            load_axial=load_axial,
            lubrication=lubrication,
            lubricant_base=lub.ehl_class,  # a grease by its base oil (mineral or synthetic)
            **kw,
        )
    else:
        if btype in ("deep_groove_ball", "angular_contact_ball", "thrust_ball") and "static_rating" not in kw:
            kw["static_rating"] = _static_rating(row, btype)
        if btype in ("angular_contact_ball", "spherical_roller") and "contact_angle" not in kw:
            kw["contact_angle"] = abs(float(np.max(row.contact_angle)))
        res = engineering_friction_moment(
            "palmgren",
            btype,
            pitch_diameter=dm,
            speed=speed,
            kinematic_viscosity=nu,
            load_radial=load_radial,
            load_axial=load_axial,
            lubrication=lubrication,
            **kw,
        )
    return EngineeringFrictionResult(
        model=res.model,
        bearing_type=btype,
        components=res.components,
        total=res.total,
        factors=res.factors,
        inputs=inputs,
        references=res.references,
        notes=tuple(notes) + res.notes,
    )


__all__ = [
    "BEARING_TYPES",
    "ELEMENT_TO_SECTION",
    "ENGINEERING_MODELS",
    "MODEL_COMPONENTS",
    "NOT_COVERED",
    "EngineeringFrictionResult",
    "bearing_type_of",
    "engineering_friction_moment",
    "engineering_friction_torque",
]
