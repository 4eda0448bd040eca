"""Mutated example files through the loader and through the command line (issues 23 and 24).

Two fuzzers:

- hypothesis drops, renames or replaces one value of an example (random strings and numbers, NaN and
  infinities, negated, huge, wrong dimension) and runs loader → solver → JSON export: either finite
  numbers only or the one-line InputError;
- a seeded generator (:class:`Mutator`) applies one to three mutations to EVERY example file —
  deleted keys and sections, wrong types, extreme magnitudes (1e-12 … 1e12), NaN/inf strings, unit
  swaps, unicode, deep nesting, huge arrays, typos, truncation of the text — writes the mutant as
  TOML and runs it through ``analyze``, ``rating``, ``friction`` and ``report`` in-process (typer's
  CliRunner), the shaft files through ``shaft``. Every run must end with exit code 0, 1 or 2 and no
  traceback; no output may hold NaN or Infinity; a failure is exactly one stderr line
  ``error: FILE: …`` naming the file and a field (or a file-level problem); a failed report leaves
  nothing behind. The study files go through the study loader's validation the same way.
  :data:`N_MUTANTS` run in the normal suite, 10,000 in the ``slow`` test.
"""

from __future__ import annotations

import copy
import datetime
import json
import math
import random
import re
import tomllib
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import MAX_MESSAGE_CHARS, InputError
from bearingkit.io import export
from bearingkit.io.loader import BUILDERS, from_dict
from bearingkit.units import UNIT_LOOKALIKES

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TEXT = {p.stem: p.read_text(encoding="utf-8") for p in sorted(EXAMPLES.glob("*.toml"))}
DATA = {k: tomllib.loads(v) for k, v in TEXT.items()}
DATA = {k: v for k, v in DATA.items() if v.get("bearing", {}).get("type") in BUILDERS}
STUDY_TEXT = {p.stem: p.read_text(encoding="utf-8") for p in sorted((EXAMPLES / "studies").glob("*.toml"))}
#: Shaft files (systems of several bearings, the ``shaft`` command); they name bearing files nearby.
SHAFT_DATA = {
    p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(EXAMPLES.glob("shaft_*.toml"))
}
SOURCE = "mutant.toml"
UNITS = ["N", "kN", "mm", "m", "um", "N*m", "rpm", "deg", "degC", "GPa", "kg", "s", "kg/m^3", "", "furlong"]
#: Mutants per run of the normal suite (each through one command; the slow test runs 10,000).
N_MUTANTS = 200


def _leaves(obj, path=()):
    """Every (path, value) of a leaf, tables and arrays included as leaves themselves."""
    out = [(path, obj)] if path else []
    if isinstance(obj, dict):
        for k, v in obj.items():
            out += _leaves(v, (*path, k))
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            out += _leaves(v, (*path, i))
    return out


def _parent(data, path):
    node = data
    for p in path[:-1]:
        node = node[p]
    return node


def _negated(value):
    if isinstance(value, bool):
        return not value
    if isinstance(value, (int, float)):
        return -value
    if isinstance(value, str):
        return value[1:] if value.startswith("-") else "-" + value
    return value


def _number_of(value) -> str:
    text = value.split()[0] if isinstance(value, str) and value.split() else "1"
    return text


replacement = st.one_of(
    st.text(max_size=12),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**12), max_value=10**12),
    st.booleans(),
    st.sampled_from(UNITS).map(lambda u: f"1e30 {u}"),
    st.sampled_from(UNITS).map(lambda u: f"-1e-30 {u}"),
    st.lists(st.integers(), max_size=2),
)


@st.composite
def mutants(draw):
    name = draw(st.sampled_from(sorted(DATA)))
    data = copy.deepcopy(DATA[name])
    path, value = draw(st.sampled_from(_leaves(data)))
    parent = _parent(data, path)
    key = path[-1]
    kind = draw(st.sampled_from(["drop", "rename", "replace", "negate", "wrong_unit", "huge"]))
    if kind == "drop":
        if isinstance(parent, list):
            parent.pop(key)
        else:
            del parent[key]
    elif kind == "rename" and isinstance(parent, dict):
        parent[draw(st.sampled_from(["F_q", "diameter", "Type", "ball_diameter", "free"]))] = parent.pop(key)
    elif kind == "negate":
        parent[key] = _negated(value)
    elif kind == "wrong_unit":
        parent[key] = f"{_number_of(value)} {draw(st.sampled_from(UNITS))}"
    elif kind == "huge":
        parent[key] = (
            f"1e12 {value.split(maxsplit=1)[1]}" if isinstance(value, str) and " " in value else 1e300
        )
    else:
        parent[key] = draw(replacement)
    return name, path, kind, data


def _assert_one_line(exc: InputError):
    msg = str(exc)
    assert "\n" not in msg, msg
    assert msg.startswith(f"{SOURCE}: "), msg


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutants())
def test_mutated_file_gives_result_or_one_line_error(mutant):
    name, path, kind, data = mutant
    try:
        bearing = from_dict(data, SOURCE)
        if not bearing.cases:
            return
        result = bearing.solve()
        out = export.analysis_dict(bearing, result)
    except InputError as exc:
        _assert_one_line(exc)
        return
    assert export.non_finite_paths(out) == [], (name, path, kind)
    export.to_json(out)


def test_nan_and_inf_in_toml_are_refused():
    """TOML spells nan and inf; every numeric field must refuse them with the one-line error."""
    data = copy.deepcopy(DATA["seed000_composite"])
    for value in (float("nan"), float("inf"), "nan mm", "inf kN"):
        data["geometry"]["groove_curvature"] = value
        try:
            from_dict(data, SOURCE)
        except InputError as exc:
            _assert_one_line(exc)
            assert "groove_curvature" in str(exc)
        else:  # pragma: no cover - the assertion is the test
            raise AssertionError(f"{value!r} accepted")


# ---------------------------------------------------------------------------------------------
# The seeded generator: mutants of every example file, written as TOML text.
# ---------------------------------------------------------------------------------------------
def _short_leaves(obj, path=(), longest: int = 50):
    """As :func:`_leaves`, without descending into arrays longer than ``longest`` (a huge array is
    one leaf: mutants stay small enough to write, and the next mutation need not visit 100,000 items)."""
    out = [(path, obj)] if path else []
    if len(path) > 32:  # a deeply nested mutant is one leaf too (a later mutation would recurse 1000 deep)
        return out
    if isinstance(obj, dict):
        for k, v in obj.items():
            out += _short_leaves(v, (*path, k), longest)
    elif isinstance(obj, list) and len(obj) <= longest:
        for i, v in enumerate(obj):
            out += _short_leaves(v, (*path, i), longest)
    return out


class Raw(str):
    """TOML text written verbatim as a value (deep nesting, malformed numbers)."""


def toml_text(data: dict) -> str:
    """TOML text of a parsed file: top-level tables as [sections], arrays of tables as [[sections]],
    everything below as inline values (keys always quoted: mutated keys may hold any character)."""
    head, body = [], []
    for k, v in data.items():
        if isinstance(v, dict):
            body.append(f"\n[{_key(k)}]")
            body += [f"{_key(kk)} = {_value(vv)}" for kk, vv in v.items()]
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for item in v:
                body.append(f"\n[[{_key(k)}]]")
                body += [f"{_key(kk)} = {_value(vv)}" for kk, vv in item.items()]
        else:
            head.append(f"{_key(k)} = {_value(v)}")
    return "\n".join(head + body) + "\n"


def _key(k) -> str:
    return json.dumps(str(k), ensure_ascii=False)


def _value(v) -> str:
    if isinstance(v, Raw):
        return str(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if v != v else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, (datetime.date, datetime.datetime, datetime.time)):
        return v.isoformat()
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + "}"
    return "[" + ", ".join(_value(x) for x in v) + "]"


ALL_UNITS = sorted({u for names in UNIT_LOOKALIKES.values() for u in names})
SWAP_UNITS = [*ALL_UNITS, "kn", "KN", "Nm", "MM", "furlong", "%", "1/s", "", "m/s", "kg*m", "N**2", "°"]
UNICODE = [
    "５ kN",  # fullwidth digit
    "5 kN\u200b",  # zero-width space
    "5\u00a0kN",  # no-break space
    "\u202e5 kN",  # right-to-left override
    "5 µm",
    "5 μm",
    "😀",
    "名前",
    "Ø45",
    "a\u0000b",
    "line\nbreak",
    "\ud800",  # lone surrogate: not valid TOML
    "\u007f",
]
WRONG_TYPES = [True, False, 7, -3, 2.5, "text", "", [1, 2], [], {"a": 1}, {}, datetime.date(2020, 1, 1)]
NON_FINITE = ["nan N", "inf kN", "-inf mm", "NaN", "Infinity N", float("nan"), float("inf"), float("-inf")]
DEEP = [Raw("[" * n + "]" * n) for n in (17, 1000, 5000)] + [
    Raw("{a = " * n + "1" + "}" * n) for n in (17, 1000)
]
MUTATIONS = (
    "delete",
    "rename",
    "wrong_type",
    "magnitude",
    "non_finite",
    "unit_swap",
    "unicode",
    "deep",
    "huge_array",
    "many_cases",
    "truncate",
)


@dataclass
class Mutant:
    """One mutated file: its text, the mutations applied, and whether it came from a study file."""

    name: str
    text: str
    mutations: list = field(default_factory=list)
    study: bool = False


class Mutator:
    """Seeded mutants of the example files (one to three mutations each)."""

    def __init__(self, seed: int, huge: int = 100_000):
        self.rng = random.Random(seed)
        self.huge = huge  # items of a huge array (the normal suite uses fewer: TOML parses ~10^5/s)

    def bearing(self, name: str, max_cases: int | None = None) -> Mutant:
        data = copy.deepcopy(DATA[name])
        if max_cases is not None and isinstance(data.get("load_cases"), list):
            data["load_cases"] = data["load_cases"][:max_cases]
        return self._mutate(name, data, study=False)

    def shaft(self, name: str) -> Mutant:
        return self._mutate(name, copy.deepcopy(SHAFT_DATA[name]), study=False)

    def study(self, name: str) -> Mutant:
        return self._mutate(name, tomllib.loads(STUDY_TEXT[name]), study=True)

    def _mutate(self, name: str, data: dict, study: bool) -> Mutant:
        rng = self.rng
        done = []
        truncate = False
        for _ in range(rng.choice((1, 1, 2, 3))):
            kind = rng.choice(MUTATIONS)
            if kind == "truncate":
                truncate = True
            else:
                done.append(self._apply(kind, data))
        text = toml_text(data)
        if truncate:
            cut = rng.randrange(len(text) + 1)
            text = text[:cut]
            done.append(f"truncate at {cut}")
        return Mutant(name, text, done, study)

    def _apply(self, kind: str, data: dict) -> str:
        rng = self.rng
        leaves = _short_leaves(data)
        if not leaves:
            return f"{kind}: nothing to mutate"
        path, value = rng.choice(leaves)
        parent, key = _parent(data, path), path[-1]
        where = ".".join(str(p) for p in path)
        if kind == "delete":
            parent.pop(key)
        elif kind == "rename" and isinstance(parent, dict):
            parent[self._typo(str(key))] = parent.pop(key)
        elif kind == "wrong_type":
            parent[key] = rng.choice(WRONG_TYPES)
        elif kind == "magnitude":
            parent[key] = self._magnitude(value)
        elif kind == "non_finite":
            parent[key] = rng.choice(NON_FINITE)
        elif kind == "unit_swap":
            parent[key] = f"{_number_of(value)} {rng.choice(SWAP_UNITS)}".strip()
        elif kind == "unicode":
            if isinstance(parent, dict) and rng.random() < 0.3:
                parent[rng.choice(UNICODE)] = parent.pop(key)
            else:
                parent[key] = rng.choice(UNICODE)
        elif kind == "deep":
            parent[key] = rng.choice(DEEP)
        elif kind == "huge_array":
            n = self.huge
            huge = rng.choice(
                [lambda: [13] * n, lambda: ["1 kN"] * (n // 5), lambda: [[1.5] * 50 for _ in range(n // 50)]]
            )
            parent[key] = huge()
        elif kind == "many_cases":
            cases = data.get("load_cases")
            if isinstance(cases, list) and cases:
                n = rng.choice((101, 1001, 5000))
                # copies of the first case without its huge arrays (5,000 × 20,000 items is 200 MB of text)
                first = cases[0] if isinstance(cases[0], dict) else {"F_x": "1 kN"}
                first = {k: v for k, v in first.items() if not (isinstance(v, list) and len(v) > 50)}
                data["load_cases"] = [{**first, "name": f"c{i}"} for i in range(n)]
                where = f"load_cases × {n}"
        return f"{kind} {where}"

    def _typo(self, key: str) -> str:
        rng = self.rng
        if len(key) < 2:
            return key + "x"
        i = rng.randrange(len(key) - 1)
        return rng.choice([key[:i] + key[i + 1 :], key[:i] + key[i + 1] + key[i] + key[i + 2 :], key.upper()])

    def _magnitude(self, value):
        rng = self.rng
        power = rng.randint(-12, 12)
        sign = rng.choice((1, 1, -1))
        if isinstance(value, str) and " " in value.strip():
            return f"{sign * 10.0**power:g} {value.split(maxsplit=1)[1]}"
        if isinstance(value, int) and not isinstance(value, bool):
            return sign * 10 ** abs(power)
        return sign * 10.0**power


# ---------------------------------------------------------------------------------------------
# Running a mutant through the command line, and what every run must satisfy.
# ---------------------------------------------------------------------------------------------
#: Commands and their options; report runs on at most one load case (it draws two figures per case).
COMMANDS = {
    "analyze": [],
    "analyze --json": ["--json"],
    "rating": ["--speed", "1000rpm"],
    "rating --json": ["--json"],
    "friction": ["--lubricant", "ISO_VG100", "--speed", "100rpm", "--json"],
    "friction table": ["--lubricant", "ISO_VG100", "--speed", "100rpm"],
    "report": [],
    "shaft": [],
    "shaft --json": ["--json"],
}
_NON_FINITE_TEXT = re.compile(r"(?<![A-Za-z0-9_])[-+]?(?:nan|inf|infinity)(?![A-Za-z0-9_])", re.IGNORECASE)
_DATA_URI = re.compile(r"data:[a-z/+]+;base64,[A-Za-z0-9+/=]+")
runner = CliRunner()


def _reject_constant(name):
    raise ValueError(f"{name} in JSON output")


def check_command(mutant: Mutant, command: str, tmp: Path, index: int) -> list[str]:
    """Run ``command`` on the mutant; the list of broken promises (empty: all kept)."""
    _copy_examples(tmp)  # shaft files name bearing files next to them
    path = tmp / f"mutant_{index}.toml"
    path.write_text(mutant.text, encoding="utf-8", errors="surrogatepass")
    out_dir = tmp / f"report_{index}"
    out = out_dir / "report.html"
    name = command.split()[0]
    args = [name, str(path), *COMMANDS[command]] + (["-o", str(out)] if name == "report" else [])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = runner.invoke(app, args)
    problems = []
    if res.exception is not None and not isinstance(res.exception, SystemExit):
        problems.append(f"traceback {type(res.exception).__name__}: {str(res.exception)[:200]}")
    if res.exit_code not in (0, 1, 2):
        problems.append(f"exit code {res.exit_code}")
    numpy_warnings = [str(w.message)[:80] for w in caught if issubclass(w.category, RuntimeWarning)]
    if numpy_warnings:
        problems.append(f"RuntimeWarning {numpy_warnings[0]}")
    stdout, stderr = res.stdout, res.stderr
    if res.exit_code != 0:
        lines = stderr.splitlines()
        if len(lines) != 1 or not lines[0].startswith(f"error: {path}: "):
            problems.append(f"error not one line naming the file: {stderr[:300]!r}")
        elif len(lines[0]) > len(f"error: {path}: ") + MAX_MESSAGE_CHARS:
            problems.append(f"error longer than {MAX_MESSAGE_CHARS} characters")
        elif not _names_a_field(lines[0][len(f"error: {path}: ") :]):
            problems.append(f"error names no field: {lines[0]!r}")
    if "Traceback" in stdout + stderr:
        problems.append("traceback text in the output")
    text_with_names = _NON_FINITE_TEXT.search(mutant.text) is not None  # a name may be "nan"
    if "--json" in args and res.exit_code in (0, 1) and stdout.strip():
        try:
            json.loads(stdout, parse_constant=_reject_constant)
        except ValueError as exc:
            problems.append(f"JSON output: {str(exc)[:100]}")
    elif not text_with_names and _NON_FINITE_TEXT.search(stdout + stderr):
        problems.append(f"NaN/Infinity in the output: {_NON_FINITE_TEXT.search(stdout + stderr).group()!r}")
    if name == "report":
        if res.exit_code != 0 and (out.exists() or (out_dir.exists() and any(out_dir.iterdir()))):
            problems.append("a failed report left files behind")
        if res.exit_code == 0 and out.exists():
            html = _DATA_URI.sub("", out.read_text(encoding="utf-8"))
            if not text_with_names and _NON_FINITE_TEXT.search(html):
                problems.append("NaN/Infinity in the report")
    return problems


#: Words of a message that name a field or a file-level problem.
_FILE_LEVEL = (
    "not valid TOML",
    "cannot read the file",
    "is not UTF-8",
    "nested more than",
    "load case",
    "load_cases",
    "lubricant",
    "geometry",
    "material",
    "bearing",
    "solver",
    "shaft",
    "row '",
    "--",
)
#: "field (value)…" or "field: …"; a key the mutator made up is quoted and may hold spaces ('5 kN').
_FIELD = re.compile(r"^(?:[^\s('\"]|'[^']*'|\"[^\"]*\")+ \(|^[A-Za-z_][\w.\[\]]*: ")


def _names_a_field(message: str) -> bool:
    return bool(_FIELD.match(message)) or any(w in message for w in _FILE_LEVEL)


def _copy_examples(tmp: Path) -> None:
    """The example files in ``tmp`` (once), for the relative paths of shaft and study files."""
    for p in EXAMPLES.glob("*.toml"):
        if not (tmp / p.name).exists():
            (tmp / p.name).write_text(p.read_text(encoding="utf-8"), encoding="utf-8")


def check_study(mutant: Mutant, tmp: Path, index: int) -> list[str]:
    """Validate a mutated study file (the study loader, no run): a definition or one line."""
    from bearingkit.studies.definition.load import load_study

    folder = tmp / "studies"
    folder.mkdir(exist_ok=True)
    _copy_examples(tmp)  # relative bearing paths ("../x.toml") resolve as in examples/
    path = folder / f"study_{index}.toml"
    path.write_text(mutant.text, encoding="utf-8", errors="surrogatepass")
    try:
        load_study(path)
    except InputError as exc:
        msg = str(exc)
        if (
            "\n" in msg
            or not msg.startswith(f"{path}: ")
            or len(msg) > len(str(path)) + 2 + MAX_MESSAGE_CHARS
        ):
            return [f"study error not one line naming the file: {msg[:300]!r}"]
    except Exception as exc:  # anything else is the finding
        return [f"study traceback {type(exc).__name__}: {str(exc)[:200]}"]
    return []


def run_fuzz(
    n: int, seed: int, tmp: Path, report_share=0.03, study_share=0.1, shaft_share=0.04, huge=100_000
):
    """``n`` mutants of every example (round robin), each through one command; the findings."""
    mutator = Mutator(seed, huge)
    rng = random.Random(seed + 1)
    names, studies, shafts = sorted(DATA), sorted(STUDY_TEXT), sorted(SHAFT_DATA)
    commands = [c for c in COMMANDS if c != "report" and not c.startswith("shaft")]
    findings = []
    for i in range(n):
        draw = rng.random()
        if draw < study_share:
            mutant = mutator.study(studies[i % len(studies)])
            problems = check_study(mutant, tmp, i)
            command = "study"
        elif draw < study_share + shaft_share:
            mutant = mutator.shaft(shafts[i % len(shafts)])
            command = rng.choice(["shaft", "shaft --json"])
            problems = check_command(mutant, command, tmp, i)
        elif draw < study_share + shaft_share + report_share:
            mutant = mutator.bearing(names[i % len(names)], max_cases=1)
            command = "report"
            problems = check_command(mutant, command, tmp, i)
        else:
            mutant = mutator.bearing(names[i % len(names)])
            command = rng.choice(commands)
            problems = check_command(mutant, command, tmp, i)
        if problems:
            findings.append((i, mutant.name, command, mutant.mutations, problems))
    return findings


def test_mutants_of_every_example_through_the_commands(tmp_path):
    findings = run_fuzz(N_MUTANTS, seed=2024, tmp=tmp_path, shaft_share=0.02, huge=20_000)
    assert findings == []


@pytest.mark.slow
def test_ten_thousand_mutants_through_the_commands(tmp_path):
    findings = run_fuzz(10_000, seed=7, tmp=tmp_path, shaft_share=0.01, huge=20_000)
    assert findings == []
