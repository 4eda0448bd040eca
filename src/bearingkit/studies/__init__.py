"""Generic study machinery (SI units in every table; units in column names).

Sub-packages, bottom first (imports point down only, ``tests/test_architecture.py``):

- ``designs/`` — case generators: sweeps, factorials, orthogonal arrays, Monte Carlo, levels × samples;
- ``results/`` — analysis of results (main effects, range analysis, point statistics) and plots;
- ``evaluators`` — the evaluator registry (pure functions of a case table → outputs);
- ``generic/`` — the generic evaluator on any bearing file: factor paths, named output quantities;
- ``definition/`` — a study file → a validated, SI-valued definition (schema, values, checks);
- ``run/`` — cases and fingerprint, executors (in process, processes, Dask), the Parquet store with
  resume, its lock and the atomic publication of outputs, the optimiser, and :func:`run_study`;
- ``__main__`` — ``python -m bearingkit.studies`` / ``bearingkit study``.
"""
