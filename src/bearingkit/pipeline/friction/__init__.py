"""Friction models of the pipeline, chosen by name (SI units: N·m, W).

``models`` holds the registry (:data:`~bearingkit.pipeline.friction.models.FRICTION_MODELS`,
:func:`~bearingkit.pipeline.friction.models.register_friction_model`) with the component and the
engineering models; ``extra`` the tapered-roller model of seed 001 and the comparison of models;
``slewing`` the slewing-ring makers' model; ``paired`` the catalogue models of a matched set (DB/DF/DT),
per bearing. Importing :mod:`bearingkit.pipeline` registers them all.
"""
