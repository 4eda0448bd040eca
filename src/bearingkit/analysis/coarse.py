"""The coarse model of the first Newton iterations: the bearing with its sliced rollers at few slices.

The solver's starting point (:func:`bearingkit.analysis.newton.starting_point`) closes every contact
with one common approach: it ignores clearance, preload, crowning and which side of a row is loaded,
so the first Newton iterations mostly find the load zones. Those iterations need the bearing's
stiffness, not its slice detail. Both solver cores therefore run :data:`COARSE_ITERATIONS` Newton
iterations on a coarse copy of the bearing first, whose cylindrical rows have :data:`COARSE_SLICES`
slices (the same rows, profiles and slice law, sampled coarsely), and start the full model from there.
The last coarse step is taken without evaluating its end: the full model's first evaluation is
there. The full model then decides convergence to ``rtol`` as before: the coarse stage moves the
start, not the equilibrium (results agree with the plain start to the solver tolerance).

Measured on the seed-000 composite bearing under 2,000 random loads (issue 19): 6.4 full
evaluations per case (at most 14) become 4.0 full (at most 6) + 2.0 coarse ones, a coarse
evaluation costing about 60 % of a full one (7.3 against 11.7 µs: the balls and the per-roller
work are not reduced by coarsening): serial CPU per case
94 → 81 µs. A YRT turntable: 6.6 → 4.1 + 2.1; a cylindrical roller bearing with 20 µm clearance
under radial loads: 9.6 → 4.7 + 4.9.

The stage applies only where it pays and cannot change the problem:

* rows of :class:`~bearingkit.rows.cylindrical.CylindricalKernel` exactly (a kernel at speed adds
  physics the coarse copy would have to repeat) with at least :data:`COARSE_FROM_SLICES` slices;
* no user-given start (a given displacement is usually a good one) and no imposed raceway offsets
  (flexible rings iterate on their own).
"""

from __future__ import annotations

import dataclasses

from bearingkit.rows.cylindrical import CylindricalKernel

#: Slices per roller of the coarse model. Odd, so a slice sits at the roller middle: even counts
#: (4, 6) took 9–12 coarse evaluations (line-search halvings) for two iterations on the seed-000
#: bearing against 3 for 5 or 7 (issue 19; the cause was not pursued).
COARSE_SLICES = 5
#: Rows with at least this many slices are coarsened. Chosen, not measured: 3 × :data:`COARSE_SLICES`,
#: since a coarse evaluation already costs ~60 % of a full one at 20 slices and its share grows as
#: the full row has fewer slices.
COARSE_FROM_SLICES = 15
#: Newton iterations on the coarse model. 1 left 4.9 full evaluations per seed-000 case, 2 left
#: 4.0 and 3 left 4.0 (issue 19), so a third does not repay its evaluation.
COARSE_ITERATIONS = 2


def coarse_kernels(kernels) -> list | None:
    """The kernels of the coarse model (unchanged rows shared), or None when no row is coarsened."""
    out, changed = [], False
    for k in kernels:
        if type(k) is CylindricalKernel and k.row.n_slices >= COARSE_FROM_SLICES:
            out.append(dataclasses.replace(k.row, n_slices=COARSE_SLICES).kernel())
            changed = True
        else:
            out.append(k)
    return out if changed else None


__all__ = ["COARSE_FROM_SLICES", "COARSE_ITERATIONS", "COARSE_SLICES", "coarse_kernels"]
