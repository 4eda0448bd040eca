"""ISO 281 contamination levels → e_C (middle of the Table 13 ranges, by pitch diameter)."""

import pytest

from bearingkit.errors import InputError
from bearingkit.physics.life.iso281_contamination import contamination_factor, contamination_levels


def test_levels_and_columns():
    assert contamination_levels()[0] == "extreme_cleanliness" and len(contamination_levels()) == 7
    assert contamination_factor("normal_cleanliness", 0.065) == pytest.approx(0.55)
    assert contamination_factor("normal_cleanliness", 0.15) == pytest.approx(0.7)
    assert contamination_factor("very_severe_contamination", 0.05) == 0.0
    values = [contamination_factor(level, 0.05) for level in contamination_levels()]
    assert values == sorted(values, reverse=True)  # cleaner → larger e_C


def test_unknown_level_suggests():
    with pytest.raises(InputError, match="did you mean normal_cleanliness"):
        contamination_factor("normal_cleanlines", 0.05)
