#!/usr/bin/python3
"""vobench's speed targets (reports/papers/vobench.py) from hand-made records: a target holds
on a dataset only when every view meets its bound (the worst view decides, upper and lower
bounds alike, the bound itself included), a view lacking one side of a ratio makes the claim
"not measured", HAVS's rate counts only records at the target's thread count, and a target
without records still gets its claim ("not measured").

usage: check_speed_targets.py REPORTS_DIR
"""
import os
import sys

REPORTS = sys.argv[1]
sys.path.insert(0, REPORTS)
sys.path.insert(0, os.path.join(REPORTS, "papers"))
import vobench  # noqa: E402
from vobtables.doc import Doc  # noqa: E402


def fail(why):
    sys.exit(f"check_speed_targets: {why}")


DATASETS = {t["suite"]: t["datasets"] for t in vobench.TARGETS}


def rec(suite, algorithm, view, seconds, row=None, threads=1, n=1000, prepare=None):
    r = {"suite": "speed-targets/" + suite, "algorithm": algorithm, "row": row or DATASETS[suite][0], "view_index": view,
         "threads": threads, "n": n, "total": {"median": seconds}}
    if prepare is not None:
        r["prepare"] = {"seconds": prepare}
    return r


def claims(records):
    doc = Doc("speed-targets", "t")
    vobench.speed_targets(records, {}, doc)
    return doc


def verdict(records, what):
    # The first dataset's claim of the target named `what`.
    found = [c for c in claims(records).claims if c["claim"].split(":")[1].strip() == what][:1]
    if len(found) != 1:
        fail(f"{what}: {len(found)} claims")
    return found[0]["holds"], found[0]["ours"]


def pair(suite, num, den, view, a, b, row=None):
    return [rec(suite, num, view, a, row), rec(suite, den, view, b, row)]


S = "SXMPVO / MPVONC"
cases = [
    ("ratio at the bound holds", pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.012, 0.010), S, True, 1.2),
    ("the worst view decides", pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.011, 0.010)
     + pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 4, 0.013, 0.010), S, False, 1.3),
    ("a view without its denominator is not measured", pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.011, 0.010)
     + [rec("sxmpvo-mpvonc", "sxmpvo", 4, 0.011)], S, None, None),
    ("records of another suite do not count", pair("xmpvo-sxmpvo", "sxmpvo", "mpvonc", 0, 0.011, 0.010), S, None,
     None),
    ("records of another dataset (the tiny scale's) are not the target's",
     pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.011, 0.010, row="helix(cells=3000)"), S, None, None),
    ("a lower bound: 10 holds", pair("centroid-peer", "vtk-centroid", "centroid", 0, 0.100, 0.010),
     "vtk-centroid / centroid", True, 10.0),
    ("a lower bound: the smallest view decides", pair("centroid-peer", "vtk-centroid", "centroid", 0, 0.200, 0.010)
     + pair("centroid-peer", "vtk-centroid", "centroid", 4, 0.099, 0.010), "vtk-centroid / centroid", False, 9.9),
    ("prepare under 2 s", [rec("bsp-prepare", "bsp-xmpvo", 0, 1.0, prepare=1.99)],
     "BSP-XMPVO preprocessing (seconds)", True, 1.99),
    ("prepare of 2 s is not under 2 s", [rec("bsp-prepare", "bsp-xmpvo", 0, 1.0, prepare=2.0)],
     "BSP-XMPVO preprocessing (seconds)", False, 2.0),
    ("HAVS at 2 threads", [rec("havs-k2", "havs:k=2,analyze=false", 0, 0.05, threads=2, n=200000)],
     "software HAVS frame at k = 2 (cells per second)", True, 4.0e6),
    ("HAVS too slow", [rec("havs-k2", "havs:k=2,analyze=false", 0, 0.11, threads=2, n=200000)],
     "software HAVS frame at k = 2 (cells per second)", False, 200000 / 0.11),
    ("HAVS with one thread is not the target's run", [rec("havs-k2", "havs:k=2,analyze=false", 0, 0.05, n=200000)],
     "software HAVS frame at k = 2 (cells per second)", None, None),
]
for name, records, what, holds, ours in cases:
    got_holds, got_ours = verdict(records, what)
    if got_holds is not holds or (ours is None) != (got_ours is None) or (
            ours is not None and abs(got_ours - ours) > 1e-9 * abs(ours)):
        fail(f"{name}: holds {got_holds}, ours {got_ours}; expected {holds}, {ours}")

# Every dataset of every target has a claim, measured or not, judged apart from the others.
two = DATASETS["sxmpvo-mpvonc"]
doc = claims(pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.011, 0.010, row=two[0])
             + pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.013, 0.010, row=two[1]))
expected = sum(len(t["datasets"]) for t in vobench.TARGETS)
if len(doc.claims) != expected:
    fail(f"{len(doc.claims)} claims for {expected} target datasets")
if [c["holds"] for c in doc.claims[:2]] != [True, False]:
    fail("the two datasets of one target must be judged apart")
if any(c["holds"] is not None for c in doc.claims[2:]):
    fail("targets without records must read 'not measured'")
if "measured on" not in claims(pair("sxmpvo-mpvonc", "sxmpvo", "mpvonc", 0, 0.011, 0.010, row="x")).claims[0]["criterion"]:
    fail("a target run on other datasets only must say where it was measured")
print(f"check_speed_targets: {len(cases)} cases and the claim count agree")
