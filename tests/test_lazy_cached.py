"""The lock-free cached property (bearingkit.lazy): per instance, computed once, and two instances
computed in two threads at the same time (Python 3.11's functools.cached_property serialised them:
a study's chunks solved one at a time, issue 34)."""

from __future__ import annotations

import ast
import threading
from pathlib import Path

import pytest

from bearingkit.lazy import cached_property

SRC = Path(__file__).resolve().parents[1] / "src" / "bearingkit"


class Counted:
    calls = 0

    def __init__(self, barrier=None, value=1.0):
        self.barrier, self.value = barrier, value

    @cached_property
    def doubled(self):
        """Twice the value."""
        type(self).calls += 1
        if self.barrier is not None:
            self.barrier.wait()  # both instances must be inside the property at once
        return 2 * self.value


def test_value_is_computed_once_per_instance_and_kept():
    Counted.calls = 0
    a, b = Counted(value=3.0), Counted(value=5.0)
    assert (a.doubled, a.doubled, b.doubled) == (6.0, 6.0, 10.0)
    assert Counted.calls == 2
    assert a.__dict__["doubled"] == 6.0
    del a.doubled  # forgets: computed again
    assert a.doubled == 6.0 and Counted.calls == 3
    assert Counted.doubled.__doc__ == "Twice the value."


def test_two_instances_compute_at_the_same_time_in_two_threads():
    """Each thread waits inside the property until the other is inside too: with a lock shared by the
    class attribute (functools on Python 3.11) the second never enters and the barrier times out."""
    barrier = threading.Barrier(2, timeout=10)
    objs = [Counted(barrier, 1.0), Counted(barrier, 2.0)]
    out, errors = {}, []

    def read(i):
        try:
            out[i] = objs[i].doubled
        except Exception as exc:  # reported below
            errors.append(exc)

    threads = [threading.Thread(target=read, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(30)
    assert not errors and out == {0: 2.0, 1: 4.0}


def test_a_name_of_two_attributes_is_refused():
    prop = cached_property(lambda self: 1)
    prop.__set_name__(object, "a")
    with pytest.raises(TypeError, match="cannot be both"):
        prop.__set_name__(object, "b")


def test_no_module_uses_functools_cached_property():
    """The package's cached properties are this one (a new functools one would bring the lock back)."""
    found = []
    for path in SRC.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module == "functools":
                names = [a.name for a in node.names]
                if "cached_property" in names:
                    found.append(f"{path.name}:{node.lineno}: from functools import cached_property")
            if isinstance(node, ast.Attribute) and node.attr == "cached_property":
                if isinstance(node.value, ast.Name) and node.value.id == "functools":
                    found.append(f"{path.name}:{node.lineno}: functools.cached_property")
    assert not found, found
