"""Planetary thread-roller rows (seed 004): equivalent-ball contact pairs per tooth (``geometry``), load
shares over rollers and teeth (``distribution``), the row (``row``) and its compiled point contacts
(``compiled``). SI units."""
