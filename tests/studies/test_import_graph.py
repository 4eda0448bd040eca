"""No import circles inside bearingkit.studies, counting the imports inside functions too.

A circle hidden in function bodies (runner ↔ optimize) works at run time but ties the two modules
together: neither can be read, tested or moved alone (design.md §1: no circles, not even in a folder).
"""

import ast
from pathlib import Path

import bearingkit.studies

PACKAGE = Path(bearingkit.studies.__file__).resolve().parent


def _imports(path: Path) -> set[str]:
    """Modules of bearingkit.studies that ``path`` imports anywhere (top level or in a function)."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module:
            if node.module == "bearingkit.studies":
                found |= {a.name for a in node.names}
            elif node.module.startswith("bearingkit.studies."):
                found.add(node.module.split(".")[2])
        elif isinstance(node, ast.Import):
            found |= {a.name.split(".")[2] for a in node.names if a.name.startswith("bearingkit.studies.")}
    return found


def _graph() -> dict[str, set[str]]:
    mods = {p.stem for p in PACKAGE.glob("*.py")}
    return {p.stem: _imports(p) & mods for p in PACKAGE.glob("*.py")}


def _cycle(graph):
    state = dict.fromkeys(graph, 0)

    def visit(m, path):
        state[m] = 1
        for n in sorted(graph[m]):
            if state[n] == 1:
                return [*path[path.index(n) :], n] if n in path else [m, n]
            if state[n] == 0 and (c := visit(n, [*path, n])):
                return c
        state[m] = 2
        return None

    for m in sorted(graph):
        if state[m] == 0 and (c := visit(m, [m])):
            return c
    return None


def test_the_graph_sees_function_level_imports():
    graph = _graph()
    assert "cases" in graph["optimize"], "optimize takes StudyResult and the fingerprint from cases"
    assert "optimize" in graph["runner"]


def test_no_import_circle_in_studies():
    cycle = _cycle(_graph())
    assert cycle is None, " -> ".join(cycle)
