"""The web app's HTTP interface (FastAPI): the page, its assets, and a small JSON API over the pipeline.

SI in every JSON value (units in keys, as :meth:`bearingkit.pipeline.Analysis.to_dict`); units are
parsed only from the form's text, by the loader. The app calls :func:`bearingkit.pipeline.analyze` and
reads the :class:`~bearingkit.pipeline.Analysis`; it computes no physics. Routes:

- ``GET /`` the page; ``GET /static/…`` its CSS and JavaScript (package data, no CDN);
- ``GET /api/meta`` examples, lubricants, friction models, limits;
- ``POST /api/open`` a source (example, designation, uploaded text) → what the form shows;
- ``POST /api/analyze`` the page's state → ``{"id", "analysis": Analysis.to_dict(), …}``;
- ``POST /api/sweep`` a one-factor sweep (:mod:`bearingkit.app.sweep`);
- ``GET /api/download/<id>.toml|json|html`` the input, the JSON and the HTML report of an analysis;
- ``GET /api/figure/<id>/pressure.svg`` the slice-pressure map of roller rows
  (:mod:`bearingkit.report.plots`);
- the workbench's routes (catalogue, comparison, shaft, drivetrain, studies, duty cycles):
  :mod:`bearingkit.app.workbench.routes`.

Errors are one line of JSON, ``{"error": …, "field": …}``: bad input → 400 with the loader's message
and the form field it is about; a malformed request → 422; too large → 413; unknown → 404; anything
else → 500 with one line and no traceback (the traceback goes to the server's log only).
"""

from __future__ import annotations

import contextlib
import importlib.resources
import logging
import threading
import time

from fastapi import FastAPI, HTTPException, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, Response
from fastapi.staticfiles import StaticFiles
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.middleware.trustedhost import TrustedHostMiddleware

from bearingkit.app.common import PageError, on_field
from bearingkit.app.common import error_response as _error
from bearingkit.app.common import json_response as _json
from bearingkit.app.form import (
    FRICTION_CHOICES,
    MAX_TOML_BYTES,
    AnalyzeRequest,
    OpenRequest,
    build_document,
    examples,
    field_of,
    open_source,
)
from bearingkit.app.store import Kept, Store, request_id
from bearingkit.app.sweep import MAX_POINTS, SweepRequest, run_sweep
from bearingkit.app.workbench.routes import register as register_workbench
from bearingkit.errors import InputError
from bearingkit.io import loader

__all__ = ["LOOPBACK_HOSTS", "MAX_REQUEST_BYTES", "create_app"]

log = logging.getLogger("bearingkit.app")

#: Largest request body [bytes]: an uploaded file at its cap, escaped in JSON (≤ 2x), plus the form.
MAX_REQUEST_BYTES = 2 * MAX_TOML_BYTES + 16 * 1024
#: Host names a loopback-bound server answers to (others are refused: DNS-rebinding protection).
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]")
#: Every page and asset comes from this server; nothing is fetched from elsewhere.
CONTENT_SECURITY_POLICY = (
    "default-src 'self'; img-src 'self' data: blob:; style-src 'self'; script-src 'self'; "
    "connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'self'"
)
STATIC = importlib.resources.files("bearingkit.app") / "static"


def _on_field(source: str):
    """An InputError → a PageError naming the form field of its message (:func:`form.field_of`)."""
    return on_field(source, field_of)


class _BodyLimit:
    """Refuse request bodies above ``limit`` bytes (declared or streamed) with 413 and one line."""

    def __init__(self, app, limit: int):
        self.app = app
        self.limit = limit

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        declared = dict(scope["headers"]).get(b"content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.limit):
            response = _error(
                413,
                f"request too large: at most {self.limit} bytes (files at most {MAX_TOML_BYTES} bytes)",
                "source",
            )
            return await response(scope, receive, send)
        seen = 0

        async def limited():
            nonlocal seen
            message = await receive()
            seen += len(message.get("body", b""))
            if seen > self.limit:
                raise HTTPException(413, f"request too large: at most {self.limit} bytes")
            return message

        return await self.app(scope, limited, send)


def create_app(
    store: Store | None = None,
    *,
    allowed_hosts=LOOPBACK_HOSTS,
    warm: bool = False,
) -> FastAPI:
    """The web app.

    Parameters
    ----------
    store : Store, optional
        Where analyses and downloads are kept (default: a new temporary folder, removed at shutdown).
    allowed_hosts : sequence of str
        Host names the server answers to (``("*",)`` when exposed on purpose).
    warm : bool
        Load the engine and matplotlib in the background at start-up, so the first analysis is fast.
    """
    store = store or Store()
    compute = threading.Lock()  # one analysis at a time: the solver uses the cores itself

    @contextlib.asynccontextmanager
    async def lifespan(_app):
        if warm:
            threading.Thread(target=_warm_up, args=(compute,), daemon=True, name="warm-up").start()
        yield
        bench.close()  # stop a running study before its folder goes with the store's
        store.close()

    app = FastAPI(title="bearingkit", docs_url=None, redoc_url=None, openapi_url=None, lifespan=lifespan)
    app.state.store = store
    app.add_middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts))
    app.add_middleware(_BodyLimit, limit=MAX_REQUEST_BYTES)

    @app.middleware("http")
    async def headers(request: Request, call_next):
        response = await call_next(request)
        response.headers["Content-Security-Policy"] = CONTENT_SECURITY_POLICY
        response.headers["X-Content-Type-Options"] = "nosniff"
        response.headers["Referrer-Policy"] = "no-referrer"
        return response

    @app.exception_handler(PageError)
    async def page_error(_request, exc: PageError):
        return _error(exc.status, exc.message, exc.field)

    @app.exception_handler(InputError)
    async def input_error(_request, exc: InputError):
        return _error(400, str(exc), "source")

    @app.exception_handler(RequestValidationError)
    async def bad_request(_request, exc: RequestValidationError):
        err = exc.errors()[0] if exc.errors() else {"loc": (), "msg": "malformed request"}
        where = ".".join(str(p) for p in err.get("loc", ()) if p != "body") or "request"
        return _error(422, f"{where}: {err.get('msg', 'invalid')}", "source")

    @app.exception_handler(StarletteHTTPException)  # also the router's own 404/405
    async def http_error(_request, exc: StarletteHTTPException):
        return _error(exc.status_code, str(exc.detail))

    @app.exception_handler(Exception)
    async def internal_error(request: Request, exc: Exception):
        log.error("internal error on %s", request.url.path, exc_info=exc)
        return _error(500, f"internal error ({type(exc).__name__}); the server's log has the details")

    def analyze_document(document: dict, source: str, request: AnalyzeRequest):
        """The one way the app analyses: loader → pipeline (parts computed lazily, by the caller)."""
        from bearingkit.pipeline import analyze

        with _on_field(source):
            bearing = loader.from_dict(document, source=source)
            return analyze(
                bearing,
                contamination=request.contamination.strip() or None,
                friction_model=request.friction_model,
            )

    @app.get("/", include_in_schema=False)
    def index():
        return FileResponse(STATIC / "index.html", media_type="text/html")

    app.mount("/static", StaticFiles(directory=str(STATIC)), name="static")

    @app.get("/api/meta")
    def meta():
        from bearingkit import __version__
        from bearingkit.app.workbench.studies import MAX_STUDY_CASES
        from bearingkit.app.workbench.systems import system_examples
        from bearingkit.catalogue.search import KINDS as catalogue_kinds
        from bearingkit.lubricants import BASE_OILS, THICKENERS, lubricant_names

        return {
            "version": __version__,
            "examples": examples(),
            "lubricants": list(lubricant_names()),
            "base_oils": list(BASE_OILS),
            "thickeners": list(THICKENERS),
            "friction_models": list(FRICTION_CHOICES),
            "max_file_bytes": MAX_TOML_BYTES,
            "max_sweep_points": MAX_POINTS,
            "catalogue_kinds": list(catalogue_kinds),
            "systems": system_examples(),
            "max_study_cases": MAX_STUDY_CASES,
        }

    @app.post("/api/open")
    def open_bearing(request: OpenRequest):
        with compute, _on_field(request.source.name):
            return open_source(request.source).model_dump()

    @app.post("/api/analyze")
    def analyze_page(request: AnalyzeRequest):
        start = time.perf_counter()
        key = request_id(request.model_dump())
        kept = store.get(key)
        if kept is None:
            with _on_field(request.source.name):
                document, source = build_document(request)
            with compute:
                analysis = analyze_document(document, source, request)
                with _on_field(source):
                    data = page_data(analysis, request.subsurface)
            kept = Kept(analysis, document, source, request.contamination, request.friction_model)
            store.put(key, kept)
        else:
            with compute:
                data = page_data(kept.analysis, request.subsurface)
        from bearingkit.report.plots import roller_rows

        return _json(
            {
                "id": key,
                "analysis": data,
                "pressure_map": bool(roller_rows(kept.analysis.statics)),
                "downloads": {ext: f"/api/download/{key}.{ext}" for ext in ("toml", "json", "html")},
                "elapsed_ms": 1e3 * (time.perf_counter() - start),
            },
            kept.source,
        )

    @app.post("/api/sweep")
    def sweep(request: SweepRequest):
        start = time.perf_counter()
        with compute, _on_field(request.base.source.name):
            out = run_sweep(request, analyze_document)
        out["elapsed_ms"] = 1e3 * (time.perf_counter() - start)
        return _json(out, request.base.source.name)

    @app.get("/api/download/{name}")
    def download(name: str):
        try:
            with compute:
                path, media, filename = store.download(name)
        except LookupError:
            raise HTTPException(
                404, f"no download {name[:80]!r}: analyse again and use the new link"
            ) from None
        return FileResponse(path, media_type=media, filename=filename)

    @app.get("/api/figure/{key}/pressure.svg")
    def pressure_map(key: str):
        from bearingkit.report.plots import slice_pressure_figure

        kept = store.get(key) if len(key) == 16 else None
        if kept is None:
            raise HTTPException(404, "no such analysis: analyse again")
        with compute:
            fig = slice_pressure_figure(kept.analysis.statics, 0)
            if fig is None:
                raise HTTPException(404, "no roller row with slices: no pressure map")
            image = fig.to_svg().encode("utf-8")
        return Response(image, media_type="image/svg+xml", headers={"Cache-Control": "no-store"})

    # the workbench's pages: catalogue, shaft, drivetrain, studies, duty cycles (same middleware)
    bench = register_workbench(app, store, compute, analyze_document)
    app.state.workbench = bench
    return app


def page_data(analysis, subsurface: bool) -> dict:
    """``Analysis.to_dict()``, with ``rows[].subsurface`` (stresses against depth, the case check) and
    the settings as ``subsurface`` where asked for or where a raceway is case-hardened (the check then
    runs for every face, docs/subsurface.md)."""
    if not (subsurface or not analysis.hardness.through_hardened):
        return analysis.to_dict()
    below = analysis.subsurface  # before the warnings, which carry the case check
    data = analysis.to_dict()
    rows = analysis.statics_dict(subsurface=below)
    for case, case_rows in zip(data["cases"], rows["cases"], strict=True):
        for row, row_below in zip(case["rows"], case_rows["rows"], strict=True):
            row["subsurface"] = row_below.get("subsurface")
            if "truncation" in row_below:
                row["truncation"] = row_below["truncation"]
    data["subsurface"] = rows["subsurface"]
    return data


def _warm_up(lock: threading.Lock) -> None:
    """Import the engine and matplotlib and run one small analysis, so the user's first one is fast."""
    from bearingkit.app.form import EXAMPLES_DIR

    try:
        with lock:
            from bearingkit.pipeline import analyze
            from bearingkit.report.plots import polar_load_figure

            example = EXAMPLES_DIR / "dgbb_6209.toml"
            a = analyze(str(example) if example.is_file() else "6209", load={"F_x": "1 kN"}, speed="1000 rpm")
            a.to_dict()
            polar_load_figure(a.statics, 0).to_svg()
            import matplotlib.backends.backend_agg  # noqa: F401  (the system and study figures' backend)
    except Exception:  # a failed warm-up only costs time later; the request will report the real error
        log.debug("warm-up failed", exc_info=True)
