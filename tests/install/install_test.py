#!/usr/bin/python3
"""vobench installed like a library, used from outside its tree (issue 15, item 3):

1. `cmake --install BUILD --component vobench` into a fresh temporary prefix, which is then
   MOVED (the RPATH and the resource lookup must follow it); the installed headers compile
   from the prefix alone;
2. the out-of-tree orderer project (tests/install/orderer: only find_package(vobench) and
   vobench_add_plugin) configures and builds against the moved prefix, and finds the
   package there (not the build tree);
3. `vobench --plugin LIB list` shows its orderer; `check` with it passes on zoo, its
   deliberately wrong variant (reverse=true) fails (exit 1): the plugin's order is judged;
4. a broken --plugin (missing file, not a library, no entry point, built for another
   vobench version) -> exit 2, one line;
5. the installed program reads share/vobench of the moved prefix (a reproduction added
   there is listed; the build tree's program does not list it);
6. a tiny suite with the plugin's orderer runs (the same counts as the built-in centroid it
   imitates) and `vobench report` writes its report with
   the installed scripts; `reproduce quick --tiny` from another folder writes
   ./vobench-out/quick-tiny and nothing into the prefix.

usage: install_test.py CMAKE BUILD_DIR ORDERER_SOURCE WORKDIR GENERATOR [CXX_LAUNCHER]
"""
import json
import os
import shutil
import subprocess
import sys
import time

CMAKE, BUILD, ORDERER, WORK, GENERATOR = sys.argv[1:6]
LAUNCHER = sys.argv[6] if len(sys.argv) > 6 else ""


def fail(why):
    sys.exit(f"install_test: {why}")


def run(args, cwd=None, ok=(0,)):
    t = time.monotonic()
    p = subprocess.run(args, capture_output=True, text=True, cwd=cwd)
    print(f"[{time.monotonic() - t:6.2f} s] {' '.join(args)} -> {p.returncode}", flush=True)
    if p.returncode not in ok:
        fail(f"{' '.join(args)} exited {p.returncode} (want {ok}):\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
    return p


def files_under(root):
    return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
first, prefix = os.path.join(WORK, "prefix-installed"), os.path.join(WORK, "prefix-moved")

# 1. Install, then move the prefix.
run([CMAKE, "--install", BUILD, "--prefix", first, "--component", "vobench"])
os.rename(first, prefix)
vobench = os.path.join(prefix, "bin", "vobench")
for f in ["lib/libvobench.so", "lib/libvobench-gmsh.so", "lib/cmake/vobench/vobenchConfig.cmake",
          "lib/cmake/vobench/vobenchConfigVersion.cmake", "lib/cmake/vobench/VobenchPlugin.cmake",
          "include/vobench/harness/bench/plugin.h", "include/vobench/harness/bench/orderer.h",
          "include/vobench/harness/oracle/oracle.h", "include/vobench/harness/view/camera.h",
          "share/vobench/reports/report.py", "share/vobench/datasets/suites/quick.json",
          "share/vobench/shaders/havs/gl/shaders/draw.frag", "share/vobench/source-revision"]:
    if not os.path.isfile(os.path.join(prefix, f)):
        fail(f"{f} not installed")
if any(f.startswith("share/vobench/reports/out/") or "__pycache__" in f for f in files_under(prefix)):
    fail("report outputs or caches installed")

# Every installed header compiles from the prefix alone (nothing it includes is missing).
include = os.path.join(prefix, "include", "vobench")
headers = [os.path.relpath(os.path.join(d, f), include) for d, _, fs in os.walk(include) for f in fs]
all_h = os.path.join(WORK, "all_headers.cpp")
open(all_h, "w").write("".join(f'#include "{h}"\n' for h in sorted(headers)))
run(["c++", "-std=c++20", "-fsyntax-only", "-I", include, all_h])

# 2. The out-of-tree project against the moved prefix only.
proj = os.path.join(WORK, "orderer-build")
configure = [CMAKE, "-S", ORDERER, "-B", proj, "-G", GENERATOR, "-DCMAKE_BUILD_TYPE=Release",
             f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"]
if LAUNCHER:
    configure.append(f"-DCMAKE_CXX_COMPILER_LAUNCHER={LAUNCHER}")
run(configure)
cache = open(os.path.join(proj, "CMakeCache.txt")).read()
want_dir = os.path.join(prefix, "lib", "cmake", "vobench")
if f"vobench_DIR:PATH={want_dir}" not in cache:
    fail(f"find_package(vobench) did not find the moved prefix ({want_dir})")
run([CMAKE, "--build", proj])
plugin = os.path.join(proj, "liboot_centroid.so")
if not os.path.isfile(plugin):
    fail(f"{plugin} not built")

# 3. The plugin's orderer is listed and judged.
p = run([vobench, "--plugin", plugin, "list", "--json"])
listed = {o["name"]: o for o in json.loads(p.stdout)["orderers"]}
if "sxmpvo" not in listed or listed.get("oot-centroid", {}).get("plugin") != plugin \
        or "plugin" in listed["sxmpvo"]:
    fail(f"list --json with the plugin: {listed.get('oot-centroid')}, orderers {sorted(listed)}")
if "oot-centroid" in run([vobench, "list"]).stdout:
    fail("oot-centroid listed without --plugin")
scene = ["-d", "zoo", "--views", "3", "--size", "64x64", "--json"]
good = json.loads(run([vobench, "--plugin", plugin, "check", "-a", "oot-centroid", *scene]).stdout)
if good["algorithm"] != "oot-centroid" or good["failing_views"] != 0 or len(good["views"]) != 3:
    fail(f"check oot-centroid on zoo: {({k: v for k, v in good.items() if k != 'views'})}")
bad = json.loads(run([vobench, "--plugin", plugin, "check", "-a", "oot-centroid:reverse=true", *scene],
                     ok=(1,)).stdout)
if bad["failing_views"] != 3 or sum(v["violating_pixels"] for v in bad["views"]) == 0:
    fail(f"check oot-centroid:reverse=true on zoo passed: {bad['failing_views']} failing views")

# 4. Broken plugins: one line naming the path, exit 2.
junk = os.path.join(WORK, "junk.so")
open(junk, "w").write("not a library\n")
for path, reason in [(os.path.join(WORK, "missing.so"), "no such file"),
                     (junk, "cannot be loaded as a shared library"),
                     (os.path.join(prefix, "lib", "libvobench.so"), "has no entry point")]:
    p = run([vobench, "--plugin", path, "list"], ok=(2,))
    lines = p.stderr.strip().splitlines()
    if len(lines) != 1 or path not in lines[0] or reason not in lines[0]:
        fail(f"--plugin {path}: want one line with '{reason}', got {p.stderr!r}")

# A plugin built for another vobench version is refused before its entry point runs.
stale = os.path.join(WORK, "stale.cpp")
open(stale, "w").write('#include <cstdlib>\n#include "harness/bench/plugin.h"\n'
                       'extern "C" const char* vobench_plugin_version() { return "0.1.0"; }\n'
                       'extern "C" void vobench_register_orderers() { std::abort(); }\n')
stale_so = os.path.join(WORK, "libstale.so")
run(["c++", "-std=c++20", "-shared", "-fPIC", "-I", include, stale, "-L", os.path.join(prefix, "lib"),
     "-lvobench", "-o", stale_so])
p = run([vobench, "--plugin", stale_so, "list"], ok=(2,))
if "was built for vobench 0.1.0" not in p.stderr or len(p.stderr.strip().splitlines()) != 1:
    fail(f"--plugin of another version: {p.stderr!r}")

# 5. Files come from the moved prefix's share/vobench.
marker = os.path.join(prefix, "share", "vobench", "datasets", "suites", "install-marker.json")
json.dump({"reproduction": "install-marker", "summary": "only in the temporary prefix"}, open(marker, "w"))
if "install-marker" not in run([vobench, "list"]).stdout:
    fail("the installed vobench does not read share/vobench of its (moved) prefix")
if "install-marker" in run([os.path.join(BUILD, "harness", "cli", "vobench"), "list"]).stdout:
    fail("the build tree's vobench reads the installed prefix")
os.remove(marker)

# The .msh reader is a module beside libvobench.so, loaded on the first .msh file: found
# from the moved prefix too.
tet_msh = os.path.join(WORK, "tet.msh")
open(tet_msh, "w").write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
                         "4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n")
if "1 cell," not in run([vobench, "validate", tet_msh]).stdout:
    fail("the installed vobench did not read a .msh file")

# 6. A tiny suite with the plugin, its report; reproduce's default output outside the prefix.
before = files_under(prefix)
suite = {"name": "install", "datasets": [{"name": "gap", "set": {"nx": 3, "ny": 3, "nz": 4, "gaps": 1}},
                                          {"name": "zoo"}],
         "algorithms": ["oot-centroid", "centroid"], "views": 2, "sizes": ["48x48"],
         "repeats": 1, "warmup": 0, "oracle": True}
suite_path = os.path.join(WORK, "install-suite.json")
json.dump(suite, open(suite_path, "w"))
out = os.path.join(WORK, "run")
run([vobench, "--plugin", plugin, "run", suite_path, "-o", os.path.join(out, "results.jsonl")])
records = [r for r in map(json.loads, open(os.path.join(out, "results.jsonl"))) if r.get("type") not in ("context", "plan")]
if sorted({r["algorithm"] for r in records}) != ["centroid", "oot-centroid"] or len(records) != 8:
    fail(f"run: {len(records)} records of {sorted({r.get('algorithm') for r in records})}")
# The plugin sorts like the built-in centroid (eye distance, back to front): same counts.
counts = {}
for r in records:
    view = (r["dataset"], r["camera"]["eye"][0])
    counts.setdefault(view, {})[r["algorithm"]] = r["oracle"]["violating_pixels"]
if any(c["oot-centroid"] != c["centroid"] for c in counts.values()):
    fail(f"oot-centroid and centroid disagree: {counts}")
run([vobench, "--plugin", plugin, "report", out])
for f in ["report.md", "report.html"]:
    if not os.path.isfile(os.path.join(out, f)):
        fail(f"report: no {f} in {out} ({os.listdir(out)})")
if "oot-centroid" not in open(os.path.join(out, "report.md")).read():
    fail("report.md does not name oot-centroid")
elsewhere = os.path.join(WORK, "elsewhere")
os.makedirs(elsewhere)
run([vobench, "reproduce", "quick", "--tiny"], cwd=elsewhere)
if not os.path.isfile(os.path.join(elsewhere, "vobench-out", "quick-tiny", "quick.md")):
    fail("reproduce quick --tiny (installed) did not write ./vobench-out/quick-tiny/quick.md")
if files_under(prefix) != before:
    fail(f"the prefix changed: {sorted(set(files_under(prefix)) ^ set(before))[:10]}")
print("install_test: ok")
