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


# cook-table2's stand-ins, as the suite labels them (the label names the paper's data set).
COOK_TABLE2_BLUNTFIN = ("helix", {"cells": 600}, "helix 600 (tiny, for bluntfin)")
COOK_TABLE2_F117 = ("gap", {"gaps": 1, "nx": 3, "ny": 3, "nz": 10}, "gap 3x3x10, 1 gap (tiny, for f117)")


def cook_table2_records(datasets=(COOK_TABLE2_BLUNTFIN, COOK_TABLE2_F117)):
    """cook-table2's records of `datasets` ((name, spec, label)) at views 0, 4 and 9: BSP-XMPVO and
    XMPVO at 64x64, SXMPVO at 64x64 and 80x80, SXMPVO the fastest."""
    out = []
    for name, spec, label in datasets:
        for v in (0, 4, 9):
            for orderer, secs, sizes in (("bsp-xmpvo", 0.01, ("64x64",)), ("xmpvo", 0.02, ("64x64",)),
                                         ("sxmpvo", 0.001, ("64x64", "80x80"))):
                for size in sizes:
                    r = orderer_record("cook-table2", orderer, orderer, name, spec, v, secs, size=size, paper="xmpvo")
                    r["row"] = label
                    out.append(r)
    return out


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


def row_cells(t, first):
    """The rows of table t whose first cell is `first`, each as {column: cell}."""
    return [dict(zip(t.columns, r)) for r in t.rows if r[0] == first]


def close(a, b):
    return isinstance(a, float) and b is not None and abs(a - b) <= 1e-9 * max(abs(a), abs(b))


class Checks:
    """Failures gathered over a check script's cases, reported at the end (exit status 1)."""

    def __init__(self, script, work):
        self.script, self.work, self.failures = script, work, []

    def check(self, cond, why):
        if not cond:
            self.failures.append(why)

    def expect(self, module, name, paper, recs, words, expected, why, reason=None):
        """Builds table `name` from recs; the claim containing `words` must be judged `expected`
        ('holds', 'does not hold', 'not measured') and its criterion say `reason`. Returns the Doc."""
        doc = build(module, name, recs, paper, os.path.join(self.work, name))
        c = claim(doc, words)
        got = verdict(c)
        self.check(got == expected, f"{name}, {why}: '{words}' is {got}, expected {expected} ({c['criterion']})")
        if reason is not None:
            self.check(reason in c["criterion"], f"{name}, {why}: the criterion does not say '{reason}': "
                                                 f"{c['criterion']}")
        return doc

    def cells(self, doc, title, first):
        """The one row of the table titled with `title` whose first cell is `first`, as {column: cell}."""
        t = table(doc, title)
        rows = row_cells(t, first)
        self.check(len(rows) == 1, f"{len(rows)} rows '{first}' in '{t.title}': {[r[0] for r in t.rows]}")
        return rows[0] if len(rows) == 1 else {}

    def done(self, ok_text):
        if self.failures:
            sys.exit(f"{self.script}:\n  " + "\n  ".join(self.failures))
        print(f"{self.script}: {ok_text}")
