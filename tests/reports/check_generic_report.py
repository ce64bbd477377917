#!/usr/bin/python3
"""The generic report (reports/report.py) from hand-made records: the "vs mpvonc" ratio
compares the views both orderers measured and says "incomplete: N of M views" when their view
sets differ (never a median over 5 views against one over 10); an orderer without records on a
scene reads "not measured" in the overview, not a blank; the frame / stream table has a host /
run column when the records come from more than one host or run, and none otherwise.

usage: check_generic_report.py REPORTS_DIR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
failures = []
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)


def check(cond, why):
    if not cond:
        failures.append(why)


def rec(orderer, dataset, spec, view, seconds, host="vm", run_id="run-a"):
    r = H.orderer_record("t", "s", orderer, dataset, spec, view, seconds, fit=False, host=host, run_id=run_id,
                         paper=None)
    for k in ("reproduction", "paper", "scale"):
        r.pop(k)
    r["key"] = r["key"].replace("|tiny", "")
    r["oracle"] = {"violating_pixels": 0, "covered_pixels": 100, "max_k": 1}
    r["context"] = {"git_sha": "abc1234", "date": "2026-01-01T00:00:00Z", "host_name": host}
    return r


def report(recs, name):
    path = os.path.join(WORK, name + ".jsonl")
    with open(path, "w") as f:
        f.writelines(json.dumps(r) + "\n" for r in recs)
    out = os.path.join(WORK, name)
    p = subprocess.run(["/usr/bin/python3", os.path.join(REPORTS, "report.py"), path, "--out", out],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"check_generic_report: report.py failed on {name}: {p.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        rows = json.load(f)
    with open(os.path.join(out, "report.md")) as f:
        return rows, f.read()


GAP, HELIX = ("gap", {"gaps": 1, "nx": 3, "ny": 3, "nz": 4}), ("helix", {"cells": 500})

# mpvo on views 0-4 at 1 ms, mpvonc on views 0-9: 2 ms on 0-4, 10 ms on 5-9 (median over its 10: 6 ms).
recs = [rec("mpvo", *GAP, v, 0.001) for v in range(5)]
recs += [rec("mpvonc", *GAP, v, 0.002 if v < 5 else 0.010) for v in range(10)]
recs += [rec("centroid", *GAP, v, 0.0005) for v in range(10)]
recs += [rec(o, *HELIX, v, 0.001) for o in ("mpvo", "mpvonc") for v in range(10)]  # no centroid on the helix
rows, md = report(recs, "views")
mpvo = [r for r in rows if r["algorithm"] == "mpvo" and r["dataset"] == "gap"][0]
check(abs((mpvo["vs_mpvonc"] or 0) - 0.5) < 1e-9, f"mpvo vs mpvonc over their 5 common views is 0.5, got "
      f"{mpvo['vs_mpvonc']} (over different view sets: 1 ms / 6 ms = 0.167)")
check(mpvo.get("vs_mpvonc_views") == [5, 10], f"mpvo vs mpvonc must say 5 of 10 views: {mpvo.get('vs_mpvonc_views')}")
check("(incomplete: 5 of 10 views)" in md, "the gap table does not say the ratio is over 5 of 10 views")
centroid = [r for r in rows if r["algorithm"] == "centroid"][0]
check(centroid.get("vs_mpvonc_views") is None, "centroid and mpvonc share all 10 views: no 'incomplete'")
overview = md[md.index("## Overview"):]
line = [x for x in overview.splitlines() if x.startswith("| centroid")][0]
check(line.rstrip(" |").endswith("not measured"), f"overview: centroid on the helix must read 'not measured': {line}")
limits = md[md.index("## Against the machine's limits"):md.index("## Overview")]
check("host / run" not in limits, "one host and run: no host / run column")

# The same records from two hosts (runs): the frame / stream rows say whose they are.
two = [rec("mpvonc", *GAP, v, 0.002, host=h, run_id=f"run-{h}") for h in ("vm", "otherbox") for v in range(3)]
rows, md = report(two, "hosts")
limits = md[md.index("## Against the machine's limits"):]
check("host / run" in limits, "records of two hosts: the frame / stream table needs a host / run column")
check("otherbox / run-otherbox" in limits and "vm / run-vm" in limits,
      "the host / run column must name each row's host and run")

if failures:
    sys.exit("check_generic_report:\n  " + "\n  ".join(failures))
print("check_generic_report: ratios over common views, 'not measured' cells, host / run column")
