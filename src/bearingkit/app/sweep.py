"""A one-factor sweep of the page's bearing: a load component, speed, temperature or a clearance.

SI inside. The factor's values are spaced evenly between two texts with units and written back into
the input document as text in SI (``"6000.0 N"``), so the loader parses them as any file value. Loads,
speed and temperature vary per load case: the whole sweep is ONE analysis of N load cases (one
batched solve). A clearance changes the bearing itself: one analysis per value. The outputs are read
from each :class:`~bearingkit.pipeline.Analysis` (``to_dict``); nothing is recomputed here.
"""

from __future__ import annotations

import copy
from typing import Literal

import numpy as np
from pydantic import Field

from bearingkit.app.form import (
    LOAD_FIELDS,
    AnalyzeRequest,
    StrictModel,
    bearing_type_of,
    build_document,
    clearance_fields,
)
from bearingkit.errors import InputError
from bearingkit.units import SI_UNITS, parse

__all__ = ["MAX_POINTS", "SweepRequest", "run_sweep"]

#: Most values of one sweep (each a load case; a clearance sweep is one analysis per value).
MAX_POINTS = 50
#: Per-case factors → dimension of their values (clearances: ``geometry.<field>``, a length).
CASE_FACTORS = {
    **{k: "force" for k in LOAD_FIELDS[:3]},
    **{k: "moment" for k in LOAD_FIELDS[3:]},
    "speed": "angular_velocity",
    "temperature": "temperature",
}


class SweepRequest(StrictModel):
    """Sweep ``factor`` from ``start`` to ``stop`` (texts with units) in ``n`` evenly spaced values."""

    base: AnalyzeRequest
    factor: str = Field(max_length=64)
    start: str = Field(max_length=64)
    stop: str = Field(max_length=64)
    n: int = Field(ge=2, le=MAX_POINTS)
    spacing: Literal["linear"] = "linear"


def _dimension(factor: str, bearing_type: str | None) -> str:
    if factor in CASE_FACTORS:
        return CASE_FACTORS[factor]
    if factor.startswith("geometry.") and factor.removeprefix("geometry.") in clearance_fields(bearing_type):
        return "length"
    choices = [*CASE_FACTORS, *(f"geometry.{c}" for c in clearance_fields(bearing_type))]
    raise InputError(f"sweep factor ({factor!r}) must be one of {', '.join(choices)}")


def _outputs(case: dict) -> dict:
    """The plotted outputs of one analysed case (``Analysis.to_dict()['cases'][i]``); None = not available."""
    rows = case.get("rows", [])
    rating = (case.get("rating") or {}).get("system", {})
    friction = case.get("friction") or {}
    return {
        "converged": bool(case.get("converged")),
        "max_load_N": max((r["max_load_N"] for r in rows), default=None),
        "max_pressure_Pa": max((r["max_pressure_Pa"] for r in rows), default=None),
        "L10r_rev": rating.get("L10r_rev"),
        "L10h_h": rating.get("L10h_h"),
        "Lnmr_h": rating.get("Lnmr_h"),
        "static_safety": rating.get("static_safety"),
        "friction_torque_Nm": friction.get("total_Nm"),
        "power_loss_W": friction.get("power_loss_W"),
        "warnings": len(case.get("warnings", [])),
    }


def run_sweep(request: SweepRequest, analyze) -> dict:
    """Run the sweep; ``analyze(document, source, request)`` is the server's one way to analyse a document.

    Returns
    -------
    dict
        ``factor``, ``unit`` (SI), ``values`` [SI], ``outputs`` (one dict per value), ``analyses``
        (how many analyses it took: 1 for per-case factors), ``notes``.
    """
    document, source = build_document(request.base)
    header = document.get("bearing")
    bearing_type = bearing_type_of(header) if isinstance(header, dict) else None
    dimension = _dimension(request.factor, bearing_type)
    field = f"sweep {request.factor}"
    lo = parse(request.start, dimension, f"{field} from")
    hi = parse(request.stop, dimension, f"{field} to")
    values = np.linspace(lo, hi, request.n)
    unit = "degC" if dimension == "temperature" else SI_UNITS[dimension]
    as_text = [f"{v!r} {unit}".strip() for v in values.tolist()]
    base_case = document["load_cases"][0]
    if request.factor in CASE_FACTORS:
        doc = copy.deepcopy(document)
        doc["load_cases"] = [
            {**base_case, "name": f"{request.factor}={t}", request.factor: t} for t in as_text
        ]
        analysis = analyze(doc, source, request.base)
        cases = analysis.to_dict()["cases"]
        notes, n_analyses = analysis.notes, 1
    else:
        key = request.factor.removeprefix("geometry.")
        cases, notes = [], []
        for t in as_text:
            doc = copy.deepcopy(document)
            doc.setdefault("geometry", {})[key] = t
            analysis = analyze(doc, source, request.base)
            cases.append(analysis.to_dict()["cases"][0])
            notes = analysis.notes
        n_analyses = len(as_text)
    return {
        "factor": request.factor,
        "unit": "°C" if dimension == "temperature" else SI_UNITS[dimension],
        "dimension": dimension,
        "values": values.tolist(),
        "outputs": [_outputs(c) for c in cases],
        "analyses": n_analyses,
        "notes": list(notes),
    }
