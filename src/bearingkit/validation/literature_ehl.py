"""Literature validation cases for EHL film thickness and traction (SI values).

No case is registered yet. A published worked example with its inputs and printed result (e.g.
the ball- and cylindrical-roller-bearing problems of Hamrock, Schmid & Jacobson, *Fundamentals of
Fluid Film Lubrication*, or Harris & Kotzalas) could not be retrieved in a form that gives both the
inputs and the published film thickness, so no number is pinned here rather than pinning one
copied from bearingkit's own output. Add cases as ``hamrock/example-<x>/film-central`` (unit
``"m"``) with :func:`bearingkit.validation.registry.register` once the printed values are at hand.
"""

from __future__ import annotations
