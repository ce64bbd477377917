"""Fuzz cases for the .off reader: mutations of one valid closed surface (a tetrahedron)."""

from fuzz_helpers import check_cases

READER = "off"

PTS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
FACES = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def off(points=PTS, faces=FACES, header="OFF", counts=None):
    counts = f"{len(points)} {len(faces)} 0" if counts is None else counts
    return (f"{header}\n{counts}\n" + "\n".join(" ".join(str(c) for c in p) for p in points) + "\n" +
            "\n".join(f"{len(f)} " + " ".join(str(v) for v in f) for f in faces) + "\n").encode()


def cases(work):
    good = off()
    files = {f"trunc-{int(f * 100)}": good[: int(len(good) * f)] for f in (0.05, 0.25, 0.45, 0.65, 0.85, 0.95)}
    files.update({
        "bad-header": off(header="OFX"),
        "4off-header": off(header="4OFF"),
        "huge-vertices": off(counts="1000000000 4 0"),
        "huge-faces": off(counts="4 1000000000 0"),
        "negative-count": off(counts="-4 4 0"),
        "junk-count": off(counts="4z 4 0"),
        "nan": off(points=PTS[:1] + [("nan", 0, 0)] + PTS[2:]),
        "inf": off(points=PTS[:3] + [(0, 0, "-inf")]),
        "huge-coordinate": off(points=PTS[:3] + [(0, 0, "1e160")]),
        "tiny-extent": off(points=[tuple(f"{c}e-200" for c in p) for p in PTS]),
        "text-coordinate": off(points=PTS[:3] + [(0, 0, "one")]),
        "index-out-of-range": off(faces=FACES[:3] + [(0, 3, 9)]),
        "negative-index": off(faces=FACES[:3] + [(0, 3, -2)]),
        "two-vertex-face": off(faces=FACES[:3] + [(0, 3)]),
        "degenerate-face": off(faces=FACES[:3] + [(0, 3, 3)]),
        "no-faces": off(faces=[]),
        "empty": b"",
        "garbage": bytes((i * 67 + 1) % 256 for i in range(1200)),
        "control-bytes": off(header="OFF\x01\x02\x03"),
        "long-token": off(header="O" * 5000),
    })
    return check_cases(files, "off", "triangle-centroid")
