"""Outputs of the generic evaluator: named quantities of the pipeline's Analysis.

SI units: every output names its unit in its name (``u_x_m``, ``k_xx_N_per_m``, ``L10r_h``) and in
:attr:`Quantity.unit`. :func:`catalogue` lists what a bearing input offers (the row names and the
duty-cycle bins make it input-specific); :func:`extract` reads the asked-for ones from an Analysis of
G study cases (its first G load cases) — each part of the Analysis (statics, per-row states, rating,
friction, duty cycle) is computed only when an asked-for output needs it. Values a part cannot give
for a case (a life of a case that did not converge, friction without a lubricant) are NaN.

``bearingkit study --list-outputs FILE`` prints the catalogue of a bearing file with units.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["DOFS", "Quantity", "catalogue", "extract", "parts_of"]

#: Degrees of freedom of the inner ring, in the solver's order, as they appear in output names.
DOFS = ("x", "y", "z", "thx", "thy")
_DOF_LONG = ("u_x", "u_y", "u_z", "theta_x", "theta_y")

#: The parts of an Analysis, in the order they are computed (a later part may need an earlier one).
PARTS = ("statics", "rows", "rating", "lubrication", "friction", "duty", "subsurface")


@dataclass(frozen=True)
class Quantity:
    """One output: its column name, SI unit, meaning, the Analysis part it needs and how to read it.

    ``get(ctx)`` returns an array (G,) for the G study cases of the context (:class:`_Context`).
    """

    name: str
    unit: str
    description: str
    part: str
    get: Callable


@dataclass
class _Context:
    """An Analysis whose first ``n`` load cases are the study cases; ``duty`` the (n, B) bin block."""

    analysis: object
    n: int
    duty: dict | None = None

    @property
    def statics(self):
        """The solve the outputs read: the coupled flexible-ring solve where the input has one."""
        flex = self.analysis.flexible
        return self.analysis.statics if flex is None else flex.result

    @property
    def converged(self):
        flex = self.analysis.flexible
        return self.statics.converged if flex is None else flex.converged


def _first(values, n):
    return np.asarray(values)[:n]


def _masked(values, n):
    return np.ma.filled(np.ma.asarray(values).astype(float), np.nan)[:n]


def _stiffness_unit(i: int, j: int) -> str:
    rot = (i >= 3) + (j >= 3)
    return ("N/m", "N/rad", "N·m/rad")[rot]


def _stiffness_name(i: int, j: int) -> str:
    a, b = DOFS[i], DOFS[j]
    key = f"k_{a}{b}" if i < 3 and j < 3 else f"k_{a}_{b}"
    suffix = {"N/m": "N_per_m", "N/rad": "N_per_rad", "N·m/rad": "Nm_per_rad"}[_stiffness_unit(i, j)]
    return f"{key}_{suffix}"


def _element(kind: str) -> str:
    return "ball" if kind == "ball" else "roller"


def _group_share(c: _Context, members: Sequence[str], rows: Sequence[str], what: str) -> np.ndarray:
    return sum(_share(c, r, rows, what) for r in members)


def _groups(model_rows) -> list[Quantity]:
    """Shares of the ball rows and of the roller rows, for bearings that have both."""
    rows = tuple(r.name for r in model_rows)
    groups: dict[str, list[str]] = {}
    for r in model_rows:
        groups.setdefault(_element(r.kind), []).append(r.name)
    if len(groups) < 2:
        return []
    out = []
    for element, members in groups.items():
        for what in ("radial", "axial"):
            out.append(
                Quantity(
                    f"{element}_rows_{what}_share",
                    "-",
                    f"share of the rows' {what} forces the {element} rows ({', '.join(members)}) carry",
                    "statics",
                    lambda c, m=tuple(members), w=what: _group_share(c, m, rows, w),
                )
            )
    return out


def _statics(rows: Sequence[str]) -> list[Quantity]:
    out = []
    for k, (dof, unit) in enumerate(zip(_DOF_LONG, ("m", "m", "m", "rad", "rad"), strict=True)):
        out.append(
            Quantity(
                f"{dof}_{unit}",
                unit,
                f"displacement {dof} of the inner ring",
                "statics",
                lambda c, k=k: c.statics.displacement[: c.n, k],
            )
        )
    out += [
        Quantity(
            "radial_displacement_m",
            "m",
            "radial displacement √(u_x² + u_y²)",
            "statics",
            lambda c: np.hypot(c.statics.displacement[: c.n, 0], c.statics.displacement[: c.n, 1]),
        ),
        Quantity(
            "tilt_rad",
            "rad",
            "tilt √(θ_x² + θ_y²) of the inner ring",
            "statics",
            lambda c: np.hypot(c.statics.displacement[: c.n, 3], c.statics.displacement[: c.n, 4]),
        ),
    ]
    for i in range(5):
        for j in range(i, 5):
            out.append(
                Quantity(
                    _stiffness_name(i, j),
                    _stiffness_unit(i, j),
                    f"tangent stiffness −∂F_{DOFS[i]}/∂{DOFS[j]} at the solution",
                    "statics",
                    lambda c, i=i, j=j: c.statics.stiffness[: c.n, i, j],
                )
            )
    out += [
        Quantity("converged", "bool", "the case converged", "statics", lambda c: _first(c.converged, c.n)),
        Quantity(
            "iterations", "count", "Newton iterations", "statics", lambda c: _first(c.statics.iterations, c.n)
        ),
    ]
    for name in rows:
        out += [
            Quantity(
                f"{name}_radial_load_N",
                "N",
                f"radial force row {name!r} carries",
                "statics",
                lambda c, r=name: np.hypot(*c.statics.row_load(r)[: c.n, :2].T),
            ),
            Quantity(
                f"{name}_axial_load_N",
                "N",
                f"axial force row {name!r} carries (signed, along +z)",
                "statics",
                lambda c, r=name: c.statics.row_load(r)[: c.n, 2],
            ),
        ]
    if len(rows) > 1:
        for name in rows:
            out += [
                Quantity(
                    f"{name}_radial_share",
                    "-",
                    f"share of the rows' radial forces row {name!r} carries",
                    "statics",
                    lambda c, r=name, rows=tuple(rows): _share(c, r, rows, "radial"),
                ),
                Quantity(
                    f"{name}_axial_share",
                    "-",
                    f"share of the rows' |axial forces| row {name!r} carries",
                    "statics",
                    lambda c, r=name, rows=tuple(rows): _share(c, r, rows, "axial"),
                ),
            ]
    return out


def _share(c: _Context, row: str, rows: Sequence[str], what: str) -> np.ndarray:
    def size(r):
        f = c.statics.row_load(r)[: c.n]
        return np.hypot(f[:, 0], f[:, 1]) if what == "radial" else np.abs(f[:, 2])

    total = sum(size(r) for r in rows)
    mine = size(row)
    return np.divide(mine, total, out=np.full_like(total, np.nan), where=total > 0)


def _row_state(c: _Context, name: str):
    return c.statics.row(name)


def _contact_angle(c: _Context, name: str) -> np.ndarray:
    state = _row_state(c, name)
    load = state.load[: c.n]
    k = np.argmax(load, axis=1)
    angle = np.asarray(np.broadcast_to(state.contact_angle, state.load.shape))[: c.n]
    return np.take_along_axis(angle, k[:, None], axis=1)[:, 0]


def _rows(rows: Sequence[str]) -> list[Quantity]:
    out = []
    for name in rows:
        out += [
            Quantity(
                f"{name}_max_load_N",
                "N",
                f"largest element load of row {name!r}",
                "rows",
                lambda c, r=name: _row_state(c, r).max_load[: c.n],
            ),
            Quantity(
                f"{name}_max_pressure_Pa",
                "Pa",
                f"largest contact pressure of row {name!r}",
                "rows",
                lambda c, r=name: _row_state(c, r).max_pressure[: c.n].max(axis=-1),
            ),
            Quantity(
                f"{name}_loaded_count",
                "count",
                f"elements of row {name!r} in contact",
                "rows",
                lambda c, r=name: _row_state(c, r).loaded_count[: c.n],
            ),
            Quantity(
                f"{name}_contact_angle_rad",
                "rad",
                f"operating contact angle of the most loaded element of row {name!r}",
                "rows",
                lambda c, r=name: _contact_angle(c, r),
            ),
        ]
    out += [
        Quantity(
            "max_load_N",
            "N",
            "largest element load of the bearing",
            "rows",
            lambda c: np.max([_row_state(c, r).max_load[: c.n] for r in rows], axis=0),
        ),
        Quantity(
            "max_pressure_Pa",
            "Pa",
            "largest contact pressure of the bearing",
            "rows",
            lambda c: np.max([_row_state(c, r).max_pressure[: c.n].max(axis=-1) for r in rows], axis=0),
        ),
    ]
    return out


def _edge_ratio(c: _Context, name: str) -> np.ndarray:
    """Largest end-slice pressure over the row's largest slice pressure (what the edge-loading flag tests)."""
    ex = _row_state(c, name).extras
    p = np.maximum(ex["slice_pressure_inner"], ex["slice_pressure_outer"])[: c.n]
    p_row = p.max(axis=(-2, -1))
    p_end = np.maximum(p[..., 0], p[..., -1]).max(axis=-1)
    return np.divide(p_end, p_row, out=np.full_like(p_row, np.nan), where=p_row > 0)


def _edges(sliced: Sequence[str]) -> list[Quantity]:
    return [
        Quantity(
            f"{name}_edge_pressure_ratio",
            "-",
            f"largest end-slice pressure over the largest slice pressure of row {name!r} (edge loading "
            "when it reaches the rating's edge_pressure_ratio)",
            "rows",
            lambda c, r=name: _edge_ratio(c, r),
        )
        for name in sliced
    ]


def _flag(c: _Context, row: str, flag: str) -> np.ndarray:
    rating = _rating(c)
    if rating is None:
        return np.zeros(c.n, bool)
    return np.asarray(rating.row(row).flags.get(flag, np.zeros(rating.n_cases, bool)), bool)[: c.n]


def _flags(rows) -> list[Quantity]:
    """Rating flags per row: static overload; truncated ellipse (ball rows), edge loading (sliced rollers)."""
    out = []
    for row in rows:
        names = ["static_overload"]
        if row.kind == "ball":
            names.append("truncated_ellipse")
        if row.kind in ("cylindrical", "tapered") and int(getattr(row, "n_slices", 1)) > 1:
            names.append("edge_loading")
        out += [
            Quantity(
                f"{row.name}_{flag}",
                "bool",
                f"rating flag {flag.replace('_', ' ')} of row {row.name!r}",
                "rating",
                lambda c, r=row.name, f=flag: _flag(c, r, f),
            )
            for flag in names
        ]
    return out


def _rating(c: _Context):
    # a [structure]'s outputs are the coupled solution's (as the statics above), its lives and s0 too
    flexible = getattr(c.analysis, "flexible_rating", None)
    return flexible if flexible is not None else c.analysis.rating


def _rated(c: _Context, get) -> np.ndarray:
    rating = _rating(c)
    if rating is None:
        return np.full(c.n, np.nan)
    return get(rating)


def _ratings(rows: Sequence[str]) -> list[Quantity]:
    out = [
        Quantity(
            "L10r_rev",
            "rev",
            "basic reference rating life of the bearing (ISO/TS 16281, from the load distribution)",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.life, c.n)),
        ),
        Quantity(
            "L10r_h",
            "h",
            "L10r in hours at the case's speed",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.hours(r.life), c.n)),
        ),
        Quantity(
            "Lnr_rev",
            "rev",
            "L10r at the analysis's reliability (a1 L10r)",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.life_reliability, c.n)),
        ),
        Quantity(
            "Lnmr_rev",
            "rev",
            "modified reference rating life a1 a_ISO L10r (ISO/TS 16281; needs a lubricant, e_C and a speed)",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.modified_life, c.n)),
        ),
        Quantity(
            "Lnmr_h",
            "h",
            "L_nmr in hours at the case's speed",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.hours(r.modified_life), c.n)),
        ),
        Quantity(
            "s0",
            "-",
            "static safety factor of the bearing (ISO 76, from the largest contact pressure)",
            "rating",
            lambda c: _rated(c, lambda r: _masked(r.static_safety, c.n)),
        ),
    ]
    for name in rows:
        out += [
            Quantity(
                f"{name}_L10r_rev",
                "rev",
                f"basic reference rating life of row {name!r}",
                "rating",
                lambda c, n=name: _rated(c, lambda r: _masked(r.row(n).life, c.n)),
            ),
            Quantity(
                f"{name}_s0",
                "-",
                f"static safety factor of row {name!r}",
                "rating",
                lambda c, n=name: _rated(c, lambda r: _masked(r.row(n).static_safety, c.n)),
            ),
            Quantity(
                f"{name}_a_ISO",
                "-",
                f"life modification factor a_ISO of row {name!r} (ISO 281 9.3)",
                "rating",
                lambda c, n=name: _rated(c, lambda r: _masked(r.row(n).life_modification, c.n)),
            ),
        ]
    return out


def _warnings() -> list[Quantity]:
    return [
        Quantity(
            "warnings_count",
            "count",
            "warnings of the case (statics and ratings: non-convergence, overload, edge loading …)",
            "rating",
            lambda c: np.array([len(w) for w in c.analysis.warnings[: c.n]], dtype=int),
        )
    ]


def _below(c: _Context, rows, get, combine) -> np.ndarray:
    """``combine`` over rows of ``get(row result)[:n]`` of the analysis's subsurface check; NaN if none."""
    sub = c.analysis.subsurface
    values = [np.asarray(get(r), float)[: c.n] for r in sub.rows if r.name in rows]
    return combine(values, axis=0) if values else np.full(c.n, np.nan)


def _truncation_safety(c: _Context, rows) -> np.ndarray:
    values = [t.safety[: c.n] for t in c.analysis.truncation.rows if t is not None and t.name in rows]
    if not values:
        return np.full(c.n, np.nan)
    low = np.min(values, axis=0)
    return np.where(np.isfinite(low), low, np.nan)


def _subsurface(model_rows) -> list[Quantity]:
    """Subsurface maxima and the hardened-layer check (docs/subsurface.md), of the bearing and per row."""
    names = tuple(r.name for r in model_rows if r.kind != "threaded")
    balls = tuple(r.name for r in model_rows if r.kind in ("ball", "four_point", "self_aligning_ball"))

    def quantities(suffix: str, rows: tuple, who: str) -> list[Quantity]:
        out = [
            Quantity(
                f"{suffix}max_von_mises_Pa",
                "Pa",
                f"largest von Mises stress below the contacts of {who} (subsurface, frictionless)",
                "subsurface",
                lambda c, r=rows: _below(c, r, lambda s: s.max_von_mises[0], np.max),
            ),
            Quantity(
                f"{suffix}case_safety",
                "-",
                f"case safety of {who}: yield strength from hardness over von Mises stress below the "
                "hardened surface (NaN through-hardened)",
                "subsurface",
                lambda c, r=rows: _below(c, r, lambda s: s.case.case_safety, np.fmin.reduce),
            ),
        ]
        if set(rows) & set(balls):
            out.append(
                Quantity(
                    f"{suffix}truncation_safety",
                    "-",
                    f"track-truncation safety of {who}: shoulder height over the height the ellipses need",
                    "subsurface",
                    lambda c, r=rows: _truncation_safety(c, r),
                )
            )
        return out

    out = quantities("", names, "the bearing")
    if len(names) > 1:
        for name in names:
            out += quantities(f"{name}_", (name,), f"row {name!r}")
    return out


def catalogue(bearing) -> dict[str, Quantity]:
    """Every output the generic evaluator offers for ``bearing`` (a BearingInput), by name.

    Lubrication and friction outputs need a lubricant (the file's, or ``lubricant.name`` set by the
    study; NaN without one); duty-cycle outputs are offered when the input has a ``[[duty_cycle]]``.
    """
    rows = [r.name for r in bearing.model.rows]
    sliced = [
        r.name
        for r in bearing.model.rows
        if r.kind in ("cylindrical", "tapered") and int(getattr(r, "n_slices", 1)) > 1
    ]
    from bearingkit.studies.generic.lives import duty_quantities, iso281_quantities

    items = (
        iso281_quantities(Quantity, _rated, _masked)
        + _statics(rows)
        + _groups(bearing.model.rows)
        + _rows(rows)
        + _edges(sliced)
    )
    items += _ratings(rows)
    items += _flags(bearing.model.rows)
    items += _subsurface(bearing.model.rows)
    items += _warnings()
    from bearingkit.studies.generic.limits import limit_quantities
    from bearingkit.studies.generic.lubricated import lubricated_quantities

    items += limit_quantities(Quantity)  # speed and load limits (NaN where no catalogue rule covers it)
    items += lubricated_quantities(Quantity, rows)  # NaN without a lubricant (a study may set lubricant.name)
    cycle = getattr(bearing, "duty_cycle", None)
    if cycle is not None:
        items += duty_quantities(Quantity, cycle.names)
    return {q.name: q for q in items}


def parts_of(quantities) -> set[str]:
    """The Analysis parts the given quantities need."""
    return {q.part for q in quantities}


def extract(analysis, n: int, quantities, duty: dict | None = None) -> dict[str, np.ndarray]:
    """Read ``quantities`` (Quantity objects) of the first ``n`` cases of ``analysis`` → name → (n,)."""
    ctx = _Context(analysis, n, duty)
    return {q.name: np.asarray(q.get(ctx)) for q in quantities}
