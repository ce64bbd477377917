"""Hand-made records for the report checks (tests/reports/check_*.py): just the fields the
table scripts and the generic report read, so a check can build a small case, delete some
records and look at the verdicts. Nothing here runs vobench."""
import json
import os
import sys


def use_reports(reports):
    """Makes reports/ (vobtables, papers, generic) importable."""
    for p in (reports, os.path.join(reports, "papers")):
        if p not in sys.path:
            sys.path.insert(0, p)


def paper_numbers(reports, paper):
    with open(os.path.join(reports, "papers", paper + ".json")) as f:
        return json.load(f)


def orderer_record(reproduction, suite, orderer, dataset, spec, view, seconds, n=1000, b=100, w=120, h=100,
                   size="128x128", threads=1, fit=True, algorithm=None, parameters=None, phases=None, host="vm",
                   run_id="run-a", paper="cook", extra_key=""):
    """One orderer record as `vobench reproduce NAME --tiny` writes it (the fields reports read)."""
    row = dataset + "(" + ",".join(f"{k}={v}" for k, v in sorted(spec.items())) + ")"
    algorithm = algorithm or orderer
    key = "|".join([f"{reproduction}/{suite}", algorithm, row, f"v{view}/14", size, "r1w0", "nooracle", "ss1",
                    f"t{threads}"] + (["fit"] if fit else []) + ([extra_key] if extra_key else []) + ["tiny"])
    return {"key": key, "reproduction": reproduction, "paper": paper, "scale": "tiny", "suite": f"{reproduction}/{suite}",
            "algorithm": algorithm, "orderer": orderer, "parameters": parameters or {}, "dataset": dataset,
            "dataset_spec": {"name": dataset, "set": dict(spec)}, "row": row, "n": n, "b": b, "w": w, "h": h,
            "view_index": view, "views": 14, "threads": threads, "repeats": 1, "warmup": 0,
            "phases": {k: {"median": v, "min": v, "samples": [v]} for k, v in (phases or {}).items()},
            "total": {"median": seconds, "min": seconds, "samples": [seconds]},
            "prepare": {"seconds": 0.001, "phases": {}, "derived": {}},
            "bytes": {"orderer": 1000, "scene": 2000, "derived": 500}, "cycles": {"count": 0, "primitives": 0},
            "counters": {}, "host": host, "run_id": run_id}


def build(module, name, records, paper, out_dir):
    """Runs one table script's builder on `records` into out_dir; returns the Doc."""
    from vobtables.doc import Doc
    os.makedirs(out_dir, exist_ok=True)
    doc = Doc(name, name, out_dir=out_dir)
    module.TABLES[name](records, paper, doc)
    return doc


def claim(doc, words):
    """The one claim whose text contains `words`."""
    found = [c for c in doc.claims if words in c["claim"]]
    if len(found) != 1:
        raise AssertionError(f"{len(found)} claims contain {words!r}: {[c['claim'] for c in doc.claims]}")
    return found[0]


def table(doc, words):
    found = [t for t in doc.tables if words in t.title]
    if len(found) != 1:
        raise AssertionError(f"{len(found)} tables titled with {words!r}: {[t.title for t in doc.tables]}")
    return found[0]


def verdict(c):
    return "not measured" if c["holds"] is None else ("holds" if c["holds"] else "does not hold")
