"""Every public physics function documents each parameter (with its unit in brackets) and a source."""

import importlib
import inspect
import pkgutil
import re

import pytest

import bearingkit.physics as physics

#: Every module under physics/, its sub-packages included (walk_packages recurses).
MODULES = [
    importlib.import_module(m.name)
    for m in pkgutil.walk_packages(physics.__path__, prefix="bearingkit.physics.")
    if not m.ispkg
]
YEAR = re.compile(r"(1[89]\d\d|20[0-3]\d)")


def _public_functions():
    for mod in MODULES:
        for name, fn in inspect.getmembers(mod, inspect.isfunction):
            if fn.__module__ == mod.__name__ and not name.startswith("_"):
                yield pytest.param(fn, id=f"{mod.__name__.removeprefix('bearingkit.physics.')}.{name}")


@pytest.mark.parametrize("fn", list(_public_functions()))
def test_physics_function_docstring(fn):
    doc = inspect.getdoc(fn) or ""
    assert doc, "no docstring"
    params = [
        p
        for p in inspect.signature(fn).parameters.values()
        if p.kind not in (p.VAR_KEYWORD, p.VAR_POSITIONAL)
    ]
    if params:
        assert "Parameters" in doc, "no Parameters section"
        for p in params:
            assert re.search(rf"^\s*{p.name}\b", doc, re.M) or re.search(rf"\b{p.name}\b", doc), (
                f"{p.name} undocumented"
            )
    module_doc = inspect.getdoc(inspect.getmodule(fn)) or ""
    assert YEAR.search(doc) or YEAR.search(module_doc), "no dated reference in the function or its module"


@pytest.mark.parametrize("mod", MODULES, ids=lambda m: m.__name__)
def test_physics_module_says_si(mod):
    doc = inspect.getdoc(mod) or ""
    assert "SI" in doc or "units" in doc.lower(), "module docstring must state the unit system"
