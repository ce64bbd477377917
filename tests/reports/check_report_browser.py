#!/usr/bin/python3
"""report.browser (tests/reports/CMakeLists.txt): a tiny run (one suite with the oracle and
images, one without), `vobench report DIR` started from another folder, DIR moved; then
every HTML page opened offline in headless chromium must load every image; the run without
the oracle must read "not checked" with no error value; a second report, split into one page
per scene, written into another folder from the moved results, must load every image too;
a screenshot of report.html is written to WORK/report.png; and with one image deleted the
check must report it broken.

usage: check_report_browser.py VOBENCH CHROMIUM WORK REPORT_PY"""
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import browser  # noqa: E402

VOBENCH, CHROMIUM, WORK, REPORT_PY = sys.argv[1:5]


def fail(why):
    sys.exit(f"report.browser: {why}")


def vobench(args, cwd):
    r = subprocess.run([VOBENCH] + args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        print(r.stdout)
        fail(f"`vobench {' '.join(args)}` exited {r.returncode}")


SUITES = {
    "checked": {"name": "browser-checked", "datasets": [{"name": "helix", "set": {"cells": 500}}],
                "algorithms": ["mpvonc", "centroid"], "views": 2, "sizes": ["64x64"], "repeats": 1,
                "warmup": 0, "oracle": True, "image_error": True, "image_views": [0],
                "images_of_violations": True},
    "unchecked": {"name": "browser-unchecked", "datasets": [{"name": "gap", "set": {"nx": 4, "ny": 4, "nz": 4,
                                                                                    "gaps": 1}}],
                  "algorithms": ["mpvonc", "centroid"], "views": 2, "sizes": ["64x64"], "repeats": 1,
                  "warmup": 0, "oracle": False},
}

shutil.rmtree(WORK, ignore_errors=True)
run_dir, elsewhere, moved = (os.path.join(WORK, d) for d in ("run", "elsewhere", "moved/run"))
for d in (run_dir, elsewhere):
    os.makedirs(d)
results = os.path.join(run_dir, "results.jsonl")
for key, suite in SUITES.items():
    path = os.path.join(WORK, key + ".json")
    with open(path, "w") as f:
        json.dump(suite, f)
    vobench(["run", path, "-o", results], cwd=elsewhere)  # not the results' folder
vobench(["report", run_dir], cwd=elsewhere)
os.makedirs(os.path.dirname(moved))
shutil.move(run_dir, moved)

# One page per scene, in a folder that is not the results' folder.
paged = os.path.join(WORK, "moved", "paged")
r = subprocess.run(["/usr/bin/python3", REPORT_PY, "--out", paged, "--page-scenes", "1",
                    os.path.join(moved, "results.jsonl")], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
if r.returncode != 0:
    print(r.stdout)
    fail("report.py --page-scenes 1 failed")
pages = browser.pages(moved) + browser.pages(paged)
if len(browser.pages(paged)) != 1 + len(SUITES):
    fail(f"{paged}: expected an index and one page per scene, got {browser.pages(paged)}")
profile = os.path.join(WORK, "chromium-profile")
total = 0
for page in pages:
    missing, n = browser.missing_files(page)
    if missing:
        fail(f"{page}: {len(missing)} of {n} images name no file: {missing[:3]}")
    with open(page) as f:
        if re.search(r"""(src|href)=['"]?(https?:)?//""", f.read()):
            fail(f"{page}: refers to the network; a report must load offline")
    seen, broken = browser.broken_in_browser(CHROMIUM, page, profile)
    if seen != n or broken:
        fail(f"{page}: chromium loaded {seen - broken} of {n} images ({seen} seen, {broken} broken)")
    total += n
with open(os.path.join(moved, "summary.json")) as f:
    rows = json.load(f)
unchecked = [r for r in rows if r["dataset"].startswith("gap")]
if not unchecked or any(r["err"] is not None or r.get("verdict") != "not checked" for r in unchecked):
    fail(f"rows without the oracle must have no error and read 'not checked': {unchecked}")
with open(os.path.join(moved, "report.md")) as f:
    if "not checked" not in f.read():
        fail("report.md never says 'not checked'")

shot = os.path.join(WORK, "report.png")
if not browser.screenshot(CHROMIUM, os.path.join(moved, "report.html"), shot, profile):
    fail("no screenshot written")

# The check itself: an image deleted must be caught, by the file check and by the browser.
page = os.path.join(moved, "report.html")
_, n = browser.missing_files(page)
victim = os.path.join(moved, "figures", sorted(os.listdir(os.path.join(moved, "figures")))[0])
os.remove(victim)
missing, _ = browser.missing_files(page)
seen, broken = browser.broken_in_browser(CHROMIUM, page, profile)
if not missing or broken < 1:
    fail(f"a deleted image ({victim}) went unnoticed: {len(missing)} missing files, {broken} broken in chromium")
print(f"report.browser: {len(pages)} page(s), {total} images all loaded after the move; "
      f"a deleted image is caught; screenshot {shot}")
