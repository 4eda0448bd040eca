"""Structures: thin-ring bending, ring beam between supports, thread tooth strength. SI units throughout."""
