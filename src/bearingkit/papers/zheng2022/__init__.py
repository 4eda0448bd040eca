"""Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051.

The planetary thread roller bearing (seed 004): design rules, parameter studies, NSGA-II and validation.

SI units throughout.
"""
