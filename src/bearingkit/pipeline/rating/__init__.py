"""What the pipeline's rating reads beyond the solved statics (SI units): the cases re-solved with the
ISO/TS 16281 pitch-radius arm (``statics``), the notes of a mounted single bearing whose DOF is held
(``mounting``), and the stresses below the surface with the raceways' hardness and the truncated
contacts (``subsurface``)."""
