"""Random light and combined loads on the TRB 32008J example and its DB/DF pairs (issue 24 item 6).

SI units. Shared by the test (tests/rows/test_tapered_light_loads.py: every case converges or is
refused as uncarriable, equilibrium holds) and the benchmark (benchmarks/bench_tapered_light.py:
time per case). The bearings are ``examples/trb_32008.toml`` as written (single row, seed 001's
eq. (4) deviation law with Table 2 series 1, tilts held) and the same rows paired back-to-back and
face-to-face (``arrangement = "DB"/"DF"``, ``row_spacing = 19 mm``, the 32008's width; all five DOF
free), with zero clearance and, for DB, also 10 µm preload.

Loads: |F| log-uniform from 1 N to 50 kN (moments counted as M/L, L the solver's length scale).
Single row (u_x, u_y, u_z free): its contact cone is F_z ≥ |F_r| tan α_e / cos(π/Z) (sufficient) and
F_z ≥ |F_r| tan α_e (necessary), α_e the cup angle: a case is drawn inside the first bound
(``carriable``) or outside the second (not carriable), never in the 2 % band around the boundary.
Pairs with free tilts carry every direction (the two rows' cones, about distinct pressure centres,
add up to all of R⁵), so every pair case is carriable.
"""

from __future__ import annotations

import copy
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "trb_32008.toml"
#: Smallest and largest |F| [N].
LOAD_RANGE = (1.0, 50_000.0)
#: Margin kept from the single row's cone boundary [-].
CONE_MARGIN = 1.02
#: Axial distance of the paired rows [m] (the 32008's width, 19 mm).
PAIR_SPACING = "19 mm"
#: Bearing variants: name → (arrangement, clearance or None for the file's).
VARIANTS = {
    "single": ("single", None),
    "DB": ("DB", None),
    "DF": ("DF", None),
    "DB_preload": ("DB", "-10 um"),
}


@dataclass
class LightCases:
    """One bearing variant and its random loads."""

    name: str
    input: object  # bearingkit.io.loader.BearingInput
    loads: np.ndarray  # (C, 5) [N, N, N, N·m, N·m]
    carriable: np.ndarray  # (C,) bool


def bearing(variant: str):
    """The example (``"single"``) or its pair as a :class:`bearingkit.io.loader.BearingInput`."""
    from bearingkit.io.loader import from_dict

    arrangement, clearance = VARIANTS[variant]
    data = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    data = copy.deepcopy(data)
    if arrangement != "single":
        data["geometry"]["arrangement"] = arrangement
        data["geometry"]["row_spacing"] = PAIR_SPACING
        data.pop("solver", None)  # pairs: all five DOF free
    if clearance is not None:
        data["geometry"]["clearance"] = clearance
    return from_dict(data, source=f"{EXAMPLE.name} [{variant}]")


def random_loads(variant: str, n: int, seed: int = 0) -> LightCases:
    """``n`` random loads on ``variant`` (see the module docstring)."""
    inp = bearing(variant)
    rng = np.random.default_rng(seed)
    kernels = inp.model.kernels
    length = max(k.char_length for k in kernels)
    magnitude = np.exp(rng.uniform(*np.log(LOAD_RANGE), size=n))
    if variant != "single":
        v = rng.normal(size=(n, 5))
        v /= np.linalg.norm(v, axis=1, keepdims=True)
        loads = v * magnitude[:, None]
        loads[:, 3:] *= length
        return LightCases(variant, inp, loads, np.ones(n, bool))
    row = inp.model.rows[0]
    tan_a, z = np.tan(row.contact_angle_outer), row.n_elements
    inside = np.cos(np.pi / z) / CONE_MARGIN  # largest |F_r| tan α_e / F_z drawn as carriable
    carriable = rng.random(n) < 0.75
    # ρ = |F_r| tan α_e / F_z: inside [0, inside] or outside [CONE_MARGIN, 4]; a quarter of the
    # uncarriable cases push the wrong way (F_z·direction < 0).
    rho = np.where(carriable, rng.uniform(0.0, inside, n), rng.uniform(CONE_MARGIN, 4.0, n))
    angle = rng.uniform(0.0, 2.0 * np.pi, n)
    f_z = 1.0 / np.sqrt(1.0 + (rho / tan_a) ** 2)
    f_r = rho / tan_a * f_z
    wrong_way = ~carriable & (rng.random(n) < 0.25)
    f_z = np.where(wrong_way, -f_z, f_z) * row.direction
    loads = np.zeros((n, 5))
    loads[:, 0] = f_r * np.cos(angle) * magnitude
    loads[:, 1] = f_r * np.sin(angle) * magnitude
    loads[:, 2] = f_z * magnitude
    return LightCases(variant, inp, loads, carriable)


def cases(n_per_variant: int, seed: int = 0) -> list[LightCases]:
    """Random loads for every variant of :data:`VARIANTS`."""
    return [random_loads(v, n_per_variant, seed + i) for i, v in enumerate(VARIANTS)]
