"""Literature cases for Hertz point contact (dimensionless, SI unit "1").

Harris & Kotzalas (2007), Rolling Bearing Analysis 5th ed., Table 6.1 lists the dimensionless
contact coefficients a*, b*, delta* against the curvature difference F(rho). bearingkit's exact
elliptic-integral solution (``bearingkit.physics.contact.hertz.contact_coefficients``) must reproduce every
row to 0.2 %: the table is printed with 4–5 significant digits, so 0.2 % covers its rounding and
the interpolation error of the book's own numerics with margin, while a wrong formula (e.g. a
missing factor in delta*) misses by whole percents.
"""

from __future__ import annotations

from bearingkit.physics.contact.hertz import contact_coefficients
from bearingkit.validation.registry import Case, register

SOURCE_TABLE_6_1 = "Harris & Kotzalas (2007) Rolling Bearing Analysis 5th ed., Table 6.1"
TOLERANCE_TABLE_6_1 = 0.002

#: (F(rho) as printed, a*, b*, delta*) — Harris & Kotzalas (2007), Table 6.1.
HARRIS_TABLE_6_1: tuple[tuple[str, float, float, float], ...] = (
    ("0", 1.0, 1.0, 1.0),
    ("0.1075", 1.0760, 0.9318, 0.9974),
    ("0.3204", 1.2623, 0.8114, 0.9761),
    ("0.4795", 1.4556, 0.7278, 0.9429),
    ("0.5916", 1.6440, 0.6687, 0.9077),
    ("0.6716", 1.8258, 0.6245, 0.8733),
    ("0.7332", 2.011, 0.5881, 0.8394),
    ("0.7948", 2.265, 0.5480, 0.7961),
    ("0.83495", 2.494, 0.5186, 0.7602),
    ("0.87366", 2.800, 0.4863, 0.7169),
    ("0.90999", 3.233, 0.4499, 0.6636),
    ("0.93657", 3.738, 0.4166, 0.6112),
    ("0.95738", 4.395, 0.3830, 0.5551),
    ("0.97290", 5.267, 0.3490, 0.4960),
    ("0.983797", 6.448, 0.3150, 0.4352),
    ("0.990902", 8.062, 0.2814, 0.3745),
    ("0.995112", 10.222, 0.2497, 0.3176),
    ("0.997300", 12.789, 0.2232, 0.2705),
    ("0.9981847", 14.839, 0.2072, 0.2427),
    ("0.9989156", 17.974, 0.18822, 0.2106),
    ("0.9994785", 23.55, 0.16442, 0.17167),
    ("0.9998527", 37.38, 0.13050, 0.11995),
)

_QUANTITIES = (
    ("a_star", "dimensionless semi-major axis a* of the contact ellipse"),
    ("b_star", "dimensionless semi-minor axis b* of the contact ellipse"),
    ("delta_star", "dimensionless contact approach delta*"),
)


def _compute(f_rho: float, index: int):
    def compute() -> float:
        return float(contact_coefficients(f_rho, method="exact")[index])

    return compute


for _f_text, *_published in HARRIS_TABLE_6_1:
    for _index, (_name, _what) in enumerate(_QUANTITIES):
        register(
            Case(
                id=f"harris/table6.1/F{_f_text}/{_name}",
                source=SOURCE_TABLE_6_1,
                quantity=f"{_what} at F(rho) = {_f_text} (exact Hertz)",
                unit="1",
                published=float(_published[_index]),
                compute=_compute(float(_f_text), _index),
                tolerance=TOLERANCE_TABLE_6_1,
            )
        )
