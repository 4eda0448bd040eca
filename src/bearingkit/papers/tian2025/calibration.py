"""Seed 000 (Tian et al. 2025): the ONE place where the friction reproduction is calibrated.

SI units (N·m, kg, 1). Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588.

The paper gives neither its lubricant nor its traction data (refs. [28]–[31] were not available), so
one coefficient of bearingkit's component model is identified on ONE published number and every other
published number of the paper is then a prediction:

* :data:`ROLLER_SLIDING` — μ_rs of the load-proportional sliding of the two axial roller rows at their
  pitch radius (:func:`bearingkit.physics.friction.components.roller_sliding_torque`), identified on
  Table 3 run 1 (2871.7 N·mm) = 0.00269 (recomputed by
  :func:`bearingkit.papers.tian2025.friction.calibrated_sliding` of the ``"seed000"`` reading).
  For comparison, SKF puts the constant friction coefficient of cylindrical roller thrust bearings
  at 0.005 (M = 0.5 μ P d with the bore d; thrust ball bearings 0.0013): the identified term is that
  order. It is what the paper's
  torques show and the component model lacked — the published Table 3 torques grow with the axial
  roller load by 0.33 N·m per kN (a coefficient ≈ 0.004 at the 83.5 mm pitch radius), three times
  what hysteresis and the pitch-line differential sliding E2 (μ from the film parameter) give.

Not calibrated (assumed inputs, stated here so that they sit with the calibration):

* :data:`VISCOSITY_FACTOR` = 1: the grease acts with its base oil's viscosity (bearingkit's default for a
  grease). Until issue 32 this factor was the calibration (3.60 on run 1, no sliding term); with
  μ_rs identified it is no longer needed, and runs 2–9 come out within 10 % (they were −7 … −38 %).
* :data:`CAGE_MASS` = 2 × 0.158 kg: two brass cages of an assumed section (annulus Ø160–185 mm ×
  3.5 mm minus 31 roller and 31 ball pockets), not fitted.
"""

from __future__ import annotations

#: Table 3 run(s) a constant is identified on (1-based run numbers).
CALIBRATION_RUNS = (1,)
#: Two brass cages of the assumed geometry (module docstring) [kg]; an input, not fitted.
CAGE_MASS = 2 * 0.158
#: η_eff/η_base of the grease [1]: 1 = base oil (not calibrated since issue 32).
VISCOSITY_FACTOR = 1.0
#: μ_rs of the axial roller rows at their pitch radius [1], identified on Table 3 run 1 (regenerate it with
#: ``friction.calibrated_sliding(dataclasses.replace(friction.VARIANTS["seed000"], roller_sliding=None))``
#: when the model changes; a test checks that the two agree).
ROLLER_SLIDING = 0.002687
