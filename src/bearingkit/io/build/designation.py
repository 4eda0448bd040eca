"""A bearing file that gives ``bearing.designation``: the catalogue's type and estimated geometry,
overridden field by field by the file's own ``[geometry]``.

The estimate (:func:`bearingkit.catalogue.resolve`, SI floats) is written back as the input format's
strings with units so that the schema validates it exactly as if it had been typed into the file.
"""

from __future__ import annotations

import math

from bearingkit.errors import InputError
from bearingkit.io import schema

#: Geometry fields of the catalogue estimate that are angles (radians); other floats are lengths (m)
#: except the dimensionless conformities.
_CATALOGUE_ANGLES = ("contact_angle", "contact_angle_outer", "contact_angle_inner", "roller_angle")


#: Significant digits of an estimated value written back as text: far below any tolerance of the estimate
#: (its rules are good to a few per cent), far above the float round-off that would otherwise show as
#: ``0.015499999999999998 m`` in the inputs a user reads.
SHOWN_DIGITS = 12


def _catalogue_value(key: str, value):
    """A catalogue geometry value (SI) written as the input format expects it (string with unit), rounded
    to :data:`SHOWN_DIGITS` significant digits; angles in degrees (``"40 deg"``, not ``0.6981… rad``)."""
    if isinstance(value, (dict, str, int, bool)):
        return value
    if key.startswith(("conformity", "osculation")):
        return float(f"{float(value):.{SHOWN_DIGITS}g}")
    if key in _CATALOGUE_ANGLES:
        return f"{float(value) * 180.0 / math.pi:.{SHOWN_DIGITS}g} deg"
    return f"{float(value):.{SHOWN_DIGITS}g} m"


def from_designation(source: str, spec: schema.BearingFile) -> schema.BearingFile:
    """Type, geometry (estimate, overridden by the file's [geometry]), name and source from a designation."""
    from bearingkit.catalogue import resolve

    header = spec.bearing
    try:
        preload = _preload(header.preload)
        found = resolve(
            header.designation, C=header.C, clearance_position=header.class_position(), preload=preload
        )
    except InputError as exc:
        field = "bearing." if str(exc).startswith(("designation", "preload")) else ""
        raise InputError(f"{source}: {field}{exc}") from None
    if header.type and header.type != found.bearing_type:
        raise InputError(
            f"{source}: bearing.type ({header.type!r}) does not match designation {header.designation!r} "
            f"({found.bearing_type!r}); omit type"
        )
    geometry = {k: _catalogue_value(k, v) for k, v in found.geometry.items() if v is not None}
    geometry.update(spec.geometry)
    overridden = sorted(set(spec.geometry) & set(found.geometry))
    given = f"; given in the file, not estimated: {', '.join(overridden)}" if overridden else ""
    note = found.source + given
    bearing = header.model_copy(
        update={
            "type": found.bearing_type,
            "name": header.name or header.designation,
            "source": header.source or note,
        }
    )
    update = {"bearing": bearing, "geometry": geometry}
    operating = dict(spec.operating or {})
    if found.preload_force is not None:
        if "preload_force" in operating or "preload_displacement" in operating:
            note += "; [operating] preload of the file used, not the designation's class"
            bearing = bearing.model_copy(update={"source": header.source or note})
            update["bearing"] = bearing
        else:
            operating["preload_force"] = f"{found.preload_force!r} N"
            update["operating"] = operating
    return spec.model_copy(update=update)


def _preload(value: str | None):
    """``[bearing] preload``: a class name, or a force with its unit → N; None when not given."""
    from bearingkit.catalogue.suffixes import PRELOAD_CLASSES
    from bearingkit.units import parse

    if value is None or value in PRELOAD_CLASSES:
        return value
    try:
        return parse(value, "force", "preload")
    except InputError:
        raise InputError(
            f"preload ({value!r}) must be one of {', '.join(PRELOAD_CLASSES)} or a force such as '480 N'"
        ) from None
