#!/usr/bin/python3
"""`vobench run --shard I/N` and `vobench merge` on a tiny suite (issue 17):

1. the two shards of the suite split its job groups ((dataset, orderer or probe), never
   split), and merged they give exactly the keys of the serial run, each once, with the same
   oracle verdict record by record; records name host, rank and shard;
2. `report` and `compare` take the merged file;
3. merging a file with itself keeps every key once, no conflict (exit 0); a duplicate with
   other settings, another revision or another host is a conflict named on stderr (exit 1);
   one measured again on the same host is counted (exit 0);
4. `--dry-run --ranks R` prints the makespan and the largest indivisible group; with
   `--costs FILE` the total line is calibrated from FILE's records.

usage: check_shards.py VOBENCH WORKDIR
"""
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from farm_common import by_key, fail, run, same_records, write_suite  # noqa: E402

VOBENCH, WORK = sys.argv[1:3]
WHO = "check_shards"
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
suite = write_suite(WORK, "farm")
out = lambda name: os.path.join(WORK, name + ".jsonl")  # noqa: E731

run([VOBENCH, "run", suite, "-o", out("serial")], WHO)
serial = by_key(WHO, out("serial"))
shards = []
for i in (1, 2):
    p = run([VOBENCH, "run", suite, "-o", out(f"shard{i}"), "--shard", f"{i}/2"], WHO)
    if f"shard {i}/2:" not in p.stderr:
        fail(WHO, f"shard {i}/2 did not say which groups it runs:\n{p.stderr[-1000:]}")
    shards.append(by_key(WHO, out(f"shard{i}")))
    if any(r.get("shard") != f"{i}/2" or r.get("rank") != 0 or not r.get("host") or r.get("ranks_on_host") != 1
           for r in shards[-1].values()):
        fail(WHO, f"shard {i}/2: records do not name shard, rank, host and ranks_on_host")
if not shards[0] or not shards[1] or set(shards[0]) & set(shards[1]):
    fail(WHO, f"the shards are not a split: {len(shards[0])} and {len(shards[1])} records, "
              f"{len(set(shards[0]) & set(shards[1]))} keys in both")
group = lambda r: (r.get("dataset"), r.get("algorithm") or r.get("probe"))  # noqa: E731
if {group(r) for r in shards[0].values()} & {group(r) for r in shards[1].values()}:
    fail(WHO, "a (dataset, orderer) group was split between the shards")

run([VOBENCH, "merge", out("shard1"), out("shard2"), "-o", out("merged")], WHO)
same_records(WHO, serial, by_key(WHO, out("merged")), "two shards merged")
run([VOBENCH, "report", out("merged"), "-o", os.path.join(WORK, "report")], WHO)
if not os.path.exists(os.path.join(WORK, "report", "report.md")):
    fail(WHO, "report of the merged file wrote no report.md")
run([VOBENCH, "compare", out("serial"), out("merged"), "--threshold", "100"], WHO)

p = run([VOBENCH, "merge", out("merged"), out("merged"), "-o", out("self")], WHO)
if "conflict" in p.stderr.replace("(0 conflicting)", "") or len(by_key(WHO, out("self"))) != len(serial):
    fail(WHO, f"a file merged with itself: {p.stderr[-1000:]}")
p = run([VOBENCH, "merge", out("merged"), out("merged"), "-o", out("self")], WHO, codes=(2,))
if "exists" not in p.stderr:
    fail(WHO, f"merge onto an existing file was not refused by name: {p.stderr}")

# A duplicate from a run with other settings and another revision: a conflict, named.
lines = [json.loads(ln) for ln in open(out("shard1")) if ln.strip()]
ctx = next(r for r in lines if r.get("type") == "context")
rec = next(r for r in lines if r.get("type") != "context" and "oracle" in r)
ctx = dict(ctx, run_id="other-run", key="context|other-run", context=dict(ctx["context"], git_sha="0123abc"))
rec = dict(rec, run_id="other-run", repeats=rec["repeats"] + 4)
with open(out("other"), "w") as f:
    f.write(json.dumps(ctx) + "\n" + json.dumps(rec) + "\n")
p = run([VOBENCH, "merge", out("merged"), out("other"), "-o", out("conflict")], WHO, codes=(1,))
for word in (rec["key"], "settings: repeats", "revision", "0123abc"):
    if word not in p.stderr:
        fail(WHO, f"the conflict message does not name {word!r}:\n{p.stderr[-1500:]}")
kept = by_key(WHO, out("conflict"))
if len(kept) != len(serial) or kept[rec["key"]]["repeats"] != serial[rec["key"]]["repeats"]:
    fail(WHO, "the conflicting merge did not keep every key once, the first file's record")

# The same job measured on another machine: a conflict naming the host (every key once:
# its record cannot share the file); measured again on the same host: counted, exit 0.
first_ctx = next(r for r in lines if r.get("type") == "context")  # the plan line comes first
other_host = dict(lines[lines.index(next(r for r in lines if r.get("type") != "context" and "oracle" in r))],
                  run_id=first_ctx["run_id"], host="another-machine")
with open(out("host"), "w") as f:
    f.write(json.dumps(first_ctx) + "\n" + json.dumps(other_host) + "\n")
p = run([VOBENCH, "merge", out("merged"), out("host"), "-o", out("hosts")], WHO, codes=(1,))
if "host" not in p.stderr or "another-machine" not in p.stderr:
    fail(WHO, f"another host's record was dropped without a word:\n{p.stderr[-1500:]}")
again = dict(other_host, host=rec.get("host"), run_id="again-run", total=dict(rec["total"], median=1.0))
with open(out("again"), "w") as f:
    f.write(json.dumps(dict(first_ctx, run_id="again-run", key="context|again-run")) + "\n" + json.dumps(again) + "\n")
p = run([VOBENCH, "merge", out("merged"), out("again"), "-o", out("agains")], WHO)
if "1 measured again by another run on the same host" not in p.stderr:
    fail(WHO, f"a record measured again was not counted:\n{p.stderr[-1500:]}")

p = run([VOBENCH, "run", suite, "-o", out("serial"), "--dry-run", "--ranks", "3"], WHO)
if "makespan on 3 ranks" not in p.stdout or "largest indivisible group" not in p.stdout:
    fail(WHO, f"--dry-run --ranks 3 printed no makespan:\n{p.stdout[-1500:]}")
# --costs calibrates the total line too, from another file's records, for an empty -o file.
p = run([VOBENCH, "run", suite, "-o", os.path.join(WORK, "empty.jsonl"), "--dry-run", "--ranks", "2",
         "--costs", out("serial")], WHO)
if f"records in {out('serial')}" not in p.stdout or "uncalibrated" in p.stdout:
    fail(WHO, f"--dry-run --costs FILE did not calibrate the total from FILE:\n{p.stdout[-1500:]}")
print("check_shards: ok")
