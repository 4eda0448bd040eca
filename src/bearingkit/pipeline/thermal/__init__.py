"""The bearing's temperature (SI units, temperatures in °C): ``balance`` finds the operating temperature
where friction heat equals the heat carried away and runs the analysis at it; ``reference`` gives the
thermal reference speed (ISO 15312) and the compact heat balance of ``friction --heat``."""
