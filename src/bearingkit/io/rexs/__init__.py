"""The FVA's REXS exchange format of gearbox models: ``reader`` turns a REXS 1.4 model (XML or JSON) into
a drivetrain input, ``export`` writes the bearing results back into it."""
