"""Range analysis, main effects and interactions: known additive model and seed 000 Table 3."""

import numpy as np
import pandas as pd
import pytest
from bk_study_helpers import EFFECTS, _additive

from bearingkit.studies.designs import generators
from bearingkit.studies.results import analysis


@pytest.mark.parametrize("array", ["L9", "L27"])
def test_range_analysis_recovers_known_additive_effects(array):
    design = generators.orthogonal_design({f: [0, 1, 2] for f in EFFECTS}, array)
    design["y"] = _additive(design)["y"]
    table = analysis.range_analysis(design, list(EFFECTS), "y")
    true_range = {f: max(e) - min(e) for f, e in EFFECTS.items()}
    np.testing.assert_allclose(
        table.set_index("factor")["range"].loc[list(EFFECTS)], list(true_range.values())
    )
    assert list(table["factor"]) == sorted(true_range, key=true_range.get, reverse=True)  # p, r, q, s
    me = analysis.main_effects(design, list(EFFECTS), "y").set_index(["factor", "level"])["mean"]
    # level means differ exactly by the effects (balanced design: other factors average out)
    for f, eff in EFFECTS.items():
        np.testing.assert_allclose(me.loc[f].to_numpy() - me.loc[f].to_numpy()[0], np.subtract(eff, eff[0]))
    assert table.set_index("factor").loc["r", "best_level"] in (2, 3)


def test_interaction_strength_zero_for_additive_and_not_otherwise():
    ff = generators.full_factorial({"a": [0.0, 1.0, 2.0], "b": [0.0, 1.0, 2.0]})
    ff["y"] = 2 * ff["a"] + 3 * ff["b"]
    assert analysis.interaction_strength(ff, "a", "b", "y") < 1e-12
    ff["y2"] = ff["a"] * ff["b"]
    assert analysis.interaction_strength(ff, "a", "b", "y2") > 0.1
    t = analysis.interaction_table(ff, "a", "b", "y2")
    assert t.loc[2.0, 2.0] == 4.0


#: Seed 000 Table 3 (Tian et al. 2025): runs 1–9 friction torque [N·mm].
TABLE3_TORQUE = [2871.7, 4045.4, 5379.6, 5692.0, 3208.1, 4092.0, 4767.5, 5774.0, 3772.4]


def test_published_table3_gives_the_published_ranking():
    """Range analysis of the published torques → D > A > C > B (seed 000 §6.2, Figure 20)."""
    design = generators.orthogonal_design(
        {"A": [0, -1, -2], "B": [-4, -5, -6], "C": [0.51, 0.52, 0.53], "D": [0.2, 0.3, 0.4]}, "L9"
    )
    design["M"] = TABLE3_TORQUE
    assert analysis.sensitivity_ranking(design, list("ABCD"), "M") == ["D", "A", "C", "B"]


def test_plots_are_written(tmp_path):
    design = generators.orthogonal_design({f: [0, 1, 2] for f in EFFECTS}, "L9")
    design["y"] = _additive(design)["y"]
    me = analysis.main_effects(design, list(EFFECTS), "y")
    analysis.plot_main_effects(me, tmp_path / "me.png", "y")
    analysis.plot_range(analysis.range_analysis(design, list(EFFECTS), "y"), tmp_path / "r.png", "y")
    analysis.plot_interaction(design, "p", "q", "y", tmp_path / "i.png")
    front = pd.DataFrame({"f1": [0.0, 0.5, 1.0], "f2": [1.0, 0.3, 0.0]})
    analysis.plot_pareto(front, ["f1", "f2"], tmp_path / "p.png", front.iloc[[1]].assign(selection="knee"))
    assert all((tmp_path / n).stat().st_size > 1000 for n in ("me.png", "r.png", "i.png", "p.png"))
