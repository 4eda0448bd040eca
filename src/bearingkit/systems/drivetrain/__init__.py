"""Several shafts joined by gear meshes and planetary stages (SI units): the model (``model``), gear
geometry and mesh stiffness (``gearing``), planetary stages (``planetary``), the drivetrain file
(``input``), one global solve over every shaft (``solver``, ``result``), the bearings' analyses and the
system lives (``analysis``), power flow and losses (``power_flow``) and the JSON/table output
(``output``)."""
