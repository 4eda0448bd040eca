"""Validation registry: every published number bearingkit reproduces, with its tolerance.

A :class:`Case` pairs a published value with a function that recomputes it. Modules that add
cases live in this package (``literature.py``, ``seed000.py`` …) and register them on import;
:func:`all_cases` imports them all. ``bearingkit validate`` runs them.
"""

from bearingkit.validation.registry import Case, CaseResult, all_cases, register, run_cases

__all__ = ["Case", "CaseResult", "all_cases", "register", "run_cases"]
