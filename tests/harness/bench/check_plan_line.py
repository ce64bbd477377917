#!/usr/bin/python3
"""`vobench run` writes its suite's plan line before its jobs (docs/pipeline.md "Records",
"Plan lines"): every job's key, data set, orderer or probe, size, view and threads; a resumed
run with jobs left writes a new one, a run with nothing left writes none. `vobench merge`
keeps each plan line once, `vobench compare` and `vobench report` accept files with them, and
the report of a file whose plan lists a data set without records says it is incomplete.

usage: check_plan_line.py VOBENCH WORKDIR
"""
import json
import os
import shutil
import subprocess
import sys

VOBENCH, WORK = sys.argv[1:3]


def fail(why):
    sys.exit(f"check_plan_line: {why}")


def run(*args, ok=(0,)):
    p = subprocess.run([VOBENCH, *args], capture_output=True, text=True)
    if p.returncode not in ok:
        fail(f"vobench {' '.join(args)} exited {p.returncode}: {p.stderr[-2000:]}")
    return p


def lines(path):
    return [json.loads(ln) for ln in open(path) if ln.strip()]


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
suite = {"name": "plan", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}},
                                      {"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 5}}],
         "algorithms": ["mpvo", "centroid"], "views": 2, "sizes": ["32x32"], "repeats": 1, "warmup": 0}
suite_path = os.path.join(WORK, "suite.json")
with open(suite_path, "w") as f:
    json.dump(suite, f)
a_dir = os.path.join(WORK, "a")
a = os.path.join(a_dir, "results.jsonl")
run("run", suite_path, "-o", a)
got = lines(a)
plans = [r for r in got if r.get("type") == "plan"]
recs = [r for r in got if "type" not in r]
if len(plans) != 1 or got[0] is not plans[0]:
    fail(f"expected one plan line first, got types {[r.get('type') for r in got]}")
plan = plans[0]
for k in ("key", "run_id", "suite", "scale", "jobs"):
    if k not in plan:
        fail(f"plan line without {k!r}: {plan}")
jobs = {j["key"]: j for j in plan["jobs"]}
if sorted(jobs) != sorted(r["key"] for r in recs) or len(recs) != 8:
    fail(f"the plan's keys {sorted(jobs)} are not the run's {len(recs)} records' keys")
for r in recs:
    j = jobs[r["key"]]
    for k in ("dataset", "dataset_spec", "algorithm", "w", "h", "view_index", "threads"):
        if j.get(k) != r.get(k):
            fail(f"plan job {r['key']}: {k} {j.get(k)!r}, its record says {r.get(k)!r}")
    if r["run_id"] != plan["run_id"]:
        fail("the records' run_id is not the plan's")

# Nothing left to do: no new plan line. One data set's records lost: the next run plans again.
run("run", suite_path, "-o", a)
if sum(r.get("type") == "plan" for r in lines(a)) != 1:
    fail("a run with nothing left to do wrote a plan line")
lost = next(iter(jobs.values()))["dataset"]
b_dir = os.path.join(WORK, "b")
os.makedirs(b_dir)
b = os.path.join(b_dir, "results.jsonl")
with open(b, "w") as f:
    for r in lines(a):
        if r.get("dataset") != lost or r.get("type"):
            f.write(json.dumps(r) + "\n")
# The report of the file missing a data set says so (a planned data set with no record).
p = run("report", b_dir)
md = open(os.path.join(b_dir, "report.md")).read()
if "Incomplete: 4 of 8 planned jobs have no record" not in md or lost not in md:
    fail(f"the report does not say {lost}'s 4 planned jobs have no record:\n{md[:1500]}")
run("compare", a, b, ok=(0, 1))
c = os.path.join(WORK, "c.jsonl")
shutil.copy(b, c)
run("run", suite_path, "-o", c)
if sum(r.get("type") == "plan" for r in lines(c)) != 2:
    fail("a resumed run with jobs left did not write its plan line")

# merge: each plan line once, whichever files hold it; the merged file reports.
m_dir = os.path.join(WORK, "m")
os.makedirs(m_dir)
merged = os.path.join(m_dir, "results.jsonl")
run("merge", a, b, c, "-o", merged)
ml = lines(merged)
pk = [r["key"] for r in ml if r.get("type") == "plan"]
if len(pk) != 2 or len(set(pk)) != 2:
    fail(f"merge kept plan lines {pk}, expected the 2 distinct ones once each")
if sum("type" not in r for r in ml) != 8:
    fail("merge did not keep the 8 records")
run("report", m_dir)
if "Incomplete" in open(os.path.join(m_dir, "report.md")).read():
    fail("the merged, complete file's report calls it incomplete")
print("check_plan_line: plan lines written, resumed, merged once, compared and reported")
