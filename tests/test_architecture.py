"""The import structure of src/bearingkit: no circles, and imports only from the same or a lower layer.

The layer order is docs/architecture.md's, written once here (top first). A module may import modules
of its own layer or of any layer below; never one above. Every ``import`` statement counts, those
inside functions too (a lazy import is still a dependency). The root package ``bearingkit/__init__.py``
is the library's face and may re-export from any layer.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
PACKAGE = SRC / "bearingkit"

#: Layers from the top (faces) to the bottom (constants, errors); first match of the module path wins.
LAYERS: tuple[tuple[str, ...], ...] = (
    ("app", "cli", "__main__"),
    ("papers",),
    ("report",),
    ("studies",),
    ("validation",),
    ("pipeline", "systems"),
    ("io", "catalogue"),
    ("bearings",),
    ("analysis",),
    ("rows", "rings"),
    ("physics",),
    ("materials", "lubricants", "hardness"),
    ("units", "errors", "references", "checks", "data", "lazy", "extras", "paths", "display", "budget"),
)


def layer_of(module: str) -> int | None:
    """Index of the layer of ``bearingkit.x.y`` (0 = top), None for the root package."""
    parts = module.split(".")
    if len(parts) < 2:
        return None
    for i, names in enumerate(LAYERS):
        if parts[1] in names:
            return i
    raise AssertionError(f"{module} is in no layer of tests/test_architecture.py: add its folder to LAYERS")


def modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        name = ".".join(path.relative_to(SRC).with_suffix("").parts)
        out[name.removesuffix(".__init__")] = path
    return out


def _resolve(name: str, known: dict) -> str | None:
    while name and name not in known:
        name = name.rpartition(".")[0]
    return name or None


def imports(module: str, path: Path, known: dict) -> set[str]:
    """Modules of bearingkit that ``module`` imports (file level, every statement)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*up, base] if base else up)
            # ``from pkg import sub`` depends on pkg.sub; ``from pkg import name`` on pkg itself
            targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in known else base for a in node.names]
        else:
            continue
        for t in targets:
            if t.startswith("bearingkit."):
                hit = _resolve(t, known)
                if hit and hit not in (module, "bearingkit"):  # the root package is the face, not a layer
                    found.add(hit)
    return found


def graph() -> dict[str, set[str]]:
    known = modules()
    return {m: imports(m, p, known) for m, p in known.items() if m != "bearingkit"}


def circles(g: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in g[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in g:
        if v not in index:
            visit(v)
    return out


def upward(g: dict[str, set[str]]) -> list[str]:
    bad = []
    for m, deps in g.items():
        lm = layer_of(m)
        if lm is None:
            continue
        for d in deps:
            ld = layer_of(d)
            if ld is not None and ld < lm:
                bad.append(f"{m} (layer {lm}) imports {d} (layer {ld})")
    return sorted(bad)


def test_no_import_circles():
    assert circles(graph()) == []


def test_imports_point_down_only():
    assert upward(graph()) == []


def test_the_checks_can_fail():
    """The two checks find a planted circle and a planted upward import."""
    g = {"bearingkit.rows.a": {"bearingkit.rows.b"}, "bearingkit.rows.b": {"bearingkit.rows.a"}}
    assert circles(g) == [["bearingkit.rows.a", "bearingkit.rows.b"]]
    g = {"bearingkit.physics.x": {"bearingkit.pipeline.y"}, "bearingkit.pipeline.y": set()}
    assert upward(g) == ["bearingkit.physics.x (layer 10) imports bearingkit.pipeline.y (layer 5)"]


def test_every_module_is_in_a_layer():
    for m in modules():
        layer_of(m)  # raises for a folder the layer list does not know


@pytest.mark.parametrize("folder", ["studies"])
def test_generic_machinery_holds_no_paper_module(folder):
    """studies/ is generic: no module names a seed paper (papers/ holds them)."""
    for path in (PACKAGE / folder).rglob("*.py"):
        text = path.read_text(encoding="utf-8").lower()
        for needle in ("seed0", "tian2025", "liu2022", "li2025", "zheng2022"):
            assert needle not in text, f"{path.name} mentions {needle}"


#: Inside a package that holds sub-packages: the order of its parts (direct sub-packages and modules),
#: top first. A module of one part may import a module of the same part or of a part in a LOWER layer,
#: never one of its own layer or above (parts of one layer are independent). ``__init__`` and
#: ``__main__`` are the package's faces and may import any part.
SUBLAYERS: dict[str, tuple[tuple[str, ...], ...]] = {
    "app": (
        ("server",),
        ("api",),
        ("workbench",),
        ("sweep",),
        ("form", "store"),
        ("common",),
    ),
    "app.workbench": (
        ("routes",),
        ("studies",),
        ("catalogue", "duty", "jobs", "systems"),
    ),
    "analysis": (
        ("truncation",),
        ("rating", "friction"),
        ("flexible", "structure", "slewing", "scatter", "clearance", "lubrication", "subsurface"),
        ("solver",),
    ),
    "analysis.solver": (
        ("quasistatic",),
        ("options",),
        ("backend",),
        ("compiled_newton",),
        ("compiled_linalg",),
        ("newton", "coarse", "speed"),
        ("cone", "solution"),
        ("model", "threads"),
    ),
    "rows": (
        ("ball", "cylindrical", "tapered", "threaded", "self_aligning"),
        ("base", "numba_cache"),
    ),
    "studies": (
        ("run",),
        ("definition",),
        ("generic",),
        ("evaluators",),
        ("designs", "results"),
    ),
    "io": (
        ("loader", "rexs"),
        ("build", "load_cases", "export"),
        ("optional_sections",),
        ("messages",),
        ("schema",),
        ("sections",),
        ("geometries", "schema_hardness"),
        ("fields", "reading"),
    ),
}
#: The most modules (``__init__.py`` aside) one folder may hold before it wants sub-packages by subject.
MAX_MODULES_PER_FOLDER = 12


def _part(package: str, module: str) -> str | None:
    """The part of ``package`` that ``module`` belongs to (None: the package's ``__init__``/``__main__``)."""
    rest = module[len("bearingkit." + package) + 1 :].split(".")
    return None if rest[0] in ("", "__main__") else rest[0]


def sideways(g: dict[str, set[str]], sublayers=None) -> list[str]:
    """Imports inside a package with sub-layers that go up or across its layer order."""
    sublayers = SUBLAYERS if sublayers is None else sublayers
    bad = []
    for package, order in sublayers.items():
        rank = {name: i for i, names in enumerate(order) for name in names}
        prefix = f"bearingkit.{package}."
        for m, deps in g.items():
            if not m.startswith(prefix) or (pm := _part(package, m)) is None:
                continue
            for d in deps:
                if not d.startswith(prefix) or (pd := _part(package, d)) is None or pd == pm:
                    continue
                if rank[pd] <= rank[pm]:
                    bad.append(f"{m} ({package}: {pm}) imports {d} ({pd}, not in a lower layer)")
    return sorted(bad)


def test_sub_packages_keep_their_layer_order():
    assert sideways(graph()) == []


def test_every_part_of_a_layered_package_is_placed():
    """Each sub-package or module of a package in SUBLAYERS has its place (a new one must be given one)."""
    for package, order in SUBLAYERS.items():
        folder = PACKAGE.joinpath(*package.split("."))
        parts = {p.stem for p in folder.glob("*.py")}
        parts |= {p.name for p in folder.iterdir() if (p / "__init__.py").exists()}
        parts -= {"__init__", "__main__"}
        placed = {name for names in order for name in names}
        assert parts == placed, f"{package}: unplaced {sorted(parts - placed)}, gone {sorted(placed - parts)}"


def test_the_sub_layer_check_can_fail():
    """The check finds a planted import across one layer (two kinds) and one upward (solver to rating)."""
    g = {"bearingkit.rows.ball.row": {"bearingkit.rows.tapered.kernel"}}
    assert sideways(g) == [
        "bearingkit.rows.ball.row (rows: ball) imports bearingkit.rows.tapered.kernel"
        " (tapered, not in a lower layer)"
    ]
    g = {"bearingkit.analysis.solver.model": {"bearingkit.analysis.rating.assembly"}}
    assert len(sideways(g)) == 1
    g = {"bearingkit.analysis.rating.assembly": {"bearingkit.analysis.solver.model"}}
    assert sideways(g) == []


def test_folders_stay_small():
    """A folder of more than ~12 modules wants sub-packages by subject (design rule)."""
    big = {}
    for folder in [PACKAGE, *(p for p in PACKAGE.rglob("*") if p.is_dir())]:
        n = len([p for p in folder.glob("*.py") if p.name != "__init__.py"])
        if n > MAX_MODULES_PER_FOLDER:
            big[str(folder.relative_to(SRC))] = n
    assert big == {}


def test_modules_stay_small():
    """A module past 600 lines holds two ideas (design rule, the hard limit here since issue 31): split it."""
    long = {p.name: n for p in PACKAGE.rglob("*.py") if (n := len(p.read_text().splitlines())) > 600}
    assert long == {}
