"""One analysis pipeline: input → statics (+ flexible ring) → friction → lubrication → rating → ``Analysis``.

SI units inside. The faces (CLI, HTML report, flagship, studies, web app) call :func:`analyze` and read
the parts of the returned :class:`Analysis`; none of them orchestrates by itself.
"""

from bearingkit.pipeline.analysis import RENDERERS, Analysis, analyze
from bearingkit.pipeline.friction import extra as friction_extra  # noqa: F401  (registers the "trb" model)
from bearingkit.pipeline.friction import paired as friction_paired  # noqa: F401  (sets: skf per bearing)
from bearingkit.pipeline.friction.models import FRICTION_MODELS, FrictionOutcome, register_friction_model
from bearingkit.pipeline.friction.slewing import slewing_friction  # registers friction model "slewing"
from bearingkit.pipeline.inputs import ModelInput, load_cases_from, load_input
from bearingkit.pipeline.operating import DEFAULT_TEMPERATURE, Operating

__all__ = [
    "DEFAULT_TEMPERATURE",
    "FRICTION_MODELS",
    "RENDERERS",
    "Analysis",
    "FrictionOutcome",
    "ModelInput",
    "Operating",
    "analyze",
    "load_cases_from",
    "load_input",
    "register_friction_model",
    "slewing_friction",
]
