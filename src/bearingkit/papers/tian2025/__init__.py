"""Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588.

The ball–roller composite turntable bearing (seed 000): friction-torque studies, statics studies, L9
study, validation.

SI units throughout.
"""
