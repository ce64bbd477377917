#!/usr/bin/python3
"""Planned jobs without a record (docs/pipeline.md "Incomplete data"), from hand-made records
and plan lines: a data set of cook-table3's plan with no record makes both of its claims over
every data set "not measured" (never judged on the data set left), its row still appears and
says "not measured", and the Conditions say which jobs are missing; the complete records with
the same plan still give verdicts (so the check cannot pass vacuously), a per-mesh claim on a
complete mesh keeps its verdict, and build_tables.py does the same from a results file.

usage: check_plan_missing.py REPORTS_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
H.use_reports(REPORTS)
import cook  # noqa: E402
from vobtables.doc import Doc  # noqa: E402

shutil.rmtree(WORK, ignore_errors=True)
C = H.Checks("check_plan_missing", WORK)
check = C.check
COOK = H.paper_numbers(REPORTS, "cook")
HEAD = "insertions into the PIX lists occur at the head"
ORACLE3 = "SXMPVO's order passes the oracle on every view"


def table3():
    out = []
    for name, spec, n in (("helix", {"cells": 2000, "faces": 430}, 2000), ("zoo", {"scale": 1}, 3000)):
        for v in (0, 4, 9):
            r = H.orderer_record("cook-table3", "table3", "sxmpvo", name, spec, v, 0.01, n=n, size="120x100",
                                 phases={p: 0.0025 for p in cook.PHASES})
            r["counters"] = {"head_insertion_rate": 0.995, "abuffer_entries": 100}
            r["oracle"] = {"violating_pixels": 0}
            out.append(r)
    return out


def plan_of(recs, run_id="plan-run"):
    """The plan line `vobench reproduce` writes before these records' jobs."""
    jobs = [{"key": r["key"], "dataset": r["dataset"], "dataset_spec": r["dataset_spec"], "row": r["row"],
             "algorithm": r["algorithm"], "w": r["w"], "h": r["h"], "view_index": r["view_index"],
             "threads": r["threads"]} for r in recs]
    return {"key": f"plan|{run_id}|cook-table3/table3", "type": "plan", "run_id": run_id, "schema_version": 2,
            "suite": "cook-table3/table3", "reproduction": "cook-table3", "scale": "tiny", "jobs": jobs}


def build(recs, plans, where):
    doc = Doc("cook-table3", "cook-table3", out_dir=os.path.join(WORK, where))
    doc.row_of = cook.ROW_OF
    doc.set_plan(recs, plans, "cook-table3")
    cook.TABLES["cook-table3"](recs, COOK, doc)
    doc.write()
    return doc


complete = table3()
plan = plan_of(complete)
# The complete records with their plan: verdicts, no "incomplete" condition.
doc = build(complete, [plan], "complete")
for words in (HEAD, ORACLE3):
    c = H.claim(doc, words)
    check(H.verdict(c) == "holds", f"complete: '{words}' is {H.verdict(c)} ({c['criterion']})")
check("Incomplete" not in doc.conditions, f"complete: the conditions call it incomplete: {doc.conditions}")

# The zoo planned but never reached (a run stopped in the helix): both claims are not measured.
partial = [r for r in complete if r["dataset"] != "zoo"]
doc = build(partial, [plan], "partial")
for words in (HEAD, ORACLE3):
    c = H.claim(doc, words)
    check(H.verdict(c) == "not measured", f"zoo missing: '{words}' is {H.verdict(c)} ({c['criterion']})")
    check("planned job" in c["criterion"] and "zoo" in c["criterion"],
          f"zoo missing: the criterion of '{words}' does not name the missing jobs: {c['criterion']}")
    check(c["ours"] is None, f"zoo missing: '{words}' still shows ours = {c['ours']}")
ours = H.table(doc, "Ours: seconds per frame")
zoo = H.row_cells(ours, "zoo")
check(len(zoo) == 1 and "not measured" in zoo[0].values(),
      f"zoo missing: no 'not measured' zoo row in '{ours.title}': {ours.rows}")
check(len(H.row_cells(ours, "helix 0.002M")) == 1, f"zoo missing: the helix row is gone: {ours.rows}")
check("Incomplete: 3 of 6 planned jobs have no record" in doc.conditions and "zoo" in doc.conditions,
      f"zoo missing: the conditions do not say which jobs are missing: {doc.conditions}")
md = open(os.path.join(WORK, "partial", "cook-table3.md")).read()
check("| zoo | not measured |" in md, "zoo missing: the Markdown has no 'not measured' zoo row")

# A claim about one mesh keeps its verdict when that mesh is complete, and loses it otherwise.
doc = Doc("x", "x", out_dir=os.path.join(WORK, "scoped"))
doc.row_of = cook.ROW_OF
doc.set_plan(partial, [plan], "cook-table3")
doc.claim("about the helix", 1, 1, "ours == 1", True, scope={"row": "helix 0.002M"})
doc.claim("about the zoo", 1, 1, "ours == 1", True, scope={"row": "zoo"})
doc.claim("about every mesh", 1, 1, "ours == 1", True)
doc.claim("about a probe", 1, 1, "ours == 1", True, scope={"probe": "havs-sorts"})
doc.claim("about another suite", 1, 1, "ours == 1", True, scope={"suite": "table3-207k"})
doc.claim("about this suite", 1, 1, "ours == 1", True, scope={"suite": "table3"})
doc.claim("about sxmpvo", 1, 1, "ours == 1", True, scope={"orderer": "sxmpvo"})
got = [H.verdict(c) for c in doc.claims]
want = ["holds", "not measured", "not measured", "holds", "holds", "not measured", "not measured"]
check(got == want, f"scoped claims: {got}, expected {want}")

# The latest plan of a suite counts: an older plan with a job since dropped is ignored.
old = plan_of(complete + [dict(complete[0], key=complete[0]["key"] + "|gone")], run_id="old-run")
doc = build(complete, [old, plan], "latest")
check(all(H.verdict(c) == "holds" for c in doc.claims if HEAD in c["claim"] or ORACLE3 in c["claim"]),
      f"latest plan: claims not judged: {[(c['claim'], H.verdict(c)) for c in doc.claims]}")

# From a results file, as `vobench report DIR` builds it: plan lines are not records.
for where, recs in (("file-complete", complete), ("file-partial", partial)):
    d = os.path.join(WORK, where)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "results.jsonl"), "w") as f:
        for line in [plan] + recs:
            f.write(json.dumps(line) + "\n")
    p = subprocess.run(["/usr/bin/python3", os.path.join(REPORTS, "build_tables.py"), d], capture_output=True, text=True)
    check(p.returncode == 0, f"{where}: build_tables.py exited {p.returncode}: {p.stderr[-2000:]}")
    if p.returncode:
        continue
    with open(os.path.join(d, "cook-table3.json")) as f:
        page = json.load(f)
    want = "holds" if where == "file-complete" else "not measured"
    for c in page["claims"]:
        if HEAD in c["claim"] or ORACLE3 in c["claim"]:
            check(H.verdict(c) == want, f"{where}: '{c['claim']}' is {H.verdict(c)}, expected {want}")
    if where == "file-partial":
        rows = next(t for t in page["tables"] if t["title"].startswith("Ours: seconds per frame"))["rows"]
        check(any(r.get("data set") == "zoo" for r in rows), f"{where}: no zoo row: {rows}")

C.done("a planned data set without records makes cook-table3's claims not measured and keeps its row")
