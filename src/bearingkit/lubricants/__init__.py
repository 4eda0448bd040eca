"""Lubricants as data: oils and greases, their viscosity–temperature law, presets and a library.

SI inside (m²/s, Pa·s, 1/Pa, kg/m³; temperatures in °C). The package, one idea per module:

- :mod:`~bearingkit.lubricants.walther` — ASTM D341 (Walther) ν–T law;
- :mod:`~bearingkit.lubricants.viscosity_index` — ASTM D2270 viscosity index both ways;
- :mod:`~bearingkit.lubricants.base_oils` — base-oil types (mineral, PAO, ester, PAG): the
  pressure–viscosity law α(η) and typical properties, sourced in ``data/base_oils.csv``;
- :mod:`~bearingkit.lubricants.model` — :class:`Lubricant` (and :class:`Grease`): properties at
  temperature (ν, η, ρ, α, β);
- :mod:`~bearingkit.lubricants.presets` — the ISO VG and seed presets (:data:`LUBRICANTS`);
- :mod:`~bearingkit.lubricants.library` — typical oils and greases (``data/lubricant_library.csv``);
- :mod:`~bearingkit.lubricants.forms` — every form a lubricant is given in (name, fields, text) → one
  :class:`Lubricant` (:func:`as_lubricant`, :func:`lubricant_from_fields`), shared by every face.

docs/lubricants.md describes the forms and the sources.
"""

from bearingkit.lubricants.base_oils import BASE_OILS, pressure_viscosity
from bearingkit.lubricants.forms import (
    FIELDS,
    ISO_VG_GRADES,
    as_lubricant,
    fields_from_text,
    lubricant_from_fields,
    lubricant_names,
    named_lubricant,
)
from bearingkit.lubricants.library import LIBRARY
from bearingkit.lubricants.model import GREASE_LIFE_CLASSES, NLGI_CLASSES, THICKENERS, Grease, Lubricant
from bearingkit.lubricants.presets import LUBRICANTS, REFERENCE_KEYS, SEED_LUBRICANTS, get_lubricant
from bearingkit.lubricants.viscosity_index import nu100_from_vi, viscosity_index
from bearingkit.lubricants.walther import (
    WALTHER_TEMPERATURE_MAX_C,
    WALTHER_TEMPERATURE_MIN_C,
    walther_coefficients,
    walther_kinematic_viscosity,
)

__all__ = [
    "BASE_OILS",
    "FIELDS",
    "GREASE_LIFE_CLASSES",
    "ISO_VG_GRADES",
    "LIBRARY",
    "LUBRICANTS",
    "NLGI_CLASSES",
    "REFERENCE_KEYS",
    "SEED_LUBRICANTS",
    "THICKENERS",
    "WALTHER_TEMPERATURE_MAX_C",
    "WALTHER_TEMPERATURE_MIN_C",
    "Grease",
    "Lubricant",
    "as_lubricant",
    "fields_from_text",
    "get_lubricant",
    "lubricant_from_fields",
    "lubricant_names",
    "named_lubricant",
    "nu100_from_vi",
    "pressure_viscosity",
    "viscosity_index",
    "walther_coefficients",
    "walther_kinematic_viscosity",
]
