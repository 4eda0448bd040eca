"""Case generators of design studies (``generators``): sweeps, factorials, orthogonal arrays, Monte Carlo."""
