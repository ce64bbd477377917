"""Suite cases: mutations of one small valid suite given to `vobench run`. Every mistake
must be found before any dataset is generated (the first dataset is big enough that a
progress line would appear first) and named by the suite file and the entry.
"""
import json
import random

from fuzz_helpers import DELETE, mutate

READER = "suite"

VALID = {
    "name": "fuzz",
    "datasets": [{"name": "gap", "set": {"nx": 20, "ny": 20, "nz": 20}},
                 {"name": "sphere", "set": {"subdiv": 1}}],
    "algorithms": ["mpvo", "triangle-centroid"],
    "views": 3, "view_indices": [0, 2], "sizes": ["32x32"], "repeats": 1, "warmup": 0,
    "oracle": True, "supersample": 1, "zoom": 1.0, "image_views": [1],
}

# (case name, path into the suite, new value or DELETE, substring of the error line)
MUTATIONS = [
    ("views-zero", ["views"], 0, "suite.json: views"),
    ("views-negative", ["views"], -1, "suite.json: views"),
    ("views-2^32+2", ["views"], 2**32 + 2, "suite.json: views"),
    ("views-2^64", ["views"], 2**64, "suite.json: views"),
    ("views-huge", ["views"], 1000000, "suite.json: views"),
    ("views-fraction", ["views"], 1.5, "suite.json: views"),
    ("views-string", ["views"], "3", "suite.json: views"),
    ("views-bool", ["views"], True, "suite.json: views"),
    ("views-null", ["views"], None, "suite.json: views"),
    ("repeats-zero", ["repeats"], 0, "suite.json: repeats"),
    ("repeats-2^31", ["repeats"], 2**31, "suite.json: repeats"),
    ("warmup-negative", ["warmup"], -1, "suite.json: warmup"),
    ("warmup-2^32", ["warmup"], 2**32, "suite.json: warmup"),
    ("supersample-17", ["supersample"], 17, "suite.json: supersample"),
    ("zoom-zero", ["zoom"], 0, "suite.json: zoom"),
    ("zoom-string", ["zoom"], "x", "suite.json: zoom"),
    ("view-indices-past", ["view_indices"], [5], "suite.json: view_indices[0]"),
    ("view-indices-negative", ["view_indices"], [0, -1], "suite.json: view_indices[1]"),
    ("view-indices-2^32", ["view_indices"], [2**32], "suite.json: view_indices[0]"),
    ("view-indices-scalar", ["view_indices"], 0, "suite.json: view_indices"),
    ("image-views-past", ["image_views"], [99], "suite.json: image_views[0]"),
    ("sizes-zero", ["sizes"], ["0x5"], "suite.json: sizes[0]"),
    ("sizes-no-x", ["sizes"], ["32x32", "32"], "suite.json: sizes[1]"),
    ("sizes-number", ["sizes"], [32], "suite.json: sizes[0]"),
    ("sizes-empty", ["sizes"], [], "suite.json: sizes"),
    ("sizes-overflow", ["sizes"], ["4294967328x32"], "suite.json: sizes[0]"),
    ("ortho-string", ["ortho"], "yes", "suite.json: ortho"),
    ("name-number", ["name"], 5, "suite.json: name"),
    ("unknown-key", ["colour"], 1, "suite.json: colour"),
    ("datasets-empty", ["datasets"], [], "suite.json: datasets"),
    ("datasets-missing", ["datasets"], DELETE, "suite.json: datasets"),
    ("datasets-object", ["datasets"], {"name": "gap"}, "suite.json: datasets"),
    ("dataset-number", ["datasets", 1], 5, "suite.json: datasets[1]"),
    ("dataset-unknown", ["datasets", 1, "name"], "nope", "suite.json: datasets[1].name"),
    ("dataset-key-typo", ["datasets", 1, "nme"], "gap", "suite.json: datasets[1].nme"),
    ("dataset-name-and-input", ["datasets", 1, "input"], "x.vtu", "suite.json: datasets[1]"),
    ("dataset-input-missing", ["datasets", 1], {"input": "missing.vtu"}, "suite.json: datasets[1].input"),
    ("set-negative", ["datasets", 1, "set", "subdiv"], -1, "suite.json: datasets[1].set"),
    ("set-out-of-range", ["datasets", 1, "set", "subdiv"], 9, "suite.json: datasets[1].set"),
    ("set-2^32+2", ["datasets", 1, "set", "subdiv"], 2**32 + 2, "suite.json: datasets[1].set"),
    ("set-unknown", ["datasets", 1, "set", "colour"], 3, "suite.json: datasets[1].set"),
    ("set-array", ["datasets", 1, "set", "subdiv"], [1], "suite.json: datasets[1].set.subdiv"),
    ("set-object", ["datasets", 1, "set", "subdiv"], {"a": 1}, "suite.json: datasets[1].set.subdiv"),
    ("set-null", ["datasets", 1, "set", "subdiv"], None, "suite.json: datasets[1].set.subdiv"),
    ("set-not-object", ["datasets", 1, "set"], [1, 2], "suite.json: datasets[1].set"),
    ("set-impossible", ["datasets", 0, "set", "gaps"], 30, "suite.json: datasets[0].set"),
    ("algorithms-empty", ["algorithms"], [], "suite.json: algorithms"),
    ("algorithms-missing", ["algorithms"], DELETE, "suite.json: algorithms"),
    ("algorithm-unknown", ["algorithms", 1], "nope", "suite.json: algorithms[1]"),
    ("algorithm-bad-parameter", ["algorithms", 1], "havs:k=99", "suite.json: algorithms[1]"),
    ("algorithm-unknown-parameter", ["algorithms", 0], "mpvo:zzz=1", "suite.json: algorithms[0]"),
    ("algorithm-bad-choice", ["algorithms", 1], "centroid:key=bogus", "suite.json: algorithms[1]"),
    ("algorithm-number", ["algorithms", 1], 5, "suite.json: algorithms[1]"),
    ("algorithms-string", ["algorithms"], "mpvo", "suite.json: algorithms"),
]


def run_case(name, text, names):
    return {"name": name, "files": {"suite.json": text},
            "argv": ["run", "{dir}/suite.json", "-o", "{dir}/results.jsonl"], "names": names}


def cases(work):
    valid = json.dumps(VALID, indent=1).encode()
    out = [run_case(name, json.dumps(mutate(VALID, path, v)).encode(), names)
           for name, path, v, names in MUTATIONS]
    # Not a suite at all, or not JSON.
    for name, text in [("top-array", b"[1, 2]"), ("top-string", b'"suite"'), ("empty", b""),
                       ("nan-literal", valid.replace(b'"views": 3', b'"views": NaN')),
                       ("huge-exponent", valid.replace(b'"zoom": 1.0', b'"zoom": 1e400')),
                       ("bad-utf8", valid.replace(b'"fuzz"', b'"fu\xff\xfez"')),
                       ("nul-byte", valid.replace(b'"fuzz"', b'"fu\x00z"'))]:
        out.append(run_case(name, text, "suite.json"))
    # Deep nesting, in the file and inside a comment value.
    out.append(run_case("deep-array", b"[" * 200000, "suite.json"))
    out.append(run_case("deep-object", b'{"a":' * 100000, "suite.json"))
    deep = json.dumps(dict(VALID, comment="X")).encode().replace(b'"X"', b"[" * 5000 + b"]" * 5000)
    out.append(run_case("deep-comment", deep, "suite.json"))
    # Truncations of the valid suite at several offsets.
    for k in range(1, 8):
        cut = len(valid) * k // 8
        out.append(run_case(f"truncated-{k}of8", valid[:cut], "suite.json"))
    # Binary garbage with control bytes (seeded: the same cases every run).
    rng = random.Random(11)
    for k in range(4):
        garbage = bytes(rng.randrange(256) for _ in range(200 + 300 * k))
        out.append(run_case(f"garbage-{k}", garbage, "suite.json"))
    return out
