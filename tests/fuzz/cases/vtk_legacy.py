"""Fuzz cases for the legacy .vtk reader, ASCII and binary: mutations of one valid
unstructured grid (a cube hexahedron, point scalars, and a triangle and a vertex beside it,
as gmsh writes them) and of one structured-points volume."""
import struct

READER = "vtk-ascii"

CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
HEX = [8, 0, 1, 2, 3, 4, 5, 6, 7]
CELLS = [HEX, [3, 0, 1, 2], [1, 0]]
TYPES = [12, 5, 1]


def ascii_grid(points=CUBE, cells=CELLS, types=TYPES, npts=None, ncells=None, csize=None,
               ntypes=None, scalars=None, head="# vtk DataFile Version 3.0\ncube\nASCII\n",
               dataset="UNSTRUCTURED_GRID", points_kw="POINTS"):
    npts = len(points) if npts is None else npts
    ncells = len(cells) if ncells is None else ncells
    csize = sum(len(c) for c in cells) if csize is None else csize
    ntypes = len(types) if ntypes is None else ntypes
    scalars = [str(i) for i in range(len(points))] if scalars is None else scalars
    t = head + f"DATASET {dataset}\n{points_kw} {npts} double\n"
    t += "\n".join(" ".join(str(c) for c in p) for p in points) + "\n"
    t += f"CELLS {ncells} {csize}\n" + "\n".join(" ".join(str(i) for i in c) for c in cells) + "\n"
    t += f"CELL_TYPES {ntypes}\n" + "\n".join(str(x) for x in types) + "\n"
    t += f"POINT_DATA {len(points)}\nSCALARS s double 1\nLOOKUP_TABLE default\n" + " ".join(scalars) + "\n"
    return t.encode()


def binary_grid(points=CUBE, cells=CELLS, types=TYPES, npts=None, coord=None):
    npts = len(points) if npts is None else npts
    b = b"# vtk DataFile Version 3.0\ncube\nBINARY\nDATASET UNSTRUCTURED_GRID\n"
    b += f"POINTS {npts} double\n".encode()
    flat = [float(c) for p in points for c in p]
    if coord is not None:
        flat[coord[0]] = coord[1]
    b += struct.pack(f">{len(flat)}d", *flat) + b"\n"
    ids = [i for c in cells for i in c]
    b += f"CELLS {len(cells)} {len(ids)}\n".encode() + struct.pack(f">{len(ids)}i", *ids) + b"\n"
    b += f"CELL_TYPES {len(types)}\n".encode() + struct.pack(f">{len(types)}i", *types) + b"\n"
    b += f"POINT_DATA {len(points)}\nSCALARS s double 1\nLOOKUP_TABLE default\n".encode()
    b += struct.pack(f">{len(points)}d", *range(len(points))) + b"\n"
    return b


def binary_grid51(version="5.1"):
    """The binary grid in format 5.1 (OFFSETS and CONNECTIVITY), as VTK 9 writes it."""
    b = f"# vtk DataFile Version {version}\ncube\nBINARY\nDATASET UNSTRUCTURED_GRID\n".encode()
    flat = [float(c) for p in CUBE for c in p]
    b += f"POINTS {len(CUBE)} double\n".encode() + struct.pack(f">{len(flat)}d", *flat) + b"\n"
    conn = [i for c in CELLS for i in c[1:]]
    offsets = [0]
    for c in CELLS:
        offsets.append(offsets[-1] + len(c) - 1)
    b += f"CELLS {len(offsets)} {len(conn)}\nOFFSETS vtktypeint64\n".encode() + struct.pack(f">{len(offsets)}q", *offsets)
    b += b"\nCONNECTIVITY vtktypeint64\n" + struct.pack(f">{len(conn)}q", *conn) + b"\n"
    b += f"CELL_TYPES {len(TYPES)}\n".encode() + struct.pack(f">{len(TYPES)}i", *TYPES) + b"\n"
    return b


def volume(dims="2 2 2", spacing="1 1 1", origin="0 0 0", values="1 2 3 4 5 6 7 8", n=8):
    return (f"# vtk DataFile Version 3.0\nvol\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS {dims}\n"
            f"SPACING {spacing}\nORIGIN {origin}\nPOINT_DATA {n}\nSCALARS v float 1\n"
            f"LOOKUP_TABLE default\n{values}\n").encode()


def cases(work):
    good_a, good_b = ascii_grid(), binary_grid()
    out = []

    def add(name, data, reader="vtk-ascii", algorithm="mpvo"):
        out.append({"name": name, "reader": reader, "files": {f"{name}.vtk": data},
                    "argv": ["check", "--algorithm", algorithm, "--input", "{dir}/" + f"{name}.vtk",
                             "--views", "2", "--size", "32x32"],
                    "names": f"{name}.vtk"})

    for frac in (0.1, 0.25, 0.4, 0.55, 0.7, 0.85, 0.95):
        add(f"ascii-trunc-{int(frac * 100)}", good_a[: int(len(good_a) * frac)])
    for frac in (0.15, 0.3, 0.45, 0.6, 0.75, 0.9, 0.97):
        add(f"binary-trunc-{int(frac * 100)}", good_b[: int(len(good_b) * frac)], "vtk-binary")
    add("ascii-nan", ascii_grid(points=CUBE[:3] + [("nan", 1, 0)] + CUBE[4:]))
    add("ascii-text-coordinate", ascii_grid(points=CUBE[:3] + [("abc", 1, 0)] + CUBE[4:]))
    add("ascii-huge-coordinate", ascii_grid(points=CUBE[:7] + [(0, 1, "1e300")]))
    add("ascii-absurd-unused-point", ascii_grid(points=CUBE + [("-1e200", 0, 0)]))
    add("ascii-tiny-extent", ascii_grid(points=[tuple(f"{c}e-200" for c in p) for p in CUBE]))
    add("ascii-nan-scalar", ascii_grid(scalars=["0", "1", "nan", "3", "4", "5", "6", "7"]))
    add("ascii-huge-points", ascii_grid(npts=1000000000))
    add("ascii-huge-cells", ascii_grid(ncells=1000000000, csize=4000000000))
    add("ascii-junk-points", ascii_grid(npts="8abc"))
    add("ascii-negative-points", ascii_grid(npts=-8))
    add("ascii-huge-types", ascii_grid(ntypes=999999999))
    add("ascii-no-cells", ascii_grid(cells=[], types=[]))
    add("ascii-only-lower-dim", ascii_grid(cells=CELLS[1:], types=TYPES[1:]))
    add("ascii-polyhedron", ascii_grid(types=[42, 5, 1]))
    add("ascii-quadratic-hex", ascii_grid(types=[25, 5, 1]))
    add("ascii-voxel", ascii_grid(types=[11, 5, 1]))
    add("ascii-unknown-type", ascii_grid(types=[250, 5, 1]))
    add("ascii-index-out-of-range", ascii_grid(cells=[[8, 0, 1, 2, 3, 4, 5, 6, 70]] + CELLS[1:]))
    # A point count that does not fit the cell list: VTK walked it unchecked (heap corruption,
    # or in a binary file a silently different mesh).
    add("ascii-negative-point-count", ascii_grid(cells=[HEX, [-1, 0, 1, 2], [1, 0]]))
    add("ascii-point-count-past-list", ascii_grid(cells=[HEX, [9, 0, 1, 2], [1, 0]]))
    add("ascii-inverted", ascii_grid(cells=[[8, 4, 5, 6, 7, 0, 1, 2, 3]] + CELLS[1:]))
    add("ascii-nonconvex-twisted-hex", ascii_grid(points=CUBE[:6] + [(0.4, 1.3, 1.9)] + CUBE[7:]))
    add("ascii-short-scalars", ascii_grid(scalars=["0", "1"]))
    add("ascii-bad-magic", good_a.replace(b"# vtk DataFile", b"# xyz DataFile"))
    add("ascii-polydata", ascii_grid(dataset="POLYDATA"))
    add("ascii-control-keyword", ascii_grid(points_kw="POINTS\x01\x02\x7f"))
    add("ascii-long-keyword", ascii_grid(points_kw="P" * 4000))
    add("ascii-empty", b"")
    add("binary-garbage", bytes((i * 91 + 7) % 256 for i in range(4000)), "vtk-binary")
    add("binary-nan", binary_grid(coord=(4, float("nan"))), "vtk-binary")
    add("binary-huge-coordinate", binary_grid(coord=(20, 1e250)), "vtk-binary")
    add("binary-huge-points", binary_grid(npts=2000000000), "vtk-binary")
    add("binary-index-out-of-range", binary_grid(cells=[[8, 0, 1, 2, 3, 4, 5, 6, 1 << 30]] + CELLS[1:]),
        "vtk-binary")
    add("binary-negative-point-count", binary_grid(cells=[HEX, [-1, 0, 1, 2], [1, 0]]), "vtk-binary")
    add("binary-point-count-past-list", binary_grid(cells=[HEX, [40, 0, 1, 2], [1, 0]]), "vtk-binary")
    # A 5.1 body under a header without its version: VTK reads it as the older cell lists
    # (it crashed walking the OFFSETS bytes as point counts).
    add("binary-51-without-version", binary_grid51(version=""), "vtk-binary")
    add("binary-only-lower-dim", binary_grid(cells=CELLS[1:], types=TYPES[1:]), "vtk-binary")
    add("binary-quadratic-tetra", binary_grid(types=[24, 5, 1]), "vtk-binary")
    add("volume-huge-dims", volume(dims="100000 100000 100000"), algorithm="distance-sort")
    add("volume-nan-spacing", volume(spacing="nan 1 1"), algorithm="distance-sort")
    add("volume-text-origin", volume(origin="0 abc 0"), algorithm="distance-sort")
    add("volume-short-values", volume(values="1 2 3"), algorithm="distance-sort")
    add("volume-zero-spacing", volume(spacing="0 1 1"), algorithm="distance-sort")
    # A vector array is not read as its first component; a volume of no voxel above the
    # threshold (0) would pass every check on nothing.
    add("volume-vectors", volume().replace(b"SCALARS v float 1\nLOOKUP_TABLE default\n1 2 3 4 5 6 7 8",
                                           b"VECTORS v float\n" + b"1 2 3 " * 8), algorithm="distance-sort")
    add("volume-all-zero", volume(values="0 0 0 0 0 0 0 0"), algorithm="distance-sort")
    return out
