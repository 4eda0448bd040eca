"""Liu et al. (2022) Lubricants 10:154.

The tapered roller bearing 32008J with roller-diameter scatter (seed 001): Monte Carlo study and
validation.

SI units throughout.
"""
