"""What the fuzz sends: mutants of every example file, designations, command-line values, paths and
requests to the web app, each made from ``(seed, index)`` alone (any mutant can be made again).

The inputs are discovered, not listed: every ``examples/**/*.toml`` is an input, its kind read from its
top table (``[bearing]``, ``[shaft]``, ``[study]``, or any other table a later input file brings); the
commands and their options come from the typer app (:func:`commands`), the app's routes from the
FastAPI app. A command, option, input file or route added later is fuzzed without a change here; what
is known about a name (good values of ``--speed``, which file kind a help text asks for) only makes
the mutants more likely to pass the first checks and reach deeper code.

Mutation kinds (:data:`FILE_MUTATIONS`): deleted keys and sections, renamed keys (typos), wrong types,
magnitudes 1e-12 … 1e12, NaN/inf, unit swaps, unicode, deep nesting, huge arrays, many load cases,
truncated text, and values chosen by their key's name: paths (``~/.bashrc``, ``/etc/passwd``, NUL,
names past 255 bytes), milli-newton loads, huge speeds, temperatures below absolute zero, quantiles
NaN/1.5, designations thousands of characters long, lists of tables repeated (bearings of a shaft, bins,
tolerances, plots, factors).
"""

from __future__ import annotations

import copy
import datetime
import json
import math
import random
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def example_files() -> dict[str, tuple[str, Path, dict]]:
    """Every example input: name → (kind, path, parsed document); kind = its first top table."""
    out = {}
    for path in sorted(EXAMPLES.rglob("*.toml")):
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except (tomllib.TOMLDecodeError, UnicodeDecodeError):
            continue
        tables = [k for k, v in data.items() if isinstance(v, dict)]
        kind = next((k for k in ("study", "shaft", "bearing") if k in data), tables[0] if tables else "other")
        out[str(path.relative_to(EXAMPLES))] = (kind, path, data)
    return out


# ------------------------------------------------------------------------------------ value pools
UNITS = ["N", "kN", "mm", "m", "um", "N*m", "rpm", "deg", "degC", "GPa", "kg", "s", "kn", "KN", "Nm", "MM"]
UNITS += ["furlong", "%", "1/s", "", "m/s", "kg*m", "N**2", "°", "K", "degF", "rad/s", "Pa", "W"]
UNICODE = [
    "５ kN",  # fullwidth digit
    "5 kN\u200b",  # zero-width space
    "5\u00a0kN",  # no-break space
    "\u202e5 kN",  # right-to-left override
    "5 µm",
    "😀",
    "名前",
    "Ø45",
    "a\u0000b",
    "line\nbreak",
    "\u007f",
    "[red]markup[/]",
    "%s%n{0}",
]
WRONG_TYPES = [True, False, 7, -3, 2.5, "text", "", [1, 2], [], {"a": 1}, {}, datetime.date(2020, 1, 1)]
NON_FINITE = ["nan N", "inf kN", "-inf mm", "NaN", "Infinity N", float("nan"), float("inf"), float("-inf")]
#: File names a data file (or the command line) may give: hostile ones and good ones.
PATHS = [
    "~/.bashrc",
    "/etc/passwd",
    "/proc/self/environ",
    "/dev/zero",
    "../../../../../../etc/passwd",
    "dgbb_6209.toml\x00",
    "dgbb\x00_6209.toml",
    "a" * 300 + ".toml",
    "/".join(["d" * 200] * 30) + ".toml",
    ".hidden.toml",
    "../.ssh/config",
    "nope.toml",
    "",
    " ",
    "line\nbreak.toml",
    "dgbb_6209.toml",
    "../dgbb_6209.toml",
    "crb_nu209.toml",
]
DESIGNATIONS = [
    "6209",
    "6205-2RS C3",
    "6205 C3",
    "6308-2RS1/C3",
    "7014 CD/P4ADBB",
    "7209 B DB",
    "NU 209",
    "NU209 ECP",
    "32008",
    "51209",
    "22220",
    "1209",
    "QJ 208",
    "NA4910",
    "618/500",
    "6205-2rs c3",
]
#: Values of options by name that each option takes (the mutants that reach deep code use these)
#: and values it must refuse in one line.
OPTION_GOOD = {
    "--load": ["Fr=5kN", "Fa=1kN", "Fx=3kN", "My=600N*m", "F_x=2 kN", "Fz=0.001N", "Fr=0.01N"],
    "--speed": ["3000rpm", "100 rpm", "-1500rpm", "0rpm", "2021rpm", "12000rpm"],
    "--temperature": ["60degC", "20 degC", "400 K", "-40degC"],
    "--lubricant": ["ISO_VG100", "ISO_VG32", "ISO_VG68"],
    "--model": ["components", "skf", "palmgren", "trb", "slewing"],
    "--friction-model": ["components", "skf", "palmgren"],
    "--rotating": ["inner", "outer"],
    "--contamination": ["0.5", "normal_cleanliness", "slight_contamination"],
    "--reliability": ["0.9", "0.99", "0.9995"],
    "--load-rating": ["balls=30kN", "rollers=50kN"],
    "--case": ["radial_4kN", "axial_10kN"],
    "--life": ["20000 h", "5000h"],
    "--s0": ["1", "2"],
    "--count": ["3", "5"],
    "--pattern": ["62*", "7*", "NU*"],
    "--d": ["45", "40mm"],
    "--d-min": ["20"],
    "--d-max": ["60"],
    "--D-min": ["50"],
    "--D-max": ["100", "3.15in"],
    "--B-max": ["30"],
    "--C-min": ["20kN"],
    "--C0-min": ["10kN"],
    "--workers": ["1", "2"],
    "--port": ["8765", "1"],
    "--host": ["127.0.0.1", "::1", "localhost"],
    "--kind": ["deep_groove", "angular_contact", "tapered", "cylindrical"],
}
OPTION_BAD = {
    "--load": ["Fr=1e9kN", "Fr=-3kN", "Fr", "=5kN", "Fr=5kN=3", "Fq=5kN", "Fr=nan kN"],
    "--speed": ["1e9rpm", "5kN", "nan rpm", "1e308rpm"],
    "--temperature": ["-300degC", "1e6degC", "5 kN"],
    "--lubricant": ["nope", "", "ISO_VG100\x00"],
    "--model": ["nope", ""],
    "--friction-model": ["nope"],
    "--rotating": ["both", ""],
    "--contamination": ["2", "-1", "dirty"],
    "--reliability": ["2", "0", "nan"],
    "--load-rating": ["foo=3kN", "balls", "balls=-1kN"],
    "--preload": ["light", "medium", "480N", "heavy!", "-5N", "5 kg"],
    "--case": ["nope", ""],
    "--workers": ["0", "-1", "12", "abc"],
    "--scheduler": ["nonsense", "", "tcp://", "udp://x", "tcp://[::1", "tcp://host:99999"],
    "--allow-plugin": ["os:system", "bk:NOPE", "nomodule"],
    "--port": ["0", "70000", "-1", "abc"],
    "--host": ["", "999.1.1.1", "not-a-host", "0.0.0.0"],
    "--kind": ["nope"],
}
OPTION_VALUES = {k: OPTION_GOOD.get(k, []) + OPTION_BAD.get(k, []) for k in {*OPTION_GOOD, *OPTION_BAD}}
#: Values of an option whose name says it is a dimension (``--d``, ``--D-max``, ``--C-min`` …).
DIMENSION_VALUES = ["40", "45mm", "1.5in", "-1", "nan", "1e308", "5kN", "30kN", "abc", "0"]
GENERIC_VALUES = ["", " ", "0", "-1", "1e308", "nan", "abc", "5kN", "x" * 5000, "\u202e", "a\u0000b"]


def designation(rng: random.Random) -> str:
    """A standard designation, often mutated (long, unicode, NUL, junk suffixes, lower case)."""
    d = rng.choice(DESIGNATIONS)
    how = rng.randrange(9)
    if how == 0:
        return (d * (rng.randint(6000, 10240) // len(d) + 1))[: rng.randint(6000, 10240)]
    if how == 1:
        return d + rng.choice([" XYZ", "/P9", "-ZZZ", " C9", "/", " DBX", "  ", "-"])
    if how == 2:
        return d + rng.choice(UNICODE)
    if how == 3:
        return d.lower()
    if how == 4:
        return "x" * rng.choice((256, 300, 4097)) + d
    return d


# ------------------------------------------------------------------------------ TOML text of a mutant
class Raw(str):
    """TOML text written verbatim as a value (deep nesting)."""


def toml_text(data: dict) -> str:
    """TOML text of a document: top tables as [sections], arrays of tables as [[sections]], the rest
    inline (keys always quoted: mutated keys may hold any character)."""
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


# ---------------------------------------------------------------------------------- file mutations
FILE_MUTATIONS = (
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
    "by_key",
    "repeat_tables",
    "designation",
)
DEEP = [Raw("[" * n + "]" * n) for n in (17, 1000, 5000)] + [
    Raw("{a = " * n + "1" + "}" * n) for n in (17, 1000)
]


def _leaves(obj, path=(), longest: int = 50):
    """Every (path, value), tables and arrays included; huge arrays and deep nests are one leaf."""
    out = [(path, obj)] if path else []
    if len(path) > 32:
        return out
    if isinstance(obj, dict):
        for k, v in obj.items():
            out += _leaves(v, (*path, k), longest)
    elif isinstance(obj, list) and len(obj) <= longest:
        for i, v in enumerate(obj):
            out += _leaves(v, (*path, i), longest)
    return out


def _parent(data, path):
    node = data
    for p in path[:-1]:
        node = node[p]
    return node


def _number_of(value) -> str:
    return value.split()[0] if isinstance(value, str) and value.split() else "1"


def _by_key(key, value, rng: random.Random):
    """A value chosen by what the key names (a path, a load, a speed, a temperature, quantiles …)."""
    k = str(key).lower()
    if k in ("bearing", "file", "path") or k.endswith("_file"):
        return rng.choice(PATHS + DESIGNATIONS[:3])
    if k == "designation":
        return designation(rng)
    if k.startswith(("f_", "m_")) or k in ("load", "axial_load", "radial_load"):
        return rng.choice(["0.001 N", "1e-3 mN", "0 N", "1e-9 N", "1e9 kN", "-0.001 N"])
    if "speed" in k:
        return rng.choice(["1e9 rpm", "1e6 rpm", "2021 rpm", "-3000 rpm", "0 rpm", "1e308 rpm"])
    if "temperature" in k:
        return rng.choice(["-300 degC", "-273.15 degC", "1e6 degC", "0 K", "-1 K"])
    if "quantiles" in k:
        return rng.choice([[float("nan")], [1.5], [0.0], [-0.1], [0.5] * 1000, []])
    if k in ("y", "outputs"):
        return rng.choice([["u_x_m"] * 1000, ["nonexistent_output"], [], "u_x_m", ["converged"]])
    if k in ("x", "series", "response", "output"):
        return rng.choice(["nonexistent", "converged", "u_x_m", "", "geometry.clearance_radial"])
    if k in ("samples", "per_point", "pop_size", "generations", "chunk_size", "n_elements", "n_slices"):
        return rng.choice([0, 1, -1, 10**7, 10**9, 2**63, 3.5])
    if k == "name":
        return rng.choice(["..", "../x", "/abs", "a" * 300, "", "ok_name", "名前", 7])
    if k in ("levels", "values"):
        return rng.choice([[], [1] * 100000, ["1 kN", 5, True], [float("nan")], list(range(5000))])
    return rng.choice(WRONG_TYPES + NON_FINITE[:2])


@dataclass
class FileMutant:
    """A mutated input file: its kind, the example it came from, its text and what was done."""

    kind: str
    origin: str
    text: str
    mutations: list = field(default_factory=list)


def mutate_file(origin: str, kind: str, data: dict, rng: random.Random, huge: int = 20_000) -> FileMutant:
    """One to three mutations of a parsed example (module docstring)."""
    data = copy.deepcopy(data)
    done, truncate = [], False
    for _ in range(rng.choice((1, 1, 2, 3))):
        what = rng.choice(FILE_MUTATIONS)
        if what == "truncate":
            truncate = True
            continue
        done.append(_apply(what, data, rng, huge))
    text = toml_text(data)
    if truncate:
        cut = rng.randrange(len(text) + 1)
        text = text[:cut]
        done.append(f"truncate at {cut}")
    return FileMutant(kind, origin, text, done)


def _apply(what: str, data: dict, rng: random.Random, huge: int) -> str:
    if what == "designation":
        header = data.get("bearing")
        if isinstance(header, dict):
            header["designation"] = designation(rng)
            if rng.random() < 0.7:
                data.pop("geometry", None)
            return "designation"
        what = "by_key"
    if what == "repeat_tables":
        tables = [(p, v) for p, v in _leaves(data) if isinstance(v, list) and v and isinstance(v[0], dict)]
        if tables:
            path, v = rng.choice(tables)
            n = rng.choice((17, 101, 1001))
            _parent(data, path)[path[-1]] = [copy.deepcopy(v[i % len(v)]) for i in range(n)]
            return f"repeat_tables {'.'.join(map(str, path))} x {n}"
        what = "by_key"
    leaves = _leaves(data)
    if not leaves:
        return f"{what}: nothing to mutate"
    path, value = rng.choice(leaves)
    parent, key = _parent(data, path), path[-1]
    where = ".".join(str(p) for p in path)
    if what == "delete":
        parent.pop(key)
    elif what == "rename" and isinstance(parent, dict):
        parent[_typo(str(key), rng)] = parent.pop(key)
    elif what == "wrong_type":
        parent[key] = rng.choice(WRONG_TYPES)
    elif what == "magnitude":
        parent[key] = _magnitude(value, rng)
    elif what == "non_finite":
        parent[key] = rng.choice(NON_FINITE)
    elif what == "unit_swap":
        parent[key] = f"{_number_of(value)} {rng.choice(UNITS)}".strip()
    elif what == "unicode":
        if isinstance(parent, dict) and rng.random() < 0.3:
            parent[rng.choice(UNICODE)] = parent.pop(key)
        else:
            parent[key] = rng.choice(UNICODE)
    elif what == "deep":
        parent[key] = rng.choice(DEEP)
    elif what == "huge_array":
        n = huge
        parent[key] = rng.choice([[13] * n, ["1 kN"] * (n // 5), [[1.5] * 50 for _ in range(n // 50)]])
    elif what == "many_cases":
        cases = data.get("load_cases")
        if isinstance(cases, list) and cases and isinstance(cases[0], dict):
            n = rng.choice((101, 1001, 5000))
            # The copied case keeps only small values: a huge array nested inside it (a drivetrain's
            # torques.sun after huge_array) copied 5000 times made a 500 MB mutant whose making
            # alone ran past the hang limit (seed 20261201, #4179), a finding of the fuzz itself.
            first = {k: v for k, v in cases[0].items() if _small(v)}
            data["load_cases"] = [{**first, "name": f"c{i}"} for i in range(n)]
            where = f"load_cases x {n}"
    elif what == "by_key":
        key_name = key if isinstance(parent, dict) else (path[-2] if len(path) > 1 else key)
        parent[key] = _by_key(key_name, value, rng)
    return f"{what} {where}"


def _small(value, limit: int = 2_000) -> bool:
    """Whether a value, however nested, writes as fewer than ``limit`` characters."""
    return len(repr(value)) < limit


def _typo(key: str, rng: random.Random) -> str:
    if len(key) < 2:
        return key + "x"
    i = rng.randrange(len(key) - 1)
    return rng.choice([key[:i] + key[i + 1 :], key[:i] + key[i + 1] + key[i] + key[i + 2 :], key.upper()])


def _magnitude(value, rng: random.Random):
    power = rng.randint(-12, 12)
    sign = rng.choice((1, 1, -1))
    if isinstance(value, str) and " " in value.strip():
        return f"{sign * 10.0**power:g} {value.split(maxsplit=1)[1]}"
    if isinstance(value, int) and not isinstance(value, bool):
        return sign * 10 ** abs(power)
    return sign * 10.0**power


# ------------------------------------------------------------------------------ app requests
def app_requests() -> list[tuple[str, str, dict | None]]:
    """Good requests of the web app (method, path, JSON body) that the mutants start from."""
    example = {"kind": "example", "name": "dgbb_6209.toml"}
    form = {"source": example, "loads": {"F_x": "6 kN"}, "speed": "3000 rpm", "temperature": "70 degC"}
    text = (EXAMPLES / "dgbb_6209.toml").read_text(encoding="utf-8")
    return [
        ("GET", "/api/meta", None),
        ("GET", "/", None),
        ("POST", "/api/open", {"source": example}),
        ("POST", "/api/open", {"source": {"kind": "designation", "name": "6205-2RS C3"}}),
        ("POST", "/api/open", {"source": {"kind": "upload", "name": "b.toml", "text": text}}),
        ("POST", "/api/analyze", form),
        ("POST", "/api/analyze", {**form, "friction_model": "skf", "lubricant": "ISO_VG68"}),
        (
            "POST",
            "/api/sweep",
            {"base": form, "factor": "speed", "start": "100 rpm", "stop": "3000 rpm", "n": 3},
        ),
        ("GET", "/api/download/0123456789abcdef.json", None),
        ("GET", "/api/figure/0123456789abcdef/pressure.svg", None),
    ]


#: Path forms that must never leave the app's folders (each gives 404).
TRAVERSALS = [
    "../../../etc/passwd",
    "..%2f..%2f..%2fetc%2fpasswd",
    "%2e%2e/%2e%2e/etc/passwd",
    "....//....//etc/passwd",
    "..\\..\\windows\\win.ini",
    "/etc/passwd",
    "%252e%252e%252fetc%252fpasswd",
    "..%c0%af..%c0%afetc/passwd",
]
HOSTS = ["evil.example", "127.0.0.1.nip.io", "localhost:8765", "127.0.0.1", "[::1]", "", "a" * 300]


def mutate_request(rng: random.Random, routes: list[str]) -> dict:
    """A mutated request: a good one with a mutated body, path, host or content type."""
    method, path, body = rng.choice(app_requests())
    headers = {}
    how = rng.randrange(6)
    raw = None
    if how == 0 and body is not None:
        doc = {"body": copy.deepcopy(body)}
        _apply(
            rng.choice(("delete", "wrong_type", "unicode", "non_finite", "by_key", "huge_array")),
            doc,
            rng,
            2000,
        )
        body = doc.get("body")
    elif how == 1:
        prefix = rng.choice(routes or ["/api/download/"])
        path = prefix.split("{")[0] + rng.choice(TRAVERSALS)
    elif how == 2:
        headers["host"] = rng.choice(HOSTS)
    elif how == 3 and body is not None:
        headers["content-type"] = rng.choice(
            ["text/plain", "application/x-www-form-urlencoded", "multipart/form-data"]
        )
    elif how == 4:
        raw = rng.choice(
            [b"{" * 5000 + b"}" * 5000, b"[" * 100000, b"\xff\xfe", b"", b"null", b"x" * 600_000]
        )
        method = "POST"
        path = rng.choice(["/api/analyze", "/api/open", "/api/sweep"])
    return {"method": method, "path": path, "json": body, "raw": raw, "headers": headers}
