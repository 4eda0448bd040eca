"""A case that fails at speed but converges at rest is told so (analysis/solver/speed.explain_at_rest): a
light load on a large tapered bearing at 1000 r/min (NSK's limiting speed for the 32364 is 480/670 r/min)
was answered "the load exceeds what the contacts carry" — the opposite of the cause."""

import bearingkit as bk
from bearingkit.analysis.solver.speed import AT_REST_REASON


def test_a_light_load_at_speed_is_told_the_speed_is_the_cause():
    light = {"F_x": "30 kN", "F_z": "15 kN"}  # 0.7 % of C = 4200 kN
    at_speed = bk.analyze("32364", load=light, speed="1000 rpm").statics
    assert not at_speed.converged[0]
    assert at_speed.reason[0] == AT_REST_REASON.format(rpm="1000")
    assert bk.analyze("32364", load=light, speed="100 rpm").statics.converged[0]  # slower: it holds


def test_a_load_that_fails_at_rest_too_keeps_the_solvers_reason():
    huge = {"F_x": "1e9 N", "F_z": "15 kN"}
    at_speed = bk.analyze("32364", load=huge, speed="1000 rpm").statics
    assert not at_speed.converged[0]
    assert "converges at rest" not in at_speed.reason[0]
    assert at_speed.reason[0].startswith("the load cannot be carried")
