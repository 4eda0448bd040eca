"""The estimate's ISO 281 C and ISO 76 C0 against the catalogues: the sizes of issue 33 within 15 %, and
every size outside 10 % named with its cause (docs/catalogue.md, "Known deviations").

Published ratings: NSK *Rolling Bearings*, CAT. No. E1102e (English edition), and for the 70 AC rows
NTN's ULTAGE spindle bearing table and for the 70 B and some 72/73/70 C rows KOYO's CAT. No. B2001RUS, as
transcribed into the data files (whose ``source`` column names the page); repeated here with the page so
that a change of a data file shows. CALIBRATIONS (a constant chosen on that size, so not a prediction):
the 6309 (Conrad fill angle 189°, catalogue.internal.CONRAD_FILL_ANGLE), the 1205 (self-aligning cage
pitch 1.205, RULES) and the 32008 X (roller end allowance 1.0 mm, ROLLER_END_ALLOWANCE, from seed 001's
published roller against NSK's C0); the 34 sizes 7204-7220 of the 72 series (72B and 72C; 72A shares
72B's bearings; 7221-7240, rated later, are predictions) are the calibration set of the angular contact
ball size and cage pitches (k_w = 0.317, pressed steel 1.145, machined 1.227: the medians of the geometry
NSK's C and C0 imply); the 23 sizes 7000C-7022C of NSK's 70 C are the calibration set of the light
angular contact sections' ball (0.295 (D - d), 70 and 719); the 41 sizes of the spherical 230 series and
the 16 EA sizes 22208-22226 are the calibration sets of the radial spherical roller rules
(catalogue.internal.SPHERICAL_RULES, the same method).
Every other size is a prediction of rules chosen before or elsewhere (73, QJ: the 72 rule; 70 A/AC/B and
719: the light-section rule).
"""

from __future__ import annotations

import pytest

from bearingkit.catalogue import FAMILIES, entries, estimate, ratings

#: designation (table key) → (C [N], C0 [N], where printed).
NSK = "NSK E1102e"
ISSUE_SIZES = {
    "6004": (9400, 5000, f"{NSK} B8"),
    "6005": (10100, 5850, f"{NSK} B10"),
    "6006": (13200, 8300, f"{NSK} B10"),
    "6007": (16000, 10300, f"{NSK} B10"),
    "6008": (16800, 11500, f"{NSK} B10"),
    "6009": (20900, 15200, f"{NSK} B10"),
    "6010": (21800, 16600, f"{NSK} B12"),
    "6204": (12800, 6600, f"{NSK} B8"),
    "6205": (14000, 7850, f"{NSK} B10"),
    "6206": (19500, 11300, f"{NSK} B10"),
    "6207": (25700, 15300, f"{NSK} B10"),
    "6208": (29100, 17900, f"{NSK} B10"),
    "6209": (31500, 20400, f"{NSK} B10"),
    "6210": (35000, 23200, f"{NSK} B12"),
    "6304": (15900, 7900, f"{NSK} B8"),
    "6305": (20600, 11200, f"{NSK} B10"),
    "6306": (26700, 15000, f"{NSK} B10"),
    "6307": (33500, 19200, f"{NSK} B10"),
    "6308": (40500, 24000, f"{NSK} B10"),
    "6309": (53000, 32000, f"{NSK} B10 (calibration size of the fill angle)"),
    "6310": (62000, 38500, f"{NSK} B12"),
    "7205B": (14800, 9400, f"{NSK} B52 (72 series: calibration set of the angular contact rule)"),
    "7206B": (20500, 13500, f"{NSK} B52 (72 series: calibration set of the angular contact rule)"),
    "NU205E": (29300, 27700, f"{NSK} B84"),
    "NU206E": (39000, 37500, f"{NSK} B84"),
    "NU207E": (50500, 50000, f"{NSK} B84"),
    "NU208E": (55500, 55500, f"{NSK} B86"),
    "30205": (32000, 35000, f"{NSK} B112"),
    "30206": (43000, 47500, f"{NSK} B114"),
    "30305": (47500, 46000, f"{NSK} B112"),
    "32206": (52000, 60000, f"{NSK} B114"),
    "1205": (12200, 3300, f"{NSK} B74 (C0: calibration size of the self-aligning cage pitch)"),
    "1206": (15800, 4650, f"{NSK} B74"),
}


def _entry(name: str):
    return next(fam[name] for fam in (entries(f) for f in FAMILIES) if name in fam)


@pytest.mark.parametrize("name", sorted(ISSUE_SIZES))
def test_issue_sizes_within_15_percent(name):
    c_pub, c0_pub, where = ISSUE_SIZES[name]
    e = _entry(name)
    assert (e.C, e.C0) == (c_pub, c0_pub) and where.split()[2] in e.source, where
    c, c0 = ratings(estimate(e))
    assert c == pytest.approx(c_pub, rel=0.15), (name, c, where)
    assert c0 == pytest.approx(c0_pub, rel=0.15), (name, c0, where)


#: Every rated size whose C or C0 is more than 10 % off, by cause (docs/catalogue.md "Known deviations").
EXCEPTIONS = {
    "618/619 thin sections: balls of 2.4-5 mm, one ball more or less is 7-12 %, and the ball sizes and "
    "counts NSK's C and C0 imply need fill angles up to 224° (thin rings take more balls) above the rule's "
    "189°; 618 at B = 5 mm: NSK's 3/32 in ball (2.381 mm = 0.48 B) is below the 0.55 B of the 618 rule": [
        "61800", "61801", "61802", "61808", "61809", "61816",
        "61900", "61901", "61906", "61911",
    ],
    "618 from 130 mm (NSK B16-B24, machined brass cages from 61840): C -6…-23 %, C0 -11…-25 %: the "
    "rule's ball (0.55 B cap) is 11 % smaller to 3 % larger than the 0.53-0.62 B NSK's C and C0 imply, "
    "and NSK's counts need "
    "fill angles of 211-253° (where the two ratings can be solved for a ball and a count), above the "
    "rule's 189°: the large thin rings take more balls": [
        "61826", "61828", "61830", "61832", "61834", "61836", "61838", "61840", "61844", "61848",
        "61852", "61856", "61860", "61864", "61868", "61872", "61876", "61880", "61884", "61888",
        "61892", "61896", "618/500", "618/530", "618/560", "618/600", "618/630", "618/670", "618/710",
        "618/750", "618/800",
    ],
    "62 95-130 mm, 63 100-110 mm and 180 mm, 160 at 90-190 and 280-320 mm (NSK B14-B20): C -9…-14 %, "
    "C0 -7…-16 %: the width cap 0.70 B holds the ball below the 0.74-0.81 B NSK's C and C0 imply at the "
    "rule's count (implied fill angles 180-194°)": [
        "6219", "6220", "6221", "6222", "6224", "6226", "6320", "6321", "6322", "6336",
        "16018", "16019", "16022", "16026", "16028", "16032", "16036", "16038", "16056", "16060", "16064",
    ],
    "61938, 619/530, 6232, 60/630, 60/670 (NSK B18-B24): C and C0 +9…+27 %: the rule's ball is larger "
    "than the one NSK's C and C0 imply (61938 20.5 against 21.7 mm, 6232 31.7 against 33.6 mm, 619/530 "
    "0.26 (D - d), 60/630 and 60/670 0.24-0.27 (D - d) against the rule's 0.31); why NSK's ball is smaller "
    "at these sizes than at their neighbours: cause not found": [
        "61938", "619/530", "6232", "60/630", "60/670",
    ],
    "6021: NSK's ratings imply 15 balls at a 204° fill angle, two more than the 189° rule (C0 -10.4 %)": [
        "6021"
    ],
    "smallest bores: the rule's ball 0.31 (D - d) is 5-30 % above the one NSK's C and C0 imply "
    "(6200: 6.2 against 4.7 mm)": ["6003", "6008", "16003", "6200"],
    "6215: NSK's ratings imply 11 balls at a 198° fill angle, one more than the 189° rule": ["6215"],
    "64 (SKF 6000, Explorer ratings): the width cap 0.80 B holds the ball 8-11 % below the one SKF's C and "
    "C0 imply": ["6404", "6409", "6410"],
    "7204C, the smallest 15° size: NSK's C and C0 imply 9.9 balls of 7.98 mm at a cage pitch of 1.33, above "
    "the machined-cage median 1.227 of the 72C table (C, C0 +13 %)": ["7204C"],
    "7200 A/B/C (NSK B50): C +39…+45 %, C0 +26…+37 %: NSK rates the 7200 (D = 30 mm) at 5.0-5.4 kN, 67-68 % "
    "of its 7201's 7.45-8.0 kN (D = 32 mm); the estimate steps 7200 → 7201 by 9-10 %: cause not found": [
        "7200A", "7200B", "7200C",
    ],
    "7202C, 7203C, the 15° sizes below 7204 (NSK B50): C +11…+13 %, C0 +10…+13 %, as the 7204C above: "
    "cause not found": ["7202C", "7203C"],
    "7301 A/B (NSK B50): C and C0 +17…+19 %: NSK rates the 7301 (D = 37, B = 12 mm) at 2 % above the 7300 "
    "(D = 35, B = 11 mm; 9.45 against 9.3 kN, 30°), the estimate 12 % above: cause not found": [
        "7301A", "7301B",
    ],
    "72 A/B 140-180 mm (NSK B62-B64, machined brass cages from 7224): C -7…-11 %, C0 -11…-15 %: NSK's C "
    "and C0 imply 16-17 balls at a cage pitch of 1.11-1.16, the rule's machined-cage pitch 1.227 gives 14-15 "
    "(the ball, at the 0.80 B width cap, is within 2 % of the implied one); 7224, 7226, 7232, 7238, 7240 are "
    "within 10 %": [
        "7228A", "7228B", "7230A", "7230B", "7234A", "7234B", "7236A", "7236B",
    ],
    "spindle series 70 and 719, small sizes (NSK B50-B62, KOYO B2001RUS; 7000B-7005x, 71900-71916): C "
    "+4…+23 %, C0 +8…+21 %: the light-section ball 0.295 (D - d) is the median of NSK's 70 C; the "
    "ratings of these sizes imply balls of 0.26-0.30 (D - d) at wider cage pitches (1.22-1.45) than the "
    "rule's (machined 1.227, pressed steel 1.145), i.e. fewer, mostly smaller balls than the estimate; "
    "NSK prints no ball size": [
        "7000B", "7002A", "7002B", "7003A", "7003B", "7003C", "7004B", "7005A", "7005B", "7005C",
        "71900C", "71900AC", "71901C", "71901AC", "71902C", "71904C", "71904AC", "71905C", "71905AC",
        "71906C", "71906AC", "71909C", "71909AC", "71911C", "71911AC", "71912C", "71912AC", "71915C",
        "71916C",
    ],
    "70 series from 55 mm, NTN's AC (ULTAGE p. 4) 7011AC-7021AC, KOYO's 7021B, 7024B and NSK's 7038A: C "
    "-7…-11 %, C0 -10…-14 %: their ratings imply the rule's ball (0.294-0.303 (D - d)) at a tighter cage "
    "pitch (1.12-1.18) than the rule's machined 1.227, so more balls than the estimate's": [
        "7011AC", "7014AC", "7015AC", "7016AC", "7017AC", "7018AC", "7019AC", "7020AC", "7021AC",
        "7021B", "7024B", "7038A",
    ],
    "NSK's 7022A, 7022C, 7024A (B56): C -10…-14 %, C0 -8…-13 %: NSK's ratings imply the 72 series' ball "
    "(0.317 (D - d)) at a cage pitch of 1.17-1.21: larger balls, about as many as the estimate's": [
        "7022A", "7022C", "7024A",
    ],
    "KOYO's 73 C and 72 C (machined cage): 7304C +10 %; 7310C, 7311C C0 -10 %; 7228C, 7230C (the bores of "
    "NSK's 72 A/B deviation) C0 -11…-15 %; 7328C-7332C C0 -12 %: cause not found": [
        "7304C", "7310C", "7311C", "7228C", "7230C", "7328C", "7330C", "7332C",
    ],
    "ZVL's 6422 (ZVL Bearing Catalogue p. 089, ZVL's rating): C +13 %: ZVL prints C0 above C (C0/C 1.06 "
    "against 0.75-0.82 at its 6415-6418 and the estimate's 0.92); for one ball set on d_m ISO 76/ISO 281 "
    "give C0/C in proportion to Z^(1/3) D_w^0.6 / f_c, so no ball set within the ISO 15 section gives both "
    "numbers; cause on the catalogue side not found": ["6422"],
    "NU19 (KRW Lieferprogramm 2006 pp. 180-187, KRW's E design, the only NU19 design KRW prints): "
    "C -16…-36 %, C0 -13…-33 %: the NU19 rule is the NU10 rule, chosen over NSK's standard-design NU10; "
    "KRW's E-design NU10 lines are 1.17-1.49 x NSK's NU10 and the estimate sits -23…-37 % below them too": [
        "NU1910", "NU1911", "NU1912", "NU1913", "NU1914", "NU1915", "NU1916", "NU1917", "NU1918", "NU1919",
        "NU1920", "NU1921", "NU1922", "NU1924", "NU1926", "NU1928", "NU1930", "NU1932", "NU1934", "NU1936",
        "NU1938", "NU1940",
    ],
    "AKE's 72 AC (AKE CSKGB072009 p. 13, B72..ATA): 7203AC, 7204AC C +14 %, C0 +13 %; AKE's 15° rows of "
    "these bores equal NSK's 72 C: cause not found": ["7203AC", "7204AC"],
    "double row: ball size and count against those NSK's C and C0 imply (3200 ball too large; 3303, 3304, "
    "3306 one ball fewer or width-capped; 3214 rated by NSK above the larger 3215; 3206 one ball fewer)": [
        "3200", "3206", "3214", "3303", "3304", "3306",
    ],
    "self-aligning 12: small α keeps the balls below d_m tan α (the engine's rows may not cross the centre "
    "plane; real rows are staggered): too many small balls at small bores, too small at large ones": [
        "1200", "1201", "1203", "1204", "1207", "1212", "1215", "1216", "1217", "1218", "1219", "1220",
        "1222",
    ],
    "self-aligning 22: count discreteness (one ball per row is 6-8 %)": ["2200", "2205", "2206"],
    "self-aligning 13 (NSK B74-B78): C -10…-29 %, C0 up to -27 %, low at every size from 1305 and more "
    "so with the bore; the self-aligning rule was chosen on the 12 series (cage pitch on 1205) and NSK's "
    "13 ratings imply more ball than it gives: cause not found. 1301: NSK rates it 9650 N, next to the "
    "1302's 9700 N at D = 42 against 37 mm (1300: 7350 N), a step the estimate does not follow": [
        "1301", "1305", "1306", "1308", "1309", "1310", "1311", "1312", "1313", "1314", "1315", "1316",
        "1317", "1318", "1319", "1320", "1321", "1322",
    ],
    "double-row cylindrical NN30 (NSK B102-B104): C0 +10…+19 %, C up to +13 % (their mean +6.9 %/+11.8 %): "
    "the estimate's double-row roller set is above the one NSK's ratings imply (NSK prints E_w, not checked "
    "against the estimate's): cause not found. NN3015: NSK rates it 96.5 kN, below the smaller NN3014's "
    "97.5 kN; the estimate steps up": [
        "NN3006", "NN3008", "NN3009", "NN3010", "NN3011", "NN3012", "NN3013", "NN3015", "NN3016", "NN3017",
        "NN3018", "NN3019", "NN3020", "NN3026", "NN3028", "NN3030", "NN3032", "NN3034", "NN3040",
    ],
    "double-row cylindrical NN30 220-360 mm (NN3048-NN3072, NSK B104): C +7…+15 %, C0 +14…+22 %: NSK's NN30 "
    "C and C0 are 1.46-1.64 and 1.76-1.98 times its NU10's of the same d and D (NSK's E_w equal to the "
    "NU10's within 2 mm), at or below two NU10 rows (2^(7/9) = 1.71 and 2), while the "
    "estimate's are 1.97-2.08 and 2.41-2.57 times its NU10's: its per-row roller length (0.63 B/2 - 1 mm) "
    "is 20-24 % longer than its NU10 roller (0.42 B - 1 mm), where NSK's ratios imply rows no stronger than "
    "its NU10's (NSK prints no roller length; the rule is not changed)": [
        "NN3048", "NN3052", "NN3056", "NN3060", "NN3064", "NN3068", "NN3072",
    ],
    "self-aligning 23 (NSK B74-B78): C and C0 -10…-14 % at these sizes (the series' mean -7.5 %/-5.7 %): "
    "cause not found": ["2301", "2305", "2311", "2312", "2313", "2319"],
    "cylindrical: count discreteness at the ends of the 2/22 tables (one roller is 7-8 %)": [
        "NU205E", "NU2204E", "NU2216E",
    ],
    "NU10, bores 55-65 mm: NSK's rollers are shorter there than the 0.42 B - 1 mm rule (C0 +11…+15 %)": [
        "NU1011", "NU1012", "NU1013",
    ],
    "NU10 from 110 mm (NSK B92-B98): C -10…-18 %, C0 -7…-15 %: the NU10 roller (0.22 (D - d), 0.42 B - 1 mm, "
    "chosen on the 25-80 mm sizes) is below the one NSK's ratings imply; NSK's E_w - F_w gives D_w = "
    "0.24-0.25 (D - d) at every size, and a length 0.47 B would bring C to -8…+1 % (tried, not adopted)": [
        "NU1022", "NU1024", "NU1026", "NU1030", "NU1032", "NU1034", "NU1036", "NU1038", "NU1044", "NU1048",
        "NU1052", "NU1056", "NU1060", "NU1064", "NU1068", "NU1072", "NU1076", "NU1080", "NU1084", "NU1088",
        "NU1092", "NU1096", "NU10/500",
    ],
    "cylindrical wide series 22/23 E, 100-200 mm (NSK B92-B96): C0 -10…-14 % (NU2220E also C -12 %): NSK's "
    "ratings imply more roller length or rollers than the family rule (0.63 B - 1 mm, 0.27 (D - d), chosen "
    "on the 20-80 mm sizes); NSK publishes neither": [
        "NU2220E", "NU2236E", "NU2240E", "NU2320E", "NU2324E", "NU2326E",
    ],
    "30202: NSK's non-HR design (the HR series is NSK's high-capacity one)": ["30202"],
    "long rollers: the 1.0 mm end allowance on top of the 0.23 (D - d) roller leaves C −10…−11 %": [
        "30211", "30217", "30309", "32211", "32216", "32319",
    ],
    "tapered, NSK's standard (non-HR) design, the only one NSK prints for these sizes (B124-B130): where NSK "
    "prints both designs of one size (30326, 30330, 30332, 30334) the non-HR C is 12-16 % and C0 12-19 % "
    "below the HR one's, and the rules follow the HR rows (C +5…+16 %, C0 +10…+24 %); other non-HR sizes "
    "(30344-30352, 32244-32264, 32328-32364, 32980, 32984) are within 10 %": [
        "30244", "30248", "30252", "30256", "30260", "30264", "30336", "30338", "30340", "32326", "32976",
    ],
    "330/331 wide sections 85-100 mm (33018-33020, 33117; NSK B122): C -11…-14 %, C0 -9…-12 %: NSK's "
    "ratings imply more roller length or more rollers than the rule gives (L_we/D_w 2.25-2.35; 33018-33020 "
    "share D - d = 50 mm and so the rule's roller); NSK publishes neither": [
        "33018", "33019", "33020", "33117",
    ],
    "329 light sections 30-95 mm (NSK B114-B122): C +6…+29 %, C0 +8…+28 % (32906 the most): the estimate "
    "(roller 0.23 (D - d), L_we/D_w 1.9, count from the cage pitch) rates above NSK, whose ratings imply "
    "less roller capacity; NSK publishes no roller; the neighbours 32912, 32914-32916, 32918, 32920 are "
    "within 10 %: cause not found": [
        "32906", "32907", "32908", "32909", "32910", "32911", "32913", "32917", "32919",
    ],
    "332 (HR 332xx J, 25-85 mm, NSK B112-B122): C -3…-12 % (series mean -8 %), 33208, 33210, 33215 and 33216 "
    "beyond -10 % (33216 C0 -10 %): the estimate (roller 0.23 (D - d), length 0.72 B - 1 mm) rates below NSK "
    "throughout; NSK publishes no roller: cause not found; KOYO's 33218 (B2001RUS p. 214) C -10.2 % the same "
    "way": ["33208", "33210", "33215", "33216", "33218"],
    "30228: NSK's C0 (515 kN, B126) is 2 % above the smaller 30226's (505 kN) and 23 % below the 30230's "
    "(665 kN); the estimate steps evenly (C0 +11.5 %, C +3 %)": ["30228"],
    "32232: NSK's C0 in N (1 120 000, B126) disagrees with its own {kgf} column (125 000 kgf = 1 226 000 N); "
    "the row keeps the N value, against the kgf one the estimate is +1.7 %": ["32232"],
    "31318: steep cup angle (e = 0.83): C0 +15 %; NSK rates its C0 at the smaller 31317's (315 kN, B122)": [
        "31318"
    ],
    "thrust ball, small and 115 mm sizes: the cage pitch 1.05 gives one ball more than NSK's": [
        "51100", "51101", "51115", "51203", "51315",
    ],
    "cylindrical roller thrust: NSK prints D_w; the rule's roller and length (0.45 (D - d)/2) miss NSK's "
    "C0 by −11…−22 % on the 812 series": [
        "81109", "81117", "81212", "81216", "81222", "81224", "81230", "81234",
    ],
    "spherical 22205-22207: NSK's design C (B178-B180, lower capacity), C +5…+14 %, C0 +14…+24 %: the "
    "standard rule rates them between NSK's design C and SKF's E design (test_estimate_kinds)": [
        "22205", "22206", "22207",
    ],
    "spherical 223 EA (22309, 22315-22324) and 22226 EA (NSK B180-B186): C -6…-10 %, C0 -10…-13 %: the "
    "EA rule is the 222 EA sizes' median (L_we 0.753 B/2); NSK's 223 EA ratings imply longer rollers "
    "(median 0.807 B/2) and 22226, the largest 222 EA size, the longest of its set; the rule is not split "
    "by series": [
        "22309", "22315", "22316", "22317", "22318", "22319", "22320", "22322", "22324", "22226",
    ],
    "spherical 213 CD (21304-21307; NSK B180): C +12…+29 %, C0 +8…+28 % (21304, d = 20 mm, the most): "
    "NSK's ratings of these small designs imply shorter, thinner rollers (D_we 0.22-0.23 (D - d), L_we "
    "0.52-0.64 B/2) than the standard rule's (0.247, 0.716; calibrated on the 230 series)": [
        "21304", "21305", "21306", "21307",
    ],
    "spherical 213 EA (NSK B180-B184): NSK's ratings imply rollers thinner than the EA rule's (D_we median "
    "0.203 against 0.261 (D - d)), so C runs above NSK's and C0 below: 21317, 21318 C +10…+15 %; NSK's "
    "uneven steps make the rest: 21311 is rated as the smaller 21310 (142 kN, 174 kN; C +19 %), 21314 as "
    "the larger 21315 (250 kN, 325 kN; C0 -16 %), 21312's 190 kN lies between 142 and 212 kN (C0 -10.2 %; "
    "D_we held by the centre plane, as at 21309, 21310, 21313)": [
        "21311", "21312", "21314", "21317", "21318",
    ],
    "spherical 24120: NSK prints the CA design and rates it at the C of the narrower 23120 C (345 kN each, "
    "B = 65 against 52 mm; B184); the estimate follows the width (C +12 %, C0 +16 %)": ["24120"],
    "needle: the needle size grows with the section (NA49 small bores +10…+16 %, NA4926/28 and large NA48 "
    "−10…−12 %): the needle count and size are not the real ones": [
        "NA4900", "NA4902", "NA4903", "NA4905", "NA49/28", "NA4907", "NA4909", "NA4926", "NA4928",
        "NA4852", "NA4860", "NA4864",
    ],
    "spherical roller thrust 292 (NSK B225-B229, standard design): C +6…+11 %, C0 +8…+14 %: the standard "
    "design's rule (calibrated on the 294 standard sizes) gives L_we = 0.518 T; NSK's 292 ratings imply, "
    "at the same alpha, d_m and cage pitch, a roller of the same D_we/T (0.36-0.37) but shorter for its "
    "diameter (L_we/D_we 1.19-1.28 against 1.38-1.49 in 294): NSK prints no roller; the rule is not "
    "split by series": [
        "29240", "29244", "29248", "29260", "29264", "29268", "29272", "29276", "29280", "29284", "29288",
        "29292", "292/500",
    ],
}  # fmt: skip


def test_every_size_outside_10_percent_is_named_with_its_cause():
    """The sizes outside ±10 % (C or C0) are exactly the named exceptions: a change of the rules that
    moves a size in or out shows here (and docs/catalogue.md must follow)."""
    named = {d for names in EXCEPTIONS.values() for d in names}
    outside = set()
    for fam in FAMILIES:
        for e in entries(fam).values():
            if e.C is None or e.extra.get("inner_ring") == "no":
                continue
            c, c0 = ratings(estimate(e))
            if abs(c / e.C - 1) > 0.10 or abs(c0 / e.C0 - 1) > 0.10:
                outside.add(e.designation)
    assert outside == named, (sorted(outside - named), sorted(named - outside))
