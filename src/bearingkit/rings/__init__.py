"""Ring compliance: section properties and flexible outer rings (seed 002). SI units."""

from bearingkit.rings.flexible import FlexibleOuterRing, RingLoads
from bearingkit.rings.section import RingSection

__all__ = ["FlexibleOuterRing", "RingLoads", "RingSection"]
