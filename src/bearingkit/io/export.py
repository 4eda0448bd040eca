"""JSON-ready dicts of results, SI values with the unit in every key (``max_load_N``, ``u_x_m``).

Faces (CLI, reports) call these; nothing here recomputes the mechanics: the load distribution comes
from :meth:`bearingkit.analysis.solver.quasistatic.QuasiStaticResult.to_dict`, the Hertz summary from
:func:`bearingkit.physics.contact.hertz.point_contact`. Output must never hold NaN or infinity:
:func:`to_json` refuses them (``allow_nan=False``) and :func:`non_finite_paths` lists offenders.
"""

from __future__ import annotations

import json
import math

import numpy as np


def case_dict(bearing, result, index: int) -> dict:
    """One solved load case: its name and operating point, then ``result.to_dict(index)``.

    Parameters
    ----------
    bearing : bearingkit.io.loader.BearingInput
    result : bearingkit.analysis.solver.quasistatic.QuasiStaticResult
        The solve of ``bearing.cases`` (same order).
    index : int
        Case index.
    """
    case = bearing.cases[index]
    return {**case.to_dict(), **result.to_dict(index)}


def analysis_dict(bearing, result) -> dict:
    """Every load case of a solve, with the file, bearing type, name and source (JSON-ready)."""
    return {
        "file": bearing.source,
        "bearing_type": bearing.bearing_type,
        "bearing_name": bearing.model.name,
        "source": bearing.spec.bearing.source,
        "free_dofs": [
            n for n, f in zip(("u_x", "u_y", "u_z", "theta_x", "theta_y"), bearing.free, strict=True) if f
        ],
        "cases": [case_dict(bearing, result, c) for c in range(result.n_cases)],
    }


def _header(bearing) -> dict:
    return {
        "file": bearing.source,
        "bearing_type": bearing.bearing_type,
        "bearing_name": bearing.model.name,
        "source": bearing.spec.bearing.source,
    }


def rating_dict(bearing, rating) -> dict:
    """Ratings and lives of every load case (``RatingResult.to_dict`` per case, case names added).

    Parameters
    ----------
    bearing : bearingkit.io.loader.BearingInput
    rating : bearingkit.analysis.rating.assembly.RatingResult
        Rating of the solve of ``bearing.cases`` (same order). Masked values are ``None``.
    """
    cases = [{"case": c.name, **rating.to_dict(i)} for i, c in enumerate(bearing.cases)]
    return {**_header(bearing), "cases": cases}


def friction_case_dict(case_name: str, operating_point, friction, index: int) -> dict:
    """One case of a friction calculation: operating point (SI) and ``{"friction": to_dict(index)}``.

    Parameters
    ----------
    case_name : str
    operating_point : bearingkit.analysis.friction.components.OperatingPoint
        Speeds [rad/s] (scalar or per case), lubricant, temperature [°C].
    friction : bearingkit.analysis.friction.components.FrictionResult
    index : int
        Case index in ``friction`` (and in per-case speeds of ``operating_point``).
    """
    op = operating_point

    def pick(v):
        a = np.asarray(v, dtype=float)
        return float(a if a.ndim == 0 else a[index])

    return {
        "case": case_name,
        "speed_inner_rad_s": pick(op.speed_inner),
        "speed_outer_rad_s": pick(op.speed_outer),
        "temperature_C": float(op.temperature),
        "lubricant": op.lubricant.name,
        "viscosity_factor": float(op.viscosity_factor),
        "cage_mass_kg": float(op.cage_mass),
        "friction": friction.to_dict(index),
    }


def engineering_friction_case_dict(case_name: str, result, index: int, speed, temperature) -> dict:
    """One case of an engineering friction model (SKF, Palmgren) in the layout of :func:`friction_case_dict`.

    Parameters
    ----------
    case_name : str
    result : bearingkit.analysis.friction.engineering.EngineeringFrictionResult
        Batched over the cases (leading axis).
    index : int
    speed : ndarray (C,) [rad/s]
        Relative ring speed.
    temperature : ndarray (C,) [°C]
    """

    def pick(v):
        a = np.asarray(v, dtype=float)
        return float(a if a.ndim == 0 else a[index])

    return {
        "case": case_name,
        "speed_rad_s": pick(speed),
        "temperature_C": pick(temperature),
        "friction": {
            "model": result.model,
            "bearing_type": result.bearing_type,
            "total_Nm": pick(result.total),
            "components_Nm": {k: pick(v) for k, v in result.components.items()},
            "references": list(result.references),
            "notes": list(result.notes),
        },
    }


def friction_dict(bearing, cases: list[dict]) -> dict:
    """Friction of every load case (dicts of :func:`friction_case_dict`, in the file's case order)."""
    return {**_header(bearing), "cases": cases}


def hertz_ball_summary(
    load, element_diameter, pitch_diameter, contact_angle, conformity_inner, conformity_outer, e_reduced
) -> dict:
    """Hertz contact of one ball with its inner and outer raceway (SI in, SI out, units in keys).

    Parameters
    ----------
    load : float [N]
        Ball load Q (the same on both contacts: the ball is in equilibrium between them).
    element_diameter : float [m]
    pitch_diameter : float [m]
    contact_angle : float [rad]
    conformity_inner, conformity_outer : float
        f = r / D_w of the grooves.
    e_reduced : float [Pa]
        E′ of ball and raceway.

    Returns
    -------
    dict
        ``{"load_N", "inner": {...}, "outer": {...}}`` with ``semi_major_m``, ``semi_minor_m``,
        ``deflection_m``, ``max_pressure_Pa``, ``ellipticity``, ``curvature_sum_1_m``,
        ``curvature_difference`` per contact (Harris & Kotzalas 2007 ch. 2 and 6 via
        :mod:`bearingkit.physics.contact.hertz`).
    """
    from bearingkit.physics.contact.hertz import ball_raceway_curvature, point_contact

    out = {"load_N": float(load)}
    for raceway, conformity in (("inner", conformity_inner), ("outer", conformity_outer)):
        s_rho, f_rho = ball_raceway_curvature(
            element_diameter, pitch_diameter, contact_angle, conformity * element_diameter, raceway
        )
        pc = point_contact(load, s_rho, f_rho, e_reduced)
        out[raceway] = {
            "curvature_sum_1_m": float(s_rho),
            "curvature_difference": float(f_rho),
            "semi_major_m": float(pc.semi_major),
            "semi_minor_m": float(pc.semi_minor),
            "deflection_m": float(pc.deflection),
            "max_pressure_Pa": float(pc.max_pressure),
            "ellipticity": float(pc.ellipticity),
        }
    return out


def non_finite_paths(obj, path: str = "") -> list[str]:
    """Paths of every NaN or infinite float inside nested dicts/lists (empty when all finite)."""
    if isinstance(obj, dict):
        return [p for k, v in obj.items() for p in non_finite_paths(v, f"{path}.{k}" if path else str(k))]
    if isinstance(obj, (list, tuple)):
        return [p for i, v in enumerate(obj) for p in non_finite_paths(v, f"{path}[{i}]")]
    if isinstance(obj, (float, np.floating)) and not math.isfinite(obj):
        return [path]
    return []


def to_json(obj, indent: int | None = 1) -> str:
    """JSON text; raises ValueError naming the first non-finite value instead of writing NaN."""
    bad = non_finite_paths(obj)
    if bad:
        raise ValueError(f"non-finite value in results at {bad[0]} ({len(bad)} in all)")
    return json.dumps(obj, indent=indent, allow_nan=False)


def write_atomic(path, write, what: str = "file"):
    """Write an output file through ``write(tmp_path)`` and rename it onto ``path``: all or nothing.

    The one writer of the files a command is asked for (reports, figures, tables): missing parent
    folders are created, the content goes to a temporary name in the same folder, flushed to disk
    by ``write`` (or closed by it), and is renamed onto ``path`` only when complete. On any error —
    a bad name, a full disk, an error of ``write`` itself — nothing is left behind: no partial file,
    no temporary file, no folder this call created (a refused command leaves no stray file).

    Parameters
    ----------
    path : path
        The file to write.
    write : callable
        ``write(tmp)`` writes the whole content to the path ``tmp``.
    what : str
        What the file is, for messages (``"report"``, ``"figure"``).

    Returns
    -------
    Path
        ``path``. An operating-system error becomes one :class:`~bearingkit.errors.InputError` line.
    """
    import os
    import tempfile
    from pathlib import Path

    from bearingkit.errors import InputError, os_reason, shown

    path = Path(path)
    if path.is_dir():
        raise InputError(
            f"{shown(path)}: the {what} path is a directory; give a file name such as "
            f"{shown(path / ('report.html' if what == 'report' else 'x'))}"
        )
    created: list = []
    tmp = None
    done = False
    try:
        missing, p = [], path.parent
        while not p.exists():
            missing.append(p)
            p = p.parent
        for d in reversed(missing):
            d.mkdir()
            created.append(d)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name[:100]}.", suffix=".tmp", dir=path.parent)
        os.close(fd)
        write(Path(tmp))
        os.replace(tmp, path)
        done = True
    except (OSError, ValueError) as exc:  # ValueError: a name with a NUL byte
        raise InputError(f"{shown(path)}: cannot write the {what}: {os_reason(exc)}") from None
    finally:
        if not done:
            if tmp is not None:
                Path(tmp).unlink(missing_ok=True)
            for d in reversed(created):
                try:
                    d.rmdir()
                except OSError:
                    pass
    return path
