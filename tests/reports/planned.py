"""Results files with plan lines for the report checks: hand-made records (handmade.py), the plan
line `vobench reproduce` writes before them, and one job's records taken out as an interrupted
run leaves them; the page is rebuilt by build_tables.py, as `vobench report DIR` does."""
import json
import os
import shutil
import subprocess


def plan_lines(recs, run_id="plan-run"):
    """One plan line per suite of `recs`, listing every record's job (file order)."""
    by_suite = {}
    for r in recs:
        j = {k: r[k] for k in ("key", "dataset", "dataset_spec", "row") if k in r}
        if "probe" in r:
            j["probe"] = r["probe"]
        else:
            j.update(algorithm=r["algorithm"], w=r["w"], h=r["h"], view_index=r["view_index"])
        j["threads"] = r.get("threads", 1)
        by_suite.setdefault(r["suite"], []).append(j)
    return [{"key": f"plan|{run_id}|{s}", "type": "plan", "run_id": run_id, "schema_version": 2, "suite": s,
             "reproduction": s.split("/")[0], "scale": "tiny", "jobs": jobs} for s, jobs in by_suite.items()]


def page(reports, work, name, lines):
    """Writes `lines` as work/results.jsonl and rebuilds NAME's page from it: (exit status, stderr,
    the page's JSON or None)."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(os.path.join(work, "results.jsonl"), "w") as f:
        for line in lines:
            f.write(json.dumps(line) + "\n")
    p = subprocess.run(["/usr/bin/python3", os.path.join(reports, "build_tables.py"), work, "--only", name],
                       capture_output=True, text=True)
    path = os.path.join(work, name + ".json")
    if p.returncode or not os.path.exists(path):
        return p.returncode, p.stderr, None
    with open(path) as f:
        return p.returncode, p.stderr, json.load(f)


def verdict(c):
    return "not measured" if c["holds"] is None else ("holds" if c["holds"] else "does not hold")


def verdicts(claims, words):
    """{words: the verdict of the one claim containing them (None: not one such claim)}."""
    out = {}
    for w in words:
        hit = [c for c in claims if w in c["claim"]]
        out[w] = verdict(hit[0]) if len(hit) == 1 else None
    return out


_complete = {}


def check_drop(C, reports, work, name, complete, drop, gone, kept, why):
    """The complete records judge every claim of `gone` and `kept`; with the records `drop` picks
    taken out (their plan kept), each claim of `gone` reads "not measured" and each of `kept`
    keeps its verdict. `gone` and `kept`: words of claims (see verdicts)."""
    plans = plan_lines(complete)
    # The complete page once per set of records (a check drops several jobs from one set).
    cache = (name, json.dumps(complete, sort_keys=True))
    if cache not in _complete:
        _complete[cache] = page(reports, os.path.join(work, "complete"), name, plans + complete)
    rc, err, full = _complete[cache]
    C.check(full is not None, f"{name}: complete records: build_tables.py exited {rc}: {err[-1500:]}")
    rest = [r for r in complete if not drop(r)]
    C.check(0 < len(complete) - len(rest) < len(complete), f"{name}, {why}: the drop takes {len(complete) - len(rest)} "
            f"of {len(complete)} records")
    rc, err, part = page(reports, os.path.join(work, "dropped"), name, plans + rest)
    C.check(part is not None, f"{name}, {why}: build_tables.py exited {rc}: {err[-1500:]}")
    if full is None or part is None:
        return
    before, after = verdicts(full["claims"], gone + kept), verdicts(part["claims"], gone + kept)
    for w in gone + kept:
        C.check(before[w] not in (None, "not measured"),
                f"{name}: complete records: '{w}' is {before[w]} (no verdict: the check would pass vacuously)")
    for w in gone:
        C.check(after[w] == "not measured", f"{name}, {why}: '{w}' is {after[w]}, expected not measured")
    for w in kept:
        C.check(after[w] == before[w], f"{name}, {why}: '{w}' is {after[w]}, was {before[w]} with every record")
    C.check("Incomplete" in part["conditions"], f"{name}, {why}: the conditions do not say incomplete")
