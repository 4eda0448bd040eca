"""Number formatting of the CLI tables (bearingkit.cli.tables)."""

from __future__ import annotations

import pytest

from bearingkit.cli.tables import _compact


@pytest.mark.parametrize(
    "value, scale, text",
    [
        (4003e6, 1e-6, "4.00e3"),  # a 7206 B life printed as '4e3' (one digit) before
        (1150e6, 1e-6, "1.15e3"),
        (2.0e5, 1.0, "2.00e5"),
        (100.0, 1.0, "100"),  # no '100.' from the '#' flag
        (65.3, 1.0, "65.3"),
        (6.0, 1.0, "6.00"),
        (0.00892, 1.0, "0.00892"),
        (None, 1.0, "—"),
    ],
)
def test_compact_keeps_three_significant_digits(value, scale, text):
    assert _compact(value, scale) == text
