"""The mutation fuzz: every command of the ``bearingkit`` app, every input kind, run in-process.

    python tests/fuzz/bk_fuzz_run.py --seed 20261128 --n 10000      (``make fuzz SEED=… N=…``)
    python tests/fuzz/bk_fuzz_run.py --seed 20261128 --only 4711    (one mutant again, with its output)

A few long-lived worker processes (one per core) each import bearingkit once and run mutants through
typer's CliRunner (the app's requests through FastAPI's TestClient): no interpreter starts per mutant.
Mutant ``i`` of seed ``s`` is made from ``(s, i)`` alone (:mod:`bk_fuzz_inputs`), so any finding can
be made again with ``--only i``. The parent hands out indices and kills a worker whose mutant runs
past ``--hang`` seconds (a hang), then starts a fresh one.

Finding classes (:data:`FINDINGS`), each checked on every run:

- ``traceback``: an exception escaped the command (or it printed a traceback, or exited 70, the code of
  bearingkit's own "internal error" line), or an exit code other than 0, 1, 2, 75 (:data:`EXIT_CODES`);
- ``hang``: the mutant ran past ``--hang`` seconds (30 by default);
- ``json``: ``--json`` given, exit code 0 or 1, and stdout is not strict JSON (NaN and Infinity refused);
- ``message``: a failure (exit code ≠ 0) whose stderr is not exactly one line ``error: …`` of at most
  :data:`MAX_MESSAGE` characters;
- ``stray``: a failure that left a file or folder behind (the run's folders are compared before and after);
- ``warning``: numpy warned (a NaN or an overflow computed on the way);
- ``server``: a request to the app answered 5xx, or with a body that is not one line of strict JSON.

The workers run with small work budgets (``BEARINGKIT_MAX_WORK_S``, ``BEARINGKIT_CASE_SECONDS``): a
mutant that asks for minutes is refused in one line, as a user's would be, only sooner.
"""

from __future__ import annotations

import argparse
import importlib
import json
import multiprocessing
import os
import random
import shutil
import sys
import tempfile
import time
import traceback
import warnings
from collections import Counter
from dataclasses import dataclass, field
from multiprocessing.connection import wait
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import bk_fuzz_inputs as inputs  # noqa: E402

FINDINGS = ("traceback", "hang", "json", "message", "stray", "warning", "server")
#: Longest failure line [characters]: ``error: `` + a shortened file name + a 300-character message.
MAX_MESSAGE = 2000
#: Exit codes of a command that kept its promises: done, a doubtful result, refused input, and a run
#: stopped part-way by its environment (a killed worker, a full disk; resumable: 75).
EXIT_CODES = (0, 1, 2, 75)
#: Seconds past which a mutant is a hang.
HANG_SECONDS = 30.0
#: Relative weights of the commands (others 1): those that compute a lot for any valid input are
#: drawn less often, never left out.
COMMAND_WEIGHTS = {
    "run-flagship": 0.002,
    "validate": 0.2,
    "schema": 0.05,
    "serve": 0.2,
    "report": 0.35,
    "shaft": 0.35,
}
#: Share of the mutants that are requests to the web app.
APP_SHARE = 0.06
#: Arguments whose every value must stay cheap (``validate ""`` would run every validation case).
ARGUMENT_VALUES = {
    "validate": ["zzz", "no-such-case", "名前", "x" * 300, "[red]x[/]", "\x00"],
    "catalogue": ["62*", "6209", "NU22*", "7206*", "[", "x" * 5000, "名前", "62*", "6209", "NU22*", "*"],
}
#: Values of options that name a file or folder to write.
OUTPUT_PATHS = ["out/x.html", "o/report.html", "x.png", "s.csv", "s.json", "o", "nodir/deeper/x.html", "."]
OUTPUT_PATHS += ["a" * 300, "\x00", "x.txt"]
#: What the workers run with: small budgets, one solver thread, no display.
WORKER_ENV = {
    "BEARINGKIT_MAX_WORK_S": "1",
    "BEARINGKIT_CASE_SECONDS": "2",
    "BEARINGKIT_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "OPENBLAS_NUM_THREADS": "1",
    "MPLBACKEND": "Agg",
}


def default_seed() -> int:
    """The day's seed (YYYYMMDD): it changes every day, and a day's runs agree."""
    return int(time.strftime("%Y%m%d"))


def commands(app) -> dict:
    """Command name → click command, from the typer app (so later commands are fuzzed too)."""
    import typer.main

    group = typer.main.get_command(app)
    return dict(sorted(group.commands.items()))


@dataclass
class Case:
    """One mutant: an argv (files to write with it) or a request to the app."""

    index: int
    kind: str  # "cli" or "app"
    command: str = ""
    argv: list = field(default_factory=list)
    files: dict = field(default_factory=dict)  # relative path → text
    inputs: list = field(default_factory=list)  # input kinds used (bearing, shaft, study, designation …)
    mutations: list = field(default_factory=list)
    request: dict | None = None


# ------------------------------------------------------------------------------ making a case
def _file_kinds(help_text: str) -> list[str]:
    """The input kinds an argument's help asks for (all kinds when it says nothing recognisable)."""
    h = (help_text or "").lower()
    kinds = [k for k, word in (("study", "study"), ("shaft", "shaft")) if word in h]
    if "designation" in h or "input file" in h or "bearing file" in h:
        kinds += ["bearing", "designation"]
    return kinds


def make_case(seed: int, index: int, cmds: dict, files: dict, routes: list) -> Case:
    """Mutant ``index`` of ``seed`` (deterministic)."""
    rng = random.Random(f"{seed}/{index}")
    if rng.random() < APP_SHARE:
        return Case(
            index, "app", command="app", inputs=["app request"], request=inputs.mutate_request(rng, routes)
        )
    names = list(cmds)
    name = rng.choices(names, weights=[COMMAND_WEIGHTS.get(n, 1.0) for n in names])[0]
    # What is mutated: the input file alone (options take good values), the options alone (the file
    # as it is), or both; mutants of one kind reach past the first checks of the other.
    mode = rng.choice(("file", "file", "options", "both"))
    case = Case(index, "cli", command=name, argv=[name], mutations=[f"mode {mode}"])
    by_kind: dict[str, list[str]] = {}
    for origin, (kind, _, _) in files.items():
        by_kind.setdefault(kind, []).append(origin)
    chosen_cases: list[str] = []
    for param in cmds[name].params:
        if getattr(param, "param_type_name", "") == "argument":
            for value in _argument_values(param, name, rng, case, by_kind, files, chosen_cases, mode):
                case.argv.append(value)
            continue
        if not param.opts or not param.opts[0].startswith("-"):
            continue
        opt = max(param.opts, key=len)
        if getattr(param, "is_flag", False):
            if rng.random() < 0.3:
                case.argv.append(param.opts[0])
            continue
        if not param.required and rng.random() > 0.35:
            continue
        for _ in range(rng.choice((1, 1, 2, 3)) if param.multiple else 1):
            case.argv += [opt, _option_value(param, opt, rng, chosen_cases, good=mode == "file")]
            case.mutations.append(f"option {opt}")
    if mode == "file" and "designation" in case.inputs and "--load" not in case.argv:
        if any("--load" in p.opts for p in cmds[name].params if getattr(p, "opts", None)):
            case.argv += ["--load", rng.choice(inputs.OPTION_GOOD["--load"])]  # a designation has no cases
    case.inputs.append("cli options")
    return case


def _good_default(param, opt: str) -> str:
    """A value an option takes when nothing is known of it: its default, else a plain one."""
    default = getattr(param, "default", None)
    if default not in (None, [], ()) and not isinstance(default, bool):
        return str(default[0] if isinstance(default, (list, tuple)) else default)
    if "Path" in _annotation(param):
        return rng_free_path(opt)
    return "1" if "int" in _annotation(param) else "40"


def rng_free_path(opt: str) -> str:
    """An output path a command may write (in the mutant's own folder)."""
    return {"--stiffness": "k.csv", "--plot": "lines.png", "--out": "study_out"}.get(opt, "out/report.html")


def _annotation(param) -> str:
    """The declared type of a typer parameter, as text (``<class 'pathlib.Path'>``, ``list[str]`` …)."""
    return str(getattr(getattr(param, "type_descriptor", None), "annotation", ""))


def _argument_values(param, command, rng, case, by_kind, files, chosen_cases, mode="both") -> list[str]:
    count = rng.choice((1, 1, 2)) if param.nargs == -1 or "list[" in _annotation(param) else 1
    if command in ARGUMENT_VALUES:
        return [rng.choice(ARGUMENT_VALUES[command]) for _ in range(count)]
    is_path = "Path" in _annotation(param) or param.name in ("file", "path")
    if not is_path:
        return [rng.choice(inputs.GENERIC_VALUES + inputs.DESIGNATIONS) for _ in range(count)]
    kinds = _file_kinds(getattr(param, "help", "") or "") or [*sorted(by_kind), "designation"]
    out = []
    for _ in range(count):
        draw = rng.random()
        if draw < 0.08 and mode != "file":
            case.inputs.append("path")
            out.append(rng.choice([*inputs.PATHS, "@fifo", "@dir", "/dev/zero"]))
            continue
        kind = rng.choice(kinds) if draw < 0.9 else rng.choice(sorted(by_kind))
        if kind == "designation":
            case.inputs.append("designation")
            out.append(inputs.designation(rng))
            continue
        origin = rng.choice(by_kind.get(kind) or sorted(files))
        kind, _, data = files[origin]
        if mode != "options" and rng.random() < 0.9:
            mutant = inputs.mutate_file(origin, kind, data, rng)
            text, done = mutant.text, mutant.mutations
        else:
            text, done = inputs.toml_text(data), ["unmutated"]
        cases = data.get("load_cases") if isinstance(data, dict) else None
        if isinstance(cases, list):
            chosen_cases += [
                c["name"] for c in cases if isinstance(c, dict) and isinstance(c.get("name"), str)
            ]
        if isinstance(data, dict) and "tolerances" in data:
            case.inputs.append("tolerances")
        if isinstance(data, dict) and "duty_cycle" in data:
            case.inputs.append("duty cycle")
        folder = Path(origin).parent
        rel = str(folder / f"mutant_{case.index}_{len(case.files)}.toml")
        case.files[rel] = text
        case.inputs.append(kind)
        case.mutations += done
        out.append("@" + rel)
    return out


def _option_value(param, opt: str, rng, chosen_cases, good: bool = False) -> str:
    if opt == "--case" and chosen_cases and rng.random() < 0.7:
        return rng.choice(chosen_cases)
    if good:
        return rng.choice(inputs.OPTION_GOOD.get(opt) or [_good_default(param, opt)])
    if opt in inputs.OPTION_VALUES and rng.random() < 0.85:
        return rng.choice(inputs.OPTION_VALUES[opt])
    if "Path" in _annotation(param):
        return rng.choice(OUTPUT_PATHS)
    if "int" in _annotation(param):
        return rng.choice(["1", "0", "-1", "abc", "99999999999999999999", "2"])
    if len(opt) <= 8 or opt.lower().endswith(("-min", "-max")):
        return rng.choice(inputs.DIMENSION_VALUES + inputs.GENERIC_VALUES[:6])
    return rng.choice(inputs.GENERIC_VALUES)


# ------------------------------------------------------------------------------ running a case
@dataclass
class Worksite:
    """A worker's folders: ``ex`` holds a copy of the examples (mutants are written beside them, so
    the relative names of shaft and study files resolve), ``run`` is each mutant's working folder."""

    root: Path

    @property
    def ex(self) -> Path:
        return self.root / "ex"

    def prepare(self) -> None:
        if not self.ex.exists():
            shutil.copytree(inputs.EXAMPLES, self.ex, ignore=shutil.ignore_patterns("*.png", "*.md"))
        special = self.root / "special"
        special.mkdir(exist_ok=True)
        fifo = special / "fifo"
        if not fifo.exists() and hasattr(os, "mkfifo"):
            os.mkfifo(fifo)
        (special / "dir").mkdir(exist_ok=True)

    def listing(self) -> set:
        return {str(p.relative_to(self.root)) for p in self.root.rglob("*")}


def run_cli_case(app, case: Case, site: Worksite, runner) -> tuple[list, float, str, int]:
    """Run a CLI case; (problems, seconds, output excerpt, exit code)."""
    written = []
    for rel, text in case.files.items():
        path = site.ex / rel
        path.write_text(text, encoding="utf-8", errors="surrogatepass")
        written.append(path)
    run_dir = site.root / "run"
    if run_dir.exists():
        shutil.rmtree(run_dir)
    run_dir.mkdir()
    argv = []
    for a in case.argv:
        if a == "@fifo":
            argv.append(str(site.root / "special" / "fifo"))
        elif a == "@dir":
            argv.append(str(site.root / "special" / "dir"))
        elif isinstance(a, str) and a.startswith("@"):
            argv.append(str(site.ex / a[1:]))
        else:
            argv.append(a)
    before = site.listing()
    cwd = os.getcwd()
    os.chdir(run_dir)
    started = time.perf_counter()
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            res = runner.invoke(app, argv)
    finally:
        seconds = time.perf_counter() - started
        os.chdir(cwd)
    problems = check_result(res, argv, caught)
    if res.exit_code != 0:
        new = site.listing() - before
        if new:
            problems.append(("stray", f"left behind: {sorted(new)[:3]}"))
    for path in written:
        path.unlink(missing_ok=True)
    shutil.rmtree(run_dir, ignore_errors=True)
    excerpt = f"rc={res.exit_code} stdout={res.stdout[-300:]!r} stderr={res.stderr[-600:]!r}"
    return problems, seconds, excerpt, res.exit_code


def check_result(res, argv, caught=()) -> list:
    """The broken promises of one CLI run (module docstring)."""
    problems = []
    exc = res.exception
    if exc is not None and not isinstance(exc, SystemExit):
        where = "".join(traceback.format_exception(exc)[-2:])[-400:]
        problems.append(("traceback", f"{type(exc).__name__}: {str(exc)[:200]} at {where}"))
    elif res.exit_code not in EXIT_CODES:
        problems.append(("traceback", f"exit code {res.exit_code}: {res.stderr[-300:]!r}"))
    out, err = res.stdout, res.stderr
    if "Traceback (most recent call last)" in out + err:
        problems.append(("traceback", "traceback text in the output"))
    if res.exit_code != 0:
        lines = err.splitlines()
        if len(lines) != 1 or not lines[0].startswith("error: "):
            problems.append(("message", f"not one line 'error: …': {err[:300]!r}"))
        elif len(lines[0]) > MAX_MESSAGE:
            problems.append(("message", f"{len(lines[0])} characters: {lines[0][:200]!r}"))
    if "--json" in argv and res.exit_code in (0, 1) and out.strip():
        try:
            json.loads(out, parse_constant=_no_constant)
        except ValueError as e:
            problems.append(("json", f"{str(e)[:120]}: {out[:120]!r}"))
    numpy_warnings = [str(w.message)[:100] for w in caught if issubclass(w.category, RuntimeWarning)]
    if numpy_warnings:
        problems.append(("warning", numpy_warnings[0]))
    return problems


def _no_constant(name):
    raise ValueError(f"{name} in JSON output")


def run_app_case(client, case: Case) -> tuple[list, float, str, int]:
    """Send a mutated request to the app; (problems, seconds, excerpt, status)."""
    r = case.request
    started = time.perf_counter()
    kwargs = {"headers": r["headers"]}
    if r["raw"] is not None:
        kwargs["content"] = r["raw"]
        kwargs["headers"] = {"content-type": "application/json", **r["headers"]}
    elif r["json"] is not None:  # NaN and Infinity written as JavaScript would never send them
        kwargs["content"] = json.dumps(r["json"], default=str).encode()
        kwargs["headers"] = {"content-type": "application/json", **r["headers"]}
    try:
        resp = client.request(r["method"], r["path"], **kwargs)
    except Exception as exc:  # the test client re-raises what the app let escape
        return [("server", f"{type(exc).__name__}: {str(exc)[:200]}")], time.perf_counter() - started, "", 0
    seconds = time.perf_counter() - started
    problems = []
    if resp.status_code >= 500:
        problems.append(("server", f"{resp.status_code}: {resp.text[:200]!r}"))
    if resp.headers.get("content-type", "").startswith("application/json"):
        try:
            body = json.loads(resp.text, parse_constant=_no_constant)
        except ValueError as e:
            problems.append(("server", f"body not strict JSON: {e}"))
            body = None
        if resp.status_code >= 400 and isinstance(body, dict):
            msg = str(body.get("error", ""))
            if "\n" in msg or len(msg) > MAX_MESSAGE or "Traceback" in msg:
                problems.append(("server", f"error not one short line: {msg[:200]!r}"))
    return problems, seconds, f"{r['method']} {r['path'][:80]} -> {resp.status_code}", resp.status_code


# ------------------------------------------------------------------------------ worker and parent
def _patch_for_fuzzing() -> None:
    """What a fuzzed ``serve`` must not do: serve forever, open a browser, ask a name server."""
    import socket
    import webbrowser

    import uvicorn

    uvicorn.Server.run = lambda self, *a, **k: None
    webbrowser.open = lambda *a, **k: False
    real = socket.getaddrinfo

    def offline(host, *args, **kwargs):
        text = host.decode() if isinstance(host, bytes) else str(host)
        try:
            import ipaddress

            ipaddress.ip_address(text.strip("[]"))
        except ValueError:
            if text not in ("localhost", "", "None"):
                raise socket.gaierror(socket.EAI_NONAME, "no name server in the fuzz") from None
        return real(host, *args, **kwargs)

    socket.getaddrinfo = offline


def _build_once(app) -> None:
    """typer's CliRunner builds the click command of the app on every invoke (~7 ms for bearingkit's,
    the cost of a whole refused mutant): the worker builds it once. (The command line builds it once
    per process anyway.)"""
    import typer.testing

    built = typer.testing._get_command(app)
    original = typer.testing._get_command
    typer.testing._get_command = lambda a: built if a is app else original(a)


def worker_main(conn, seed: int, root: str, app_spec: str) -> None:
    """A worker: import once, then run the indices the parent sends until it sends None."""
    os.environ.update(WORKER_ENV)
    module, _, attr = app_spec.partition(":")
    app = getattr(importlib.import_module(module), attr)
    _patch_for_fuzzing()
    from fastapi.testclient import TestClient
    from typer.testing import CliRunner

    from bearingkit.app import create_app
    from bearingkit.app.store import Store

    site = Worksite(Path(root))
    site.prepare()
    cmds = commands(app)
    files = inputs.example_files()
    store = Store(Path(root) / "serve")
    web = create_app(store, allowed_hosts=("127.0.0.1", "localhost"))
    client = TestClient(web, base_url="http://127.0.0.1", raise_server_exceptions=False)
    routes = [r.path for r in web.routes if hasattr(r, "path")]
    runner = CliRunner()
    _build_once(app)
    conn.send(("ready", os.getpid()))
    while True:
        index = conn.recv()
        if index is None:
            break
        case = make_case(seed, index, cmds, files, routes)
        try:
            if case.kind == "app":
                problems, seconds, excerpt, code = run_app_case(client, case)
            else:
                problems, seconds, excerpt, code = run_cli_case(app, case, site, runner)
        except Exception as exc:  # the harness itself: reported, never silent
            problems, seconds, excerpt, code = (
                [("traceback", f"harness: {type(exc).__name__}: {exc}")],
                0.0,
                "",
                -1,
            )
        conn.send(_summary(case, problems, seconds, excerpt, code))
    store.close()


def _summary(case: Case, problems, seconds, excerpt, code=None) -> dict:
    argv = [a if len(a) < 80 else a[:60] + f"…({len(a)} chars)" for a in map(str, case.argv)]
    return {
        "index": case.index,
        "command": case.command,
        "argv": argv,
        "inputs": case.inputs,
        "mutations": case.mutations,
        "problems": problems,
        "seconds": seconds,
        "excerpt": excerpt,
        "code": code,
    }


class Pool:
    """Worker processes the parent feeds one index at a time, killing those that hang."""

    def __init__(self, n: int, seed: int, root: Path, app_spec: str):
        self.ctx = multiprocessing.get_context("spawn")
        self.seed, self.root, self.app_spec = seed, root, app_spec
        self.slots = [self._start(i) for i in range(n)]

    def _start(self, i: int) -> dict:
        parent, child = self.ctx.Pipe()
        proc = self.ctx.Process(
            target=worker_main,
            args=(child, self.seed, str(self.root / f"w{i}-{time.monotonic_ns()}"), self.app_spec),
        )
        proc.daemon = True
        proc.start()
        child.close()
        return {"proc": proc, "conn": parent, "index": None, "since": None, "ready": False, "i": i}

    def restart(self, slot: dict) -> dict:
        slot["proc"].kill()
        slot["proc"].join(5)
        new = self._start(slot["i"])
        self.slots[self.slots.index(slot)] = new
        return new

    def close(self) -> None:
        for s in self.slots:
            try:
                s["conn"].send(None)
            except (BrokenPipeError, OSError):
                pass
        for s in self.slots:
            s["proc"].join(10)
            if s["proc"].is_alive():
                s["proc"].kill()


def fuzz(seed: int, n: int, workers: int | None = None, hang: float = HANG_SECONDS, start: int = 0,
         app_spec: str = "bearingkit.cli:app", echo=print, only=None) -> dict:  # fmt: skip
    """Run mutants ``start … start+n-1`` (or ``only``) of ``seed``; the summary (counts, findings, time)."""
    indices = list(only) if only is not None else list(range(start, start + n))
    workers = max(1, min(workers or os.cpu_count() or 1, len(indices)))
    load_before = os.getloadavg()
    t0 = time.perf_counter()
    results, hangs = [], []
    with tempfile.TemporaryDirectory(prefix="bk-fuzz-") as tmp:
        pool = Pool(workers, seed, Path(tmp), app_spec)
        todo = list(reversed(indices))
        peak_load = load_before[0]
        last_echo = time.perf_counter()
        try:
            while todo or any(s["index"] is not None for s in pool.slots):
                now = time.perf_counter()
                for slot in list(pool.slots):
                    if slot["index"] is not None and now - slot["since"] > hang:
                        hangs.append(slot["index"])
                        results.append(_lost(slot["index"], "hang", f"still running after {hang:g} s", hang))
                        pool.restart(slot)
                for slot in pool.slots:
                    if slot["ready"] and slot["index"] is None and todo:
                        slot["index"], slot["since"] = todo.pop(), time.perf_counter()
                        slot["conn"].send(slot["index"])
                ready = wait([s["conn"] for s in pool.slots], timeout=1.0)
                for conn in ready:
                    slot = next(s for s in pool.slots if s["conn"] is conn)
                    try:
                        msg = conn.recv()
                    except (EOFError, OSError):  # the worker died: its mutant is a finding
                        if slot["index"] is not None:
                            results.append(_lost(slot["index"], "traceback", "the worker process died", 0.0))
                        pool.restart(slot)
                        continue
                    if isinstance(msg, tuple) and msg[0] == "ready":
                        slot["ready"] = True
                        continue
                    results.append(msg)
                    slot["index"] = None
                peak_load = max(peak_load, os.getloadavg()[0])
                if time.perf_counter() - last_echo > 30:
                    last_echo = time.perf_counter()
                    found = sum(1 for r in results if r["problems"])
                    echo(f"  {len(results)}/{len(indices)} mutants, {found} with findings, "
                         f"{time.perf_counter() - t0:.0f} s, load {os.getloadavg()[0]:.1f}")  # fmt: skip
        finally:
            pool.close()
    return _report(seed, indices, results, time.perf_counter() - t0, load_before, peak_load, workers)


def _lost(index: int, cls: str, what: str, seconds: float) -> dict:
    """The result of a mutant whose worker was killed or died (run it again with --only)."""
    return {"index": index, "command": "?", "argv": [], "inputs": [], "mutations": [],
            "problems": [(cls, what)], "seconds": seconds, "excerpt": ""}  # fmt: skip


def _report(seed, indices, results, seconds, load_before, peak_load, workers) -> dict:
    counts = Counter()
    commands_seen, kinds_seen, mutations_seen = Counter(), Counter(), Counter()
    command_seconds, codes = Counter(), Counter()
    findings = []
    for r in results:
        codes[f"{'http ' if r['command'] == 'app' else 'exit '}{r.get('code')}"] += 1
        commands_seen[r["command"]] += 1
        command_seconds[r["command"]] += r["seconds"]
        for k in set(r["inputs"]):
            kinds_seen[k] += 1
        for m in r["mutations"]:
            mutations_seen[m.split()[0]] += 1
        for cls, _ in r["problems"]:
            counts[cls] += 1
        if r["problems"]:
            findings.append(r)
    return {
        "seed": seed,
        "mutants": len(results),
        "seconds": seconds,
        "workers": workers,
        "load_average_before": load_before,
        "load_average_peak": peak_load,
        "load_average_after": os.getloadavg(),
        "findings": {c: counts.get(c, 0) for c in FINDINGS},
        "outcomes": dict(codes.most_common()),
        "commands": dict(commands_seen),
        "command_seconds": {k: round(v, 1) for k, v in command_seconds.most_common()},
        "input_kinds": dict(kinds_seen),
        "mutation_kinds": dict(mutations_seen),
        "slowest": sorted(((r["seconds"], r["index"], r["command"]) for r in results), reverse=True)[:5],
        "details": findings,
        "results": results,
    }


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="bk_fuzz_run", description="The bearingkit mutation fuzz.")
    p.add_argument("--seed", type=int, default=None, help="seed (default: today's date, YYYYMMDD)")
    p.add_argument("--n", type=int, default=300, help="mutants")
    p.add_argument("--start", type=int, default=0, help="first mutant index")
    p.add_argument("--only", type=int, action="append", default=None, help="run only this index (repeatable)")
    p.add_argument("--workers", type=int, default=None, help="worker processes (default: cores)")
    p.add_argument("--hang", type=float, default=HANG_SECONDS, help="seconds after which a mutant is a hang")
    p.add_argument("--json", default=None, help="write the summary (with every finding) to this file")
    a = p.parse_args(argv)
    seed = default_seed() if a.seed is None else a.seed
    print(f"bearingkit fuzz: seed {seed}, {len(a.only) if a.only else a.n} mutants", flush=True)
    s = fuzz(seed, a.n, a.workers, a.hang, a.start, only=a.only)
    for r in s["details"][:50]:
        print(f"  #{r['index']} {r['command']} {r['argv']} {r['mutations'][:3]}: {r['problems'][:2]}")
        if a.only:
            print(f"    {r['excerpt']}")
    print(
        f"seed {seed}: {s['mutants']} mutants in {s['seconds']:.0f} s on {s['workers']} workers "
        f"(load average {s['load_average_before'][0]:.1f} before, {s['load_average_peak']:.1f} peak); "
        "findings: " + ", ".join(f"{k} {v}" for k, v in s["findings"].items())
    )
    print(f"outcomes: {s['outcomes']}")
    print(f"commands: {s['commands']}")
    print(f"seconds by command: {s['command_seconds']}")
    print(f"input kinds: {s['input_kinds']}")
    print(f"mutation kinds: {s['mutation_kinds']}")
    if a.json:
        Path(a.json).write_text(json.dumps(s, indent=1, default=str), encoding="utf-8")
    return 1 if any(s["findings"].values()) else 0


if __name__ == "__main__":
    raise SystemExit(main())
