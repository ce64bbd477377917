"""The installed Python package: `cmake --install --component vobench` to a temporary
prefix, the prefix moved, then a clean python3 (only the moved dist-packages on its path)
imports vobench, orders and checks a generated mesh, with libvobench.so loaded from the
moved prefix.

Usage: check_installed.py CMAKE BUILD_DIR WORK_DIR PYTHON_INSTALL_DIR
Exit 77 (skipped) when the install has no libvobench.so at all (no install rule for it).
"""
import os
import shutil
import subprocess
import sys

cmake, build, work, pydir = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
first, moved = os.path.join(work, "prefix"), os.path.join(work, "moved")
subprocess.run([cmake, "--install", build, "--prefix", first, "--component", "vobench"], check=True,
               stdout=subprocess.DEVNULL)
# Skipped only when the library is installed nowhere; installed elsewhere than LIBDIR, the
# module's RPATH misses it and the import below fails, as it should.
if not any("libvobench.so" in files for _, _, files in os.walk(first)):
    print("skipped: the install has no libvobench.so")
    sys.exit(77)
os.rename(first, moved)
site = os.path.join(moved, pydir)
code = r"""
import vobench
s = vobench.generate("helix", cells=2000)
cam = vobench.views(s, 4, 64, 64)[1]
ids = vobench.order(s, cam, "sxmpvo")
r = vobench.check(s, cam, ids)
assert r["violating_pixels"] == 0 and r["covered_pixels"] > 0, r
assert vobench.check(s, cam, ids[::-1])["violating_pixels"] > 0
libs = {l.split()[-1] for l in open("/proc/self/maps") if l.rstrip().endswith("libvobench.so")}
print(vobench.__file__, sorted(libs))
import os
assert os.path.realpath(vobench.__file__).startswith(PREFIX), vobench.__file__
assert libs and all(os.path.realpath(l).startswith(PREFIX) for l in libs), libs
""".replace("PREFIX", repr(os.path.realpath(moved)))
env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": site}
p = subprocess.run([sys.executable, "-c", code], env=env, cwd=work, capture_output=True, text=True)
print(p.stdout, p.stderr)
sys.exit(p.returncode)
