"""Running a study: its cases and fingerprint (``cases``), executors (``executors``), the Parquet store
with resume (``store``, ``lock``) and the atomic publication of outputs (``publish``), the optimiser
(``optimize``) and the entry point (``runner``: :func:`~bearingkit.studies.run.runner.run_study`)."""
