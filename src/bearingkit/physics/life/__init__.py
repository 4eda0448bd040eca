"""Load ratings and life: ISO 76, ISO 281, ISO/TS 16281 and the PTRB ratings. SI units throughout."""
