"""Base-oil types (mineral, PAO, ester, PAG): pressure–viscosity law and typical properties.

SI units: α in 1/Pa, η in Pa·s, ρ in kg/m³, k in W/(m·K), c_p in J/(kg·K). The data and their sources
are in ``bearingkit/data/base_oils.csv`` (one row per type, tagged with how far it was verified).

Pressure–viscosity coefficient (Barus α) as a power law of the dynamic viscosity at the same
temperature and atmospheric pressure:

.. math:: \\alpha(T) = s\\,\\bigl(\\eta(T) / 1\\,\\mathrm{Pa\\,s}\\bigr)^{t}

the form of Gold et al. (2001) and ISO/TR 15144-1 [M], with s, t per type fitted to published
measurements (data file). Because η falls with temperature, α falls too: for a mineral oil from
2.4e-8 1/Pa at 40 °C (ISO VG 68) to 1.7e-8 1/Pa at 100 °C, as the measurements of Stachowiak &
Batchelor's Table 2.3 do. At equal viscosity a PAO, an ester or a PAG has about 0.6 of a mineral oil's
α, hence a thinner EHL film.
"""

from __future__ import annotations

import difflib

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants.tables import rows

_TABLE = "base_oils.csv"
#: Unit of the viscosity in the power law [Pa·s].
ALPHA_VISCOSITY_UNIT = 1.0


def _table() -> dict[str, dict[str, str]]:
    return {r["base_oil"]: r for r in rows(_TABLE)}


#: The base-oil types bearingkit knows, in the data file's order.
BASE_OILS: tuple[str, ...] = tuple(_table())
#: Other spellings accepted for a base oil (lower case) → the type's key.
BASE_OIL_ALIASES = {
    "polyalphaolefin": "pao",
    "poly-alpha-olefin": "pao",
    "synthetic_hydrocarbon": "pao",
    "polyglycol": "pag",
    "polyalkylene_glycol": "pag",
    "glycol": "pag",
    "esters": "ester",
    "minerals": "mineral",
}


def base_oil_key(value, field: str = "base_oil") -> str:
    """The key of base oil ``value`` (case-insensitive, aliases accepted); one-line InputError otherwise."""
    if isinstance(value, str):
        key = value.strip().lower().replace(" ", "_")
        key = BASE_OIL_ALIASES.get(key, key)
        if key in BASE_OILS:
            return key
    near = difflib.get_close_matches(str(value).strip().lower(), [*BASE_OILS, *BASE_OIL_ALIASES], n=1)
    hint = f"; did you mean {BASE_OIL_ALIASES.get(near[0], near[0])}?" if near else ""
    raise InputError(f"{field} ({value!r}) must be one of {', '.join(BASE_OILS)}{hint}")


def base_oil_property(base_oil: str, column: str) -> float:
    """A numeric column of the base-oil table (``density_15C_kg_m3``, ``specific_heat_J_kgK`` …)."""
    return float(_table()[base_oil_key(base_oil)][column])


def ehl_class(base_oil: str) -> str:
    """SKF's μ_EHL class of a base oil: ``"mineral"`` or ``"synthetic"``."""
    return _table()[base_oil_key(base_oil)]["ehl_class"]


def pressure_viscosity_law(base_oil: str) -> tuple[float, float]:
    """(s [1/Pa], t [-]) of α = s (η / 1 Pa·s)^t for ``base_oil`` (module docstring)."""
    row = _table()[base_oil_key(base_oil)]
    return float(row["alpha_s_per_Pa"]), float(row["alpha_t"])


def pressure_viscosity(viscosity, base_oil: str):
    """Barus pressure–viscosity coefficient α [1/Pa] of a ``base_oil`` of dynamic viscosity η.

    .. math:: \\alpha = s\\,(\\eta / 1\\,\\mathrm{Pa\\,s})^{t}

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity η at atmospheric pressure and the temperature of interest [Pa·s], > 0.
    base_oil : str
        One of :data:`BASE_OILS`.

    Returns
    -------
    ndarray
        α [1/Pa].

    References
    ----------
    Gold P.W. et al. (2001) J. Synth. Lubr. 18(1):51–79 (the power-law form) [M]; s, t fitted to
    Stachowiak & Batchelor, Engineering Tribology, Table 2.3 (mineral) and Jones et al. (1975) NASA
    TN D-8005 (PAO, ester) — ``data/base_oils.csv``.
    """
    checks.positive("viscosity", viscosity, "Pa*s")
    s, t = pressure_viscosity_law(base_oil)
    return s * (np.asarray(viscosity, dtype=float) / ALPHA_VISCOSITY_UNIT) ** t
