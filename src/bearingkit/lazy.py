"""What is loaded or computed on first use: names a package re-exports from its sub-modules (PEP 562),
and values an object computes once (:class:`cached_property`).

A package face such as ``bearingkit.analysis.solver`` offers ``solve`` without importing its modules
when the package itself is imported: importing a sub-module stays cheap, and a module that needs only
``solver.model`` does not pull in the whole solver.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from importlib import import_module
from typing import Any


def exports(package: str, names: Mapping[str, str]) -> Callable[[str], object]:
    """A module ``__getattr__`` that loads ``names[attr]`` (a sub-module of ``package``) on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    names : mapping of str to str
        Attribute name → sub-module name (relative to ``package``) that defines it.
    """

    def __getattr__(attr: str):
        if attr in names:
            return getattr(import_module(f"{package}.{names[attr]}"), attr)
        raise AttributeError(f"module {package!r} has no attribute {attr!r}")

    return __getattr__


# A cached property without a lock shared by every instance of a class.
#
# Python 3.11's :class:`functools.cached_property` computes under one lock per *class attribute*
# (``self.lock`` of the descriptor), so two threads computing the property on two different instances
# wait for each other. A study evaluates its chunks side by side in threads (issue 34): every chunk's
# ``Analysis.statics`` runs the compiled solve, which releases the GIL, but the lock of
# ``Analysis.statics`` let only one chunk solve at a time (measured: a 10⁵-case 6209 study on two
# threads used 1.0 core; without the lock 1.8). Python 3.12 removed that lock (CPython issue 87634);
# this is the 3.12 behaviour for every supported Python.
#
# Two threads asking the same instance at once may both compute the value; the properties cached this
# way are pure functions of their instance, so either result is the same and the last one is kept.
class cached_property:
    """Compute on first access and keep the value in the instance's ``__dict__``.

    A non-data descriptor: once the value is stored, the instance attribute shadows the descriptor
    and later reads cost a dict lookup. ``del obj.name`` forgets the value.
    """

    def __init__(self, func: Callable[[Any], Any]):
        self.func = func
        self.attrname: str | None = None
        self.__doc__ = func.__doc__
        self.__module__ = func.__module__
        self.__wrapped__ = func

    def __set_name__(self, owner: type, name: str) -> None:
        if self.attrname is None:
            self.attrname = name
        elif name != self.attrname:
            raise TypeError(f"one cached_property cannot be both {self.attrname!r} and {name!r}")

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        if self.attrname is None:
            raise TypeError("cached_property used without __set_name__ (assign it in a class body)")
        value = self.func(instance)
        instance.__dict__[self.attrname] = value
        return value
