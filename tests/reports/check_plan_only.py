#!/usr/bin/python3
"""A run stopped before its first record (docs/pipeline.md "Incomplete data"): results.jsonl
holds plan lines and no record. `vobench report DIR` still writes each paper reproduction's page:
every planned job listed without a record, every claim "not measured", the Conditions saying
"Incomplete: 0 of N planned jobs have a record"; it exits as it does for a partly complete run.
A file with neither a record nor a plan line is still refused.

usage: check_plan_only.py REPORTS_DIR VOBENCH WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402
import planned as PL  # noqa: E402

REPORTS, VOBENCH, WORK = sys.argv[1:4]
shutil.rmtree(WORK, ignore_errors=True)
C = H.Checks("check_plan_only", WORK)

# cook-table3 (two suites) and xmpvo-scaling, as `vobench reproduce all --tiny` plans them.
recs = [H.orderer_record("cook-table3", suite, "sxmpvo", name, spec, v, 0.01)
        for suite, name, spec in (("table3", "helix", {"cells": 2000, "faces": 430}), ("table3", "zoo", {"scale": 1}),
                                  ("table3-207k", "helix", {"cells": 12000, "faces": 1000}))
        for v in (0, 4, 9)]
recs += [H.orderer_record("xmpvo-scaling", "gaps", o, "gap", {"gaps": g, "nx": 4, "ny": 4, "nz": 20}, 0, 0.01,
                          paper="xmpvo") for g in (0, 5) for o in ("bsp-xmpvo", "xmpvo", "sxmpvo")]
plans = PL.plan_lines(recs)
PLANNED = {"cook-table3": 9, "xmpvo-scaling": 6}


def report(where, lines):
    d = os.path.join(WORK, where)
    os.makedirs(d)
    with open(os.path.join(d, "results.jsonl"), "w") as f:
        for line in lines:
            f.write(json.dumps(line) + "\n")
    p = subprocess.run([VOBENCH, "report", d], capture_output=True, text=True,
                       env=dict(os.environ, VOBENCH_MACHINE_LIMITS="skip"))
    return d, p


d, p = report("plan-only", plans)
partial_dir, partial = report("partial", plans + recs[1:])
C.check(p.returncode == partial.returncode == 0,
        f"exit status: plan lines alone {p.returncode}, a partly complete run {partial.returncode} (expected 0 and 0): "
        f"{p.stderr[-1500:]}")
for name, n in PLANNED.items():
    path = os.path.join(d, name + ".json")
    if not os.path.exists(path):
        C.check(False, f"{name}: no page from plan lines alone ({sorted(os.listdir(d))}): {p.stderr[-1500:]}")
        continue
    with open(path) as f:
        page = json.load(f)
    C.check(f"Incomplete: 0 of {n} planned jobs have a record" in page["conditions"],
            f"{name}: the conditions do not say 'Incomplete: 0 of {n} planned jobs have a record': {page['conditions']}")
    listed = [r for t in page["tables"] for r in t["rows"] if r.get("record") == "not measured"]
    C.check(sum(r["jobs"] for r in listed) == n, f"{name}: {sum(r['jobs'] for r in listed)} of {n} planned jobs "
            f"listed as missing: {page['tables']}")
    C.check(page["claims"] and all(c["holds"] is None for c in page["claims"]),
            f"{name}: claims not all 'not measured': {page['claims']}")
    for ext in ("md", "html"):
        C.check(os.path.exists(os.path.join(d, f"{name}.{ext}")), f"{name}: no {name}.{ext}")
# The cook-table3 view-0 helix record alone is missing from the partial run: its page is the usual one.
with open(os.path.join(partial_dir, "cook-table3.json")) as f:
    page = json.load(f)
C.check("Incomplete: 1 of 9 planned jobs have no record" in page["conditions"],
        f"partial: conditions {page['conditions']}")
C.check(os.path.exists(os.path.join(d, "claims-summary.json")), "plan lines of two reproductions: no claims summary")

# Neither a record nor a plan line: still "holds no records", exit 2.
_, p = report("context-only", [{"key": "context|r1", "type": "context", "run_id": "r1", "context": {}}])
C.check(p.returncode == 2 and "holds no records" in p.stderr, f"context line alone: exit {p.returncode}: {p.stderr}")

C.done("plan lines without a record give every planned page, every job missing, every claim not measured")
