#!/usr/bin/python3
"""Cook et al. Table 4 (reports/papers/cook.py) from hand-made records: each reproduction's
figure has its own file (cook-table4 and cook-table4-512 share a folder under `reproduce
all`) and its title stays inside the image.

usage: check_cook_table4.py REPORTS_DIR WORK_DIR
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import handmade as H  # noqa: E402

REPORTS, WORK = sys.argv[1], sys.argv[2]
H.use_reports(REPORTS)
import cook  # noqa: E402
import matplotlib.image as mpimg  # noqa: E402

PAPER = H.paper_numbers(REPORTS, "cook")
VIEWS = (0, 4, 9)
failures = []


def check(cond, why):
    if not cond:
        failures.append(why)


def records(reproduction="cook-table4", fit=True):
    """Three helices and a gap mesh, SXMPVO slower than MPVONC everywhere, both linear in n."""
    out = []
    sets = [("helix", {"cells": n, "faces": n // 5}, n) for n in (2000, 6000, 12000)]
    sets.append(("gap", {"gaps": 5, "nx": 8, "ny": 8, "nz": 5}, 1920))
    for name, spec, n in sets:
        for v in VIEWS:
            for orderer, per_cell in (("sxmpvo", 2.0e-7), ("mpvonc", 1.0e-7), ("vtk-centroid", 0.5e-7)):
                out.append(H.orderer_record(reproduction, "table4", orderer, name, spec, v,
                                            1e-4 + per_cell * n * (1 + 0.01 * v), n=n, fit=fit,
                                            size="128x128" if fit else "512x512"))
    return out


def build(recs, name="cook-table4", out=None):
    return H.build(cook, name, recs, PAPER, out or os.path.join(WORK, "one"))


LINEAR_SX, LINEAR_NC = "SXMPVO time grows approximately linearly", "MPVONC time grows approximately linearly"
SLOWER = "SXMPVO is always slower than MPVONC"
shutil.rmtree(WORK, ignore_errors=True)

# --- the figure: its own file per reproduction, the title inside the image -------------------
shared = os.path.join(WORK, "shared")
d4 = build(records(), "cook-table4", shared)
d512 = build(records("cook-table4-512", fit=False), "cook-table4-512", shared)
f4, f512 = [d.figures[0]["file"] if d.figures else None for d in (d4, d512)]
check(f4 and f512 and f4 != f512, f"cook-table4 and cook-table4-512 write one figure file: {f4}, {f512}")
check(f4 and "cook-table4" in f4 and f512 and "cook-table4-512" in f512,
      f"the figure files do not name their reproductions: {f4}, {f512}")
for f in (f4, f512):
    if f and os.path.exists(os.path.join(shared, f)):
        img = mpimg.imread(os.path.join(shared, f))
        band = img[: img.shape[0] // 8, :, :3]  # the title's band
        edges = [band[:, :3], band[:, -3:]]
        check(all(e.min() > 0.95 for e in edges), f"{f}: the title runs into the left or right edge")
    else:
        check(False, f"{f}: no figure file")

if failures:
    sys.exit("check_cook_table4:\n  " + "\n  ".join(failures))
print("check_cook_table4: one figure file per reproduction, titles inside")
