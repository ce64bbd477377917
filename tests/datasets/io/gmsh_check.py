"""A gmsh mesh is read as its volume cells and ordered exactly.

Runs gmsh on a .geo kept in the repo (tetrahedra, prisms and pyramids, with gmsh's vertex,
line and surface elements beside them), checks that the file really holds all of those (so
the test cannot pass on a mesh without them), that vobench reads it with one note line about
the skipped cells, and that sxmpvo, xmpvo and bsp-xmpvo check at zero violations.

usage: gmsh_check.py VOBENCH GEO WORKDIR      exit 77 (skipped) when gmsh is absent
"""
import collections
import pathlib
import shutil
import subprocess
import sys

vobench, geo, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
gmsh = shutil.which("gmsh")
if gmsh is None:
    print("SKIP: the gmsh program is not installed (Debian package gmsh)")
    sys.exit(77)
work.mkdir(parents=True, exist_ok=True)
mesh = work / (geo.stem + ".vtk")
subprocess.run([gmsh, "-3", str(geo), "-format", "vtk", "-o", str(mesh)], check=True,
               stdout=subprocess.DEVNULL)

lines = mesh.read_text().split("\n")
at = next(i for i, l in enumerate(lines) if l.startswith("CELL_TYPES"))
types = collections.Counter(int(t) for t in lines[at + 1: at + 1 + int(lines[at].split()[1])])
print("cell types in", mesh.name, dict(sorted(types.items())))
failures = []
for code, name in ((10, "tetra"), (13, "wedge"), (14, "pyramid")):
    if types[code] == 0:
        failures.append(f"gmsh wrote no {name} (type {code})")
lower = sum(n for code, n in types.items() if code in (1, 3, 5, 9))
if lower == 0:
    failures.append("gmsh wrote no lower-dimensional elements")

for algorithm in ("sxmpvo", "xmpvo", "bsp-xmpvo"):
    argv = [vobench, "check", "--algorithm", algorithm, "--input", str(mesh),
            "--views", "6", "--size", "128x128"]
    r = subprocess.run(argv, capture_output=True, text=True, timeout=600)
    print(" ".join(argv), "->", r.returncode)
    print(r.stdout.strip())
    notes = [l for l in r.stderr.splitlines() if l.startswith("vobench: note: ")]
    if r.returncode != 0:
        failures.append(f"{algorithm}: exit {r.returncode}: {r.stderr.strip()}")
    if len(notes) != 1 or f"skipped {lower} cells of lower dimension" not in notes[0]:
        failures.append(f"{algorithm}: expected one note about {lower} skipped cells, got {r.stderr!r}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
