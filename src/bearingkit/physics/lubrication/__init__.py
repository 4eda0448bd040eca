"""Lubrication: EHL film thickness and rolling resistance, traction. SI units throughout."""
