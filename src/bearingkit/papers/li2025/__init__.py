"""Li et al. (2025) Machines 13:785.

The ball–column composite bearing with a flexible outer ring (seed 002): studies, figures and validation.

SI units throughout.
"""
