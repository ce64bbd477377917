"""Fuzz cases for the surface readers through VTK (.stl ASCII and binary, .ply ASCII and
binary, .obj): truncations and mutations of one valid closed tetrahedron surface."""
import struct

from fuzz_helpers import check_cases

READER = "surfaces"

PTS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def stl_ascii(pts=PTS, faces=FACES):
    s = "solid t\n"
    for f in faces:
        s += " facet normal 0 0 0\n  outer loop\n"
        s += "".join(f"   vertex {' '.join(str(c) for c in pts[i])}\n" for i in f)
        s += "  endloop\n endfacet\n"
    return (s + "endsolid t\n").encode()


def stl_binary(faces=FACES, count=None):
    body = b"".join(struct.pack("<12fH", 0, 0, 0, *[c for i in f for c in PTS[i]], 0) for f in faces)
    return b"\0" * 80 + struct.pack("<I", len(faces) if count is None else count) + body


def ply(fmt="ascii", nv=4, nf=4, faces=FACES, pts=PTS, extra="", x="x", index="list uchar int vertex_indices",
        faces_first=False):
    vertex = f"element vertex {nv}\nproperty float {x}\nproperty float y\nproperty float z\n"
    face = f"element face {nf}\nproperty {index}\n"
    head = f"ply\nformat {fmt} 1.0\n" + (face + vertex if faces_first else vertex + face) + f"{extra}end_header\n"
    if fmt == "ascii":
        vbody = "".join(" ".join(str(c) for c in p) + "\n" for p in pts)
        fbody = "".join(f"{len(f)} " + " ".join(str(i) for i in f) + "\n" for f in faces)
        return (head + (fbody + vbody if faces_first else vbody + fbody)).encode()
    body = b"".join(struct.pack("<3f", *p) for p in pts)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in faces)
    return head.encode() + body


def obj(pts=PTS, faces=FACES):
    return ("".join(f"v {' '.join(str(c) for c in p)}\n" for p in pts) +
            "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)).encode()


def cases(work):
    out = []
    good = stl_binary()
    stl = {f"bin-trunc-{n}": good[:n] for n in (0, 40, 83, 84, 100, len(good) - 1)}
    stl.update({
        "bin-count-high": stl_binary(count=1000000000),
        "bin-count-low": stl_binary(count=1),
        "ascii-trunc": stl_ascii()[:150],
        "ascii-nan": stl_ascii(pts=[(0, 0, 0), (1, 0, 0), (0, "nan", 0), (0, 0, 1)]),
        "ascii-degenerate": stl_ascii(faces=[(0, 1, 1)] + FACES[1:]),
        "ascii-text-number": stl_ascii(pts=[(0, 0, 0), (1, 0, 0), (0, "one", 0), (0, 0, 1)]),
        "garbage": bytes((i * 67 + 1) % 256 for i in range(1200)),
    })
    out += check_cases({"stl-" + k: v for k, v in stl.items()}, "stl", "triangle-centroid")
    goodp = ply(fmt="binary_little_endian")
    plys = {f"bin-trunc-{int(f * 100)}": goodp[: int(len(goodp) * f)] for f in (0.3, 0.6, 0.8, 0.95, 0.99)}
    plys.update({
        "ascii-trunc": ply()[:-10],
        "ascii-short-vertex": ply(pts=PTS[:3]),
        "huge-count": ply(nv=1000000000),
        "negative-count": ply(nv=-4),
        "index-out-of-range": ply(faces=FACES[:3] + [(0, 3, 9)]),
        "negative-index": ply(faces=FACES[:3] + [(0, 3, -1)]),
        # Far out of range: VTK's reader read past its points (SIGSEGV) before the prescan.
        "index-far-out": ply(faces=FACES[:3] + [(0, 3, 90000000)]),
        "bin-index-far-out": ply(fmt="binary_little_endian", faces=FACES[:3] + [(0, 3, 90000000)]),
        "bin-negative-index": ply(fmt="binary_little_endian", faces=FACES[:3] + [(0, -70000000, 2)]),
        "nan": ply(pts=PTS[:3] + [(0, 0, "nan")]),
        "text-number": ply(pts=PTS[:3] + [(0, 0, "one")]),
        "bad-format": ply(fmt="binary_middle_endian"),
        "bad-type": ply(extra="property quad w\n"),
        "no-end-header": b"ply\nformat ascii 1.0\nelement vertex 4\n",
        "not-ply": b"plx\n",
        # What VTK's reader takes from the header unchecked: it crashed on each of these.
        "no-x": ply(x="w"),
        "no-index-list": ply(index="list uchar int verts"),
        "scalar-index": ply(index="int vertex_indices", faces=[(0,), (1,), (2,), (3,)]),
        "faces-first": ply(faces_first=True),
        "vertex-index-far-out": ply(index="list uchar int vertex_index", faces=FACES[:3] + [(0, 3, 90000000)]),
        # VTK keeps a polygon's count in a byte: it read these 300 points as 44.
        "polygon-300": ply(index="list ushort int vertex_indices", faces=FACES[:3] + [tuple(i % 4 for i in range(300))]),
        "empty": b"",
    })
    out += check_cases({"ply-" + k: v for k, v in plys.items()}, "ply", "triangle-centroid")
    objs = {
        "index-out-of-range": obj(faces=FACES[:3] + [(0, 3, 9)]),
        "degenerate": obj(faces=FACES[:3] + [(0, 3, 3)]),
        "nan": obj(pts=PTS[:3] + [(0, 0, "nan")]),
        "no-faces": obj(faces=[]),
        "empty": b"",
        "garbage": bytes((i * 67 + 1) % 256 for i in range(1200)),
        # Read by VTK's OBJ reader as another surface (or crashing it) before the prescan.
        "two-coordinates": obj(pts=PTS[:3] + [(0, 0)]),
        "overflow": obj(pts=PTS[:3] + [(0, 0, "1e400")]),
        "junk-index": obj().replace(b"f 1 4 3", b"f 1 4 3x"),
        "zero-index": obj(faces=FACES[:3] + [(0, 3, -1)]),
        "relative-before-first": obj().replace(b"f 1 4 3", b"f 1 4 -9"),
        "huge-index": obj().replace(b"f 1 4 3", b"f 1 4 99999999999"),
    }
    # VTK fails on these by itself; the prescan names them (each line: line number and reason).
    objs.update({"long-line": obj() + b"f 1 2 " + b" " * 300000 + b"3\n", "comment-in-face": obj() + b"f 1 2 3 # c\n"})
    out += check_cases({"obj-" + k: v for k, v in objs.items()}, "obj", "triangle-centroid")
    # The prescan names a line: these read silently wrong or crashed without it.
    for c in check_cases({"obj-vt-segv": (b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                          b"f 1/1 3/2 2/3\nf 1/1 2/2 4/3\nf 1/1 4/2 3/3\nf 2/1 3/2 4/3\n")},
                         "obj", "triangle-centroid"):
        c["names"] = "obj-vt-segv.obj: line 5: texture coordinate index 3 is out of range"
        out.append(c)
    # --tetrahedralize on an open surface (one face missing)
    for c in check_cases({"open-tet": stl_ascii(faces=FACES[:3])}, "stl", "mpvo"):
        c["argv"].append("--tetrahedralize")
        out.append(c)
    # ... and on closed surfaces around no volume: TetGen aborted on each (signal 6 or 11).
    flat = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.2, 0.2, 0)]
    for c in check_cases({"flat-tet": obj(pts=flat), "doubled-tet": obj(faces=[(0, 1, 3), (0, 3, 1)])}, "obj", "mpvo"):
        c["argv"].append("--tetrahedralize")
        c["names"] += ": surface: all its points lie in one plane" if c["name"] == "flat-tet" else ": triangles 0 and 1: have the same"
        out.append(c)
    return out
