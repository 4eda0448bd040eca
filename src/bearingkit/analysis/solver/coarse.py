"""The coarse model of the first Newton iterations: the bearing with its sliced rollers at few slices.

The solver's starting point (:func:`bearingkit.analysis.solver.newton.starting_point`) closes every contact
with one common approach: it ignores clearance, preload, crowning and which side of a row is loaded,
so the first Newton iterations mostly find the load zones. Those iterations need the bearing's
stiffness, not its slice detail. Both solver cores therefore run :data:`COARSE_ITERATIONS` Newton
iterations on a coarse copy of the bearing first, whose cylindrical rows have :data:`COARSE_SLICES`
slices (the same rows, profiles and slice law, sampled coarsely; rows of :data:`COARSE_THIN_FROM`
or more rollers also at every other roller's place), and start the full model from there.
The last coarse step is taken without evaluating its end: the full model's first evaluation is
there. The full model then decides convergence to ``rtol`` as before: the coarse stage moves the
start, not the equilibrium (results agree with the plain start to the solver tolerance).

Measured on the seed-000 composite bearing under 2,000 random loads (issue 19): 6.4 full
evaluations per case (at most 14) become 4.0 full (at most 6) + 2.0 coarse ones, a 5-slice coarse
evaluation costing about 60 % of a full one (7.3 against 11.7 µs: the balls and the per-roller work
are not reduced by fewer slices): serial CPU per case 94 → 81 µs. Thinning the rows of 31 and 97
rollers then took 76.5 → 72.2 µs per case (one thread, 2,000 cases, one A/B run) with the same
evaluation counts. A YRT turntable: 6.6 → 4.1 + 2.1; a cylindrical roller bearing with 20 µm
clearance under radial loads: 9.6 → 4.7 + 4.9.

The stage applies only where it pays and cannot change the problem:

* rows of :class:`~bearingkit.rows.cylindrical.row.CylindricalKernel` exactly (a kernel at speed adds
  physics the coarse copy would have to repeat) with at least :data:`COARSE_FROM_SLICES` slices;
* no user-given start (a given displacement is usually a good one) and no imposed raceway offsets
  (flexible rings iterate on their own).
"""

from __future__ import annotations

import dataclasses

from bearingkit.rows.cylindrical.row import CylindricalKernel

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


#: Rows of at least this many rollers are also thinned in the coarse model: every other roller's
#: place, ⌈Z/2⌉ rollers each standing for Z/⌈Z/2⌉ (their slice stiffness scaled so). Chosen from
#: measurements (issue 19): on the seed-000 and YRT bearings (rows of 31–97 rollers) halving changed
#: no evaluation count, and a third or a sixth of the rollers neither; on a zero-clearance radial
#: row under radial loads, where the unthinned coarse start is almost exact (2 full evaluations),
#: halving added one full evaluation at 16, 24 and 32 rollers and none at 48. 30 keeps that cost
#: to rows of 30–47 rollers, whose evaluations are cheap.
COARSE_THIN_FROM = 30


def coarse_kernels(kernels) -> list | None:
    """The kernels of the coarse model (unchanged rows shared), or None when no row is coarsened."""
    out, changed = [], False
    for k in kernels:
        if type(k) is CylindricalKernel and k.row.n_slices >= COARSE_FROM_SLICES:
            out.append(_coarse_rollers(k.row))
            changed = True
        else:
            out.append(k)
    return out if changed else None


def _coarse_rollers(row) -> CylindricalKernel:
    """The coarse kernel of a cylindrical row: :data:`COARSE_SLICES` slices, thinned rollers."""
    z = row.n_elements
    z_coarse = -(-z // 2) if z >= COARSE_THIN_FROM else z
    kernel = dataclasses.replace(row, n_slices=COARSE_SLICES, n_elements=z_coarse).kernel()
    if z_coarse != z:
        # Each coarse roller carries for z / z_coarse rollers (a coarser rule over the azimuth).
        kernel.c_s = kernel.c_s * (z / z_coarse)
        kernel.start_matrix = kernel.start_matrix * (z / z_coarse)
    return kernel


__all__ = ["COARSE_FROM_SLICES", "COARSE_ITERATIONS", "COARSE_SLICES", "COARSE_THIN_FROM", "coarse_kernels"]
