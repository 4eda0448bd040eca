"""Benchmarks of bearingkit (not part of the timed test suite). Run ``python -m benchmarks``."""
