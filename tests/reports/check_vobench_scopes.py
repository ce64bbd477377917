#!/usr/bin/python3
"""Each speed-target claim (reports/papers/vobench.py) scoped to its own suite and data set
(docs/pipeline.md "Incomplete data"): two targets measured on the same 200k-cell helix, one job
of one of them taken out of a results file with plan lines: that target's claim reads "not
measured", the other keeps its verdict.

usage: check_vobench_scopes.py REPORTS_DIR WORK_DIR
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402
import planned as PL  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
H.use_reports(REPORTS)
shutil.rmtree(WORK, ignore_errors=True)
C = H.Checks("check_vobench_scopes", WORK)

recs = []
for v in (0, 1):
    for suite, spec, secs, threads in (("xmpvo-sxmpvo", "xmpvo", 0.05, 1), ("xmpvo-sxmpvo", "sxmpvo", 0.01, 1),
                                       ("havs-k2", "havs:k=2,analyze=false", 0.05, 2)):
        r = H.orderer_record("speed-targets", suite, spec.split(":")[0], "helix", {"cells": 200000}, v, secs,
                             n=200000, algorithm=spec, threads=threads, paper="vobench")
        recs.append(r)
XS, HAVS = "XMPVO / SXMPVO per view", "software HAVS frame at k = 2"
PL.check_drop(C, REPORTS, os.path.join(WORK, "havs-view-1"), "speed-targets", recs,
              lambda r: r["orderer"] == "havs" and r["view_index"] == 1, gone=[HAVS], kept=[XS],
              why="havs view 1 missing")
PL.check_drop(C, REPORTS, os.path.join(WORK, "xmpvo-view-1"), "speed-targets", recs,
              lambda r: r["orderer"] == "xmpvo" and r["view_index"] == 1, gone=[XS], kept=[HAVS],
              why="xmpvo view 1 missing")
C.done("a missing job of one speed target leaves the other target on the same data set judged")
