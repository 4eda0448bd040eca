"""The quasi-static solve and what is assembled from it (SI units).

- :mod:`~bearingkit.analysis.solver` — the batched Newton solve of a bearing model (numpy reference
  and compiled core), its model and result objects, speed effects;
- :mod:`~bearingkit.analysis.rating` — ratings and lives of a solved bearing (ISO 76, ISO 281,
  ISO/TS 16281, the PTRB ratings), one rater per row kind;
- :mod:`~bearingkit.analysis.friction` — friction assemblies on the solved contacts (the component
  model and its kinematics, the SKF/Palmgren engineering models, the tapered and thread-roller models);
- beside them: operating clearance from fits and temperatures (:mod:`.clearance`), the coupled
  flexible ring (:mod:`.flexible`), lubrication per contact (:mod:`.lubrication`), roller-diameter
  scatter (:mod:`.scatter`) and the slewing-ring static load diagram (:mod:`.slewing`).

Sub-packages import downward only: ``rating`` and ``friction`` over the root modules over ``solver``
(``tests/test_architecture.py``).
"""
