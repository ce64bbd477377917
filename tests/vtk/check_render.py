#!/usr/bin/python3
"""`vobench-vtk render` on the 2000-cell helix over 14 views (issue 18): VTK's own sort
(vtkCellCenterDepthSort) shows pixel differences from sxmpvo in some view, and sxmpvo's image
in VTK's projected-tetrahedra mapper equals xmpvo's in every view; every reference image
covers pixels (identical blank images would prove nothing). The zoo's mixed cells through
VTK's tetrahedralization (id map kept), a suite's vtk_render entry, and a bad orderer or suite
(one line, exit 2). Runs the program under xvfb-run; exit 77 (skipped) only when no X server can start.

usage: check_render.py VOBENCH_VTK OUTDIR"""
import json
import os
import shutil
import subprocess
import sys

prog, out = sys.argv[1], sys.argv[2]
if shutil.which("xvfb-run"):
    wrap = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24"]
elif os.environ.get("DISPLAY"):
    wrap = []
else:
    print("SKIP: no xvfb-run and no DISPLAY: no X server for VTK's OpenGL render window")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)

cmd = wrap + [prog, "render", "--dataset", "helix", "--set", "cells=2000", "--views", "14",
              "--algorithm", "sxmpvo", "--algorithm", "xmpvo", "--repeats", "1", "--extinction", "8",
              "-o", out]
print(" ".join(cmd))
r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
print(r.stdout, r.stderr)
if r.returncode != 0 and "xvfb-run" in r.stderr and "Xvfb failed" in r.stderr:
    print("SKIP: Xvfb could not start")
    sys.exit(77)
assert r.returncode == 0, f"exit {r.returncode}"

run = json.load(open(os.path.join(out, "render.json")))
assert run["reference"] == "sxmpvo", run["reference"]
assert [s["label"] for s in run["sorters"]] == ["vtk-default", "sxmpvo", "xmpvo"]
assert len(run["views"]) == 14
vtk_off = []
for v in run["views"]:
    res = {x["sorter"]: x for x in v["results"]}
    assert res["sxmpvo"]["covered_pixels"] > 1000, (v["view_index"], res["sxmpvo"]["covered_pixels"])
    assert res["sxmpvo"]["difference"]["pixels"] == 0
    assert res["xmpvo"]["difference"]["pixels"] == 0, \
        f"view {v['view_index']}: xmpvo differs from sxmpvo in {res['xmpvo']['difference']} pixels"
    for name in res:
        assert os.path.exists(os.path.join(out, res[name]["image"]))
        assert os.path.exists(os.path.join(out, res[name]["difference"]["image"]))
    vtk_off.append(res["vtk-default"]["difference"]["pixels"])
print("vtk-default pixels differing from sxmpvo per view:", vtk_off)
assert max(vtk_off) > 0, "VTK's default sort matched sxmpvo in every view"
assert os.path.exists(os.path.join(out, "render.html"))

bad = subprocess.run(wrap + [prog, "render", "--dataset", "helix", "--algorithm", "btf", "-o", out + "-bad"],
                     capture_output=True, text=True, timeout=120)
lines = bad.stderr.strip().splitlines()
assert bad.returncode == 2 and len(lines) == 1 and lines[0].startswith("vobench-vtk: render: "), \
    (bad.returncode, bad.stderr)
# Cells other than tetrahedra go through VTK's tetrahedralization, the id map kept; the
# orderers order those tetrahedra exactly as well.
zoo = out + "-zoo"
r = subprocess.run(wrap + [prog, "render", "--dataset", "zoo", "--views", "14", "--view-index", "5", "--size",
                           "160x120", "--algorithm", "xmpvo", "--algorithm", "sxmpvo", "--repeats", "1",
                           "--extinction", "4", "-o", zoo], capture_output=True, text=True, timeout=600)
assert r.returncode == 0, (r.returncode, r.stderr)
run = json.load(open(os.path.join(zoo, "render.json")))
assert run["tetrahedralized"] and run["tetrahedra"] > run["cells"], run
assert "vobench_cell_id" in open(os.path.join(zoo, "tetrahedra.vtu"), errors="replace").read()
res = {x["sorter"]: x for x in run["views"][0]["results"]}
assert res["xmpvo"]["covered_pixels"] > 1000 and res["sxmpvo"]["difference"]["pixels"] == 0, res

# A suite names the run: its "vtk_render" entry, datasets, views and sizes; the run goes to
# OUT/vtk/LABEL-WxH, where `vobench report OUT` finds it.
suite_dir = out + "-suite"
shutil.rmtree(suite_dir, ignore_errors=True)
os.makedirs(suite_dir)
suite = {"name": "vtk", "datasets": [{"name": "helix", "set": {"cells": 2000}, "label": "helix"}],
         "algorithms": ["xmpvo"], "views": 14, "view_indices": [3, 8], "sizes": ["160x120"],
         "vtk_render": {"algorithms": ["xmpvo", "sxmpvo"], "repeats": 1}}
with open(os.path.join(suite_dir, "suite.json"), "w") as f:
    json.dump(suite, f)
r = subprocess.run(wrap + [prog, "render", "--suite", os.path.join(suite_dir, "suite.json"), "-o", suite_dir],
                   capture_output=True, text=True, timeout=600)
assert r.returncode == 0, (r.returncode, r.stderr)
run = json.load(open(os.path.join(suite_dir, "vtk", "helix-160x120", "render.json")))
assert run["reference"] == "xmpvo" and [v["view_index"] for v in run["views"]] == [3, 8], run["views"]
assert all(x["difference"]["pixels"] == 0 for v in run["views"] for x in v["results"] if x["sorter"] == "sxmpvo")
del suite["vtk_render"]
with open(os.path.join(suite_dir, "suite.json"), "w") as f:
    json.dump(suite, f)
bad = subprocess.run([prog, "render", "--suite", os.path.join(suite_dir, "suite.json"), "-o", suite_dir],
                     capture_output=True, text=True, timeout=120)
assert bad.returncode == 2 and "vtk_render: is missing" in bad.stderr, (bad.returncode, bad.stderr)
# No X server and told not to start one: one line and exit 4 (nothing to draw on), not
# VTK's abort.
env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
nox = subprocess.run([prog, "render", "--dataset", "helix", "--xvfb", "never", "-o", out + "-nox"],
                     capture_output=True, text=True, timeout=120, env=env)
assert nox.returncode == 4 and "no X server" in nox.stderr and len(nox.stderr.strip().splitlines()) == 1, \
    (nox.returncode, nox.stderr)
print("ok")
