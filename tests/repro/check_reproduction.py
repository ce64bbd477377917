#!/usr/bin/python3
"""A reproduction at the tiny scale, end to end (tests/repro/CMakeLists.txt):

1. `vobench reproduce NAME --tiny --force -o DIR` exits 0 and writes DIR/NAME.md and
   DIR/NAME.json; every claim in NAME.json has a boolean or null "holds" and a non-empty
   criterion; every record of the run carries reproduction NAME and scale tiny.
2. With NAME.md deleted, `vobench report DIR` writes it again, byte for byte.

usage: check_reproduction.py VOBENCH NAME DIR
"""
import json
import os
import subprocess
import sys


def fail(why):
    sys.exit(f"repro {NAME}: {why}")


def run(args):
    r = subprocess.run([VOBENCH] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        print(r.stdout)
        fail(f"`vobench {' '.join(args)}` exited {r.returncode}")
    return r.stdout


VOBENCH, NAME, DIR = sys.argv[1:4]
os.makedirs(DIR, exist_ok=True)
run(["reproduce", NAME, "--tiny", "--force", "-o", DIR])
md, js = os.path.join(DIR, NAME + ".md"), os.path.join(DIR, NAME + ".json")
for path in (md, js):
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        fail(f"{path} was not written")
with open(js) as f:
    doc = json.load(f)
for c in doc.get("claims", []):
    if not (c.get("holds") is None or isinstance(c.get("holds"), bool)):
        fail(f"claim {c.get('claim')!r}: holds is {c.get('holds')!r}, not a boolean or null")
    if not isinstance(c.get("criterion"), str) or not c["criterion"].strip():
        fail(f"claim {c.get('claim')!r}: no criterion")
with open(os.path.join(DIR, "results.jsonl")) as f:
    # Context lines (one per run) are not records (docs/pipeline.md "Records").
    recs = [r for r in (json.loads(line) for line in f if line.strip()) if r.get("type") not in ("context", "plan")]
if not recs:
    fail("no records")
for r in recs:
    if r.get("reproduction") != NAME or r.get("scale") != "tiny":
        fail(f"record {r.get('key')!r}: reproduction {r.get('reproduction')!r}, scale {r.get('scale')!r}")
with open(md, "rb") as f:
    before = f.read()
os.remove(md)
run(["report", DIR])
if not os.path.isfile(md):
    fail("`vobench report DIR` did not rebuild " + md)
with open(md, "rb") as f:
    if f.read() != before:
        fail("`vobench report DIR` rebuilt " + md + " with different bytes")
print(f"repro {NAME}: {len(recs)} records, {len(doc.get('claims', []))} claims, {NAME}.md rebuilt identically")
