"""Tapered-roller rows: geometry of the meridian (``geometry``), contact laws (``laws``), the per-roller
equilibrium with raceways, rib and centrifugal force (``kernel``), the row (``row``) and its compiled
response (``compiled``). SI units."""
