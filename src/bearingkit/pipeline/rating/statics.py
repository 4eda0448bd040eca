"""The load distribution the ISO/TS 16281 rating reads: the TS's own tilt lever arm for ball rows.

SI units (m, N, rad). ISO/TS 16281:2008 writes the tilt term of a ball's approach as θ (d_m/2) cos ψ: the
ring tilts about the pitch circle (``tilt_arm = "pitch_radius"`` of
:class:`~bearingkit.rows.ball.row.BallRow`),
as commercial tools implementing the TS apply it. bearingkit's statics default to the groove-centre arm
(Harris & Kotzalas 2007, §8.1; docs/engine.md). The two give the same contacts without a tilt and differ
slightly under one; so that the life labelled ISO/TS 16281 is the TS's, the rating reads the cases solved
with the pitch-radius arm whenever a ball row uses the groove-centre arm and a ring tilts (a free tilt
under moment, or an imposed misalignment). The statics shown keep the file's arm.
"""

from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["TS_TILT_ARM", "ts_statics"]

#: The tilt lever arm of ISO/TS 16281:2008's moment equation (rows.ball.TILT_ARMS).
TS_TILT_ARM = "pitch_radius"
#: A tilt below this [rad] is the solver's round-off of a symmetric case (1e-19 rad on a DB pair under a
#: radial force), not a tilt: the two arms give the same contacts to far below it.
TILT_ROUND_OFF = 1e-12


def ts_statics(analysis):
    """(QuasiStaticResult the ISO/TS 16281 rating reads, note or None).

    ``analysis.statics`` itself when no ball row takes another arm, no case tilts or every DOF is held (an
    imposed state, e.g. a shaft's seat); else the same cases (loads, DOFs, speed, offsets of
    :attr:`Analysis.setup`; held DOFs at the statics' values) solved with every ball row on
    :data:`TS_TILT_ARM`.
    """
    res = analysis.statics
    model = analysis.input.model  # the model as built (res.model may be its speed wrapper)
    other = [
        r.name for r in model.rows if r.kind == "ball" and getattr(r, "tilt_arm", TS_TILT_ARM) != TS_TILT_ARM
    ]
    tilted = np.any(np.abs(np.asarray(res.displacement)[:, 3:5]) > TILT_ROUND_OFF)
    setup = analysis.setup
    # every DOF held: an evaluation at an imposed state (a shaft's seat displacement, docs/systems.md) —
    # the state is the system's solution on the statics' arm, rated as it is
    if not other or not tilted or not np.any(setup.free):
        return res, None
    from bearingkit.analysis.solver.quasistatic import solve

    rows = tuple(dataclasses.replace(r, tilt_arm=TS_TILT_ARM) if r.name in other else r for r in model.rows)
    b = analysis.input
    ts = analysis._in_file(
        solve,
        dataclasses.replace(model, rows=rows),
        setup.load,
        free=setup.free,
        displacement=res.displacement,  # the held DOFs' values, and the start of the free ones
        options=b.options,
        raceway_offsets=setup.offsets,
        speed=setup.speed,
    )
    note = (
        "ISO/TS 16281 lives from the loads with the TS's pitch-radius tilt arm (ball rows "
        f"{', '.join(other)}; the statics shown use the groove-centre arm of geometry.tilt_arm)"
    )
    return ts, note
