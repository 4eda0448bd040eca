"""Tapered roller bearing studies: roller-diameter scatter, Monte Carlo, contact-force statistics.

SI units (m, N, N², rad). Realisations ride on the solver's case axis: one batched solve carries every
realisation (the row's ``diameter_deviation`` has shape (C, Z)); no Python loop over realisations or
rollers. Seed 001's model is the single row under a pure axial load with the tilts fixed
(``free = [True, True, True, False, False]``, its 3-DOF d = (d_x, d_y, d_z)).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.errors import InputError
from bearingkit.physics.deviations import gaussian_deviations
from bearingkit.rows.tapered.row import TaperedRow

#: Seed 001's free DOFs (u_x, u_y, u_z free; tilts held by the rest of the shaft).
SEED001_FREE = (True, True, True, False, False)


@dataclass(frozen=True)
class ContactForceStatistics:
    """Cup contact forces of a batch of realisations and their statistics (SI).

    Attributes
    ----------
    load_outer : ndarray (C, Z) [N]
        Roller–cup contact force Q_e of each roller.
    load_inner, load_flange : ndarray (C, Z) [N]
    max_contact_force : ndarray (C,) [N]
    variance : ndarray (C,) [N²]
        Population variance over the rollers (ddof = 0).
    converged : ndarray (C,) of bool
    displacement : ndarray (C, 5)
    """

    load_outer: np.ndarray
    load_inner: np.ndarray
    load_flange: np.ndarray
    max_contact_force: np.ndarray
    variance: np.ndarray
    converged: np.ndarray
    displacement: np.ndarray

    def to_dict(self) -> dict:
        """JSON-ready summary (units in keys)."""
        return {
            "max_contact_force_N": self.max_contact_force.tolist(),
            "variance_N2": self.variance.tolist(),
            "converged": self.converged.tolist(),
        }


def contact_forces(row: TaperedRow, axial_load, deviations=None, free=SEED001_FREE) -> ContactForceStatistics:
    """Solve the row under a pure axial load for every realisation of ``deviations`` at once.

    Parameters
    ----------
    row : TaperedRow
        Template row (its own ``diameter_deviation`` is replaced).
    axial_load : float or array (C,) [N]
        F_z on the inner ring (the row's ``direction`` decides the sign it can carry).
    deviations : array (Z,) or (C, Z) [m] or None
        Roller diameter deviations, one realisation per case.
    free : sequence of 5 bool
    """
    if deviations is not None:
        dev = np.atleast_2d(np.asarray(deviations, dtype=float))
        row = dataclasses.replace(row, diameter_deviation=dev)
        n_cases = dev.shape[0]
    else:
        row = dataclasses.replace(row, diameter_deviation=None)
        n_cases = 1
    checks.finite("axial_load", axial_load, "N")
    fz = np.broadcast_to(np.asarray(axial_load, dtype=float), (n_cases,)) * row.direction
    model = BearingModel((row,), name="tapered row", references=("liu2022",))
    res = solve(model, load_vector(F_z=fz), free=list(free))
    q_i, q_e, q_f = _roller_loads(model, res.displacement, res._roller_x)
    return ContactForceStatistics(
        load_outer=q_e,
        load_inner=q_i,
        load_flange=q_f,
        max_contact_force=q_e.max(axis=-1),
        variance=q_e.var(axis=-1),
        converged=res.converged,
        displacement=res.displacement,
    )


def _roller_loads(model: BearingModel, q: np.ndarray, start=None):
    """Cone, cup and rib loads (C, Z) of the row's rollers at q: compiled where the solve was
    (``start``: the rollers' positions the compiled solve left at q, its warm start)."""
    from bearingkit.analysis.solver import backend

    kernel = model.kernels[0]
    packed = backend.compiled_pack(model) if backend.requested(None) != "numpy" else None
    if packed is not None:
        from bearingkit.rows.tapered.compiled import roller_loads

        loads = roller_loads(kernel, q, start, pack=packed.tapered)  # the solve's pack (one row)
        return loads[..., 0], loads[..., 1], loads[..., 2]
    st = kernel.roller_state(q)
    return st["load_inner"], st["load_outer"], st["load_flange"]


@dataclass(frozen=True)
class MonteCarloResult:
    """Monte Carlo over Gaussian roller-diameter deviations (SI).

    Attributes
    ----------
    deviations : ndarray (C, Z) [m]
    stats : ContactForceStatistics
    ideal : ContactForceStatistics
        The bearing with ideal rollers (one case).
    """

    deviations: np.ndarray
    stats: ContactForceStatistics
    ideal: ContactForceStatistics

    def summary(self) -> dict:
        """Mean/std/max of the max contact force and the variance over realisations (units in keys)."""
        m, v = self.stats.max_contact_force, self.stats.variance
        return {
            "n_realisations": int(m.size),
            "converged_fraction": float(self.stats.converged.mean()),
            "ideal_max_contact_force_N": float(self.ideal.max_contact_force[0]),
            "max_contact_force_mean_N": float(m.mean()),
            "max_contact_force_std_N": float(m.std()),
            "max_contact_force_max_N": float(m.max()),
            "variance_mean_N2": float(v.mean()),
        }


def monte_carlo(
    row: TaperedRow,
    axial_load: float,
    magnitude: float,
    n_realisations: int,
    *,
    arrangement: str = "random",
    seed=None,
    free=SEED001_FREE,
) -> MonteCarloResult:
    """Contact-force statistics over ``n_realisations`` Gaussian deviation draws (one batched solve).

    Parameters
    ----------
    row : TaperedRow
    axial_load : float [N]
    magnitude : float [m]
        S_d, the standard deviation of ΔD (seed 001 eq. 14).
    n_realisations : int
    arrangement : str
        ``"random"`` or ``"descending"``.
    seed : int or None
        Reproducible draws.
    """
    n = checks.integer("n_realisations", n_realisations, low=1)
    if np.ndim(axial_load) != 0:
        raise InputError(f"axial_load (shape {np.shape(axial_load)}) must be a scalar for a Monte Carlo run")
    dev = gaussian_deviations(row.n_elements, magnitude, n, arrangement=arrangement, seed=seed)
    stats = contact_forces(row, axial_load, dev, free=free)
    ideal = contact_forces(row, axial_load, None, free=free)
    return MonteCarloResult(dev, stats, ideal)


__all__ = ["SEED001_FREE", "ContactForceStatistics", "MonteCarloResult", "contact_forces", "monte_carlo"]
