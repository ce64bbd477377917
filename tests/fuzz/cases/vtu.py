"""Fuzz cases for the .vtu reader: mutations of one valid ASCII unstructured grid (a cube
hexahedron with point scalars). Every case must be refused with one line naming the file."""

from fuzz_helpers import check_cases

READER = "vtu"

CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def vtu(points=None, conn="0 1 2 3 4 5 6 7", offsets="8", types="12", npts=None, ncells=None,
        scalars=None, piece_extra="", inner="", header='<?xml version="1.0"?>\n'):
    points = CUBE if points is None else points
    ptxt = " ".join(" ".join(str(c) for c in p) for p in points)
    npts = len(points) if npts is None else npts
    ncells = len(offsets.split()) if ncells is None else ncells
    scalars = " ".join(str(i) for i in range(len(points))) if scalars is None else scalars
    return (header +
            '<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
            "<UnstructuredGrid>\n"
            f'<Piece NumberOfPoints="{npts}" NumberOfCells="{ncells}"{piece_extra}>\n'
            '<PointData Scalars="s">\n'
            f'<DataArray type="Float64" Name="s" format="ascii">{scalars}</DataArray>\n'
            "</PointData>\n"
            "<Points>\n"
            f'<DataArray type="Float64" NumberOfComponents="3" format="ascii">{ptxt}</DataArray>\n'
            "</Points>\n"
            "<Cells>\n"
            f'<DataArray type="Int64" Name="connectivity" format="ascii">{conn}</DataArray>\n'
            f'<DataArray type="Int64" Name="offsets" format="ascii">{offsets}</DataArray>\n'
            f'<DataArray type="UInt8" Name="types" format="ascii">{types}</DataArray>\n'
            "</Cells>\n" + inner +
            "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n").encode()


def moved(i, p):
    pts = list(CUBE)
    pts[i] = p
    return pts


def cases(work):
    good = vtu()
    files = {}
    # Truncations inside the content (the closing tags are always cut).
    for frac in (0.05, 0.2, 0.35, 0.5, 0.65, 0.8, 0.95):
        files[f"trunc-{int(frac * 100)}"] = good[: int(len(good) * frac)]
    files.update({
        "nan-coordinate": vtu(points=moved(3, ("nan", 1, 0))),
        "inf-coordinate": vtu(points=moved(5, (1, "inf", 1))),
        "text-coordinate": vtu(points=moved(2, (1, "abc", 0))),
        "huge-coordinate": vtu(points=moved(6, (1, 1, "1e300"))),
        "absurd-unused-point": vtu(points=CUBE + [("1e200", 0, 0)]),
        "tiny-extent": vtu(points=[tuple(f"{c}e-200" for c in p) for p in CUBE]),
        "flat-extent": vtu(points=[(x * 1e-15 + 1e3, y + 1e3, z) for x, y, z in CUBE]),
        "nan-scalar": vtu(scalars="0 1 2 nan 4 5 6 7"),
        "short-scalars": vtu(scalars="0 1 2"),
        "huge-points": vtu(npts=1000000000),
        "huge-cells": vtu(ncells=1000000000),
        "negative-points": vtu(npts=-1),
        "junk-points": vtu(npts="8abc"),
        "more-points-declared": vtu(npts=12),
        "zero-cells": vtu(conn="", offsets="", types="", ncells=0),
        "polyhedron-type": vtu(types="42"),
        "voxel-type": vtu(types="11"),
        "quadratic-tetra": vtu(points=CUBE + [(0.5, 0.5, 0.5), (0.2, 0.2, 0.2)],
                               conn="0 1 2 4 8 9 1 2 3 5", offsets="10", types="24"),
        "unknown-type": vtu(types="200"),
        "only-triangles": vtu(conn="0 1 2 4 5 6", offsets="3 6", types="5 5"),
        "only-lines-and-vertices": vtu(conn="0 1 2", offsets="2 3", types="3 1"),
        "index-out-of-range": vtu(conn="0 1 2 3 4 5 6 99"),
        "negative-index": vtu(conn="0 1 2 3 4 5 6 -1"),
        "repeated-index": vtu(conn="0 1 2 3 4 5 6 6"),
        "inverted-hex": vtu(conn="4 5 6 7 0 1 2 3"),
        "offset-past-end": vtu(offsets="80"),
        "tetra-with-8-points": vtu(types="10"),
        # Convex when its quads are split 0-2, not when split 1-3.
        "nonconvex-twisted-hex": vtu(points=moved(6, (0.4, 1.3, 1.9))),
        "deep-nesting": vtu(inner="<a>" * 100000 + "</a>" * 100000),
        "moderately-deep-nesting": vtu(inner="<a>" * 70 + "</a>" * 70),
        "control-bytes-type": vtu(types="\x01\x02\x1b[31m"),
        "long-token-type": vtu(types="7" * 5000),
        "bad-byte-order": good.replace(b"LittleEndian", b"Middle\x07Endian"),
        "wrong-root": good.replace(b'type="UnstructuredGrid"', b'type="PolyData"'),
        "not-xml": b"hello, this is not a VTK file\n",
        "empty": b"",
        "binary-garbage": bytes((i * 37 + 11) % 256 for i in range(3000)),
        "unclosed-tag": good.replace(b"</Points>", b"</Points"),
        "appended-missing": vtu(inner="").replace(b'format="ascii">0 1 2 3 4 5 6 7</DataArray>\n</PointData>',
                                                  b'format="appended" offset="0"/>\n</PointData>'),
    })
    return check_cases(files, "vtu", "mpvo")
