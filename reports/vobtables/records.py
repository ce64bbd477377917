"""Reading results.jsonl: every record, in file order."""
import json
import sys


def load_records(path, who="tables"):
    """Every record of one results file; `who` names the caller in messages."""
    recs = []
    with open(path) as f:
        for n, raw in enumerate(f, 1):
            line = raw.strip()
            if not line:
                continue
            try:
                recs.append(json.loads(line))
            except json.JSONDecodeError as e:
                # A torn last line (a writer killed mid-write); `vobench run` repairs it.
                if not raw.endswith("\n"):
                    print(f"{who}: note: {path}: line {n}: incomplete last line skipped", file=sys.stderr)
                    continue
                sys.exit(f"{who}: {path}: line {n}: not JSON ({e})")
    return recs
