"""Row kinds of the quasi-static engine (SI units), one sub-package per kind family.

Each kind turns an inner-ring displacement into contact deformations, element loads and the force on
the ring with its analytic Jacobian (docs/engine.md); its compiled (numba) response sits beside its
numpy kernel, which stays the test oracle:

- ``ball/`` — ball rows (``row``: deep-groove and angular-contact grooves; ``four_point``: gothic
  arches; ``speed``: per-ball equilibrium at speed; ``compiled``);
- ``cylindrical/`` — sliced line-contact rollers (``row``, ``needle``, ``crossed``, ``speed``, ``compiled``);
- ``tapered/`` — per-roller equilibrium with raceways and rib (``row``, ``geometry``, ``laws``,
  ``kernel``, ``compiled``);
- ``threaded/`` — the planetary thread-roller rows (``row``, ``geometry``, ``distribution``, ``compiled``);
- ``self_aligning`` — self-aligning ball and spherical roller rows (spherical outer raceway);
- ``base`` — the interface every kind implements and what they share; ``numba_cache`` — where the
  compiled core is cached.

Kinds import only ``base`` and ``numba_cache``, never each other (``tests/test_architecture.py``).
"""
