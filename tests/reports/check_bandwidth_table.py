#!/usr/bin/python3
"""The generic report's bandwidth table computed from fixed records (bandwidth.jsonl, known
numbers): frame / stream = median frame time / (orderer + scene + derived bytes / the run's
triad rate at the record's thread count); a run without machine_limits, or a thread count
its run did not measure, says "not measured".

usage: check_bandwidth_table.py REPORTS_DIR RECORDS WORKDIR
"""
import json
import math
import os
import shutil
import subprocess
import sys

REPORTS, RECORDS, WORK = sys.argv[1:4]
sys.path.insert(0, REPORTS)
from generic import limits  # noqa: E402
from generic.load import load  # noqa: E402
from generic.rows import summarise  # noqa: E402


def fail(why):
    sys.exit(f"check_bandwidth_table: {why}")


def close(a, b):
    return a is not None and math.isclose(a, b, rel_tol=1e-9)


recs, _ = load([RECORDS])
rows = {(r["algorithm"], r["threads"]): r for r in summarise(recs)}
want = {  # (orderer, threads): (stream seconds, frame / stream) or None: not measured
    ("mpvo", 1): (4e6 / 1.0e10, 0.0042 / (4e6 / 1.0e10)),  # median of 4 and 4.4 ms: 10.5
    ("mpvo", 2): (4e6 / 1.6e10, 0.003 / (4e6 / 1.6e10)),   # 12
    ("sxmpvo", 3): None,  # its run measured 1 and 2 threads only
    ("centroid", 2): None,  # its run has no machine_limits
}
if set(rows) != set(want):
    fail(f"rows {sorted(rows)}, expected {sorted(want)}")
for key, w in want.items():
    r = rows[key]
    if r["working_set"] != 4000000:
        fail(f"{key}: working set {r['working_set']}, expected 4000000 (orderer + scene + derived)")
    if w is None:
        if r["stream_s"] is not None or r["frame_over_stream"] is not None or r["triad_bps"] is not None:
            fail(f"{key}: expected not measured, got {r['stream_s']}, {r['frame_over_stream']}")
    elif not (close(r["stream_s"], w[0]) and close(r["frame_over_stream"], w[1])):
        fail(f"{key}: stream {r['stream_s']}, ratio {r['frame_over_stream']}; expected {w}")
if rows[("mpvo", 1)]["fits_llc"] is not True or rows[("centroid", 2)]["fits_llc"] is not None:
    fail("4 MB against runA's 32 MiB last-level cache must be marked as fitting; runB knows no cache")
if not close(rows[("mpvo", 1)]["frame_over_stream"], 10.5) or not close(rows[("mpvo", 2)]["frame_over_stream"], 12):
    fail("the ratios of the fixed records are not 10.5 and 12")
# The checker itself must notice a wrong rate: the same records at another bandwidth.
bumped = [dict(r, context=dict(r["context"], machine_limits={"triad": [{"threads": 1, "bytes_per_second": 2e10}]}))
          for r in recs if r["algorithm"] == "mpvo" and r["threads"] == 1]
if not close(limits.stream_seconds(bumped[0]), 2e-4):
    fail("stream_seconds does not follow the context's triad rate")

# The whole report: the table in report.md and the numbers in summary.json.
shutil.rmtree(WORK, ignore_errors=True)
p = subprocess.run(["/usr/bin/python3", os.path.join(REPORTS, "report.py"), RECORDS, "--out", WORK],
                   capture_output=True, text=True)
if p.returncode != 0:
    fail(f"report.py exited {p.returncode}: {p.stderr[-2000:]}")
md = open(os.path.join(WORK, "report.md")).read()
if "## Against the machine's limits" not in md:
    fail("report.md has no bandwidth section")
table = [ln for ln in md.splitlines() if ln.startswith("| mpvo |") or ln.startswith("| sxmpvo |")
         or ln.startswith("| centroid |")]
expect_cells = {"mpvo": [("1", "10.5"), ("2", "12")], "sxmpvo": [("3", "not measured")],
                "centroid": [("2", "not measured")]}
for algo, cells in expect_cells.items():
    for threads, ratio in cells:
        hits = [ln for ln in table if ln.startswith(f"| {algo} |") and f"| {threads} |" in ln
                and ln.rstrip(" |").endswith(ratio)]
        if not hits:
            fail(f"report.md: no bandwidth row for {algo} at {threads} threads ending in {ratio}:\n" + "\n".join(table))
if "| runB | – | not measured | not measured |" not in md:
    fail("report.md: the run without machine_limits is not listed as not measured")
if "| runA | 1 | 10 GB/s | 50 M/s |" not in md or "| runA | 2 | 16 GB/s | 80 M/s |" not in md:
    fail("report.md: the measured limits of runA are not listed")
if "Largest: 12 (mpvo on gap(nx=3) @ 64x64, 2 threads)" not in md:
    fail("report.md: the largest ratio is not named")
summary = json.load(open(os.path.join(WORK, "summary.json")))
got = {(r["algorithm"], r["threads"]): r["frame_over_stream"] for r in summary}
if not close(got[("mpvo", 1)], 10.5) or got[("centroid", 2)] is not None:
    fail(f"summary.json: {got}")
print("check_bandwidth_table: ratios 10.5 and 12 computed, 2 rows not measured")
