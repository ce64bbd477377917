"""Fuzz cases for the TetGen .node/.ele reader: mutations of one valid pair (a cube split
into five tetrahedra, one point attribute)."""

READER = "tetgen"

CUBE = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
# Five positively oriented tetrahedra (VTK order) filling the cube.
TETS = [(0, 1, 3, 4), (1, 2, 3, 6), (1, 6, 4, 5), (3, 6, 7, 4), (1, 3, 4, 6)]


def node(points=CUBE, header=None, base=0, attr=True):
    header = f"{len(points)} 3 {1 if attr else 0} 0" if header is None else header
    rows = [f"{base + i} {x} {y} {z}" + (f" {i}" if attr else "") for i, (x, y, z) in enumerate(points)]
    return ("# cube\n" + header + "\n" + "\n".join(rows) + "\n").encode()


def ele(tets=TETS, header=None, base=0):
    header = f"{len(tets)} 4 0" if header is None else header
    return (header + "\n" + "\n".join(f"{base + i} " + " ".join(str(base + v) for v in t)
                                      for i, t in enumerate(tets)) + "\n").encode()


def cases(work):
    good_node, good_ele = node(), ele()
    out = []

    def add(name, node_bytes, ele_bytes, bad="node", input_ext="node"):
        files = {}
        if node_bytes is not None:
            files[f"{name}.node"] = node_bytes
        if ele_bytes is not None:
            files[f"{name}.ele"] = ele_bytes
        out.append({"name": name, "files": files,
                    "argv": ["check", "--algorithm", "mpvo", "--input", "{dir}/" + f"{name}.{input_ext}",
                             "--views", "2", "--size", "32x32"],
                    "names": f"{name}.{bad}"})

    for f in (0.2, 0.4, 0.6, 0.8, 0.95):
        add(f"node-trunc-{int(f * 100)}", good_node[: int(len(good_node) * f)], good_ele)
        add(f"ele-trunc-{int(f * 100)}", good_node, good_ele[: int(len(good_ele) * f)], "ele")
    add("node-huge-count", node(header="1000000000 3 1 0"), good_ele)
    add("ele-huge-count", good_node, ele(header="2000000000 4 0"), "ele")
    add("node-junk-count", node(header="8x 3 1 0"), good_ele)
    add("node-dim-2", node(header="8 2 1 0"), good_ele)
    add("node-negative-attrs", node(header="8 3 -1 0"), good_ele)
    add("ele-10-nodes", good_node, ele(header="5 10 0"), "ele")
    add("node-nan", node(points=CUBE[:2] + [("nan", 1, 0)] + CUBE[3:]), good_ele)
    add("node-text", node(points=CUBE[:2] + [("1,5", 1, 0)] + CUBE[3:]), good_ele)
    add("node-huge-coordinate", node(points=CUBE[:7] + [(0, 1, "-1e180")]), good_ele)
    add("node-tiny-extent", node(points=[tuple(f"{c}e-200" for c in p) for p in CUBE]), good_ele)
    add("node-unused-absurd-point", node(points=CUBE + [("1e299", 0, 0)]), good_ele)
    add("ele-index-out-of-range", good_node, ele(tets=TETS[:4] + [(1, 3, 4, 8)]), "ele")
    add("ele-out-of-sequence", good_node, good_ele.replace(b"\n2 ", b"\n7 "), "ele")
    add("ele-inverted", good_node, ele(tets=TETS[:4] + [(3, 1, 4, 6)]))
    add("ele-flat", good_node, ele(tets=[(0, 1, 2, 3)]))
    add("ele-zero-tets", good_node, ele(tets=[]))
    add("ele-missing", good_node, None, "ele")
    add("ele-extra-data", good_node, good_ele + b"5 0 1 2 3\n", "ele")
    add("node-garbage", bytes((i * 29 + 5) % 256 for i in range(1500)), good_ele)
    add("ele-garbage", good_node, bytes((i * 31 + 9) % 256 for i in range(1500)), "ele")
    add("node-empty", b"", good_ele)
    add("node-control-bytes", node(points=CUBE[:4] + [("\x01\x1b[2J", 0, 1)] + CUBE[5:]), good_ele)
    add("node-long-token", node(points=CUBE[:4] + [("1" * 5000, 0, 1)] + CUBE[5:]), good_ele)
    add("ele-as-input-bad", good_node, ele(header="5 4 zz"), "ele", input_ext="ele")
    return out
