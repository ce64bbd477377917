"""Every format read through a library, checked end to end through the vobench program.

Files: gmsh writes the repo's .geo as .msh 2.2 and 4.1, ASCII and binary (plus a 2.2 ASCII
copy with a $NodeData field appended); make_format_files writes Exodus II (.exo, .e), a
3-piece .pvtu, STL (binary, ASCII), PLY, OBJ and .inr.gz from generated scenes with VTK's
writers. Each is checked with an exact orderer (sxmpvo for cells, stencil-layers for
triangles, distance-sort for voxels) at zero violations and the primitive count it was
written with; surfaces also through --tetrahedralize. Then one broken file per reader must
give exit 2 and exactly one line naming the file.

usage: formats_check.py VOBENCH MAKE_FORMAT_FILES GEO WORKDIR
"""
import json
import pathlib
import re
import shutil
import subprocess
import struct
import sys

vobench, maker, geo, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), pathlib.Path(sys.argv[4])
shutil.rmtree(work, ignore_errors=True)
(work / "bad").mkdir(parents=True)
failures = []


def run(argv):
    return subprocess.run([str(a) for a in argv], capture_output=True, text=True, timeout=600)


# gmsh .msh files, and the cell count gmsh's own VTK export of the same mesh holds.
gmsh = shutil.which("gmsh")
counts = {}
if gmsh is None:
    failures.append("the gmsh program is not installed (Debian package gmsh)")
else:
    for fmt in ("msh22", "msh41"):
        for binary in (False, True):
            out = work / f"{geo.stem}-{fmt}{'-bin' if binary else ''}.msh"
            run([gmsh, "-3", geo, "-format", fmt] + (["-bin"] if binary else []) + ["-o", out]).check_returncode()
    # Second-order elements are refused, not read as linear ones.
    run([gmsh, "-3", "-order", "2", geo, "-format", "msh41", "-o", work / "bad" / "order2.msh"]).check_returncode()
    vtk = work / f"{geo.stem}.vtk"
    run([gmsh, "-3", geo, "-format", "vtk", "-o", vtk]).check_returncode()
    lines = vtk.read_text().split("\n")
    at = next(i for i, l in enumerate(lines) if l.startswith("CELL_TYPES"))
    types = lines[at + 1: at + 1 + int(lines[at].split()[1])]
    volume = sum(1 for t in types if int(t) in (10, 12, 13, 14))
    for f in work.glob("*.msh"):
        counts[f.name] = volume
    # A node field in the 2.2 ASCII file: value = node tag, so the range is known.
    src = (work / f"{geo.stem}-msh22.msh").read_text()
    nodes = int(re.search(r"\$Nodes\n(\d+)\n", src).group(1))
    field = "$NodeData\n1\n\"tag\"\n1\n0.0\n3\n0\n1\n%d\n%s$EndNodeData\n" % (
        nodes, "".join(f"{i} {float(i)}\n" for i in range(1, nodes + 1)))
    (work / "field.msh").write_text(src + field)
    counts["field.msh"] = volume
    # MSH 4.1 coordinates written with a leading '+': gmsh's fscanf reads them, so must
    # vobench's block walk (datasets/gmsh/msh4_blocks.cpp).
    head, rest = (work / f"{geo.stem}-msh41.msh").read_text().split("$Nodes\n", 1)
    node_part, tail = rest.split("$EndNodes\n", 1)
    plus = "\n".join("+" + l if len(l.split()) == 3 and not l.startswith("-") else l for l in node_part.split("\n"))
    (work / "plus-msh41.msh").write_text(head + "$Nodes\n" + plus + "$EndNodes\n" + tail)
    counts["plus-msh41.msh"] = volume
    r = run([maker, "scalars", work / "field.msh"])
    print("field.msh scalars:", r.stdout.strip())
    if f"scalars {nodes} min 1 max {nodes}" not in r.stdout:
        failures.append(f"field.msh: expected {nodes} scalars 1..{nodes}, got {r.stdout!r} {r.stderr!r}")

run([maker, "write", work]).check_returncode()
counts.update(json.loads((work / "counts.json").read_text()))
for name, n in json.loads((work / "points.json").read_text()).items():
    r = run([maker, "scalars", work / name])
    print(f"{name}: {r.stdout.strip()} (the mesh had {n} points)")
    if f"points {n} scalars {n} " not in r.stdout:
        failures.append(f"{name}: expected {n} points with scalars, got {r.stdout!r} {r.stderr!r}")

# zoo.exo holds nodal variables temperature = 1 + x and pressure = 100 + y: the first is the
# default, the other is chosen by name (API and --input-variable), a wrong name is refused.
first = run([maker, "scalars", work / "zoo.exo"]).stdout.strip()
second = run([maker, "scalars", work / "zoo.exo", "pressure"]).stdout.strip()
print("zoo.exo scalars:", first, "| pressure:", second)
lo = [float(x) for x in re.findall(r"min (\S+) max (\S+)", first)[0]]
lo2 = [float(x) for x in re.findall(r"min (\S+) max (\S+)", second)[0]]
if "scalars 0" in first or not (lo[0] < 50 and lo2[0] > 50):
    failures.append(f"zoo.exo: nodal variables not read as asked: {first!r} {second!r}")
r = run([vobench, "check", "-a", "sxmpvo", "-i", work / "zoo.exo", "--input-variable", "pressure",
         "--views", "1", "--size", "32x32"])
if r.returncode != 0:
    failures.append(f"zoo.exo --input-variable pressure: exit {r.returncode}: {r.stderr.strip()}")
r = run([vobench, "check", "-a", "sxmpvo", "-i", work / "zoo.exo", "--input-variable", "nope",
         "--views", "1", "--size", "32x32"])
print("zoo.exo --input-variable nope:", r.returncode, r.stderr.strip())
if r.returncode != 2 or len(r.stderr.strip().splitlines()) != 1 or "'nope'" not in r.stderr:
    failures.append(f"zoo.exo --input-variable nope: expected exit 2 and one line, got {r.returncode} {r.stderr!r}")

ORDERER = {"cells": "sxmpvo", "triangles": "stencil-layers", "voxels": "distance-sort"}


def kind_of(name):
    if name.endswith((".stl", ".ply", ".obj")):
        return "triangles"
    return "voxels" if name.endswith(".inr.gz") else "cells"


def check(name, expected, kind, extra=()):
    argv = [vobench, "check", "-a", ORDERER[kind], "-i", work / name, "--views", "4", "--size", "96x96", *extra]
    r = run(argv)
    summary = r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ""
    print(f"{name} {' '.join(extra)}: exit {r.returncode}: {summary}")
    m = re.search(r": (\d+) of \d+ views with violations \(.*, (\d+) (\w+), \d+ threads?\)$", summary)
    if r.returncode != 0 or not m:
        failures.append(f"{name}: exit {r.returncode}: {r.stderr.strip()}")
        return
    if m.group(1) != "0" or m.group(3) != kind or (expected is not None and int(m.group(2)) != expected):
        failures.append(f"{name}: expected 0 failing views over {expected} {kind}, got {summary!r}")
    # violating pixels on every view line
    if any(" 0  fragments 0 " not in l for l in r.stdout.splitlines() if l.startswith("view")):
        failures.append(f"{name}: a view has violations: {r.stdout!r}")


for name, n in sorted(counts.items()):
    check(name, n, kind_of(name))
for name in ("sphere.obj", "spheres.stl", "spheres.ply", "sphere-ascii.stl"):
    check(name, None, "cells", ["--tetrahedralize"])

# One broken file per reader: exit 2 and one line naming it.
bad = work / "bad"
data = {n: (work / n).read_bytes() for n in counts if (work / n).exists()}
broken = {
    "cut.msh": data.get(f"{geo.stem}-msh41.msh", b"")[:2000],
    "cut-bin.msh": data.get(f"{geo.stem}-msh22-bin.msh", b"")[:3000],
    "huge.msh": b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1000000000 1 1000000000\n3 1 0 1000000000\n",
    "cut.exo": data["zoo.exo"][:40000],
    "text.e": b"not an exodus file\n",
    "cut.stl": data["spheres.stl"][:20000],
    "cut.ply": data["spheres.ply"][:9000],
    "index.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
    "cut.inr.gz": data["sparse.inr.gz"][:200],
    "plain.inr.gz": b"#INRIMAGE-4#{\n",
}
pvtu = (work / "helix.pvtu").read_text()
broken["missing.pvtu"] = pvtu.replace("helix_2.vtu", "nowhere_2.vtu").encode()
for name, content in broken.items():
    (bad / name).write_bytes(content)
for p in work.glob("helix_*.vtu"):
    shutil.copy(p, bad / p.name)
names = sorted(broken) + (["order2.msh"] if gmsh else [])
for name in names:
    kind = kind_of(name)
    r = run([vobench, "check", "-a", ORDERER[kind], "-i", bad / name, "--views", "1", "--size", "32x32"])
    err = r.stderr.strip().splitlines()
    print(f"bad/{name}: exit {r.returncode}: {err}")
    if r.returncode != 2 or len(err) != 1 or r.stdout.strip():
        failures.append(f"bad/{name}: expected exit 2 and one line, got {r.returncode} {err} {r.stdout!r}")
    elif ".vtu" not in err[0] and name not in err[0]:
        failures.append(f"bad/{name}: the line does not name the file: {err[0]}")



def fixed_data_end(b):
    """End of the last fixed-size (non-record) variable's data in a netCDF classic file
    (CDF-1 or CDF-2): a file cut before it lost data libnetcdf would read as fill values."""
    at, wide = 4, b[3] == 2

    def u32():
        nonlocal at
        at += 4
        return struct.unpack(">I", b[at - 4:at])[0]

    def name():
        nonlocal at
        n = u32()
        at += (n + 3) // 4 * 4

    def attributes():
        nonlocal at
        u32()
        for _ in range(u32()):
            name()
            typ = u32()
            values = u32()
            at += (values * {1: 1, 2: 1, 3: 2, 4: 4, 5: 4, 6: 8}[typ] + 3) // 4 * 4

    u32()  # numrecs
    u32()  # the dimension list's tag
    dims = u32()
    record_dim = None
    for i in range(dims):
        name()
        if u32() == 0:
            record_dim = i
    attributes()
    u32()
    end = 0
    for _ in range(u32()):
        name()
        ids = [u32() for _ in range(u32())]
        attributes()
        u32()
        vsize = u32()
        begin = (u32() << 32 | u32()) if wide else u32()
        if not ids or ids[0] != record_dim:
            end = max(end, begin + vsize)
    return end


# An Exodus file cut inside its fixed-size data (names, coordinates, connectivity) is cut,
# not read with zeros in place of what is missing.
zoo = data["zoo.exo"]
fixed_end = fixed_data_end(zoo)
for short in (1, 100):
    name = f"cut-{short}-before-records.exo"
    (bad / name).write_bytes(zoo[:fixed_end - short])
    r = run([vobench, "check", "-a", "sxmpvo", "-i", bad / name, "--views", "1", "--size", "32x32"])
    err = r.stderr.strip().splitlines()
    print(f"bad/{name} (fixed data ends at {fixed_end} of {len(zoo)} bytes): exit {r.returncode}: {err}")
    if r.returncode != 2 or len(err) != 1 or "file is cut" not in err[0]:
        failures.append(f"bad/{name}: expected exit 2 and one line saying the file is cut, got {r.returncode} {err}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
