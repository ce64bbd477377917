#!/usr/bin/python3
"""cook-table2 from hand-made records (session 75): our rows are paired with the paper's by the
data set each stands in for (the suite label's "for NAME", cook-table2.json's "data set"), never
by position: a data set without records is "not measured" in its own row and claim, and the
others keep their own paper row, whatever order the records come in.

usage: check_cook_table2_pairing.py REPORTS_DIR WORK_DIR
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
H.use_reports(REPORTS)
import xmpvo  # noqa: E402

shutil.rmtree(WORK, ignore_errors=True)
C = H.Checks("check_cook_table2_pairing", WORK)
check, expect, cells, close = C.check, C.expect, C.cells, H.close


# --- cook-table2: rows paired by data set, not by position ------------------------------------
XM = H.paper_numbers(REPORTS, "xmpvo")
BLUNTFIN, F117, table2 = H.COOK_TABLE2_BLUNTFIN, H.COOK_TABLE2_F117, H.cook_table2_records

ON_F117 = "SXMPVO is faster than BSP-XMPVO per view on gap 3x3x10"
ON_HELIX = "SXMPVO is faster than BSP-XMPVO per view on helix 600"
FOR_BLUNTFIN = "per view for bluntfin"
doc = expect(xmpvo, "cook-table2", XM, table2([BLUNTFIN, F117]), ON_F117, "holds", "both data sets")
check("for f117" in H.claim(doc, ON_F117)["claim"], "cook-table2: the gap row is not paired with f117")
check("for bluntfin" in H.claim(doc, ON_HELIX)["claim"], "cook-table2: the helix row is not paired with bluntfin")
# The bluntfin stand-in's records are missing: the gap row stays f117's, bluntfin is not measured.
doc = expect(xmpvo, "cook-table2", XM, table2([F117]), ON_F117, "holds", "f117 only")
check("for f117" in H.claim(doc, ON_F117)["claim"],
      f"cook-table2, f117 only: the gap row is paired with {H.claim(doc, ON_F117)['claim']}")
check("0.73 / 2.9" in H.claim(doc, ON_F117)["paper"],
      f"cook-table2, f117 only: the gap row shows another data set's paper numbers: {H.claim(doc, ON_F117)['paper']}")
expect(xmpvo, "cook-table2", XM, table2([F117]), FOR_BLUNTFIN, "not measured", "f117 only",
       "no records of a stand-in for bluntfin")
row = cells(doc, "Ours: seconds per view", "bluntfin: not measured")
check(row.get("BSP-XMPVO") == "not measured", f"cook-table2, f117 only: bluntfin's row is {row}")
check("f117" in doc.intro and "for bluntfin" not in doc.intro, f"cook-table2, f117 only: stand-ins {doc.intro!r}")
# Records written in the other order pair the same way.
doc = expect(xmpvo, "cook-table2", XM, table2([F117, BLUNTFIN]), ON_HELIX, "holds", "f117 first")
check("for bluntfin" in H.claim(doc, ON_HELIX)["claim"] and "0.60 / 2.5" in H.claim(doc, ON_HELIX)["paper"],
      f"cook-table2, f117 first: {H.claim(doc, ON_HELIX)}")

C.done("rows paired by data set")
