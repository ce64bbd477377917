"""Records for the generic report: every orderer record of the results files, each with the
folder of its results file (images are relative to it) and its run's context attached."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from vobtables import load_records  # noqa: E402


def load(paths, plans=None, keys=None):
    """(orderer records, probe count). Context lines (`"type": "context"`, one per run) are
    attached to their run's records as `context`, whether or not the loader did it already.
    `plans` (optional list) receives the files' plan lines (vobtables.plan), `keys`
    (optional set) the key of every record, probes' too."""
    recs, probes = [], 0
    for path in paths:
        base = os.path.dirname(os.path.abspath(path))
        contexts = {}
        rows = load_records(path, who="report", plans=plans)
        for r in rows:
            if r.get("type") == "context":
                contexts[r.get("run_id")] = r.get("context") or {}
        for r in rows:
            if r.get("type") == "context":
                continue
            if keys is not None:
                keys.add(r.get("key"))
            if "probe" in r:  # probes feed the paper tables, not this report
                probes += 1
                continue
            if not r.get("context") and r.get("run_id") in contexts:
                r["context"] = contexts[r["run_id"]]
            r["_base"] = base
            recs.append(r)
    return recs, probes


def image_path(r, name):
    """Absolute path of a record's image `name`, or None. Paths are relative to the folder
    holding results.jsonl; older records hold them absolute or relative to where `run` was
    started (accepted when the file is there, else looked up by name in that folder's
    images/, so a moved folder still works)."""
    p = (r.get("images") or {}).get(name)
    if not p:
        return None
    here = p if os.path.isabs(p) else os.path.normpath(os.path.join(r["_base"], p))
    if os.path.exists(here):
        return here
    # Older records: absolute, or relative to the folder `run` was started in.
    moved = os.path.join(r["_base"], "images", os.path.basename(p))
    return moved if os.path.exists(moved) else here


def revision(r):
    """What tells two measurements' code apart: the git revision of the build."""
    return (r.get("context") or {}).get("git_sha") or "?"


def run_of(r):
    """A run: its run id, or (older records, context in every record) its start date."""
    return r.get("run_id") or (r.get("context") or {}).get("date") or "?"
