#!/usr/bin/python3
"""Rebuilds every reproduction's tables, claims and figures from DIR/results.jsonl alone
(docs/pipeline.md). `vobench reproduce` and `vobench report DIR` run this; it measures
nothing.

usage: build_tables.py DIR [--only NAME]

Without --only, a folder holding records of several reproductions also gets claims-summary.md,
.json and .html: every claim of those tables with its verdict and the counts
(`vobench reproduce all`).
"""
import argparse
import importlib.util
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from vobtables import Doc, load_records  # noqa: E402
from vobtables.summary import write_summary  # noqa: E402
from vobtables.conditions import conditions  # noqa: E402
from vobtables.unmeasured import unmeasured  # noqa: E402
import signal  # noqa: E402

# Ctrl-C during `vobench reproduce` stops the script as it stops vobench, without a traceback.
signal.signal(signal.SIGINT, signal.SIG_DFL)


def load_paper(paper):
    base = os.path.join(HERE, "papers", paper)
    spec = importlib.util.spec_from_file_location(f"paper_{paper.replace('-', '_')}", base + ".py")
    if spec is None or not os.path.exists(base + ".py"):
        sys.exit(f"tables: no table script reports/papers/{paper}.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    numbers = {}
    if os.path.exists(base + ".json"):
        with open(base + ".json") as f:
            numbers = json.load(f)
    return mod, numbers


def paper_of(reproduction):
    """The paper whose script has a table for `reproduction` (a plan line does not name it), or
    None: a reproduction without a paper (the generic report's)."""
    for f in sorted(os.listdir(os.path.join(HERE, "papers"))):
        if f.endswith(".py") and not f.startswith("_"):
            mod, _ = load_paper(f[:-3])
            if reproduction in getattr(mod, "TABLES", {}):
                return f[:-3]
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--only", help="one reproduction")
    args = ap.parse_args()
    path = os.path.join(args.dir, "results.jsonl")
    if not os.path.exists(path):
        sys.exit(f"tables: {path}: no results file")
    plans = []
    recs = load_records(path, plans=plans)
    by_repro = {}
    for r in recs:
        name = r.get("reproduction")
        if name and r.get("paper"):
            by_repro.setdefault((name, r["paper"]), []).append(r)
    built = []
    for (name, paper), rs in sorted(by_repro.items()):
        if args.only and name != args.only:
            continue
        mod, numbers = load_paper(paper)
        build = getattr(mod, "TABLES", {}).get(name)
        if build is None:
            sys.exit(f"tables: reports/papers/{paper}.py has no table for '{name}'")
        doc = Doc(name, name, context=rs[0].get("context"), out_dir=args.dir)
        doc.conditions = conditions(rs, numbers)
        doc.row_of = getattr(mod, "ROW_OF", None)  # how the script labels a data set's row
        doc.set_plan(rs, plans, name)  # planned jobs without a record (vobtables.plan)
        build(rs, numbers, doc)
        print(f"tables: wrote {doc.write()}", file=sys.stderr)
        built.append((paper, doc))
    # A reproduction planned but without a record (stopped before its first): a page saying so.
    for name in sorted({p.get("reproduction") for p in plans if p.get("reproduction")} - {n for n, _ in by_repro}):
        if args.only and name != args.only:
            continue
        paper = paper_of(name)
        if paper is None:
            print(f"tables: note: {name}: planned, no record, no paper script (the generic report needs records)",
                  file=sys.stderr)
            continue
        doc = Doc(name, name, out_dir=args.dir)
        doc.row_of = getattr(load_paper(paper)[0], "ROW_OF", None)
        doc.set_plan([], plans, name)
        unmeasured(doc, paper)
        print(f"tables: wrote {doc.write()} (no record: every planned job missing)", file=sys.stderr)
        built.append((paper, doc))
    if not args.only and len(built) > 1:
        scale = next((r.get("scale") for rs in by_repro.values() for r in rs if r.get("scale")), None) or \
            next((p.get("scale") for p in plans if p.get("scale")), "default")
        print(f"tables: wrote {write_summary(built, args.dir, scale)}", file=sys.stderr)
    if args.only and not built:
        sys.exit(f"tables: {path}: no records of reproduction '{args.only}' with a paper")


if __name__ == "__main__":
    main()
