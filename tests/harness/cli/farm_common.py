"""Shared by check_shards.py and ../mpi/check_farm.py: the tiny suite they spread, and the
comparisons of results files (keys once, the oracle's verdict record by record)."""
import json
import os
import subprocess
import sys

# Two cell datasets, two orderers (one exact, one heuristic that violates), two views, a
# probe without a scene: 10 jobs in 5 groups, seconds in all.
SUITE = {"name": "farm", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4}},
                                      {"name": "helix", "set": {"cells": 600}}],
         "algorithms": ["xmpvo", "centroid"], "views": 2, "sizes": ["32x32"], "repeats": 1, "warmup": 0,
         "probes": [{"name": "sxmpvo-tiny-cells", "set": {"side": 32}}]}
VERDICT = ("covered_pixels", "violating_pixels", "violating_fragments")


def fail(who, why):
    sys.exit(f"{who}: {why}")


def write_suite(work, name, extra_datasets=()):
    suite = dict(SUITE, datasets=SUITE["datasets"] + list(extra_datasets))
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(suite, f)
    return path


def run(cmd, who, codes=(0,)):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in codes:
        fail(who, f"{' '.join(cmd)} exited {p.returncode} (want {codes}):\n{p.stdout[-1500:]}\n{p.stderr[-3000:]}")
    return p


def records(path):
    lines = [json.loads(ln) for ln in open(path) if ln.strip()]
    return [r for r in lines if r.get("type") not in ("context", "plan")], lines


def by_key(who, path):
    """key -> record, failing on a key written twice or a record before its run's context line."""
    recs, lines = records(path)
    seen, runs = {}, set()
    for r in lines:
        if r.get("type") == "context":
            runs.add(r["run_id"])
            continue
        if r.get("type") == "plan":  # a suite's plan, before any record
            continue
        if r["key"] in seen:
            fail(who, f"{path}: key {r['key']} twice")
        if r["run_id"] not in runs:
            fail(who, f"{path}: {r['key']}: no context line of run {r['run_id']} before it")
        seen[r["key"]] = r
    return seen


def verdict(r):
    o = r.get("oracle") or {}
    return tuple(o.get(k) for k in VERDICT) + (bool(r.get("input_fault")),)


def same_records(who, serial, other, what):
    """The same keys, each once, and the same oracle verdict record by record."""
    if set(serial) != set(other):
        fail(who, f"{what}: keys differ from the serial run: missing {sorted(set(serial) - set(other))[:5]}, "
                  f"extra {sorted(set(other) - set(serial))[:5]}")
    for k, r in serial.items():
        if verdict(r) != verdict(other[k]):
            fail(who, f"{what}: {k}: verdict {verdict(other[k])} against the serial run's {verdict(r)}")
    if not any(verdict(r)[1] for r in serial.values() if "oracle" in r):
        fail(who, "the suite has no record with violations: the verdict comparison would be vacuous")
