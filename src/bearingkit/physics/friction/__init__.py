"""Friction models: physical components, SKF, Palmgren, and the seed papers' TRB/PTRB models.

SI units throughout.
"""
