"""High-speed angular contact ball row under pure thrust against Jones's equations written here.

Issue 18 asks for a published high-speed angular-contact case (Harris & Kotzalas, Jones 1960, …)
within the tolerance its precision allows. No such table could be read from the reachable material
(the searches are listed in docs/engine.md, "Speed: what it is checked against"), so this module
checks the ball row at speed against an independent solution of the same theory instead: the
equilibrium of one ball of an axially loaded row (every ball alike) under the raceway-control
hypothesis of Jones (1959, 1960), as Harris & Kotzalas (2007, Advanced Concepts, ch. 3) set it out,
written from scratch in vector form:

- Hertz: Q = K δ^1.5 with K from the complete elliptic integrals (scipy), the curvature sums in
  Harris's form (ch. 2), solved for the ellipticity κ by root finding;
- kinematics: no slip at the two contact centres and no spin on the controlling raceway, three linear
  equations for the cage speed ω_m and the ball's angular velocity (Ω_r, Ω_z) — no closed-form
  attitude angle;
- inertia: F_c = ½ m d_m ω_m², and the gyroscopic moment as the rate of change of the ball's
  angular momentum J Ω carried round at ω_m (dH/dt = J ω_m ẑ × Ω), reacted by friction at the
  controlling contact only (λ = 2 there, 0 at the other);
- equilibrium: the ball's two force components and the inner ring's axial balance, solved with
  scipy for the ball centre (two unknowns) and the ring's axial approach.

bearingkit's row solves the same equations in another way (per-ball damped Newton with closed-form
kinematics, condensed into the ring's Newton), so agreement to round-off says both are right. The
bearing is Harris's 218 angular contact ball bearing under his 22,250 N thrust (Harris & Kotzalas
2007; geometry as quoted by Ricci 2009, Math. Probl. Eng. 471804 [from memory]): the values used
here are only inputs of both sides, so an error in them cannot make the test pass wrongly.

The limit speed is the model's own, found here from the independent solution. Under outer-raceway
control nothing lifts off (the inner contacts carry F_a/(Z sin α_i) at every speed): the limit is
the inner contact angle reaching :data:`bearingkit.rows.ball.speed.ANGLE_LIMIT` (the ball would ride
over the inner land), near 79,000 rpm for this bearing. Under inner-raceway control the friction
that reacts the gyroscopic moment at the inner contact carries a growing share of the thrust and
the inner contacts lift off (Q_i → 0) near 31,000 rpm. The five speeds run from 0 to 97 % of the
limit; just above it the solver must refuse the case.
"""

import functools

import numpy as np
import pytest
from scipy import optimize, special

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.analysis.solver.speed import OperatingSpeed
from bearingkit.physics.dynamics.ball_kinematics import ball_speeds
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.ball.speed import ANGLE_LIMIT

RPM = np.pi / 30.0
# Harris's 218 angular contact ball bearing [from memory, as quoted by Ricci 2009]: D, d_m, Z, f_i = f_o.
D, DM, Z, F_I, F_O = 0.02223, 0.1253, 16, 0.5232, 0.5232
ALPHA0 = np.radians(40.0)
THRUST = 22250.0  # [N] Harris's 218 example thrust, 5000 lbf [from memory]
E_STEEL, NU_STEEL, RHO = 208e9, 0.3, 7810.0  # bearingkit's GCr15 defaults
E_REDUCED = E_STEEL / (1.0 - NU_STEEL**2)  # E' = 2 / (2 (1 − ν²)/E) for two steel bodies
MASS = RHO * np.pi * D**3 / 6.0
INERTIA = MASS * D**2 / 10.0  # solid sphere
R_I, R_O = (F_I - 0.5) * D, (F_O - 0.5) * D  # groove-centre offsets from the ball centre
A = (F_I + F_O - 1.0) * D  # groove-centre distance (zero clearance)


# -- independent Jones / Harris ball ------------------------------------------------------------
def _kappa(curvature_difference):
    """Ellipticity κ from F(ρ) = [(κ² + 1) E − 2 K] / [(κ² − 1) E] (Harris ch. 2)."""

    def gap(k):
        m = 1.0 - 1.0 / k**2
        return ((k**2 + 1) * special.ellipe(m) - 2 * special.ellipk(m)) / (
            (k**2 - 1) * special.ellipe(m)
        ) - curvature_difference

    return optimize.brentq(gap, 1.0 + 1e-9, 200.0, xtol=1e-15, rtol=1e-15)


def _hertz_constant(alpha, f, side):
    """K [N/m^1.5] of one ball–raceway contact at contact angle α (Harris ch. 2, ch. 6)."""
    g = D * np.cos(alpha) / DM
    ring = 2 * g / (1 - g) if side == "inner" else -2 * g / (1 + g)
    curvature_sum = (4 - 1 / f + ring) / D
    k = _kappa((1 / f + ring) / (4 - 1 / f + ring))
    m = 1.0 - 1.0 / k**2
    delta_star = 2 * special.ellipk(m) / np.pi * (np.pi / (2 * k**2 * special.ellipe(m))) ** (1 / 3)
    # δ = δ* (Σρ/2) (3Q/(E' Σρ))^(2/3)  ⇔  Q = K δ^1.5
    return E_REDUCED / 3 * (2 / delta_star) ** 1.5 / np.sqrt(curvature_sum)


@functools.cache
def _free_constants():
    """(K_i, K_o) at the free contact angle."""
    return _hertz_constant(ALPHA0, F_I, "inner"), _hertz_constant(ALPHA0, F_O, "outer")


def _kinematics(alpha_i, alpha_o, w_inner, control):
    """Cage speed ω_m and the ball's absolute angular velocity (Ω_r, Ω_z) [rad/s].

    Frame (r, θ, z), ball centre at (d_m/2, 0, ·); contact points at ±(D/2)(cos α, 0, sin α) from it.
    Rolling without slip: the θ-velocity of the ball, ω_m d_m/2 + Ω_z ρ_r − Ω_r ρ_z, equals the ring's
    at both contact points (outer ring fixed); no spin on the controlling ring: (Ω − ω_k ẑ)·n_k = 0.
    """
    rho_o = D / 2 * np.array([np.cos(alpha_o), np.sin(alpha_o)])
    rho_i = -D / 2 * np.array([np.cos(alpha_i), np.sin(alpha_i)])
    if control == "outer":
        spin = [0.0, np.cos(alpha_o), np.sin(alpha_o)], 0.0
    else:
        spin = [0.0, np.cos(alpha_i), np.sin(alpha_i)], w_inner * np.sin(alpha_i)
    lhs = np.array([[DM / 2, -rho_o[1], rho_o[0]], [DM / 2, -rho_i[1], rho_i[0]], spin[0]])
    rhs = np.array([0.0, w_inner * (DM / 2 + rho_i[0]), spin[1]])
    return np.linalg.solve(lhs, rhs)


def _ball(x, w_inner, control, hertz_at, axial_approach):
    """Forces on one ball and on the inner ring for the ball centre x = X/D and approach δ_a."""
    s = np.array([A * np.cos(ALPHA0), A * np.sin(ALPHA0) + axial_approach])  # inner groove centre
    big_x = np.asarray(x) * D  # ball centre from the outer groove centre
    d_o, d_i = np.hypot(*big_x), np.hypot(*(s - big_x))
    n_o, n_i = big_x / d_o, (s - big_x) / d_i
    alpha_o, alpha_i = np.arctan2(n_o[1], n_o[0]), np.arctan2(n_i[1], n_i[0])
    if hertz_at == "operating":  # Jones and Harris: K at each contact's operating angle
        k_i, k_o = _hertz_constant(alpha_i, F_I, "inner"), _hertz_constant(alpha_o, F_O, "outer")
    else:  # bearingkit's stated simplification: K at the free contact angle
        k_i, k_o = _free_constants()
    q_o = k_o * max(d_o - R_O, 0.0) ** 1.5
    q_i = k_i * max(d_i - R_I, 0.0) ** 1.5
    w_m, omega_r, _ = _kinematics(alpha_i, alpha_o, w_inner, control)
    f_c = MASS * DM / 2 * w_m**2
    needed = INERTIA * w_m * omega_r  # θ-component of dH/dt = J ω_m ẑ × Ω
    # A tangential force F t (t = (−sin α, cos α)) at the outer contact has the θ-moment −F D/2 about
    # the ball centre, at the inner contact +F D/2: the controlling contact supplies the whole moment.
    f_o = -2 * needed / D if control == "outer" else 0.0
    f_i = 2 * needed / D if control == "inner" else 0.0
    t_o = np.array([-np.sin(alpha_o), np.cos(alpha_o)])
    t_i = np.array([-np.sin(alpha_i), np.cos(alpha_i)])
    on_ball = q_i * n_i + f_i * t_i - q_o * n_o + f_o * t_o + np.array([f_c, 0.0])
    ring_axial = -Z * (q_i * n_i[1] + f_i * t_i[1])  # the balls' force on the inner ring
    return dict(
        on_ball=on_ball,
        ring_axial=ring_axial,
        contact_angle_inner=alpha_i,
        contact_angle_outer=alpha_o,
        load_inner=q_i,
        load_outer=q_o,
        centrifugal_force=f_c,
        cage_speed=w_m,
        gyro=abs(needed),
    )


def _jones(w_inner, control="outer", hertz_at="free", start=None):
    """Solve (X_r/D, X_z/D, δ_a/D) for the thrust THRUST at speed w_inner; returns (state, unknowns)."""
    scale = THRUST / Z

    def residual(u):
        b = _ball(u[:2], w_inner, control, hertz_at, u[2] * D)
        return [*(b["on_ball"] / scale), (b["ring_axial"] + THRUST) / THRUST]

    if start is None:  # the zero-speed groove-centre line, both contacts lightly compressed
        start = np.array([(R_O / D + 1e-3) * np.cos(ALPHA0), (R_O / D + 1e-3) * np.sin(ALPHA0), 3e-3])
    u = start
    sol = optimize.root(residual, u, method="hybr", options=dict(xtol=1e-14))
    assert np.max(np.abs(residual(sol.x))) < 1e-11, sol.message
    out = _ball(sol.x[:2], w_inner, control, hertz_at, sol.x[2] * D)
    out["axial_approach"] = sol.x[2] * D
    return out, sol.x


def _jones_path(speeds, control="outer", hertz_at="free", start=(0.0, None)):
    """States at increasing speeds [rad/s] and their unknowns; each solve is continued in eight steps
    from the previous speed (``start``: a speed and its unknowns, None at zero speed)."""
    states, unknowns = [], []
    last, u = start
    for w in speeds:
        for sub in np.linspace(last, w, 9)[1:] if w > last else [w]:
            state, u = _jones(sub, control, hertz_at, u)
        states.append(state)
        unknowns.append(u)
        last = w
    return states, unknowns


def _advance(w, control, start, substeps=8):
    """(past, unknowns): whether speed w [rad/s] is past the model — the inner contact angle at
    ANGLE_LIMIT or beyond, or the inner contacts lifted off (Q_i = 0: no equilibrium exists, the
    solve fails) — and, when it is not, the unknowns there, continued from ``start``."""
    last, u = start
    try:
        for sub in np.linspace(last, w, substeps + 1)[1:]:
            state, u = _jones(sub, control, "free", u)
    except AssertionError:
        return True, None
    return bool(state["contact_angle_inner"] >= ANGLE_LIMIT or state["load_inner"] <= 0.0), u


def _limit_speed(control="outer"):
    """Inner-ring speed [rad/s] where the model ends (:func:`_advance`), to 1e-6 rad/s.

    Outer-raceway control: the inner contact angle reaches ANGLE_LIMIT. Inner-raceway control: the
    friction that reacts the gyroscopic moment at the inner contact carries a growing share of the
    thrust and the inner contacts lift off (Q_i → 0) first, near 31,000 rpm for this bearing."""
    step = 2500.0 * RPM
    low, u = 0.0, None
    while True:
        past, u_next = _advance(low + step, control, (low, u), substeps=2)
        if past:
            break
        low, u = low + step, u_next
        assert low < 200000.0 * RPM, "no limit below 200,000 rpm"
    high = low + step
    while high - low > 1e-6:  # bisection: past the model there is no residual to bracket a root on
        mid = 0.5 * (low + high)
        past, u_mid = _advance(mid, control, (low, u), substeps=2)
        if past:
            high = mid
        else:
            low, u = mid, u_mid
    return low


# -- the row in bearingkit ----------------------------------------------------------------------
def _model():
    row = BallRow(
        n_elements=Z,
        element_diameter=D,
        pitch_diameter=DM,
        contact_angle=ALPHA0,
        conformity_inner=F_I,
        conformity_outer=F_O,
        e_reduced=E_REDUCED,
        name="balls",
    )
    return BearingModel((row,), name="218 angular contact ball bearing")


def _bearingkit(speeds, control="outer"):
    load = np.tile([0.0, 0.0, THRUST, 0.0, 0.0], (len(speeds), 1))
    speed = OperatingSpeed(np.asarray(speeds), element_density=RHO, raceway_control=control)
    return solve(_model(), load, speed=speed)


KEYS = (
    "contact_angle_inner",
    "contact_angle_outer",
    "load_inner",
    "load_outer",
    "centrifugal_force",
    "cage_speed",
)


@pytest.fixture(scope="module")
def limit_speeds():
    return {control: _limit_speed(control) for control in ("outer", "inner")}


def test_kinematics_equal_the_vector_derivation():
    """bearingkit's closed-form cage speed and ball spin axis (tan β) equal the linear no-slip/no-spin
    solve, for both raceway-control hypotheses."""
    rng = np.random.default_rng(18)
    for control in ("outer", "inner"):
        for alpha_i, alpha_o in rng.uniform(0.05, 1.4, size=(20, 2)):
            w = 1000.0
            sp = ball_speeds(w, 0.0, alpha_i, alpha_o, D, DM, control)
            w_m, omega_r, omega_z = _kinematics(alpha_i, alpha_o, w, control)
            assert sp.cage_speed == pytest.approx(w_m, rel=1e-12)
            # The ball turns at ω_R about (−sin β, cos β) in the cage frame: Ω = ω_m ẑ + ω_R(−sin β, cos β).
            assert -sp.spin_speed * np.sin(sp.attitude_angle) == pytest.approx(omega_r, rel=1e-11)
            assert w_m + sp.spin_speed * np.cos(sp.attitude_angle) == pytest.approx(omega_z, rel=1e-11)
            spin = sp.spin_outer if control == "outer" else sp.spin_inner
            assert abs(spin) <= 1e-12 * w


@pytest.mark.parametrize("control", ["outer", "inner"])
def test_thrust_at_speed_matches_jones_up_to_the_model_limit(control, limit_speeds):
    """Contact angles, contact loads, centrifugal force, gyroscopic moment, cage speed and the ring's
    axial approach of the row at five speeds agree with the independent solution to 1e-8.

    Both sides solve the same equations to residuals of ~1e-12 of the ball load; 1e-8 leaves room
    for the conditioning near the angle limit (the inner angle turns fast with speed there) and is
    far below any model difference (the one below is 1e-4)."""
    limit = limit_speeds[control]
    speeds = np.array([0.0, 10000.0 * RPM, 0.4 * limit, 0.7 * limit, 0.97 * limit])
    res = _bearingkit(speeds, control)
    assert res.converged.all(), res.reason
    ex = res.rows[0].extras
    states, _ = _jones_path(speeds, control)
    for c, ref in enumerate(states):
        for key in KEYS:
            got = ex[key][c]
            np.testing.assert_allclose(got, ref[key], rtol=1e-8, atol=1e-12, err_msg=f"{key} at case {c}")
        np.testing.assert_allclose(np.abs(ex["gyroscopic_moment"][c]), ref["gyro"], rtol=1e-8, atol=1e-12)
        assert res.displacement[c, 2] == pytest.approx(ref["axial_approach"], rel=1e-8, abs=1e-15)
    # Not a trivial agreement: at Harris's 10,000 rpm the speed terms are large (outer control: the
    # angles part by more than 10°, F_c exceeds a quarter of the inner contact load).
    if control == "outer":
        a_i, a_o = ex["contact_angle_inner"][1, 0], ex["contact_angle_outer"][1, 0]
        assert np.degrees(a_i - a_o) > 10.0
        assert ex["centrifugal_force"][1, 0] > 0.25 * ex["load_inner"][1, 0]


@pytest.mark.parametrize(
    "control",
    # Inner control: past the lift-off the solver spends its 300 Newton iterations before it gives up
    # (~30 s of CPU), hence slow.
    ["outer", pytest.param("inner", marks=pytest.mark.slow)],
)
def test_beyond_the_model_limit_is_refused(control, limit_speeds):
    """Just above the limit speed the independent model has ended (outer control: the inner angle
    passes ANGLE_LIMIT; inner control: the inner contacts have lifted off) and the solver refuses
    the case; just below it the case converges (previous test)."""
    limit = limit_speeds[control]
    assert _advance(1.03 * limit, control, (0.0, None), substeps=40)[0]
    res = _bearingkit([1.03 * limit], control)
    assert not res.converged[0]
    if control == "outer":
        assert "above what the high-speed ball model holds" in res.reason[0]


def test_hertz_constants_at_the_operating_angles_change_little():
    """bearingkit evaluates K_i, K_o at the free contact angle (rows/ball/speed.py); Jones and Harris
    at each contact's operating angle. Up to 20,000 rpm (d_m n = 2.5e6 mm/min for the 218) the two
    differ by less than 0.02° in the angles and 0.05 % in the loads and F_c: the simplification is of
    second order, as stated."""
    speeds = np.array([10000.0, 15000.0, 20000.0]) * RPM
    free, unknowns = _jones_path(speeds, hertz_at="free")
    for w, a, u in zip(speeds, free, unknowns, strict=True):
        b, _ = _jones(w, "outer", "operating", u)
        for key in ("contact_angle_inner", "contact_angle_outer"):
            assert abs(a[key] - b[key]) < np.radians(0.02)
        for key in ("load_inner", "load_outer", "centrifugal_force"):
            assert abs(a[key] - b[key]) < 5e-4 * b[key]


def test_example_file_at_harris_conditions_matches_jones():
    """examples/acbb_7218_harris.toml through the pipeline (units, GCr15 defaults, a case's own speed, the
    default outer-raceway control) gives the independent solution at 10,000 rpm."""
    from pathlib import Path

    from bearingkit import materials
    from bearingkit.pipeline import analyze

    steel = materials.MATERIALS["GCr15"]
    assert (steel.youngs_modulus, steel.poisson_ratio, steel.density) == (E_STEEL, NU_STEEL, RHO)
    example = Path(__file__).resolve().parents[2] / "examples" / "acbb_7218_harris.toml"
    res = analyze(example, cases=["thrust_22kN_10000rpm"]).statics
    assert res.converged.all()
    (ref,), _ = _jones_path([10000.0 * RPM])
    ex = res.rows[0].extras
    for key in KEYS:
        np.testing.assert_allclose(ex[key][0], ref[key], rtol=1e-8, err_msg=key)
