"""One shaft on several bearings (SI units): the Timoshenko beam (``beam``, ``shaft``), loads and supports
(``loads``, ``supports``), the global Newton with every bearing's nonlinear law (``solver``), its result
and the bearings' analyses (``result``, ``shaft_analysis``, ``life``), the shaft file (``input``) and the
stiffness at the operating point for rotordynamics (``stiffness``)."""
