"""The compiled tooth load sharing (rows/threaded/compiled_sharing.py) against its numpy oracle.

The numpy version (physics/life/ptrb_load_sharing.py: dense Newton steps per group of equal tooth
count) and the compiled one (O(n) steps, tooth-difference equations) solve the same equations; their
f_amax agree to 1e-10 on random coefficients over four decades of load, 1–24 teeth and both supports,
on the paper's design space, and both refuse what does not converge.
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.life import ptrb_load_sharing as pls
from bearingkit.rows.threaded import compiled_sharing

RTOL = 1e-10


def _random_designs(rng, c):
    """Coefficients spanning the PTRB designs' (a_H ~ 1e-7 m/N^(2/3), compliances 1e-10–1e-8 m/N), wider."""
    return dict(
        hertz_inner=10 ** rng.uniform(-7.5, -6.5, c),
        hertz_outer=10 ** rng.uniform(-7.5, -6.5, c),
        tooth_inner=10 ** rng.uniform(-10, -8, c),
        tooth_outer=10 ** rng.uniform(-10, -8, c),
        body_roller=10 ** rng.uniform(-11, -8, c),
        body_inner=10 ** rng.uniform(-11, -8, c),
        body_outer=10 ** rng.uniform(-11, -8, c),
    )


@pytest.mark.parametrize("support", pls.SUPPORTS)
def test_random_designs_give_the_numpy_oracle_s_f_amax(support):
    rng = np.random.default_rng(34)
    c = 400
    load = 10 ** rng.uniform(1, 5, c)
    n = rng.integers(1, 25, c)
    coefs = _random_designs(rng, c)
    ours = pls.max_tooth_share(load, n, support=support, solver=compiled_sharing.max_tooth_share, **coefs)
    oracle = pls.max_tooth_share(load, n, support=support, **coefs)
    np.testing.assert_allclose(ours, oracle, rtol=RTOL, atol=0)
    assert np.all(oracle >= 1.0 - 1e-14) and oracle.max() > 5.0  # the draw reaches strongly uneven sharing
    np.testing.assert_allclose(ours[n == 1], 1.0, rtol=1e-14)  # one tooth carries the roller's load


def test_one_design_of_each_tooth_count_alone_equals_the_population():
    """A design's f_amax does not depend on the others solved with it (work arrays reused per design)."""
    rng = np.random.default_rng(5)
    c = 30
    load, n = 10 ** rng.uniform(2, 4, c), rng.integers(2, 20, c)
    coefs = _random_designs(rng, c)
    solver = compiled_sharing.max_tooth_share
    together = pls.max_tooth_share(load, n, solver=solver, **coefs)
    alone = [
        pls.max_tooth_share(load[[j]], n[[j]], solver=solver, **{k: v[[j]] for k, v in coefs.items()})[0]
        for j in range(c)
    ]
    assert np.array_equal(together, alone)


def test_the_paper_s_design_space_gives_the_numpy_f_amax():
    """design_f_amax over Zheng et al. (2022) §6's ranges (α 30–60°, n 8–16, d_R, R_rr) on both solvers."""
    from bearingkit.papers.zheng2022 import design
    from bearingkit.physics.life import ptrb_rating as pr

    base = design._prototype()
    d_pw, length = design.PROTOTYPE_PITCH_DIAMETER, design.PROTOTYPE_THREAD_LENGTH
    rng = np.random.default_rng(2022)
    c = 300
    alpha = np.radians(rng.uniform(30, 60, c))
    n = rng.integers(8, 17, c).astype(float)
    d_r = rng.uniform(4.8e-3, 7.2e-3, c)  # examples/studies/seed004_axial_nsga2.toml's bounds
    r_rr = rng.uniform(4.5e-3, 7.5e-3, c)
    inf = np.full(c, np.inf)
    kw = dict(
        n_elements=11, n_teeth=n, contact_angle=alpha, roller_pitch_diameter=d_r,
        inner_pitch_diameter=d_pw - d_r, outer_pitch_diameter=d_pw + d_r,
        roller_contact_radius=r_rr, contact_radius_inner=inf, contact_radius_outer=inf,
        thread_pitch=length / n, dedendum=base.dedendum,
        bottom_thickness_roller=base.bottom_thickness_roller,
        bottom_thickness_inner=base.bottom_thickness_inner,
        bottom_thickness_outer=base.bottom_thickness_outer, bore_diameter=base.bore_diameter,
        outside_diameter=base.outside_diameter, youngs_modulus=base.youngs_modulus,
        poisson_ratio=base.poisson_ratio, body_compliance_factor=pr.BODY_COMPLIANCE_FACTOR,
    )  # fmt: skip
    oracle = pls.design_f_amax(pr.F_AMAX_REFERENCE_LOAD, **kw)
    ours = pls.design_f_amax(pr.F_AMAX_REFERENCE_LOAD, solver=compiled_sharing.max_tooth_share, **kw)
    np.testing.assert_allclose(ours, oracle, rtol=RTOL, atol=0)
    assert 1.0 < oracle.min() and oracle.max() < 1.5  # Table 4 implies 1.03–1.10 over these ranges


@pytest.mark.parametrize("solver", [None, compiled_sharing.max_tooth_share], ids=["numpy", "compiled"])
def test_a_design_that_does_not_converge_is_refused_naming_its_tooth_count(solver):
    rng = np.random.default_rng(1)
    coefs = _random_designs(rng, 3)
    with pytest.raises(InputError, match=r"3 design\(s\) with n = 7, 9 did not converge"):
        pls.max_tooth_share([800.0, 900.0, 1e4], [7, 9, 9], solver=solver, max_iter=1, **coefs)


def test_the_compiled_solver_called_directly_refuses_an_unknown_support():
    ones = np.ones(1)
    with pytest.raises(InputError, match="support"):
        compiled_sharing.max_tooth_share(ones, [3], *(1e-9 * ones,) * 7, "middle", 60, 1e-10)


def test_the_optimisation_uses_the_core_the_solver_backend_names(monkeypatch):
    """BEARINGKIT_BACKEND=numpy keeps numpy, compiled takes the compiled sharing; under auto a study's
    chunks (the core loaded by backend.for_batches) take the compiled one, and a process that has not
    loaded the core takes it only for a large population with the core built, loading nothing itself."""
    from bearingkit.analysis.solver import backend
    from bearingkit.papers.zheng2022 import design
    from bearingkit.rows import numba_cache

    monkeypatch.setenv(backend.BACKEND_ENV, "numpy")
    assert design._share_solver(100) is None
    monkeypatch.setenv(backend.BACKEND_ENV, "compiled")
    assert design._share_solver(100) is compiled_sharing.max_tooth_share
    monkeypatch.setenv(backend.BACKEND_ENV, "auto")
    backend.for_batches()
    assert design._share_solver(1) is compiled_sharing.max_tooth_share
    monkeypatch.setattr(backend, "loaded", lambda: False)
    state = dict(backend._STATE)
    compiled = compiled_sharing.max_tooth_share
    for built, n, expected in ((True, 1000, compiled), (True, 100, None), (False, 1000, None)):
        monkeypatch.setattr(numba_cache, "is_built", lambda built=built: built)
        assert design._share_solver(n) is expected, (built, n)
    assert backend._STATE == state  # no note logged, no core loaded or built for it
