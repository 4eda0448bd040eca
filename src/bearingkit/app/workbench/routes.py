"""The workbench's HTTP routes: catalogue and comparison, shaft and drivetrain, studies, duty cycles.

SI in every JSON value (units in keys). The routes are added to the app of
:func:`bearingkit.app.api.create_app`, so they pass its middleware like every other route (the Host
check, the request-size limit, the security headers) and answer errors the same way (one line of
JSON with the form field). They compute nothing themselves: each calls the library as the command
line does (``bearingkit catalogue``, ``select``, ``shaft``, ``system``, ``study``, ``rating`` of a
duty cycle) and holds the server's compute lock while the engine runs, except a study, which runs in
its own process (:mod:`bearingkit.app.workbench.jobs`) and never holds it.

- ``POST /api/catalogue/search`` filters → rows; ``POST /api/catalogue/select`` a load, speed and life
  → candidates; ``POST /api/catalogue/compare`` up to four designations at one operating point;
- ``GET /api/systems`` the example shafts and drivetrains; ``POST /api/system/open`` an example's text;
  ``POST /api/system/analyze`` a shaft or drivetrain → its ``to_dict()``; ``GET
  /api/figure/system/<id>/<what>.png`` the report's figures (``case-<i>``, ``layout``);
- ``POST /api/study/paths`` what a study can vary and compute on a subject; ``POST /api/study`` start;
  ``GET /api/study/<id>`` progress; ``POST /api/study/<id>/stop``, ``…/resume``; ``GET
  /api/study/<id>/results``; ``GET /api/study/<id>/figure/<name>.png``; ``GET /api/study/<id>.zip``;
- ``POST /api/duty`` the bearing page's state and the table's bins → the duty cycle's result.
"""

from __future__ import annotations

import contextlib
import re
import time
from dataclasses import dataclass

from fastapi import FastAPI, HTTPException
from fastapi.responses import FileResponse, Response

from bearingkit.app.common import PageError, json_response, on_field
from bearingkit.app.form import field_of
from bearingkit.app.store import Kept, request_id
from bearingkit.app.workbench import catalogue, duty, jobs, studies, systems

__all__ = ["Workbench", "register"]

#: A system figure's name: one load case's lines, or a drivetrain's layout.
_SYSTEM_FIGURE = re.compile(r"^(case-(\d{1,3})|layout)\.png$")


@dataclass
class Workbench:
    """What the routes keep: the solved systems (for their figures) and the study jobs."""

    systems: systems.KeptSystems
    jobs: jobs.Jobs

    def close(self) -> None:
        self.jobs.close()
        self.systems.clear()


def _catalogue_field(message: str, _source: str) -> str:
    """``catalogue.d_min``, ``select.life`` … (the form field a message names), else ``catalogue``."""
    m = re.match(r"^(catalogue|select|compare)(?:\.(\w+))?", message)
    if m is None:
        return "catalogue"
    return f"{m.group(1)}.{m.group(2)}" if m.group(2) else m.group(1)


def _study_field(message: str, _source: str) -> str:
    m = re.search(r"study\.(factors\[(\d+)\]|outputs|objectives|response)", message)
    if m is None:
        return "study"
    return f"study.factor.{m.group(2)}" if m.group(2) is not None else f"study.{m.group(1)}"


def register(app: FastAPI, store, compute, analyze_document) -> Workbench:
    """Add the workbench's routes to ``app``.

    Parameters
    ----------
    store : bearingkit.app.store.Store
        The server's analyses (compared bearings are kept there, to be opened on the bearing page) and
        its temporary folder (study jobs live in it).
    compute : threading.Lock
        Held while the engine runs (one analysis at a time).
    analyze_document : callable
        The app's one way to analyse an input document (``(document, source, AnalyzeRequest)``).
    """
    bench = Workbench(systems.KeptSystems(), jobs.Jobs(lambda: store.root))

    # ------------------------------------------------------------------------------ catalogue
    @app.post("/api/catalogue/search")
    def catalogue_search(request: catalogue.SearchRequest):
        with compute, on_field("catalogue", _catalogue_field):
            return json_response(catalogue.run_search(request), "catalogue")

    @app.post("/api/catalogue/select")
    def catalogue_select(request: catalogue.SelectRequest):
        start = time.perf_counter()
        with compute, on_field("select", _catalogue_field):
            out = catalogue.run_select(request)
        out["elapsed_ms"] = 1e3 * (time.perf_counter() - start)
        return json_response(out, "select")

    @app.post("/api/catalogue/compare")
    def catalogue_compare(request: catalogue.CompareRequest):
        from bearingkit.app.form import build_document

        start = time.perf_counter()
        with on_field("compare", _catalogue_field):
            requests = catalogue.compare_requests(request)
        columns = []
        for i, r in enumerate(requests):
            key = request_id(r.model_dump())
            kept = store.get(key)
            with _refield(r.source.name, lambda m, s, i=i: _compare_field(m, s, i)):
                if kept is None:
                    document, source = build_document(r)
                    with compute:
                        analysis = analyze_document(document, source, r)
                        data = analysis.to_dict()
                    kept = Kept(analysis, document, source, r.contamination, r.friction_model)
                    store.put(key, kept)
                else:
                    with compute:
                        data = kept.analysis.to_dict()
            columns.append(catalogue.compared(r.source.name, key, data))
        out = {"bearings": columns, "elapsed_ms": 1e3 * (time.perf_counter() - start)}
        return json_response(out, "compare")

    # ------------------------------------------------------------------------------ systems
    @app.get("/api/systems")
    def system_list():
        return {"examples": systems.system_examples(), "max_cases": systems.MAX_SYSTEM_CASES}

    @app.post("/api/system/open")
    def system_open(request: systems.SystemRequest):
        with on_field(request.source.name):
            _, name, text = systems.read_system(request)
        return {"name": name, "text": text}

    @app.post("/api/system/analyze")
    def system_analyze(request: systems.SystemRequest):
        start = time.perf_counter()
        with compute, on_field(request.source.name):
            analysis, text, name = systems.analyse_system(request)
            data = analysis.to_dict()
        key = systems.system_id(request, text)
        bench.systems.put(key, analysis)
        figures = [f"/api/figure/system/{key}/case-{c}.png" for c in range(len(data["cases"]))]
        out = {
            "id": key,
            "system": request.system,
            "name": name,
            "analysis": data,
            "figures": figures,
            "layout": f"/api/figure/system/{key}/layout.png" if request.system == "drivetrain" else None,
            "elapsed_ms": 1e3 * (time.perf_counter() - start),
        }
        return json_response(out, name)

    @app.get("/api/figure/system/{key}/{name}")
    def system_figure(key: str, name: str):
        from bearingkit.report.plots import png_bytes

        m = _SYSTEM_FIGURE.fullmatch(name)
        analysis = bench.systems.get(key) if m and len(key) == 16 else None
        if analysis is None:
            raise HTTPException(404, "no such system figure: analyse the system again")
        with compute:
            if m.group(1) == "layout":
                if not hasattr(analysis, "drivetrain"):
                    raise HTTPException(404, "a shaft has no layout figure: its lines show the outline")
                from bearingkit.report.systems.drivetrain_plots import layout_figure

                fig = layout_figure(analysis.drivetrain)
            else:
                case = int(m.group(2))
                if case >= analysis.n_cases:
                    raise HTTPException(404, f"no load case {case}")
                if hasattr(analysis, "drivetrain"):
                    from bearingkit.report.systems.drivetrain_plots import shaft_lines_figure

                    fig = shaft_lines_figure(analysis.result, case)
                else:
                    from bearingkit.report.systems.shaft_plots import shaft_figure

                    fig = shaft_figure(analysis.result, case)
            png = png_bytes(fig)
        return Response(png, media_type="image/png", headers={"Cache-Control": "no-store"})

    # ------------------------------------------------------------------------------ studies
    @app.post("/api/study/paths")
    def study_paths(request: studies.PathsRequest):
        with compute, on_field("study", _study_field):
            return json_response(studies.subject_paths(request), "study")

    @app.post("/api/study")
    def study_start(request: studies.StudyRequest):
        from bearingkit.extras import check

        with on_field("study", _study_field):
            # the child runs `bearingkit study` (Parquet store, pymoo): one line before anything is written
            check("studies", "a study of the web app")
            with compute:
                made = studies.study_files(request)
            try:
                job = bench.jobs.start(
                    made.files, made.n_cases, made.design, made.subject, made.outputs, made.factors
                )
            except jobs.Busy as exc:
                raise PageError(str(exc), "study", status=409) from None
        return json_response(job.to_dict(), "study")

    def _job(key: str, action):
        try:
            return action(key)
        except LookupError:
            raise HTTPException(404, f"no study {key[:20]!r} on this server (it restarted?)") from None
        except jobs.Busy as exc:
            raise PageError(str(exc), "study", status=409) from None

    @app.get("/api/study/{key}.zip")
    def study_download(key: str):
        data = _job(key, bench.jobs.archive)
        return Response(
            data,
            media_type="application/zip",
            headers={"Content-Disposition": f'attachment; filename="study-{key}.zip"'},
        )

    @app.get("/api/study/{key}")
    def study_status(key: str):
        return json_response(_job(key, bench.jobs.get).to_dict(), "study")

    @app.post("/api/study/{key}/stop")
    def study_stop(key: str):
        return json_response(_job(key, bench.jobs.stop).to_dict(), "study")

    @app.post("/api/study/{key}/resume")
    def study_resume(key: str):
        return json_response(_job(key, bench.jobs.resume).to_dict(), "study")

    @app.get("/api/study/{key}/results")
    def study_results(key: str):
        with on_field("study", _study_field):
            return json_response(_job(key, bench.jobs.results), "study")

    @app.get("/api/study/{key}/figure/{name}")
    def study_figure(key: str, name: str):
        path = _job(key, lambda k: bench.jobs.figure(k, name))
        return FileResponse(path, media_type="image/png", headers={"Cache-Control": "no-store"})

    # ------------------------------------------------------------------------------ duty cycles
    @app.post("/api/duty")
    def duty_cycle(request: duty.DutyRequest):
        start = time.perf_counter()
        with on_field(request.base.source.name, duty.duty_field):
            document, source = duty.duty_document(request)
        with compute, _refield(source, duty.duty_field):
            analysis = analyze_document(document, source, request.base)
            result = analysis.duty_cycle
            if result is None:  # cannot happen: the document has bins; a second guard for the page
                raise PageError(f"{source}: no duty cycle", "duty")
            out = {"duty_cycle": result.to_dict(), "notes": list(analysis.notes)}
        out["elapsed_ms"] = 1e3 * (time.perf_counter() - start)
        return json_response(out, source)

    return bench


@contextlib.contextmanager
def _refield(source: str, field_of_message):
    """As :func:`~bearingkit.app.common.on_field`, and a PageError the bearing page's analysis raised
    (its fields are the bearing form's) placed by ``field_of_message`` instead."""
    try:
        with on_field(source, field_of_message):
            yield
    except PageError as exc:
        if exc.status == 400:
            exc.field = field_of_message(exc.message, source)
        raise


def _compare_field(message: str, source: str, index: int) -> str:
    """A compared bearing's error is about its column (``compare.<i>``) unless it names a field of the
    operating point (``compare.load.F_x``, ``compare.speed`` …: the bearing page's names, prefixed)."""
    field = field_of(message, source)
    return f"compare.{index}" if field == "source" else f"compare.{field}"
