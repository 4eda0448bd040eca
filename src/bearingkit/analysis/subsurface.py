"""Stresses below the contacts of a solved bearing and the check of the raceways' hardened layer.

SI units (m, Pa). For every row and load case of a
:class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult`, the most heavily loaded contact (the
largest Hertz pressure over the elements, both raceways and, for rollers, every slice) — or on demand every
loaded contact — gets the stress profiles against depth below its centre
(:mod:`bearingkit.physics.contact.subsurface` for ball contacts, :mod:`~.subsurface_line` for roller
slices): the largest von Mises and Tresca stress over the rolling position and the orthogonal-shear
amplitude, their maxima and depths, and the check of the raceway's hardness profile
(:mod:`bearingkit.physics.structure.case_depth`): the safety against depth, the case safety, where it
lies (transition zone or core) and the case depth a target safety needs.

Roller slices: a slice is a plane-strain line contact of half-width b = 2 q / (π p₀ w) (slice load q,
width w, pressure p₀), so the slice pressures resolve the edge-stress peak of a profiled roller as finely
as the slicing does: the picked slice is the end slice when the edge peaks, and the result says so.
Threaded (PTRB) rows are not covered (their contacts are thread flanks, not raceways).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.physics.contact import subsurface as point
from bearingkit.physics.contact import subsurface_line as line
from bearingkit.physics.structure import case_depth

__all__ = [
    "DEPTH_POINTS",
    "DEPTH_SPAN",
    "OUTPUT_STRIDE",
    "RowSubsurface",
    "SubsurfaceResult",
    "subsurface",
]

#: Depths of the internal profile (maxima, case check) from the surface to the deepest depth [-].
DEPTH_POINTS = 401
#: Every n-th depth goes into the output arrays (81 of the 401: the plotted profiles).
OUTPUT_STRIDE = 5
#: Deepest depth over the contact's semi-minor axis (or half-width) [-]: the von Mises stress there is
#: below ~0.15 p₀ (point) / 0.25 p₀ (line). Deeper when the hardness profile needs it (:data:`CORE_MARGIN`).
DEPTH_SPAN = 6.0
#: With a hardened layer the profile reaches CORE_MARGIN × the end of the transition zone into the core [-].
CORE_MARGIN = 1.25
#: Contacts whose profiles are computed at once (the orthogonal-shear and traction searches hold
#: (contacts, depths, samples) arrays: 16 × 401 × 401 doubles ≈ 20 MB).
CHUNK = 16
#: An end slice is the roller's edge peak when its pressure exceeds its neighbour's by this factor [-]
#: (equal pressures along a straight roller are no peak).
EDGE_PEAK = 1.0001
#: Largest |q/p| taken [-]: the traction coefficient is a friction coefficient of the contact (rolling
#: with slip 0.01–0.1; dry sliding steel on steel about 0.6, Bowden & Tabor, from memory); above 1 it is
#: not a rolling contact's, and 1e308 overflowed the stress field (the fuzz, seed 20261202 #3407).
MAX_TRACTION = 1.0
#: Raceway labels of the four contacts of a four-point ball (rows.four_point.CONTACTS order).
_FOUR_POINT_SIDES = ("outer", "outer", "inner", "inner")


@dataclass
class RowSubsurface:
    """Stresses below the most loaded contact of one row, per load case (leading axis C).

    Attributes
    ----------
    name, kind : str
        Row name and ``row.kind``.
    contact : {"point", "line"}
    raceway : list of str (C,)
        ``"inner"`` / ``"outer"`` raceway of the picked contact ("" when the row carries no load).
    element, slice_index : ndarray (C,) of int
        Element of the picked contact, and its slice (−1 for ball contacts).
    edge_slice : ndarray (C,) of bool
        The picked slice is an end slice of the roller (the edge peak).
    max_pressure : ndarray (C,) [Pa]
        p₀ of the picked contact.
    semi_minor, semi_major : ndarray (C,) [m]
        b (rolling direction; the half-width of a slice) and a (NaN for a slice).
    depth : ndarray (C, N) [m]
    von_mises, tresca, orthogonal_shear, strength, hardness, safety : ndarray (C, N)
        Profiles [Pa] (hardness [HV], safety [-]) on :data:`DEPTH_POINTS` depths.
    case : CaseCheck
        Case safety, its depth and zone per case
        (:func:`~bearingkit.physics.structure.case_depth.case_check`).
    required_case_depth : ndarray (C,) [m]
        Case depth for the target case safety (NaN through-hardened, inf unreachable, 0 not needed).
    loaded : ndarray (C,) of bool
    every : dict or None
        With ``every_contact``: ``max_von_mises``, ``depth_max_von_mises``, ``max_pressure`` (C, M) of
        every candidate contact (0 where unloaded) and their ``raceway``/``element``/``slice`` labels (M,).
    """

    name: str
    kind: str
    contact: str
    raceway: list
    element: np.ndarray
    slice_index: np.ndarray
    edge_slice: np.ndarray
    max_pressure: np.ndarray
    semi_minor: np.ndarray
    semi_major: np.ndarray
    depth: np.ndarray
    von_mises: np.ndarray
    tresca: np.ndarray
    orthogonal_shear: np.ndarray
    strength: np.ndarray
    hardness: np.ndarray
    safety: np.ndarray
    case: case_depth.CaseCheck
    required_case_depth: np.ndarray
    loaded: np.ndarray
    every: dict | None = None

    def _peak(self, values):
        k = np.argmax(np.where(self.loaded[:, None], values, -np.inf), axis=-1)
        take = lambda a: np.take_along_axis(a, k[:, None], -1)[:, 0]  # noqa: E731
        return np.where(self.loaded, take(values), 0.0), np.where(self.loaded, take(self.depth), np.nan)

    @property
    def max_von_mises(self):
        """(max σ_vM [Pa], its depth [m]) per case."""
        return self._peak(self.von_mises)

    @property
    def max_tresca(self):
        return self._peak(self.tresca)

    @property
    def max_orthogonal_shear(self):
        return self._peak(self.orthogonal_shear)

    def to_dict(self, case: int, stride: int = OUTPUT_STRIDE) -> dict:
        """JSON-ready dict of one case (SI, units in keys; arrays every ``stride``-th depth)."""

        def num(a):
            v = float(np.asarray(a)[case])
            return v if np.isfinite(v) else None

        def arr(a):
            return [float(v) if np.isfinite(v) else None for v in a[case, ::stride]]

        vm, z_vm = self.max_von_mises
        tr, z_tr = self.max_tresca
        ortho, z_o = self.max_orthogonal_shear
        loaded = bool(self.loaded[case])
        out = {
            "contact": self.contact,
            "raceway": self.raceway[case] or None,
            "element": int(self.element[case]) if loaded else None,
            "slice": int(self.slice_index[case]) if loaded and self.slice_index[case] >= 0 else None,
            "edge_slice": bool(self.edge_slice[case]),
            "max_pressure_Pa": num(self.max_pressure),
            "semi_minor_m": num(self.semi_minor) if loaded else None,
            "semi_major_m": num(self.semi_major) if loaded else None,
            "depth_m": arr(self.depth),
            "von_mises_Pa": arr(self.von_mises),
            "tresca_Pa": arr(self.tresca),
            "orthogonal_shear_Pa": arr(self.orthogonal_shear),
            "strength_Pa": arr(self.strength),
            "hardness_HV": arr(self.hardness),
            "safety": arr(np.minimum(self.safety, 1e9)),
            "max_von_mises_Pa": num(vm) if loaded else None,
            "depth_max_von_mises_m": num(z_vm),
            "max_tresca_Pa": num(tr) if loaded else None,
            "depth_max_tresca_m": num(z_tr),
            "max_orthogonal_shear_Pa": num(ortho) if loaded else None,
            "depth_max_orthogonal_shear_m": num(z_o),
            "von_mises_over_pressure": (num(vm) / num(self.max_pressure)) if loaded else None,
            "case_safety": num(self.case.case_safety) if loaded else None,
            "depth_case_safety_m": num(self.case.depth_case_safety) if loaded else None,
            "case_safety_zone": (self.case.zone[case] or None) if loaded else None,
            "required_case_depth_m": num(self.required_case_depth) if loaded else None,
        }
        if self.every is not None:
            out["every_contact"] = {
                "raceway": list(self.every["raceway"]),
                "element": [int(v) for v in self.every["element"]],
                "slice": [int(v) for v in self.every["slice"]],
                "max_pressure_Pa": [float(v) for v in self.every["max_pressure"][case]],
                "max_von_mises_Pa": [float(v) for v in self.every["max_von_mises"][case]],
                "depth_max_von_mises_m": [
                    float(v) if np.isfinite(v) else None for v in self.every["depth_max_von_mises"][case]
                ],
            }
        return out


@dataclass
class SubsurfaceResult:
    """Subsurface stresses of every row (:func:`subsurface`).

    Attributes
    ----------
    rows : list of RowSubsurface
        One per row (threaded rows at their most loaded tooth flank, see ``notes``).
    profile : HardnessProfile
        The raceways' hardness profile checked.
    traction : float
        Surface traction coefficient μ used [-].
    target_safety : float
        Case safety the required case depth is computed for [-].
    warnings : list of list of str
        Per case: overloaded transition zones or cores.
    notes : list of str
    """

    rows: list
    profile: object
    traction: float
    target_safety: float
    poisson_ratio: float
    warnings: list
    notes: list = field(default_factory=list)

    def row(self, name: str) -> RowSubsurface:
        for r in self.rows:
            if r.name == name:
                return r
        raise KeyError(name)

    def to_dict(self, case: int) -> dict:
        """Row name → that row's :meth:`RowSubsurface.to_dict` for one case."""
        return {r.name: r.to_dict(case) for r in self.rows}

    def settings_dict(self) -> dict:
        """What was assumed (hardness profile, traction, target), JSON-ready."""
        p = self.profile
        return {
            "hardness_profile": p.describe(),
            "surface_hardness_HV": p.surface_hardness,
            "case_depth_m": p.case_depth,
            "core_hardness_HV": p.core_hardness,
            "depth_definition": None if p.through_hardened else p.depth_definition,
            "limit_hardness_HV": None if p.through_hardened else p.limit,
            "strength_model": p.strength_model,
            "traction_coefficient": self.traction,
            "target_case_safety": self.target_safety,
            "poisson_ratio": self.poisson_ratio,
        }


# ------------------------------------------------------------------------------------------ contacts
def _point_candidates(state):
    """p, a, b (C, M), labels and slice indices of a row's point contacts: both raceways of a ball (a
    four-point ball's four); every tooth flank of a threaded roller (slice index = 2 tooth + flank).

    A flank contact is a Hertz ellipse like a ball's: its field below the flank surface is the same
    half-space solution, with the depth measured normal to the flank."""
    ex = state.extras
    if "max_pressure_contact" in ex:  # four-point: every contact
        p, a, b = ex["max_pressure_contact"], ex["semi_major"], ex["semi_minor"]
        c, z, k = p.shape
        sides = np.tile(np.array(_FOUR_POINT_SIDES), z)
        elems = np.repeat(np.arange(z), k)
        return p.reshape(c, -1), a.reshape(c, -1), b.reshape(c, -1), sides, elems, np.full(sides.shape, -1)
    ps, as_, bs, sides, elems, slices = [], [], [], [], [], []
    for side in ("inner", "outer"):
        if f"max_pressure_{side}" not in ex:
            continue
        p = np.asarray(ex[f"max_pressure_{side}"], float)
        a = np.broadcast_to(ex[f"semi_major_{side}"], p.shape)
        b = np.broadcast_to(ex[f"semi_minor_{side}"], p.shape)
        per = int(np.prod(p.shape[2:]))  # 1 for a ball row; teeth × flanks for a threaded one
        ps.append(p.reshape(p.shape[0], -1))
        as_.append(a.reshape(p.shape[0], -1))
        bs.append(b.reshape(p.shape[0], -1))
        sides += [side] * (p.shape[1] * per)
        elems.append(np.repeat(np.arange(p.shape[1]), per))
        slices.append(np.tile(np.arange(per), p.shape[1]) if per > 1 else np.full(p.shape[1], -1))
    cat = lambda arrays: np.concatenate(arrays, axis=1)  # noqa: E731
    return cat(ps), cat(as_), cat(bs), np.array(sides), np.concatenate(elems), np.concatenate(slices)


def _line_candidates(row, state):
    """p, b (C, M), labels and edge flags of a roller row's slices on both raceways."""
    ex = state.extras
    ps, bs, sides, elems, slices = [], [], [], [], []
    for side in ("inner", "outer"):
        key = f"slice_pressure_{side}"
        if key not in ex:
            continue
        p = np.asarray(ex[key], float)
        c, z, n_s = p.shape
        if f"half_width_{side}" in ex:
            b = np.broadcast_to(ex[f"half_width_{side}"], p.shape)
        else:
            q = np.broadcast_to(ex.get(f"slice_load_{side}", state.slice_load), p.shape)
            width = np.asarray(row.effective_length, float).reshape(-1, 1, 1) / n_s
            with np.errstate(divide="ignore", invalid="ignore"):
                b = np.where(p > 0, 2.0 * q / (np.pi * np.where(p > 0, p, 1.0) * width), 0.0)
        ps.append(p.reshape(c, -1))
        bs.append(np.broadcast_to(b, p.shape).reshape(c, -1))
        sides += [side] * (z * n_s)
        elems.append(np.repeat(np.arange(z), n_s))
        slices.append(np.tile(np.arange(n_s), z))
    n_s = state.extras[f"slice_pressure_{sides[0]}"].shape[-1]
    p = np.concatenate(ps, 1)
    if n_s > 1:  # an end slice above its neighbour: the roller's edge peak
        per = p.reshape(p.shape[0], -1, n_s)
        first = per[..., 0] > EDGE_PEAK * per[..., 1]
        last = per[..., -1] > EDGE_PEAK * per[..., -2]
        edge = np.zeros(per.shape, bool)
        edge[..., 0], edge[..., -1] = first, last
        edge = edge.reshape(p.shape)
    else:
        edge = np.zeros(p.shape, bool)
    return p, np.concatenate(bs, 1), np.array(sides), np.concatenate(elems), np.concatenate(slices), edge


def _depths(b, profile):
    """(..., DEPTH_POINTS) depth grids: DEPTH_SPAN b, deeper to reach the core of a hardened layer."""
    deepest = DEPTH_SPAN * b
    if not profile.through_hardened:
        deepest = np.maximum(deepest, CORE_MARGIN * float(profile.transition()[1]))
    return deepest[..., None] * np.linspace(0.0, 1.0, DEPTH_POINTS)


def _profiles(contact, p, a, b, nu, traction, depth):
    """DepthProfile (…, N) of the contacts (p, a, b (…)), :data:`CHUNK` contacts at a time."""
    shape = depth.shape
    flat = [np.broadcast_to(v, shape[:-1]).reshape(-1) for v in (p, a, b)]
    z = depth.reshape(-1, shape[-1])
    parts = []
    for k in range(0, z.shape[0], CHUNK):
        pk, ak, bk = (v[k : k + CHUNK, None] for v in flat)
        if contact == "point":
            parts.append(point.depth_profile(z[k : k + CHUNK], ak, bk, pk, nu, traction))
        else:
            parts.append(line.line_depth_profile(z[k : k + CHUNK], bk, pk, nu, traction))
    return point.DepthProfile(
        *(np.concatenate([getattr(q, f) for q in parts]).reshape(shape) for f in parts[0]._fields)
    )


def _row(row, state, profile, nu, traction, target, converged, every_contact):
    kind = "line" if any(k.startswith("slice_pressure_") for k in state.extras) else "point"
    if kind == "point":
        p, a, b, sides, elems, slices = _point_candidates(state)
        edge = np.zeros(p.shape, bool)
    else:
        p, b, sides, elems, slices, edge = _line_candidates(row, state)
        a = np.full(p.shape, np.nan)
    p = np.where(converged[:, None], p, 0.0)
    top = np.argmax(p, axis=1)
    pick = lambda m: np.take_along_axis(m, top[:, None], 1)[:, 0]  # noqa: E731
    p0, a0, b0 = pick(p), pick(a), pick(b)
    loaded = p0 > 0.0
    b_safe = np.where(loaded, b0, 1.0)
    a_safe = np.where(loaded & np.isfinite(a0), a0, 1.0)
    depth = _depths(b_safe, profile)
    prof = _profiles(kind, p0, a_safe, b_safe, nu, traction, depth)
    zero = ~loaded[:, None]
    vm, tr, ortho = (np.where(zero, 0.0, v) for v in prof)
    check = case_depth.case_check(depth, vm, profile)
    required = case_depth.required_case_depth(depth, vm, profile, target)
    every = None
    if every_contact:
        every = _every(kind, p, a, b, sides, elems, slices, profile, nu, traction)
    return RowSubsurface(
        name=row.name,
        kind=row.kind,
        contact=kind,
        raceway=[str(sides[t]) if ok else "" for t, ok in zip(top, loaded, strict=True)],
        element=elems[top],
        slice_index=slices[top],
        edge_slice=np.take_along_axis(edge, top[:, None], 1)[:, 0] & loaded,
        max_pressure=p0,
        semi_minor=np.where(loaded, b0, np.nan),
        semi_major=np.where(loaded, a0, np.nan),
        depth=depth,
        von_mises=vm,
        tresca=tr,
        orthogonal_shear=ortho,
        strength=profile.strength(depth),
        hardness=profile.hardness(depth),
        safety=check.safety,
        case=check,
        required_case_depth=required,
        loaded=loaded,
        every=every,
    )


def _every(kind, p, a, b, sides, elems, slices, profile, nu, traction, points=81):
    """Max von Mises and its depth for every candidate contact (C, M) on a coarser depth grid."""
    on = p > 0
    b_safe, a_safe = np.where(on, b, 1.0), np.where(on & np.isfinite(a), a, 1.0)
    depth = DEPTH_SPAN * b_safe[..., None] * np.linspace(0.0, 1.0, points)
    vm = _profiles(kind, np.where(on, p, 0.0), a_safe, b_safe, nu, traction, depth).von_mises
    k = np.argmax(vm, axis=-1)
    return {
        "raceway": [str(s) for s in sides],
        "element": elems,
        "slice": slices,
        "max_pressure": np.where(on, p, 0.0),
        "max_von_mises": np.where(on, vm.max(axis=-1), 0.0),
        "depth_max_von_mises": np.where(on, np.take_along_axis(depth, k[..., None], -1)[..., 0], np.nan),
    }


def _warnings(rows, profile, target, n_cases) -> list:
    out = [[] for _ in range(n_cases)]
    if profile.through_hardened:
        return out
    for r in rows:
        low = r.case.case_safety
        for c in np.flatnonzero(r.loaded & (low < 1.0)):
            z = float(r.case.depth_case_safety[c])
            k = int(np.argmin(np.abs(r.depth[c] - z)))
            need = float(r.required_case_depth[c])
            advice = (
                f"a case safety of {target:g} needs {profile.depth_definition} ≥ {need * 1e3:.3g} mm"
                if np.isfinite(need)
                else "no case depth reaches it: the surface hardness itself is too low for this load"
            )
            out[c].append(
                f"{r.name}: {r.case.zone[c]} overloaded below the {r.raceway[c]} raceway: von Mises "
                f"{r.von_mises[c, k] / 1e6:.0f} MPa at {z * 1e3:.3g} mm depth exceeds the local yield "
                f"strength {r.strength[c, k] / 1e6:.0f} MPa ({r.hardness[c, k]:.0f} HV): case safety "
                f"{low[c]:.2f} < 1 ({profile.describe()}); {advice}"
            )
    return out


def subsurface(
    result,
    profile,
    poisson_ratio: float,
    *,
    traction: float = 0.0,
    target_safety: float = 1.0,
    every_contact: bool = False,
) -> SubsurfaceResult:
    """Subsurface stresses and the hardened-layer check of every row of a solved bearing.

    Parameters
    ----------
    result : QuasiStaticResult
        The solved load cases (C of them).
    profile : HardnessProfile
        The raceways' hardness against depth (:class:`bearingkit.hardness.HardnessProfile`).
    poisson_ratio : float
        ν of the rings [-].
    traction : float
        Surface traction coefficient μ = q/p [-], in [−:data:`MAX_TRACTION`, :data:`MAX_TRACTION`]
        (0: frictionless; ≠ 0 searches every depth over the rolling position, slower).
    target_safety : float
        Case safety the required case depth is computed for [-].
    every_contact : bool
        Also the max von Mises and its depth of every loaded contact (``RowSubsurface.every``).

    Returns
    -------
    SubsurfaceResult
    """
    from bearingkit import checks

    checks.in_range("traction q/p", traction, -MAX_TRACTION, MAX_TRACTION)
    checks.positive("target_safety", target_safety)
    converged = np.asarray(result.converged, bool)
    rows, notes = [], []
    for row, state in zip(result.model.rows, result.rows, strict=True):
        if row.kind == "threaded" and not any(n.startswith("subsurface: threaded") for n in notes):
            notes.append(
                "subsurface: threaded rows at the most loaded tooth flank (slice index = 2 tooth + flank): "
                "the Hertz half-space field below the flank, without the tooth's own bending"
            )
        rows.append(
            _row(row, state, profile, poisson_ratio, traction, target_safety, converged, every_contact)
        )
    if any(r.edge_slice.any() for r in rows if r.contact == "line"):
        notes.append(
            "subsurface: the most loaded slice of a roller is an end slice (edge peak); its stresses are the "
            "slice's, as fine as the slicing (n_slices) resolves the edge"
        )
    return SubsurfaceResult(
        rows=rows,
        profile=profile,
        traction=float(traction),
        target_safety=float(target_safety),
        poisson_ratio=float(poisson_ratio),
        warnings=_warnings(rows, profile, target_safety, result.n_cases),
        notes=notes,
    )
