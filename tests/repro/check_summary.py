#!/usr/bin/python3
"""The claims summary from the records alone, without running any reproduction again: the
records of every reproduction with a paper, as the repro.NAME tests left them in WORK/NAME,
go into one folder OUT (what `vobench reproduce all --tiny` writes); `vobench report OUT`
must rebuild every table and claims-summary.md/json/html, whose claims are exactly the claims of
the reproductions' documents, with verdicts and counts that agree.

usage: check_summary.py VOBENCH WORK OUT
"""
import glob
import json
import os
import shutil
import subprocess
import sys


def fail(msg):
    sys.exit(f"check_summary: {msg}")


def main():
    vobench, work, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    names = []
    with open(os.path.join(out, "results.jsonl"), "w") as dst:
        for d in sorted(glob.glob(os.path.join(work, "*"))):
            res = os.path.join(d, "results.jsonl")
            if not os.path.isfile(res):
                continue
            lines = [ln for ln in open(res) if ln.strip()]
            recs = [r for r in map(json.loads, lines) if r.get("type") not in ("context", "plan")]  # runs' context lines
            if not recs or not recs[0].get("paper"):
                continue  # reproductions without a paper have no claims
            if any(r.get("scale") != "tiny" for r in recs):
                fail(f"{res}: records not all at scale tiny")
            names.append(os.path.basename(d))
            dst.writelines(lines)
            if os.path.isdir(os.path.join(d, "images")):
                shutil.copytree(os.path.join(d, "images"), os.path.join(out, "images"), dirs_exist_ok=True)
    if len(names) < 2:
        fail(f"{work}: fewer than two reproductions with a paper ({names})")
    p = subprocess.run([vobench, "report", out], capture_output=True, text=True)
    if p.returncode != 0:
        fail(f"vobench report {out} exited {p.returncode}:\n{p.stderr[-3000:]}")
    s = json.load(open(os.path.join(out, "claims-summary.json")))
    for ext in ("md", "html"):
        if not os.path.isfile(os.path.join(out, f"claims-summary.{ext}")):
            fail(f"claims-summary.{ext} missing")
    want = []
    for n in names:
        doc = json.load(open(os.path.join(out, f"{n}.json")))
        want += [(n, c["claim"], c["holds"], c["criterion"]) for c in doc["claims"]]
    got = [(c["experiment"], c["claim"], c["holds"], c["criterion"]) for c in s["claims"]]
    if got != want:
        fail(f"summary claims differ from the documents' ({len(got)} against {len(want)})")
    missing = sorted(set(names) - {c["experiment"] for c in s["claims"]})
    if missing:
        print(f"note: reproductions without claims: {', '.join(missing)}")
    for c in s["claims"]:
        if c["holds"] not in (True, False, None) or not c["criterion"]:
            fail(f"claim '{c['claim']}': holds {c['holds']!r}, criterion {c['criterion']!r}")
    n = {"holds": sum(c["holds"] is True for c in s["claims"]),
         "does not hold": sum(c["holds"] is False for c in s["claims"]),
         "not measured": sum(c["holds"] is None for c in s["claims"])}
    if s["counts"] != n:
        fail(f"counts {s['counts']} do not match the claims {n}")
    md = open(os.path.join(out, "claims-summary.md")).read()
    if f"| all | {n['holds']} | {n['does not hold']} | {n['not measured']} |" not in md:
        fail("claims-summary.md lacks the counts row")
    print(f"summary: {len(names)} reproductions, {len(got)} claims: {n}")


if __name__ == "__main__":
    main()
