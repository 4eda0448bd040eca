"""The catalogue commands: ``bearingkit catalogue`` (list and search) and ``bearingkit select`` (bearing
selection). Faces only: they call :mod:`bearingkit.catalogue.search` and
:func:`bearingkit.pipeline.selection.select` and print.

Lengths of the search options are millimetres when given as bare numbers (``--d 40``, the catalogues'
unit) or carry their unit (``--D-max 3.15in``); forces carry their unit (``--C-min 30kN``).
"""

from __future__ import annotations

import json
import sys

import typer

from bearingkit.cli.commands import app
from bearingkit.cli.common import _JSON_OPTION, _fail, console, one_line_errors
from bearingkit.errors import InputError


def _length(value: str | None, flag: str) -> float | None:
    """``40`` (mm) or ``40mm`` / ``1.5in`` → m."""
    from bearingkit.units import parse

    if value is None:
        return None
    try:
        return float(value) * 1e-3
    except ValueError:
        return parse(value, "length", flag)


def _force(value: str | None, flag: str) -> float | None:
    from bearingkit.units import parse

    return None if value is None else parse(value, "force", flag)


def _num(x, scale: float, fmt: str = ".3g") -> str:
    return "—" if x is None else format(x * scale, fmt)


def _hours(x) -> str:
    """Hours as whole numbers up to 10⁷ h, beyond in powers of ten (no '2.33e+04 h' for 23 300 h)."""
    return "—" if x is None else (f"{x:.0f}" if x < 1e7 else f"{x:.3g}")


@app.command()
@one_line_errors
def catalogue(
    pattern: str = typer.Argument("*", help="Designation pattern, e.g. '62*', 'NU22*', '7206*'."),
    kind: str = typer.Option(None, "--kind", help="deep_groove, angular_contact, tapered, cylindrical, …"),
    d: str = typer.Option(None, "--d", help="Bore d (mm, or with a unit)."),
    d_min: str = typer.Option(None, "--d-min", help="Smallest bore."),
    d_max: str = typer.Option(None, "--d-max", help="Largest bore."),
    D_min: str = typer.Option(None, "--D-min", help="Smallest outside diameter."),
    D_max: str = typer.Option(None, "--D-max", help="Largest outside diameter."),
    B_max: str = typer.Option(None, "--B-max", help="Largest width B (tapered: T)."),
    C_min: str = typer.Option(None, "--C-min", help="Smallest C, e.g. 30kN (catalogue's, else estimate's)."),
    C0_min: str = typer.Option(None, "--C0-min", help="Smallest C0, e.g. 20kN."),
    as_json: bool = _JSON_OPTION,
):
    """List or search standard bearings: d, D, B, catalogue and estimated C / C0, estimated mass."""
    from bearingkit.catalogue.search import search

    rows = search(
        None if pattern == "*" else pattern,
        kind=kind,
        d=_length(d, "--d"),
        d_min=_length(d_min, "--d-min"),
        d_max=_length(d_max, "--d-max"),
        D_min=_length(D_min, "--D-min"),
        D_max=_length(D_max, "--D-max"),
        B_max=_length(B_max, "--B-max"),
        C_min=_force(C_min, "--C-min"),
        C0_min=_force(C0_min, "--C0-min"),
    )
    if not rows:
        given = [f"pattern {pattern!r}"] if pattern != "*" else []
        for flag, value in (("--kind", kind), ("--d", d), ("--d-min", d_min), ("--d-max", d_max),
                            ("--D-min", D_min), ("--D-max", D_max), ("--B-max", B_max), ("--C-min", C_min),
                            ("--C0-min", C0_min)):  # fmt: skip
            if value is not None:
                given.append(f"{flag} {value}")
        # what the user typed, not the default pattern '*' they never wrote
        raise InputError(
            f"catalogue: no designation matches {', '.join(given) or 'the whole catalogue'}; "
            "widen a bound or the pattern (e.g. '62*')"
        )
    out = [r.to_dict() for r in rows]
    if as_json:
        sys.stdout.write(json.dumps(out, indent=1) + "\n")
        return
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=f"bearingkit catalogue {pattern}: {len(out)} designations (C, C0 in kN)")
    cols = (
        "designation",
        "d mm",
        "D mm",
        "B mm",
        "C cat.",
        "C est.",
        "C0 cat.",
        "C0 est.",
        "kg est.",
        "source",
    )
    for col in cols:
        table.add_column(col, justify="left" if col in ("designation", "source") else "right", no_wrap=True)
    for r in out:
        table.add_row(
            r["designation"],
            f"{r['d_m'] * 1e3:g}",
            f"{r['D_m'] * 1e3:g}",
            f"{r['B_m'] * 1e3:g}",
            _num(r["C_catalogue_N"], 1e-3),
            _num(r["C_estimate_N"], 1e-3),
            _num(r["C0_catalogue_N"], 1e-3),
            _num(r["C0_estimate_N"], 1e-3),
            _num(r["mass_estimate_kg"], 1.0, ".2g"),
            escape(r["source"]),  # "[from memory; …]" is text, not a rich style tag
        )
    console.print(table)
    console.print(
        "C est., C0 est.: ISO 281 / ISO 76 of the ESTIMATED internal geometry; kg est.: mass estimated from "
        "it (docs/catalogue.md)"
    )
    for fam, basis in {r["family"]: r["rating_basis"] for r in out}.items():
        if basis != "radial":
            console.print(f"{fam.replace('_', ' ')}: C, C0 are {basis}")


@app.command()
@one_line_errors
def select(
    load: list[str] = typer.Option(..., "--load", "-l", help="Fr=5kN, Fa=1kN (forces only)."),
    speed: str = typer.Option(..., "--speed", help="Speed, e.g. 3000rpm."),
    life: str = typer.Option(
        ..., "--life", help="Required L10 life, e.g. 20000h (ISO 281 and ISO/TS 16281)."
    ),
    kind: str = typer.Option(None, "--kind", help="deep_groove, angular_contact, tapered, ball, roller, …"),
    static_safety: float = typer.Option(1.0, "--s0", help="Smallest static safety s0."),
    count: int = typer.Option(5, "--count", help="Candidates wanted."),
    pattern: str = typer.Option(None, "--pattern", help="Only designations matching, e.g. '62*'."),
    d_min: str = typer.Option(None, "--d-min", help="Smallest bore (mm, or with a unit)."),
    d_max: str = typer.Option(None, "--d-max", help="Largest bore."),
    D_max: str = typer.Option(None, "--D-max", help="Largest outside diameter."),
    B_max: str = typer.Option(None, "--B-max", help="Largest width."),
    as_json: bool = _JSON_OPTION,
):
    """Catalogue bearings meeting a life (ISO 281 and ISO/TS 16281) and static safety, lightest first."""
    from bearingkit.pipeline.selection import select as run_select

    result = run_select(
        load,
        speed,
        life,
        kind=kind,
        static_safety=static_safety,
        count=count,
        pattern=pattern,
        d_min=_length(d_min, "--d-min"),
        d_max=_length(d_max, "--d-max"),
        D_max=_length(D_max, "--D-max"),
        B_max=_length(B_max, "--B-max"),
    )
    data = result.to_dict()
    if as_json:
        from bearingkit.io.export import to_json

        try:
            text = to_json(data)
        except ValueError as exc:
            _fail(f"select: {exc}", 1)
        sys.stdout.write(text + "\n")
    else:
        from rich.table import Table

        table = Table(title=f"bearingkit select: {len(data['candidates'])} candidates (lightest first)")
        cols = ("designation", "d mm", "D mm", "B mm", "kg est.", "C kN", "C0 kN", "C from", "P kN",
                "L10h ISO 281", "L10h ISO/TS 16281", "s0 ISO 76", "s0 p_max")  # fmt: skip
        for col in cols:
            table.add_column(
                col, justify="left" if col in ("designation", "C from") else "right", no_wrap=True
            )
        for c in data["candidates"]:
            table.add_row(
                c["designation"],
                f"{c['d_m'] * 1e3:g}",
                f"{c['D_m'] * 1e3:g}",
                f"{c['B_m'] * 1e3:g}",
                _num(c["mass_estimate_kg"], 1.0, ".2g"),
                _num(c["C_iso281_N"], 1e-3),
                _num(c.get("C0_iso76_N"), 1e-3),
                c["C_source"],
                _num(c["P_iso281_N"], 1e-3),
                _hours(c["L10h_iso281_h"]),
                _hours(c["L10h_iso16281_h"]),
                _num(c.get("s0_iso76"), 1.0),
                _num(c["static_safety"], 1.0),
            )
        console.print(table)
        for note in data["notes"]:
            console.print(f"  note: {note}", markup=False, highlight=False)
        shown = data["rejected"][:5]
        for r in shown:
            console.print(f"  not taken: {r['designation']}: {r['reason']}", markup=False, highlight=False)
    if not data["candidates"]:
        _fail(
            "select: no catalogue bearing meets the life and static safety; relax --life, --s0 or the bounds",
            1,
        )
