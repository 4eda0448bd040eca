"""What the page sends, as data: the bearing it opened and the edits of its form, turned into an input file.

SI inside; the form's values are text with units (``"5 kN"``, ``"3000 rpm"``) and stay text here: they
are written into the input document (the dict a TOML file parses to) and parsed by the loader and its
schema, exactly as if they had been typed into a file. So the page's errors are the loader's one-line
messages, and the document is also what "download TOML" writes.

An uploaded file is parsed by :mod:`tomllib` (data only, never executed) and validated by
:func:`bearingkit.io.loader.from_dict`; its size is capped (:data:`MAX_TOML_BYTES`).
"""

from __future__ import annotations

import copy
import re
import tomllib
from pathlib import Path
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field

from bearingkit.app.common import TooLarge
from bearingkit.errors import InputError
from bearingkit.io import loader, schema
from bearingkit.paths import examples_dir

__all__ = [
    "DUTY_FIELDS",
    "EXAMPLES_DIR",
    "LOAD_FIELDS",
    "MAX_TOML_BYTES",
    "AnalyzeRequest",
    "FormText",
    "OpenRequest",
    "Opened",
    "Source",
    "StrictModel",
    "TooLarge",
    "bearing_type_of",
    "build_document",
    "clearance_fields",
    "duty_bins",
    "examples",
    "field_of",
    "open_source",
]

#: The example files (the repository's, or the copy a wheel installs: bearingkit.paths).
EXAMPLES_DIR = examples_dir()
#: Largest input file [bytes] the app reads or accepts as an upload. The largest example is ~5 kB; a
#: hand-written bearing file with many load cases stays far below 256 kB.
MAX_TOML_BYTES = 256 * 1024
#: Longest designation [characters] (the longest real ones, e.g. "7209 BECBM/P4 DB", have < 30).
MAX_DESIGNATION = 64
#: Load-case fields the form edits (the rest of the chosen case, e.g. eccentricity, is kept).
LOAD_FIELDS = ("F_x", "F_y", "F_z", "M_x", "M_y")
#: Friction models the page offers: every key of :data:`bearingkit.pipeline.FRICTION_MODELS` (a test holds
#: them equal); "auto" (the first, the default) is the model of the bearing's kind, named with its reason
#: in the result. A model that does not apply to the bearing is not computed and the notes say why.
FRICTION_CHOICES = ("auto", "components", "skf", "palmgren", "trb", "slewing")
#: Name of the one load case the page analyses when the file has none (a designation).
PAGE_CASE = "page"


class StrictModel(BaseModel):
    """Request models: unknown fields are errors (a typo in a client is not silently ignored)."""

    model_config = ConfigDict(extra="forbid", frozen=True)


class Source(StrictModel):
    """Where the bearing comes from: an example by file name, a designation, or an uploaded file's text."""

    kind: Literal["example", "designation", "upload"]
    name: str = Field(min_length=1, max_length=256)
    text: str | None = None  # its size is checked with the file's name in the message (TooLarge)


#: One value of the form (a number with its unit, a preset name): short text.
FormText = Annotated[str, Field(max_length=64)]
#: Fields of the lubricant editor (those of a file's [lubricant], bearingkit.lubricants.FIELDS).
LubricantField = Literal[
    "iso_vg", "nu_40", "nu_100", "vi", "base_oil", "thickener", "nlgi", "temperature_max"
]
#: Fields of the heat balance (those of a file's [thermal]).
ThermalField = Literal["ambient", "heat_dissipation", "oil_flow", "oil_inlet_temperature"]
#: Editor fields that are plain numbers in a file (TOML numbers, not text).
_NUMBER_FIELDS = ("iso_vg", "vi")


class OpenRequest(StrictModel):
    """Open a bearing."""

    source: Source


class AnalyzeRequest(StrictModel):
    """The page's state: a source plus the edits of the form (values as text with units; "" = not given)."""

    source: Source
    case: str | None = Field(None, max_length=256, description="The file's load case the form started from.")
    loads: dict[Literal["F_x", "F_y", "F_z", "M_x", "M_y", "eccentricity"], FormText] = Field(
        default_factory=dict
    )
    speed: FormText = ""
    temperature: FormText = ""
    geometry: dict[Annotated[str, Field(max_length=64)], FormText] = Field(default_factory=dict, max_length=8)
    lubricant: FormText = ""
    lubricant_data: dict[LubricantField, FormText] = Field(
        default_factory=dict, description="The lubricant editor: an oil's (or grease's) data."
    )
    heat: bool | None = Field(None, description="Heat balance on/off (None: as the file's [thermal]).")
    thermal: dict[ThermalField, FormText] = Field(default_factory=dict)
    contamination: FormText = ""
    friction_model: Literal[FRICTION_CHOICES] = "auto"
    subsurface: bool = Field(
        False,
        description="Stresses below the contacts and the hardened-layer check (always for a case-"
        "hardened raceway).",
    )


def _is_bearing_file(path: Path) -> bool:
    """A bearing input file (a ``[bearing]`` table), not a shaft or study file of the same folder."""
    from bearingkit.io.reading import read_text

    try:  # the bounded reader, as every file bearingkit reads (regular files, size, UTF-8)
        text = read_text(path)
        return len(text.encode("utf-8")) <= MAX_TOML_BYTES and "bearing" in tomllib.loads(text)
    except (InputError, tomllib.TOMLDecodeError, RecursionError):
        return False


def examples() -> list[str]:
    """File names of the example bearings (``dgbb_6209.toml`` …), sorted."""
    if not EXAMPLES_DIR.is_dir():
        return []
    return sorted(p.name for p in EXAMPLES_DIR.glob("*.toml") if p.is_file() and _is_bearing_file(p))


def _parse_toml(text: str, source: str) -> dict:
    size = len(text.encode("utf-8"))
    if size > MAX_TOML_BYTES:
        raise TooLarge(f"{source}: file too large ({size} bytes); at most {MAX_TOML_BYTES} bytes")
    from bearingkit.io.reading import parse_toml

    return parse_toml(text, source)  # nesting bounded before tomllib; the loader's one-line messages


def _source_document(source: Source) -> tuple[dict, str]:
    """(raw input document, name used in messages) of ``source``."""
    if source.kind == "example":
        if source.name not in examples():  # a name from the list, never a path
            raise InputError(f"example ({source.name!r}) is not one of {', '.join(examples()) or 'none'}")
        from bearingkit.io.reading import read_text

        path = EXAMPLES_DIR / source.name
        if path.stat().st_size > MAX_TOML_BYTES:
            raise TooLarge(f"{source.name}: file too large; at most {MAX_TOML_BYTES} bytes")
        return _no_named_files(_parse_toml(read_text(path), source.name), source.name), source.name
    if source.kind == "designation":
        name = " ".join(source.name.split())
        if not name or len(name) > MAX_DESIGNATION or not name.isprintable():
            raise InputError(
                f"designation ({source.name[:MAX_DESIGNATION]!r}) must be a bearing designation such as "
                "6205-2RS C3"
            )
        return {"bearing": {"designation": name}}, name
    name = Path(source.name).name or "upload.toml"  # only the base name, for messages and downloads
    if source.text is None:
        raise InputError(f"{name}: no file content received")
    return _no_named_files(_parse_toml(source.text, name), name), name


def _no_named_files(document: dict, name: str) -> dict:
    """``document``, refused when it names other files: a ``[structure.imported]`` FE export (its matrix
    and nodes). A file sent to the server cannot make it open another (as the shaft page's bearing files,
    looked up among the examples by name): the refusal comes before any path is looked at, so it says
    nothing about the server's files."""
    structure = document.get("structure")
    if isinstance(structure, dict) and "imported" in structure:
        raise InputError(
            f"{name}: structure.imported names files (its matrix and nodes), which the web app does not "
            "open: a file sent to the server cannot make it read another; analyse it with "
            "`bearingkit analyze FILE` (the files beside it)"
        )
    return document


def _case_of(document: dict, name: str | None, source: str) -> dict:
    """The raw ``[[load_cases]]`` table called ``name`` (the first when None; {} when there is none)."""
    cases = document.get("load_cases") or []
    if not isinstance(cases, list) or not all(isinstance(c, dict) for c in cases):
        raise InputError(f"{source}: load_cases must be an array of tables [[load_cases]]")
    if name is None:
        return dict(cases[0]) if cases else {}
    for c in cases:
        if c.get("name") == name:
            return dict(c)
    names = [c.get("name") for c in cases]
    raise InputError(f"{source}: case ({name!r}) not in the file; cases are {names}")


def clearance_fields(bearing_type: str | None) -> list[str]:
    """Geometry fields of ``bearing_type`` that are clearances (what the page lets the user override)."""
    model = schema.GEOMETRY_MODELS.get(bearing_type or "")
    if model is None:
        return []
    return [k for k in model.model_fields if k.startswith("clearance")]


def build_document(request: AnalyzeRequest) -> tuple[dict, str]:
    """The input document of the page's state and the source name for messages.

    One load case: the chosen case of the file (or a new one) with the form's loads, speed and
    temperature; the form's clearances in ``[geometry]``; the chosen lubricant in ``[lubricant]``.
    Empty form values leave the file's value (loads: an empty field is 0, as in a file).
    """
    document, source = _source_document(request.source)
    document = copy.deepcopy(document)
    base = _case_of(document, request.case, source)
    case = {k: v for k, v in base.items() if k not in (*LOAD_FIELDS, "eccentricity", "speed", "temperature")}
    case.setdefault("name", PAGE_CASE)
    for key in (*LOAD_FIELDS, "eccentricity"):
        value = request.loads.get(key, "").strip() if request.loads else base.get(key, "")
        if value:
            case[key] = value
    for key in ("speed", "temperature"):
        value = getattr(request, key).strip()
        if value:
            case[key] = value
    edited = any(case.get(k) != base.get(k) for k in (*LOAD_FIELDS, "eccentricity", "speed", "temperature"))
    if edited and base:  # the file's name would now describe another load (e.g. "radial_8.9kN" at 6 kN)
        case["name"] = f"{base.get('name', PAGE_CASE)} (edited)"
    document["load_cases"] = [case]
    if request.geometry:
        header = document.get("bearing") if isinstance(document.get("bearing"), dict) else {}
        allowed = clearance_fields(bearing_type_of(header))
        geometry = document.setdefault("geometry", {})
        if not isinstance(geometry, dict):
            raise InputError(f"{source}: geometry must be a table [geometry]")
        for key, value in request.geometry.items():
            if key not in allowed:
                raise InputError(
                    f"{source}: geometry.{key}: the page edits only clearances "
                    f"({', '.join(allowed) or 'none for this bearing type'})"
                )
            if value.strip():
                geometry[key] = value.strip()
    _lubricant_table(document, request, source)
    _thermal_table(document, request, case, source)
    return document, source


def _lubricant_table(document: dict, request: AnalyzeRequest, source: str) -> None:
    """``[lubricant]`` from the chosen name and the editor's data (given fields replace the entry's)."""
    data = {k: v.strip() for k, v in request.lubricant_data.items() if v.strip()}
    for key in _NUMBER_FIELDS:
        if key in data:
            try:
                data[key] = float(data[key])
            except ValueError:
                raise InputError(f"{source}: lubricant.{key} ({data[key]!r}) must be a number") from None
    name = request.lubricant.strip()
    if not name and not data:
        return
    own = document.get("lubricant") if isinstance(document.get("lubricant"), dict) else {}
    table = {"name": name} if name else dict(own)  # the editor's fields replace the entry's
    table.update(data)
    document["lubricant"] = table


def _thermal_table(document: dict, request: AnalyzeRequest, case: dict, source: str) -> None:
    """``[thermal]`` when the heat balance is on (the page's switch; None keeps the file's)."""
    if request.heat is False:
        document.pop("thermal", None)
        return
    if request.heat is None and "thermal" not in document:
        return
    own = document.get("thermal") if isinstance(document.get("thermal"), dict) else {}
    document["thermal"] = {**own, **{k: v.strip() for k, v in request.thermal.items() if v.strip()}}
    if case.get("temperature"):
        raise InputError(
            f"{source}: temperature ({case['temperature']!r}): the heat balance finds the operating "
            "temperature; clear the temperature or switch the heat balance off"
        )


def bearing_type_of(header: dict) -> str | None:
    """The bearing type of a header, resolving a designation through the catalogue."""
    if header.get("type"):
        return header["type"]
    if header.get("designation"):
        from bearingkit.catalogue import resolve

        try:
            return resolve(str(header["designation"])).bearing_type
        except InputError:
            return None
    return None


class Opened(BaseModel):
    """What the page needs to show a freshly opened bearing (and fill its form)."""

    source: str
    bearing_name: str
    bearing_type: str
    description: str
    cases: list[dict]
    clearances: dict[str, str]
    lubricant: str | None
    free_dofs: list[str]
    thermal: bool = False
    designation: str | None = None
    duty_cycle: list[dict] = []
    duty_fraction: Literal["time", "revolution"] = "time"


def _text(value) -> str:
    """A document value as the form shows it: the file's own text (a valid file gives units as text)."""
    return "" if value is None else str(value)


def open_source(source: Source) -> Opened:
    """Load ``source`` (validating it whole) and describe it for the form."""
    document, name = _source_document(source)
    bearing = loader.from_dict(copy.deepcopy(document), source=name)
    raw_cases = document.get("load_cases") or []
    cases = []
    for raw in raw_cases:
        entry = {"name": raw.get("name", "")}
        for key in (*LOAD_FIELDS, "eccentricity", "speed", "temperature"):
            entry[key] = _text(raw.get(key))
        cases.append(entry)
    given = document.get("geometry") or {}
    clearances = {}
    for key in clearance_fields(bearing.bearing_type):
        if key in given:
            clearances[key] = _text(given[key])
        else:  # estimated (designation) or the builder's default: shown in µm, not sent back unless edited
            value = getattr(bearing.geometry, key, None)
            clearances[key] = "" if value is None else f"{value * 1e6:.6g} um"
    free = [n for n, f in zip(loader.DOF_NAMES, bearing.free, strict=True) if f]
    header = document.get("bearing") if isinstance(document.get("bearing"), dict) else {}
    bins, fraction = duty_bins(document)
    return Opened(
        source=name,
        bearing_name=bearing.model.name,
        bearing_type=bearing.bearing_type,
        description=bearing.spec.bearing.source or "",
        cases=cases,
        clearances=clearances,
        lubricant=None if bearing.lubricant is None else bearing.lubricant.name,
        free_dofs=free,
        thermal="thermal" in document,
        designation=header.get("designation") if isinstance(header.get("designation"), str) else None,
        duty_cycle=bins,
        duty_fraction=fraction,
    )


#: Fields of a duty-cycle bin the page edits (besides its name and its share).
DUTY_FIELDS = (*LOAD_FIELDS, "speed", "temperature")


def duty_bins(document: dict) -> tuple[list[dict], str]:
    """The file's ``[[duty_cycle]]`` bins as the duty page shows them (texts) and their share's kind."""
    raw = document.get("duty_cycle") or []
    bins = []
    kind = "revolution" if any(isinstance(b, dict) and "revolution_fraction" in b for b in raw) else "time"
    for b in raw:
        if not isinstance(b, dict):
            continue
        entry = {"name": _text(b.get("name"))}
        entry.update({k: _text(b.get(k)) for k in DUTY_FIELDS})
        entry["fraction"] = _text(b.get(f"{kind}_fraction"))
        bins.append(entry)
    return bins, kind


#: A loader message's field: ``SOURCE: load_cases[0].F_x (…)`` or ``load case 'x': M_x (…) acts on …``.
_PATH = re.compile(r"^(?:load_cases\[\d+\]\.)?([A-Za-z_][\w.]*)")
_CASE_FIELD = re.compile(r"load case '[^']*': (\w+) \(")


def field_of(message: str, source: str) -> str:
    """The form field an error message is about (``load.F_x``, ``speed``, ``geometry.clearance_radial``,
    ``lubricant``, ``contamination``), or ``source`` for the bearing itself."""
    text = message[len(source) + 2 :] if message.startswith(f"{source}: ") else message
    m = _CASE_FIELD.search(text)
    if m and m.group(1) in LOAD_FIELDS:
        return f"load.{m.group(1)}"
    if text.startswith("load_cases"):
        m = _PATH.match(text)
        key = m.group(1) if m else ""
        if key in (*LOAD_FIELDS, "eccentricity"):
            return f"load.{key}"
        if key in ("speed", "temperature"):
            return key
        return "source"
    m = _PATH.match(text)
    head = m.group(1) if m else ""
    if head.startswith("geometry.clearance"):
        return head
    if head.startswith("lubricant"):
        return "lubricant"
    if head.startswith("thermal") or text.startswith("heat balance"):
        return "thermal"
    if head in ("speed", "temperature", "contamination"):
        return head
    return "source"
