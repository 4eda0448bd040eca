"""Command line: ``bearingkit``. Faces only: parse, call the public API, print; never recompute physics."""

from __future__ import annotations

import json
import sys

import typer
from rich.console import Console
from rich.table import Table

from bearingkit.errors import InputError

app = typer.Typer(add_completion=False, no_args_is_help=True, help="Rolling-bearing mechanics.")
console = Console()
err_console = Console(stderr=True)


@app.command()
def validate(
    prefixes: list[str] = typer.Argument(None, help="Only cases whose id starts with one of these."),
    as_json: bool = typer.Option(False, "--json", help="Print a JSON list instead of a table."),
):
    """Recompute every published number bearingkit reproduces; exit 1 on an unexplained failure."""
    from bearingkit.validation.registry import all_cases, failures, run_cases

    cases = all_cases(prefixes or ())
    if not cases:
        err_console.print(f"error: no validation case matches {prefixes}")
        raise typer.Exit(2)
    results = run_cases(cases)
    if as_json:
        sys.stdout.write(json.dumps([r.to_dict() for r in results], indent=1) + "\n")
    else:
        table = Table(title=f"bearingkit validate: {len(results)} cases")
        for col in ("id", "unit", "published", "computed", "rel. error", "tol.", "status"):
            table.add_column(col, justify="left" if col == "id" else "right")
        for r in results:
            status = (
                "[green]pass[/]"
                if r.passed
                else ("[yellow]known[/]" if r.case.known_deviation else f"[red]FAIL[/] {r.error or ''}")
            )
            table.add_row(
                r.case.id,
                r.case.unit,
                f"{r.case.published:.6g}",
                f"{r.computed:.6g}",
                f"{r.rel_error:+.3%}",
                f"{r.case.tolerance:.1%}",
                status,
            )
        console.print(table)
        n_known = sum(1 for r in results if not r.passed and r.case.known_deviation)
        console.print(
            f"{sum(r.passed for r in results)} passed, {len(failures(results))} failed, "
            f"{n_known} known deviations"
        )
    if failures(results):
        raise typer.Exit(1)


def main() -> None:
    """Entry point: one-line errors for bad input, exit code 2."""
    try:
        app()
    except InputError as exc:
        err_console.print(f"error: {exc}")
        sys.exit(2)


if __name__ == "__main__":
    main()
