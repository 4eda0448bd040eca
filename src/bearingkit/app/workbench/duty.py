"""The duty-cycle page: the bins of a load spectrum in a table, rated in one batch, combined by Miner.

SI inside; a bin's values are text with units written into the input document's ``[[duty_cycle]]``
exactly as a file gives them, so the loader validates them and its one-line messages name the bin and
the field. The bearing and its settings (lubricant, e_C, friction model …) are the bearing page's
request; the result is :attr:`bearingkit.pipeline.Analysis.duty_cycle` (``to_dict``): every bin's life,
static safety and damage share and the Palmgren–Miner life (:mod:`bearingkit.pipeline.duty_cycle`).
"""

from __future__ import annotations

import re
from typing import Literal

from pydantic import Field

from bearingkit.app.form import DUTY_FIELDS, AnalyzeRequest, FormText, StrictModel, build_document, field_of
from bearingkit.errors import InputError

__all__ = ["MAX_BINS", "DutyBin", "DutyRequest", "duty_document", "duty_field"]

#: Bins the page edits at most (a file may hold more:
#: :data:`bearingkit.io.optional_sections.cycle.MAX_DUTY_BINS`).
MAX_BINS = 50


class DutyBin(StrictModel):
    """One row of the table: a name, a load case's fields (texts with units) and its share."""

    name: str = Field("", max_length=64)
    values: dict[Literal[DUTY_FIELDS], FormText] = Field(default_factory=dict)
    fraction: FormText = ""


class DutyRequest(StrictModel):
    """The bearing page's state and the table's bins (shares of the time or of the revolutions)."""

    base: AnalyzeRequest
    bins: list[DutyBin] = Field(min_length=1, max_length=MAX_BINS)
    fraction: Literal["time", "revolution"] = "time"


def duty_document(request: DutyRequest) -> tuple[dict, str]:
    """The page's input document with the table as its ``[[duty_cycle]]`` (the file's own bins replaced)."""
    document, source = build_document(request.base)
    bins = []
    for i, b in enumerate(request.bins):
        entry = {"name": b.name.strip() or f"bin_{i + 1}"}
        entry.update({k: v.strip() for k, v in b.values.items() if v.strip()})
        text = b.fraction.strip()
        try:
            share = float(text)
        except ValueError:
            raise InputError(
                f"{source}: duty_cycle[{i}].{request.fraction}_fraction ({text!r}) must be a number "
                "between 0 and 1"
            ) from None
        entry[f"{request.fraction}_fraction"] = share
        bins.append(entry)
    document["duty_cycle"] = bins
    return document, source


_BIN = re.compile(r"duty_cycle\[(\d+)\]\.?(\w+)?")


def duty_field(message: str, source: str) -> str:
    """The table cell a message is about (``duty.2.F_x``, ``duty.0.fraction``), ``duty`` for the table
    as a whole, else the bearing page's field (:func:`bearingkit.app.form.field_of`)."""
    m = _BIN.search(message)
    if m:
        index, key = m.group(1), m.group(2) or ""
        if key.endswith("_fraction"):
            return f"duty.{index}.fraction"
        return f"duty.{index}.{key}" if key in (*DUTY_FIELDS, "name") else f"duty.{index}"
    if "duty_cycle" in message or "fraction" in message:
        return "duty"
    return field_of(message, source)
