"""Planned jobs without a record (docs/pipeline.md "Incomplete data").

Every suite run writes a plan line before its jobs: the key, data set, orderer or probe, size,
view and threads of every job of the suite. A run stopped early (Ctrl-C, a killed CI job)
leaves jobs of the plan without a record, even whole data sets or suites it never reached;
`missing_jobs` finds them, so a page says so and a claim over them is "not measured" instead
of being judged on the rest."""
import re


def latest_plans(plans, reproduction=None):
    """The last plan line of each suite (file order), of one reproduction when given
    (None: every plan)."""
    out = {}
    for p in plans:
        if not isinstance(p, dict) or not isinstance(p.get("jobs"), list):
            continue
        if reproduction is not None and p.get("reproduction") != reproduction:
            continue
        out[p.get("suite")] = p
    return out


def missing_jobs(records, plans, reproduction=None):
    """The jobs of the latest plan of each suite with no record among `records` (by key), in
    plan order; each job dict gains "suite" (the plan's)."""
    have = {r.get("key") for r in records if isinstance(r, dict)}
    out = []
    for suite, p in latest_plans(plans, reproduction).items():
        for j in p["jobs"]:
            if isinstance(j, dict) and isinstance(j.get("key"), str) and j["key"] not in have:
                out.append(dict(j, suite=suite))
    return out


def planned_jobs(plans, reproduction=None):
    """Every job of the latest plans (as missing_jobs, with or without records)."""
    return [dict(j, suite=s) for s, p in latest_plans(plans, reproduction).items() for j in p["jobs"]
            if isinstance(j, dict) and isinstance(j.get("key"), str)]


def job_row(j):
    """The row a job's records would have: its "row", else its data set (probes without a
    scene: the probe)."""
    return str(j.get("row") or j.get("dataset") or (f"probe {j['probe']}" if j.get("probe") else "?"))


def job_unit(j):
    return str(j.get("algorithm") or (f"probe {j['probe']}" if j.get("probe") else "?"))


def ranges(nums):
    """[0, 1, 2, 5, 7, 8] -> '0-2, 5, 7-8'."""
    nums, out = sorted(set(nums)), []
    for n in nums:
        if out and n == out[-1][1] + 1:
            out[-1][1] = n
        else:
            out.append([n, n])
    return ", ".join(str(a) if a == b else f"{a}-{b}" for a, b in out)


def describe(missing, planned=None, row_of=job_row):
    """A compact sentence: how many planned jobs have no record and which data sets, orderers
    and views; '' when none."""
    if not missing:
        return ""
    groups = {}
    for j in missing:
        groups.setdefault(row_of(j), []).append(j)
    per_row = {}
    for j in planned or []:
        per_row[row_of(j)] = per_row.get(row_of(j), 0) + 1
    parts = []
    for row, js in groups.items():
        units = sorted({job_unit(j) for j in js})
        views = [j["view_index"] for j in js if type(j.get("view_index")) is int]
        sizes = sorted({f"{j.get('w')}x{j.get('h')}" for j in js if j.get("w")})
        of = per_row.get(row)
        head = (f"all {len(js)} jobs" if of == len(js) else f"{len(js)} of {of} jobs") if of else f"{len(js)} jobs"
        what = ", ".join(units[:4]) + (f" and {len(units) - 4} more" if len(units) > 4 else "")
        parts.append(f"{row} ({head}: {what}" + (f"; views {ranges(views)}" if views else "")
                     + (f"; {', '.join(sizes)}" if len(sizes) > 1 else "") + ")")
    total = f" of {len(planned)}" if planned else ""
    shown = parts[:8] + ([f"{len(parts) - 8} more data sets"] if len(parts) > 8 else [])
    return (f"{len(missing)}{total} planned jobs have no record (the run was stopped or they failed): "
            + "; ".join(shown) + ".")


def _as_set(v):
    if v is None:
        return None
    if isinstance(v, (list, tuple, set, frozenset)):
        return set(v)
    return {v}


def key_size(j):
    """The suite's size entry "WxH" in a job's key: with fitted windows ("fit") the job's w and h
    are its view's window, the key keeps the entry the tables name."""
    for part in str(j.get("key") or "").split("|"):
        if re.fullmatch(r"\d+x\d+", part):
            return part
    return None


def _spec_parts(spec):
    """'name:k=v,k2=v2' -> ('name', {('k', 'v'), ('k2', 'v2')})."""
    name, _, params = str(spec).partition(":")
    return name, {tuple(p.split("=", 1)) for p in params.split(",") if "=" in p}


def _spec_covers(scope_spec, job_spec):
    """An orderer in a scope covers a job's spec of that orderer with at least its parameters
    ('havs:k=2' covers 'havs:analyze=false,k=2'; 'havs' every havs job), in any order."""
    (a, pa), (b, pb) = _spec_parts(scope_spec), _spec_parts(job_spec)
    return a == b and pa <= pb


def in_scope(j, scope, row_of=job_row):
    """Whether a planned job falls in a claim's scope: a dict of "suite" (REPRO/SUITE or
    SUITE), "row" (or "dataset"), "orderer" (an orderer name or spec; a spec covers the jobs of
    that orderer with at least its parameters: orderer jobs only), "probe" (a probe name: probe
    jobs only), "view", "size" ("WxH": the window or, fitted, the suite's entry) and "threads",
    each one value or a collection; a key left out covers everything. None: the whole
    reproduction."""
    if scope is None:
        return True
    suites = _as_set(scope.get("suite"))
    if suites is not None:
        s = str(j.get("suite") or "")
        if s not in suites and s.split("/")[-1] not in suites:
            return False
    probes = _as_set(scope.get("probe"))
    if probes is not None and j.get("probe") not in probes:
        return False
    rows = _as_set(scope.get("row", scope.get("dataset")))
    if rows is not None and row_of(j) not in rows and j.get("dataset") not in rows:
        return False
    ords = _as_set(scope.get("orderer"))
    if ords is not None:
        spec = j.get("algorithm") or ""
        if spec not in ords and not any(_spec_covers(o, spec) for o in ords):
            return False
    views = _as_set(scope.get("view"))
    if views is not None and j.get("view_index") not in views:
        return False
    sizes = _as_set(scope.get("size"))
    if sizes is not None and f"{j.get('w')}x{j.get('h')}" not in sizes and key_size(j) not in sizes:
        return False
    threads = _as_set(scope.get("threads"))
    if threads is not None and j.get("threads") not in threads:
        return False
    return True
