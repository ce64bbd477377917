"""Results cases: bad results files (JSONL) given to `vobench report` and to `vobench run -o`
(which reads the records already present to skip them): lines that are not JSON, deep
nesting, lines that are not records, missing or mistyped fields, binary garbage. Each must be
refused with one line naming the file and the line.
"""
import json
import random

from fuzz_helpers import DELETE, mutate

READER = "results"

RECORD = {
    "key": "s|mpvo|gap|v0/1|8x8|s1", "suite": "s", "algorithm": "mpvo", "dataset": "gap(nx=1)",
    "n": 6, "b": 12, "w": 8, "h": 8, "pixels": 64, "view_index": 0, "views": 1,
    "phases": {"order": {"min": 0.001, "median": 0.001}}, "total": {"min": 0.001, "median": 0.001},
    "prepare": {"seconds": 0.01, "phases": {}, "derived": []},
    "bytes": {"orderer": 100, "scene": 200, "derived": 50},
    "cycles": {"count": 0, "primitives": []}, "counters": {},
    "claims": {"object_exact": False, "image_exact": False},
    "oracle": {"covered_pixels": 40, "violating_pixels": 0, "max_k": 0},
    "context": {"date": "2026-01-01"},
}

# (case name, field path, new value or DELETE, what the line must name besides the file)
FIELD_MUTATIONS = [
    ("no-algorithm", ["algorithm"], DELETE), ("no-dataset", ["dataset"], DELETE),
    ("no-w", ["w"], DELETE), ("no-n", ["n"], DELETE), ("no-total", ["total"], DELETE),
    ("no-total-median", ["total", "median"], DELETE), ("no-phases", ["phases"], DELETE),
    ("no-prepare-seconds", ["prepare", "seconds"], DELETE), ("no-cycles-count", ["cycles", "count"], DELETE),
    ("no-bytes-orderer", ["bytes", "orderer"], DELETE),
    ("algorithm-number", ["algorithm"], 5), ("w-fraction", ["w"], 1.5), ("h-string", ["h"], "8"),
    ("total-median-string", ["total", "median"], "fast"), ("total-array", ["total"], [1]),
    ("phase-number", ["phases", "order"], 3), ("oracle-string", ["oracle"], "ok"),
    ("covered-null", ["oracle", "covered_pixels"], None), ("images-incomplete", ["images"], {"order": "a.png"}),
    ("havs-violations-string", ["counters", "havs_violating_pixels"], "many"),
]


def report_case(name, second_line, names="results.jsonl: line 2"):
    """A file whose first line is a good record and whose second line is bad."""
    text = json.dumps(RECORD).encode() + b"\n" + second_line + b"\n"
    return {"name": name, "files": {"results.jsonl": text},
            "argv": ["report", "{dir}/results.jsonl", "-o", "{dir}/report"], "names": names}


SUITE = {"name": "s", "datasets": [{"name": "gap", "set": {"nx": 20, "ny": 20, "nz": 20}}],
         "algorithms": ["mpvo"], "views": 1, "sizes": ["8x8"], "repeats": 1, "warmup": 0}


def run_case(name, results):
    return {"name": name,
            "files": {"suite.json": json.dumps(SUITE).encode(), "results.jsonl": results},
            "argv": ["run", "{dir}/suite.json", "-o", "{dir}/results.jsonl"], "names": "results.jsonl"}


def cases(work):
    good = json.dumps(RECORD).encode()
    out = [report_case(name, json.dumps(mutate(RECORD, path, v)).encode())
           for name, path, v in FIELD_MUTATIONS]
    for name, line in [("number", b"5"), ("string", b'"record"'), ("array", b"[1, 2]"),
                       ("null", b"null"), ("true", b"true"), ("empty-object", b"{}")]:
        out.append(report_case(f"line-{name}", line))
    not_json = [("truncated", good[: len(good) // 2]), ("nan", good.replace(b'"n": 6', b'"n": NaN')),
                ("deep-array", b"[" * 100000), ("deep-object", b'{"a":' * 50000),
                ("deep-valid", b"[" * 3000 + b"]" * 3000), ("bad-utf8", good.replace(b'"mpvo"', b'"mp\xc3\x28o"')),
                ("control-bytes", b"\x01\x02\x1b[31m\x7f"), ("trailing-garbage", good + b" }")]
    for name, line in not_json:
        out.append(report_case(f"line-{name}", line))
    rng = random.Random(7)
    for k in range(3):
        garbage = bytes(rng.randrange(256) for _ in range(100 + 400 * k)).replace(b"\n", b"")
        out.append(report_case(f"garbage-{k}", garbage))
    out.append({"name": "empty-file", "files": {"results.jsonl": b""},
                "argv": ["report", "{dir}/results.jsonl", "-o", "{dir}/report"], "names": "results.jsonl"})
    out.append({"name": "blank-lines", "files": {"results.jsonl": b"\n  \n\n"},
                "argv": ["report", "{dir}/results.jsonl", "-o", "{dir}/report"], "names": "results.jsonl"})
    out.append({"name": "second-file-bad", "files": {"a.jsonl": good + b"\n", "results.jsonl": b"{"},
                "argv": ["report", "{dir}/a.jsonl", "{dir}/results.jsonl", "-o", "{dir}/report"],
                "names": "results.jsonl: line 1"})
    out.append({"name": "output-is-a-file", "files": {"results.jsonl": good + b"\n", "report": b"x"},
                "argv": ["report", "{dir}/results.jsonl", "-o", "{dir}/report"], "names": "--output"})
    # vobench run -o reads the records already present before it makes any dataset.
    for name, text in [("run-not-json", good + b"\n{oops\n"), ("run-deep", b"[" * 100000 + b"\n"),
                       ("run-garbage", bytes(rng.randrange(1, 256) for _ in range(300))),
                       ("run-truncated", good[:40] + b"\n")]:
        out.append(run_case(name, text))
    return out
