#!/usr/bin/python3
"""Every line `vobench run` writes fits docs/record.schema.json (orderer, probe, context and
plan lines, with and without the oracle), each run's plan line lists the jobs it measured,
and the schema refuses lines that break it.

usage: check_records.py VOBENCH SCHEMA WORKDIR
"""
import copy
import json
import os
import shutil
import subprocess
import sys

import jsonschema

VOBENCH, SCHEMA, WORK = sys.argv[1:4]


def fail(why):
    sys.exit(f"check_records: {why}")


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
results = os.path.join(WORK, "results.jsonl")
for name, extra in (("on", {}), ("off", {"oracle": False, "repeats": 2})):
    suite = {"name": "schema", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}}],
             "algorithms": ["mpvo", "centroid"], "views": 2, "sizes": ["32x32"], "repeats": 3, "warmup": 1,
             "probes": [{"name": "sxmpvo-tiny-cells", "set": {"side": 32}}], **extra}
    path = os.path.join(WORK, f"suite-{name}.json")
    with open(path, "w") as f:
        json.dump(suite, f)
    p = subprocess.run([VOBENCH, "run", path, "-o", results], capture_output=True, text=True)
    if p.returncode != 0:
        fail(f"vobench run {path} exited {p.returncode}: {p.stderr[-2000:]}")

with open(SCHEMA) as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)
v = jsonschema.Draft202012Validator(schema)
lines = [json.loads(ln) for ln in open(results) if ln.strip()]
kinds = {"context": 0, "plan": 0, "probe": 0, "orderer": 0}
runs = set()
plans = []
for n, rec in enumerate(lines, 1):
    errs = sorted(v.iter_errors(rec), key=str)
    if errs:
        fail(f"{results}: line {n} breaks the schema: {errs[0].message}")
    kind = rec["type"] if rec.get("type") in ("context", "plan") else "probe" if "probe" in rec else "orderer"
    kinds[kind] += 1
    if kind == "context":
        runs.add(rec["run_id"])
    elif kind == "plan":  # before its run's jobs (and its context line, written with the first record)
        plans.append(rec)
    elif rec["run_id"] not in runs:
        fail(f"line {n}: run_id {rec['run_id']!r} has no context line before it")
if kinds["context"] != 2 or kinds["plan"] != 2 or kinds["probe"] != 2 or kinds["orderer"] != 8:
    fail(f"expected 2 context lines, 2 plan lines, 2 probe and 8 orderer records, got {kinds}")
# Each run's plan line lists every job the run measured, before the first of them.
for plan in plans:
    keys = [j["key"] for j in plan["jobs"]]
    mine = [r["key"] for r in lines if r.get("run_id") == plan["run_id"] and r.get("type") is None]
    if sorted(keys) != sorted(mine):
        fail(f"plan of run {plan['run_id']} lists {sorted(keys)}, the run wrote {sorted(mine)}")
    first = min(n for n, r in enumerate(lines) if r.get("run_id") == plan["run_id"])
    if lines[first] is not plan:
        fail(f"the plan line of run {plan['run_id']} is not the run's first line")

# Lines that break the schema must be refused.
orderer = next(r for r in lines if "algorithm" in r)
context = next(r for r in lines if r.get("type") == "context")
plan = plans[0]
broken = []
for what, rec, change in (
        ("samples missing", orderer, lambda r: r["total"].pop("samples")),
        ("phase without median", orderer, lambda r: next(iter(r["phases"].values())).pop("median")),
        ("schema_version 1", orderer, lambda r: r.update(schema_version=1)),
        ("context in a record", orderer, lambda r: r.update(context={"cpu": "x"})),
        ("no run_id", orderer, lambda r: r.pop("run_id")),
        ("context without libraries", context, lambda r: r["context"].pop("libraries")),
        ("triad bandwidth 0", context, lambda r: r["context"]["machine_limits"]["triad"][0].update(bytes_per_second=0)),
        ("plan without jobs", plan, lambda r: r.pop("jobs")),
        ("plan job without key", plan, lambda r: r["jobs"][0].pop("key")),
        ("plan job with neither algorithm nor probe", plan,
         lambda r: [j.pop(k, None) for j in r["jobs"] for k in ("algorithm", "probe")])):
    bad = copy.deepcopy(rec)
    change(bad)
    if v.is_valid(bad):
        broken.append(what)
if broken:
    fail(f"the schema accepts broken lines: {broken}")
print(f"check_records: {len(lines)} lines valid ({kinds}); 10 broken lines refused")
