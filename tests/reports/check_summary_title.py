#!/usr/bin/python3
"""The claims summary (reports/vobtables/summary.py) says what its folder holds: a folder with
one paper's reproductions is titled with that paper and their number, not "every claim of the
four papers"; the speed targets are named when present.

usage: check_summary_title.py REPORTS_DIR WORK_DIR
"""
import json
import os
import shutil
import sys

REPORTS, WORK = sys.argv[1], sys.argv[2]
sys.path.insert(0, REPORTS)
from vobtables.doc import Doc  # noqa: E402
from vobtables.summary import PAPERS, write_summary  # noqa: E402

failures = []
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)


def title(docs, scale="tiny"):
    write_summary(docs, WORK, scale)
    with open(os.path.join(WORK, "claims-summary.json")) as f:
        return json.load(f)["title"]


def doc(name):
    d = Doc(name, name)
    d.claim("c", 1, 1, "ours == 1", True)
    return d


one = title([("cook", doc("cook-table4")), ("cook", doc("cook-table4-512"))])
if "four papers" in one or "every claim" in one:
    failures.append(f"one paper's folder titled as all papers': {one}")
if PAPERS["cook"] not in one or "2 reproductions" not in one:
    failures.append(f"the title must name the paper and the 2 reproductions: {one}")
both = title([("cook", doc("cook-table4")), ("havs", doc("havs-table3-4")), ("vobench", doc("speed-targets"))])
if not all(w in both for w in (PAPERS["cook"], PAPERS["havs"], "speed targets", "3 reproductions")):
    failures.append(f"the title must name both papers and the speed targets: {both}")
if failures:
    sys.exit("check_summary_title:\n  " + "\n  ".join(failures))
print("check_summary_title: the title says what the folder holds")
