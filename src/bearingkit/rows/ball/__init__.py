"""Ball rows: grooves with one or two shoulders (``row``), four-point gothic arches (``four_point``),
per-ball equilibrium at speed (``speed``) and the compiled response of ``row`` (``compiled``). SI units."""
