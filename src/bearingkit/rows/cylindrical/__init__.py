"""Cylindrical-roller rows (sliced line contacts, crowning, tilt; ``row``), needle rows (``needle``),
crossed rollers (``crossed``), per-roller equilibrium at speed (``speed``) and the compiled response of
``row`` (``compiled``). SI units."""
