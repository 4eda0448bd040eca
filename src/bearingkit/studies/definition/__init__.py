"""A study file → a validated, SI-valued definition: the pydantic models and limits (``schema``), values
in SI (``values``), the evaluator it names (``choice``), whole-definition checks (``checks``) and the
reader (``load``: :func:`~bearingkit.studies.definition.load.load_study`)."""
