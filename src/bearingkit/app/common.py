"""What every route of the app shares: the one-line error it answers with, and JSON answers.

SI inside (nothing here computes). Errors are ``{"error": one line, "field": the form field}``; a
result with a non-finite value is refused (strict JSON), never sent as ``NaN``.
"""

from __future__ import annotations

import contextlib

from fastapi.responses import JSONResponse

from bearingkit.errors import InputError
from bearingkit.io.export import non_finite_paths

__all__ = ["PageError", "TooLarge", "error_response", "json_response", "on_field"]


class TooLarge(InputError):
    """An input file above the app's cap (the server answers 413)."""


class PageError(Exception):
    """Bad input, with the form field it is about (HTTP 400)."""

    def __init__(self, message: str, field: str = "source", status: int = 400):
        super().__init__(message)
        self.message = " ".join(str(message).split())
        self.field = field
        self.status = status


@contextlib.contextmanager
def on_field(source: str, field_of=None):
    """Turn an InputError into a PageError naming the form field of its message.

    ``field_of(message, source)`` finds the field (default: every message is about ``"source"``).
    """
    try:
        yield
    except TooLarge as exc:
        raise PageError(str(exc), "source", status=413) from None
    except InputError as exc:
        field = "source" if field_of is None else field_of(str(exc), source)
        raise PageError(str(exc), field) from None


def error_response(status: int, message: str, field: str | None = None) -> JSONResponse:
    """The one-line error answer."""
    return JSONResponse({"error": " ".join(str(message).split()), "field": field}, status_code=status)


def json_response(data: dict, source: str) -> JSONResponse:
    """``data`` as strict JSON (no caching); 422 naming the first non-finite value instead."""
    bad = non_finite_paths(data)
    if bad:
        raise PageError(f"{source}: non-finite value in results at {bad[0]} ({len(bad)} in all)", status=422)
    return JSONResponse(data, headers={"Cache-Control": "no-store"})
