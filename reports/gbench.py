#!/usr/bin/python3
"""Google Benchmark's JSON from a vobench results file (`vobench run --format gbench`).

usage: gbench.py RESULTS.jsonl -o OUT.json

Every orderer record becomes one benchmark family named by its key without the settings
parts (so two runs' names match, as Google Benchmark's tools/compare.py expects): one
"iteration" row per timed repeat (real_time = the repeat's total seconds, in ms; vobench
measures wall time only, so cpu_time repeats it) and an "aggregate" median row. The
context is the last run's context line, in Google Benchmark's field names.
"""
import argparse
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare import identity  # noqa: E402
import signal  # noqa: E402

# Ctrl-C during `vobench reproduce` stops the script as it stops vobench, without a traceback.
signal.signal(signal.SIGINT, signal.SIG_DFL)


def size_bytes(text):
    """'512K', '512 KB', '32768' -> bytes."""
    m = re.match(r"^\s*(\d+)\s*([KMG]?)", str(text))
    if not m:
        return 0
    return int(m.group(1)) * {"": 1, "K": 1024, "M": 1024 ** 2, "G": 1024 ** 3}[m.group(2)]


def gbench_context(ctx, path):
    caches = []
    for c in ctx.get("caches") or []:
        level = c.get("level")
        caches.append({"type": {"Data": "Data", "Instruction": "Instruction", "Unified": "Unified"}.get(
            c.get("type"), "Unified"), "level": int(level) if str(level).isdigit() else 0,
            "size": size_bytes(c.get("size")), "num_sharing": 0})
    return {"date": ctx.get("date", ""), "host_name": ctx.get("host_name", ""), "executable": "vobench run",
            "num_cpus": ctx.get("num_cpus", 0), "mhz_per_cpu": int(ctx.get("mhz") or 0),
            "cpu_scaling_enabled": False, "caches": caches, "load_avg": ctx.get("load_avg") or [],
            "library_build_type": str(ctx.get("build_type", "")).lower(),
            "vobench": {"results": os.path.abspath(path), "git_sha": ctx.get("git_sha"),
                        "threads": ctx.get("threads"), "libraries": ctx.get("libraries")}}


def benchmarks(recs):
    out = []
    for fam, r in enumerate(recs):
        name = identity(r["key"])
        t = r.get("total") or {}
        samples = t.get("samples") or [t.get("median", 0.0)]
        common = {"family_index": fam, "per_family_instance_index": 0, "run_name": name,
                  "repetitions": len(samples), "threads": r.get("threads", 1), "time_unit": "ms"}
        for i, s in enumerate(samples):
            out.append({"name": name, **common, "run_type": "iteration", "repetition_index": i,
                        "iterations": 1, "real_time": s * 1e3, "cpu_time": s * 1e3})
        med = t.get("median", 0.0) * 1e3
        out.append({"name": name + "_median", **common, "run_type": "aggregate", "aggregate_name": "median",
                    "aggregate_unit": "time", "iterations": len(samples), "real_time": med, "cpu_time": med})
    return out


def main():
    ap = argparse.ArgumentParser(prog="gbench.py")
    ap.add_argument("results")
    ap.add_argument("-o", "--output", required=True)
    a = ap.parse_args()
    recs, ctx = [], {}
    with open(a.results) as f:
        for n, line in enumerate(f, 1):
            if not line.strip():
                continue
            try:
                r = json.loads(line)
            except json.JSONDecodeError as e:
                print(f"gbench: {a.results}: line {n}: not JSON ({e.msg})", file=sys.stderr)
                return 2
            if r.get("type") == "context":
                ctx = r.get("context") or {}
            elif r.get("type") != "plan" and "probe" not in r and isinstance(r.get("total"), dict):
                recs.append(r)
    doc = {"context": gbench_context(ctx, a.results), "benchmarks": benchmarks(recs)}
    tmp = a.output + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    os.replace(tmp, a.output)
    print(f"gbench: {len(recs)} records -> {a.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
