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
    "iso_tr1281_1": "ISO/TR 1281-1:2021 Rolling bearings - Explanatory notes on ISO 281 - Part 1: Basic "
    "dynamic load rating and basic rating life.",
    "lundberg1947": "Lundberg G., Palmgren A. (1947) Dynamic capacity of rolling bearings. Acta Polytech. "
    "Mech. Eng. Ser. 1(3).",
    "smith2015": "Smith W.A., Randall R.B. (2015) Rolling element bearing diagnostics using the Case Western "
    "Reserve University data: a benchmark study. MSSP 64-65:100-131. doi:10.1016/j.ymssp.2015.04.021",
    "lundberg1939": "Lundberg G. (1939) Elastische Berührung zweier Halbräume. "
    "Forsch. Ing.-Wes. 10(5):201-211.",
    "johns1981": "Johns P.M., Gohar R. (1981) Roller bearings under radial and eccentric loads. "
    "Tribology International 14(3):131-136.",
    "ju2000": "Ju S., Horng T., Cha K. (2000) Comparisons of contact pressures of crowned rollers. "
    "Proc. Inst. Mech. Eng. Part J: J. Eng. Tribol. 214:147.",
    "astm_d341": "ASTM D341-09(2015) Standard practice for viscosity-temperature charts for liquid "
    "petroleum products. ASTM International.",
    "astm_d2270": "ASTM D2270-10 Standard practice for calculating viscosity index from kinematic "
    "viscosity at 40 and 100 degC (= ISO 2909). ASTM International.",
    "iso3448": "ISO 3448:1992 Industrial liquid lubricants - ISO viscosity classification.",
    "gb443": "GB 443-89 Lubricating oils for total loss systems L-AN. Standardization Press of China, 1989.",
    "walther1931": "Walther C. (1931) The evaluation of viscosity data. Erdöl und Teer 7:382-384.",
    "stachowiak_batchelor": "Stachowiak G.W., Batchelor A.W. Engineering Tribology, Butterworth-Heinemann, "
    "ch. 2 (physical properties of lubricants), Table 2.3.",
    "callister2007": "Callister W.D., Rethwisch D.G. (2007) Fundamentals of Materials Science and "
    "Engineering, 3rd ed., Wiley, Appendix B, Table B.2.",
    "johnson1985": "Johnson K.L. (1985) Contact Mechanics. Cambridge University Press. "
    "doi:10.1017/CBO9781139171731",
    "hamrock1977starvation": "Hamrock B.J., Dowson D. (1977) Isothermal EHL of point contacts, Part IV - "
    "Starvation results. J. Lubr. Technol. 99(1):15-23.",
    "dowson1968": "Dowson D. (1968) Elastohydrodynamics. Proc. IMechE 182(3A):151-167; Dowson D., "
    "Higginson G.R. (1977) Elasto-Hydrodynamic Lubrication, SI ed., Pergamon.",
    "pan1989": "Pan P., Hamrock B.J. (1989) Simple formulas for performance parameters used in "
    "elastohydrodynamically lubricated line contacts. J. Tribol. 111(2):246-251.",
    "murch1975": "Murch L.E., Wilson W.R.D. (1975) A thermal elastohydrodynamic inlet zone analysis. "
    "J. Lubr. Technol. 97(2):212-216.",
    "aihara1987": "Aihara S. (1987) A new running torque formula for tapered roller bearings under axial "
    "load. J. Tribol. 109(3):471-477.",
    "bair1979": "Bair S., Winer W.O. (1979) A rheological model for elastohydrodynamic contacts based on "
    "primary laboratory data. J. Lubr. Technol. 101(3):258-264.",
    "skf_friction": "SKF Group, Rolling bearings catalogue: The SKF model for calculating the frictional "
    "moment (mu_bl, mu_EHL, phi_bl).",
}


def cite(key: str) -> str:
    """The full citation for ``key`` (KeyError if unknown, so typos fail tests)."""
    return REFERENCES[key]


def add(key: str, text: str) -> str:
    """Register a citation from a model's own module (idempotent for identical text); returns key."""
    known = REFERENCES.get(key)
    if known is not None and known != text:
        raise KeyError(f"reference key {key!r} is already registered with a different citation")
    REFERENCES[key] = text
    return key
