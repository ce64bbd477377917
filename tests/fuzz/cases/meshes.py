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


def msh41(binary=False, nodes=NODES, node_count=None, parametric=0, node_dim=3,
          blocks=((3, 1, 4, ((1, 1, 2, 3, 4),)),), element_count=None, physicals=0, order=1):
    """MSH 4.1, ASCII or binary: one volume entity, one node block, the element blocks
    (dim, entity, type, ((tag, node...), ...)); the counts in the headers may be given."""
    n_nodes = len(nodes) if node_count is None else node_count
    n_elems = sum(len(b[3]) for b in blocks) if element_count is None else element_count
    tags = [p[0] for p in nodes]
    coords = [v for p in nodes for v in list(p[1:]) + [0.0] * (node_dim * parametric)]
    if not binary:
        t = ("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n"
             f"1 0 0 0 1 1 1 {physicals} 0\n$EndEntities\n$Nodes\n"
             f"1 {n_nodes} 1 {max(tags)}\n{node_dim} 1 {parametric} {len(nodes)}\n" +
             "".join(f"{g}\n" for g in tags) +
             "".join(" ".join(str(v) for v in p[1:]) + " 0" * (node_dim * parametric) + "\n" for p in nodes) +
             f"$EndNodes\n$Elements\n{len(blocks)} {n_elems} 1 {n_elems}\n")
        for dim, entity, typ, elems in blocks:
            t += f"{dim} {entity} {typ} {len(elems)}\n" + "".join(" ".join(map(str, e)) + "\n" for e in elems)
        return (t + "$EndElements\n").encode()
    b = (b"$MeshFormat\n4.1 1 8\n" + struct.pack("<i", order) + b"\n$EndMeshFormat\n$Entities\n" +
         struct.pack("<4Q", 0, 0, 0, 1) + struct.pack("<i6dQQ", 1, 0, 0, 0, 1, 1, 1, physicals, 0) +
         b"\n$EndEntities\n$Nodes\n" + struct.pack("<4Q", 1, n_nodes, 1, max(tags)) +
         struct.pack("<3iQ", node_dim, 1, parametric, len(nodes)) + struct.pack(f"<{len(tags)}Q", *tags) +
         struct.pack(f"<{len(coords)}d", *map(float, coords)) + b"\n$EndNodes\n$Elements\n" +
         struct.pack("<4Q", len(blocks), n_elems, 1, n_elems))
    for dim, entity, typ, elems in blocks:
        b += struct.pack("<3iQ", dim, entity, typ, len(elems))
        b += b"".join(struct.pack(f"<{len(e)}Q", *e) for e in elems)
    return b + b"\n$EndElements\n"


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
    # MSH 4.1 (msh4_blocks.h), each case in ASCII and binary. Without the prescan gmsh 4.8
    # crashed on the "-over-header" cases (signal 6) and read "nodes-under-header"; the
    # others it refused itself.
    tet = (1, 1, 2, 3, 4)
    for binary, tag in ((False, "msh41-"), (True, "msh41-bin-")):
        files.update({tag + k: v for k, v in {
            "node-missing": msh41(binary, blocks=((3, 1, 4, ((1, 1, 2, 3, 9),)),)),
            "node-zero": msh41(binary, blocks=((3, 1, 4, ((1, 0, 2, 3, 4),)),)),
            "node-twice": msh41(binary, nodes=NODES[:3] + [(3, 0, 0, 1)]),
            "node-tag-zero": msh41(binary, nodes=[(0, 0, 0, 0)] + NODES[1:]),
            # The blocks hold more nodes (elements) than the header: gmsh wrote past its array.
            "nodes-over-header": msh41(binary, node_count=2),
            "elements-over-header": msh41(binary, blocks=((3, 1, 4, (tet, (2, 1, 2, 3, 4))),), element_count=1),
            "nodes-under-header": msh41(binary, node_count=5),
            "huge-node-block": msh41(binary, node_count=10**15),
            "huge-physicals": msh41(binary, physicals=10**9),
            "tet-in-surface": msh41(binary, node_dim=2, blocks=((2, 1, 4, (tet,)),)),
            "unknown-type": msh41(binary, blocks=((3, 1, 999, (tet,)),)),
            "parametric-flag": msh41(binary, parametric=7),
            "node-dim": msh41(binary, node_dim=5),
        }.items()})
    files["msh41-bin-byte-order"] = msh41(True, order=2)
    files["msh41-bin-trunc"] = msh41(True)[:-40]
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
