"""Reading results.jsonl: every record, in file order.

Each run writes one context line ({"type": "context", "run_id", "context"}) before its
records, and its records carry "run_id" (docs/pipeline.md "Records"). The loader leaves the
context lines out and gives each record its run's context as rec["context"], so table
scripts read rec["context"] as before (older files carry it in every record)."""
import json
import sys


def is_context(rec):
    return isinstance(rec, dict) and rec.get("type") == "context"


def load_records(path, who="tables", contexts=None):
    """Every record of one results file; `who` names the caller in messages. `contexts`
    (optional dict) receives run_id -> context of the file's context lines."""
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
            else:
                recs.append(rec)
    for r in recs:
        if isinstance(r, dict) and "context" not in r and r.get("run_id") in ctx:
            r["context"] = ctx[r["run_id"]]
    return recs
