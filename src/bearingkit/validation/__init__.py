"""Validation registry: every published number bearingkit reproduces, with its tolerance.

A :class:`Case` pairs a published value with a function that recomputes it. The literature cases
(Harris, ISO, Hamrock, SKF …) live in this package; each paper reproduction of :mod:`bearingkit.papers`
registers its own, declared as entry points of the group ``bearingkit.validation``. Modules register
their cases on import; :func:`all_cases` imports them all. ``bearingkit validate`` runs them.
"""

from bearingkit.validation.registry import Case, CaseResult, all_cases, register, run_cases

__all__ = ["Case", "CaseResult", "all_cases", "register", "run_cases"]
