"""Reading results.jsonl: every record, in file order.

Each run writes one context line ({"type": "context", "run_id", "context"}) before its
records, and its records carry "run_id" (docs/pipeline.md "Records"). The loader leaves the
context lines out and gives each record its run's context as rec["context"], so table
scripts read rec["context"] as before (older files carry it in every record).

Each suite run also writes a plan line ({"type": "plan", "run_id", "suite", "reproduction",
"scale", "jobs": [...]}, docs/pipeline.md "Incomplete data"): the jobs it meant to measure.
The loader leaves those out of the records too and hands them to `plans` (vobtables.plan
tells which planned jobs have no record)."""
import json
import sys


def is_context(rec):
    return isinstance(rec, dict) and rec.get("type") == "context"


def is_plan(rec):
    return isinstance(rec, dict) and rec.get("type") == "plan"


def is_meta(rec):
    """A context or plan line: a line of a results file that is not a record."""
    return is_context(rec) or is_plan(rec)


def load_records(path, who="tables", contexts=None, plans=None):
    """Every record of one results file; `who` names the caller in messages. `contexts`
    (optional dict) receives run_id -> context of the file's context lines, `plans`
    (optional list) the file's plan lines in file order."""
    recs, ctx = [], {} if contexts is None else contexts
    with open(path) as f:
        for n, raw in enumerate(f, 1):
            line = raw.strip()
            if not line:
                continue
            try:
                rec = json.loads(line)
            except json.JSONDecodeError as e:
                # A torn last line (a writer killed mid-write); `vobench run` repairs it.
                if not raw.endswith("\n"):
                    print(f"{who}: note: {path}: line {n}: incomplete last line skipped", file=sys.stderr)
                    continue
                sys.exit(f"{who}: {path}: line {n}: not JSON ({e})")
            if is_context(rec):
                ctx[rec.get("run_id")] = rec.get("context") or {}
            elif is_plan(rec):
                if plans is not None:
                    plans.append(rec)
            else:
                recs.append(rec)
    for r in recs:
        if isinstance(r, dict) and "context" not in r and r.get("run_id") in ctx:
            r["context"] = ctx[r["run_id"]]
    return recs
