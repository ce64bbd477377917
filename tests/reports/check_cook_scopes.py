#!/usr/bin/python3
"""Each claim of the cook-* pages is scoped to the records it reads (docs/pipeline.md
"Incomplete data"): from a results file with plan lines and hand-made records, one job's records
are taken out; the claims fed by that job read "not measured", the claims that do not read it
keep the verdict they have with every record (without the scope they would be not measured too).

usage: check_cook_scopes.py REPORTS_DIR WORK_DIR
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402
import planned as PL  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
H.use_reports(REPORTS)
from papers.cook_common import PHASES  # noqa: E402

shutil.rmtree(WORK, ignore_errors=True)
C = H.Checks("check_cook_scopes", WORK)


def rec(repro, suite, orderer, name, spec, view, seconds, **kw):
    return H.orderer_record(repro, suite, orderer, name, spec, view, seconds, **kw)


def drop(**match):
    """A record picker: the records whose fields equal `match` (dataset_spec.set entries by name)."""
    def pick(r):
        for k, v in match.items():
            got = r["dataset_spec"]["set"].get(k) if k in ("cells", "gaps") else r.get(k)
            if got != v:
                return False
        return True
    return pick


def case(name, recs, picked, gone, kept, why):
    PL.check_drop(C, REPORTS, os.path.join(WORK, f"{name}-{why.replace(' ', '-')}"), name, recs, picked, gone, kept,
                  why)


# --- cook-table1: the paper's helix450k and helix1.0 (their n and b), three views ---------------
t1 = []
for suite, cells, faces in (("table1", 450000, 29000), ("table1-210k", 1003520, 41472)):
    for v in (0, 1, 2):
        r = rec("cook-table1", suite, "centroid", "helix", {"cells": cells, "faces": faces}, v, 0.01, n=cells, b=faces)
        r["a"] = 1000
        t1.append(r)
case("cook-table1", t1, drop(cells=1003520, view_index=1),
     gone=["our helix for helix1.0", "typically b is below n/log2 n"], kept=["our helix for helix450k"],
     why="helix1.0 view 1 missing")

# --- cook-table4: four helices (one with Table 4's n = 187,395, so its per-mesh claims are judged)
# and a gap mesh; SXMPVO 1.25 times MPVONC, times linear in n --------------------------------------
t4 = []
for name, spec, n in (("helix", {"cells": 2000}, 2000), ("helix", {"cells": 3000}, 3000),
                      ("helix", {"cells": 4000}, 4000), ("helix", {"cells": 187395}, 187395),
                      ("gap", {"gaps": 1, "nx": 3, "ny": 3, "nz": 10}, 400)):
    for v in (0, 1, 2):
        for o, per_cell in (("sxmpvo", 1.0e-5), ("mpvonc", 0.8e-5), ("vtk-centroid", 2e-5)):
            t4.append(rec("cook-table4", "table4", o, name, spec, v, per_cell * n, n=n))
SX_LINE, NC_LINE = "SXMPVO time grows approximately linearly", "MPVONC time grows approximately linearly"
ALWAYS = "SXMPVO is always slower than MPVONC"
case("cook-table4", t4, drop(orderer="mpvonc", cells=3000, view_index=1),
     gone=[NC_LINE, ALWAYS], kept=[SX_LINE], why="mpvonc helix 3000 view 1 missing")
SAME, BAND = "same speed as MPVONC for more than 100,000 cells: SXMPVO/MPVONC on helix 0.187M", \
    "large-mesh band on helix 0.187M"
case("cook-table4", t4, drop(orderer="vtk-centroid", cells=3000, view_index=1),
     gone=[], kept=[SX_LINE, NC_LINE, ALWAYS, SAME, BAND], why="vtk-centroid helix 3000 view 1 missing")
case("cook-table4", t4, drop(orderer="vtk-centroid", cells=187395, view_index=1),
     gone=[], kept=[SAME, BAND], why="vtk-centroid helix 0.187M view 1 missing")
case("cook-table4", t4, drop(orderer="mpvonc", cells=187395, view_index=1),
     gone=[SAME, BAND, NC_LINE], kept=[SX_LINE], why="mpvonc helix 0.187M view 1 missing")
# The gap mesh's label reads its n, which a planned job lacks: it takes its records' label, so a
# job of a measured mesh does not add a second, "not measured" row.
case("cook-table4", t4, drop(orderer="sxmpvo", gaps=1, view_index=1),
     gone=[ALWAYS], kept=[SX_LINE, NC_LINE], why="sxmpvo gap view 1 missing")
page = PL.page(REPORTS, os.path.join(WORK, "cook-table4-gap-row"), "cook-table4",
               PL.plan_lines(t4) + [r for r in t4 if not drop(orderer="sxmpvo", gaps=1, view_index=1)(r)])[2]
ours = next(t for t in page["tables"] if t["title"].startswith("Ours")) if page else {"rows": []}
C.check(page is not None and not any("not measured" in r.values() for r in ours["rows"]),
        f"cook-table4: one gap job missing adds a 'not measured' row: {ours['rows']}")

# --- cook-table2-5: two sizes with the oracle (suite checked), 2M without; windows fitted ------
t25 = []
for cells in (2000, 3000):
    for suite, side, oracle in (("checked", 412, True), ("checked", 592, True), ("2M", 1414, False)):
        for v in (0, 1, 2):
            px = side * side
            r = rec("cook-table2-5", suite, "sxmpvo", "helix", {"cells": cells}, v, 0.01 + 1e-8 * px, n=cells,
                    size=f"{side}x{side}", w=side - 12, h=side + 8,
                    phases={PHASES[0]: 0.004, PHASES[1]: 0.002, PHASES[2]: 0.001 + 1e-8 * px, PHASES[3]: 0.003})
            if oracle:
                r["oracle"] = {"violating_pixels": 0}
            t25.append(r)
GROWS, PHASE3 = "SXMPVO time grows with image size", "due almost entirely to Phase III"
ORACLE25 = "SXMPVO's order passes the oracle at every checked size"
case("cook-table2-5", t25, lambda r: "592x592" in r["key"] and r["view_index"] == 1 and r["n"] == 2000,
     gone=[GROWS, ORACLE25], kept=[PHASE3], why="592x592 view 1 missing")
case("cook-table2-5", t25, lambda r: "1414x1414" in r["key"] and r["view_index"] == 1 and r["n"] == 2000,
     gone=[GROWS, PHASE3], kept=[ORACLE25], why="2M view 1 missing")

# --- cook-table6: tiny cells of a helix and a gap mesh at two image sizes (one probe job each) -----
t6 = []
for name, spec, counts in (("helix", {"cells": 2000}, (0, 0)), ("gap", {"gaps": 1, "nx": 3, "ny": 3, "nz": 10}, (9, 4))):
    for side, tiny in zip((412, 592), counts):
        r = rec("cook-table6", "table6", "sxmpvo", name, spec, 0, 0.0, n=2000, extra_key=f"side{side}")
        for k in ("algorithm", "orderer", "w", "h", "view_index", "total", "phases"):
            r.pop(k, None)
        r.update(probe="sxmpvo-tiny-cells", result={"side": side, "tiny_cells": tiny, "view_index": 0, "fit": True})
        t6.append(r)
NO_TINY, FEWER = "the helix has no tiny cells", "fewer tiny cells at larger images"
case("cook-table6", t6, lambda r: r["dataset"] == "gap" and r["result"]["side"] == 592,
     gone=[FEWER], kept=[NO_TINY], why="gap at 592 missing")

# --- cook-fig8: SXMPVO and MPVONC at S = 1 (suite orders), SXMPVO at S = 4 ----------------------
f8 = []
for suite, orderer, ss, vp in (("orders", "sxmpvo", 1, 0), ("orders", "mpvonc", 1, None), ("supersampled", "sxmpvo", 4, 3)):
    for v in (0, 1, 2):
        r = rec("cook-fig8", suite, orderer, "helix", {"cells": 4000, "faces": 1000}, v, 0.01, n=4000)
        r["oracle"] = {"violating_pixels": (90 - 20 * v) if vp is None else vp, "supersample": ss}
        r["image_error"] = {"pixels_off": 500 if orderer == "mpvonc" else 0}
        f8.append(r)
MISORDERS, VISIBLE = "MPVONC misorders the helix", "MPVONC's errors are visible"
SX_RIGHT = "SXMPVO orders the helix correctly"
case("cook-fig8", f8, lambda r: r["suite"].endswith("orders") and r["orderer"] == "mpvonc" and r["view_index"] == 2,
     gone=[MISORDERS, VISIBLE], kept=[SX_RIGHT], why="mpvonc view 2 missing")
case("cook-fig8", f8, lambda r: r["suite"].endswith("supersampled") and r["view_index"] == 2,
     gone=[], kept=[MISORDERS, VISIBLE, SX_RIGHT], why="S4 view 2 missing")

# --- cook-fig11: four gap meshes, SXMPVO time linear in a; MPVONC beside it -----------------------
f11 = []
for g in (0, 1, 2, 3):
    for o in ("sxmpvo", "mpvonc"):
        r = rec("cook-fig11", "fig11", o, "gap", {"gaps": g, "nx": 4, "ny": 4, "nz": 20}, 0, 0.01 + 0.001 * g, n=1920)
        r["counters"] = {"abuffer_entries": 1000 + 100 * g, "head_insertion_rate": 1.0, "pn_relations": 10}
        f11.append(r)
LINEAR_A = "linear function of the projected exterior-face area"
case("cook-fig11", f11, drop(orderer="mpvonc", gaps=2), gone=[], kept=[LINEAR_A], why="mpvonc 2 gaps missing")
case("cook-fig11", f11, drop(orderer="sxmpvo", gaps=2), gone=[LINEAR_A], kept=[], why="sxmpvo 2 gaps missing")

C.done("one job's records missing leave exactly the cook claims that read it not measured")
