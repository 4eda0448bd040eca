"""Citations used by models. Each model registers its source; results list what a run used."""

from __future__ import annotations

REFERENCES: dict[str, str] = {
    "harris2007": "Harris T.A., Kotzalas M.N. (2007) Rolling Bearing Analysis, 5th ed., CRC Press.",
    "hamrock1983": "Hamrock B.J., Brewe D. (1983) Simplified solution for stresses and deformations. "
    "J. Lubr. Technol. 105(2):171-177. doi:10.1115/1.3254558",
    "hamrock1977": "Hamrock B.J., Dowson D. (1977) Isothermal EHL of point contacts, Part III. "
    "J. Lubr. Technol. 99(2):264-275. doi:10.1115/1.3453074",
    "iso16281": "ISO/TS 16281:2008 Rolling bearings - Methods for calculating the modified reference "
    "rating life for universally loaded bearings.",
    "iso281": "ISO 281:2007 Rolling bearings - Dynamic load ratings and rating life.",
    "iso76": "ISO 76:2006 Rolling bearings - Static load ratings.",
    "tian2025": "Tian H., Li W., Shao X., Zhang Z., Zhang W. (2025) Analysis of friction torque "
    "characteristics of a novel ball-roller composite turntable bearing. Machines 13:588. "
    "doi:10.3390/machines13070588",
    "liu2022": "Liu et al. (2022) An investigation for the friction torque of a tapered roller bearing "
    "considering the geometric homogeneity of rollers. Lubricants 10:154. doi:10.3390/lubricants10070154",
    "li2025": "Li et al. (2025) Adaptive gradient loading mechanism of ball-column composite bearings "
    "considering collar deformation. Machines 13:785.",
    "zheng2022": "Zheng et al. (2022) Characteristics analysis and optimization of the structural "
    "parameters of PTRB. Machines 10:1051.",
    "kunert1961": "Kunert K.H. (1961) Spannungsverteilung im Halbraum bei elliptischer "
    "Flächenpressungsverteilung über einer rechteckigen Druckfläche. Forsch. Ing.-Wes. 27:165-174.",
    "palmgren1959": "Palmgren A. (1959) Ball and Roller Bearing Engineering, 3rd ed., SKF Industries.",
    "stribeck1901": "Stribeck R. (1901) Kugellager für beliebige Belastungen. Z. VDI 45:73-125.",
}


def cite(key: str) -> str:
    """The full citation for ``key`` (KeyError if unknown, so typos fail tests)."""
    return REFERENCES[key]
