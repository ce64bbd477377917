#!/usr/bin/python3
"""`vobench run` on a suite with a "vtk_render" entry (issue 18): one command gives the records
and VTK's images, with no X server given (vobench-vtk starts its own Xvfb); `vobench report`
shows "What VTK shows" from that run; without vobench-vtk the run still succeeds and the
report says "not run (reason)"; SIGTERM during the VTK part exits 143 with every record and
every finished scene kept and no half scene, and the same command then finishes the rest.
Exit 77 (skipped) only when there is no Xvfb to start.

usage: check_run_vtk.py VOBENCH OUTDIR"""
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import time

prog, out = sys.argv[1], sys.argv[2]
if not shutil.which("Xvfb"):
    print("SKIP: no Xvfb")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "VOBENCH_VTK")}


def suite(name, datasets, vtk_repeats):
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump({"name": name, "datasets": datasets, "algorithms": ["mpvonc"], "views": 14,
                   "view_indices": [3, 8], "sizes": ["160x120"], "repeats": 1, "warmup": 0,
                   "vtk_render": {"algorithms": ["sxmpvo", "centroid"], "repeats": vtk_repeats, "extinction": 6}}, f)
    return path


def run(args, extra_env=None, **kw):
    e = dict(env, **(extra_env or {}))
    r = subprocess.run([prog] + args, capture_output=True, text=True, timeout=600, env=e, **kw)
    print(" ".join(args), "->", r.returncode, "\n", r.stderr[-3000:])
    return r


def lines(path):
    return open(path).read().splitlines()


helix = [{"name": "helix", "set": {"cells": 2000}, "label": "helix"}]
# One command, no display: records, then VTK's images through an Xvfb of vobench-vtk's own.
d1 = os.path.join(out, "one")
r = run(["run", suite("one", helix, 1), "-o", os.path.join(d1, "results.jsonl")])
assert r.returncode == 0
kinds = [json.loads(l).get("type", "record") for l in lines(os.path.join(d1, "results.jsonl"))]
assert sorted(kinds) == ["context", "plan", "record", "record"], kinds  # the run's context and plan, two records
render = json.load(open(os.path.join(d1, "vtk", "helix-160x120", "render.json")))
assert [v["view_index"] for v in render["views"]] == [3, 8] and "Xvfb" in render["x_server"], render["x_server"]
assert json.load(open(os.path.join(d1, "vtk", "status-one.json")))["state"] == "done"
r = run(["report", os.path.join(d1, "results.jsonl"), "-o", os.path.join(d1, "report")])
assert r.returncode == 0
md = open(glob.glob(os.path.join(d1, "report", "*.md"))[0]).read()
assert "What VTK shows" in md and "| centroid |" in md.replace("|centroid|", "| centroid |"), md[-2000:]
assert "not run" not in md
r = run(["run", os.path.join(out, "one.json"), "-o", os.path.join(d1, "results.jsonl")])
assert r.returncode == 0 and "kept" in r.stderr  # the same run again: nothing drawn twice

# No vobench-vtk: the records still, one line, and the report names the reason.
d2 = os.path.join(out, "absent")
r = run(["run", os.path.join(out, "one.json"), "-o", os.path.join(d2, "results.jsonl")],
        {"VOBENCH_VTK": os.path.join(out, "no-such-program")})
assert r.returncode == 0 and "vtk_render: one: not run: vobench-vtk not found" in r.stderr
r = run(["report", os.path.join(d2, "results.jsonl"), "-o", os.path.join(d2, "report")])
md = open(glob.glob(os.path.join(d2, "report", "*.md"))[0]).read()
assert "Suite one: not run (vobench-vtk not found" in md, md[-2000:]

# SIGTERM while VTK draws the second scene: exit 143, records and the first scene kept, no
# half scene; the same command draws the rest.
d3 = os.path.join(out, "stop")
two = suite("two", helix + [{"name": "helix", "set": {"cells": 3000}, "label": "helix3k"}], 25)
cmd = [prog, "run", two, "-o", os.path.join(d3, "results.jsonl")]
p = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True, env=env, start_new_session=True)
first = os.path.join(d3, "vtk", "helix-160x120", "render.json")
deadline = time.time() + 600
while not os.path.exists(first) and p.poll() is None and time.time() < deadline:
    time.sleep(0.05)
assert p.poll() is None, "the run ended before its second VTK scene"
os.kill(p.pid, signal.SIGTERM)
err = p.communicate(timeout=300)[1]
print(err[-3000:])
assert p.returncode == 143, p.returncode
kinds = [json.loads(l).get("type", "record") for l in lines(os.path.join(d3, "results.jsonl"))]
assert kinds.count("record") == 4 and kinds.count("context") == 1, kinds  # four records: all of them
assert os.path.exists(first) and not os.path.exists(os.path.join(d3, "vtk", "helix3k-160x120"))
assert not glob.glob(os.path.join(d3, "vtk", "*.partial")), os.listdir(os.path.join(d3, "vtk"))
assert json.load(open(os.path.join(d3, "vtk", "status-two.json")))["state"] == "interrupted"
r = run(["run", two, "-o", os.path.join(d3, "results.jsonl")])
assert r.returncode == 0 and "kept" in r.stderr
assert os.path.exists(os.path.join(d3, "vtk", "helix3k-160x120", "render.json"))
assert json.load(open(os.path.join(d3, "vtk", "status-two.json")))["state"] == "done"
print("ok")
