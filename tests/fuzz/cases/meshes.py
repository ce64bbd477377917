"""Fuzz cases for the gmsh .msh reader (gmsh SDK) and gzipped .inr: truncations and
mutations of small valid files."""
import gzip
import struct

from fuzz_helpers import check_cases

READER = "meshes"

NODES = [(1, 0, 0, 0), (2, 1, 0, 0), (3, 0, 1, 0), (4, 0, 0, 1)]


def msh22(nodes=NODES, elements=("1 4 2 0 1 1 2 3 4",), count=None):
    n = len(nodes) if count is None else count
    return ("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + f"{n}\n" +
            "".join(" ".join(str(v) for v in p) + "\n" for p in nodes) + "$EndNodes\n$Elements\n" +
            f"{len(elements)}\n" + "".join(e + "\n" for e in elements) + "$EndElements\n").encode()


def msh22_binary(nodes=NODES, element=(1, 2, 3, 4)):
    """One tetrahedron (type 4, two tags) in MSH 2.2 binary."""
    data = b"".join(struct.pack("<i3d", int(p[0]), *map(float, p[1:])) for p in nodes)
    elem = struct.pack("<3i", 4, 1, 2) + struct.pack("<7i", 1, 0, 1, *element)
    return (b"$MeshFormat\n2.2 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n$Nodes\n" +
            f"{len(nodes)}\n".encode() + data + b"\n$EndNodes\n$Elements\n1\n" + elem +
            b"\n$EndElements\n")


def inr_gz(data=bytes(range(1, 9)), dims=("2", "2", "2")):
    head = (f"#INRIMAGE-4#{{\nXDIM={dims[0]}\nYDIM={dims[1]}\nZDIM={dims[2]}\nVDIM=1\n"
            "TYPE=unsigned fixed\nPIXSIZE=8 bits\nCPU=decm\n")
    head += "\n" * ((252 - len(head)) % 256) + "##}\n"
    return gzip.compress(head.encode() + data)


def cases(work):
    good = msh22()
    files = {f"trunc-{int(f * 100)}": good[: int(len(good) * f)] for f in (0.1, 0.3, 0.5, 0.7, 0.9)}
    files.update({
        "huge-nodes": msh22(count=1000000000),
        "node-missing": msh22(elements=("1 4 2 0 1 1 2 3 9",)),
        # The node just past the last: gmsh 4.8's MSH 2 reader crashed on it.
        "node-past-last": msh22(elements=("1 4 2 0 1 1 2 3 5",)),
        "node-past-last-no-tags": msh22(elements=("1 4 0 1 2 3 5",)),
        "node-past-last-binary": msh22_binary(element=(1, 2, 3, 5)),
        "node-zero-binary": msh22_binary(element=(0, 2, 3, 4)),
        "node-sparse-gap": msh22(nodes=NODES[:3] + [(7, 0, 0, 1)], elements=("1 4 0 1 2 3 4",)),
        "inverted": msh22(nodes=NODES[:3] + [(4, 0, 0, -1)]),
        "nan": msh22(nodes=NODES[:3] + [(4, 0, 0, "nan")]),
        "second-order": msh22(elements=("1 11 2 0 1 1 2 3 4 1 2 3 4 1 2",)),
        "no-volume": msh22(elements=("1 2 2 0 1 1 2 3",)),
        "bad-version": good.replace(b"2.2 0 8", b"9.9 0 8"),
        "bad-format-line": good.replace(b"2.2 0 8", b"x"),
        "empty": b"",
        "garbage": bytes((i * 67 + 1) % 256 for i in range(1200)),
    })
    out = check_cases({"msh-" + k: v for k, v in files.items()}, "msh", "mpvo")
    goodz = inr_gz()
    gz = {f"trunc-{n}": goodz[:n] for n in (0, 2, 10, len(goodz) // 2, len(goodz) - 4)}
    gz.update({
        "short-data": inr_gz(data=bytes(3)),
        "huge-dims": inr_gz(dims=("2000", "2000", "2000")),
        "not-gzip": b"#INRIMAGE-4#{\n",
        "corrupt": goodz[:20] + bytes(b ^ 0x5A for b in goodz[20:40]) + goodz[40:],
    })
    out += check_cases({"inrgz-" + k: v for k, v in gz.items()}, "inr.gz", "btf")
    return out
