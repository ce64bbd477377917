"""The page of a reproduction whose run wrote its plan lines but no record (stopped before its
first job finished, docs/pipeline.md "Incomplete data"): the table scripts compute their claims
from records, so none can be computed; the page lists the planned jobs, all missing, and one
claim standing for all of the paper's, not measured."""
from . import plan as _plan


def unmeasured(doc, paper):
    """Fills `doc` (set_plan already called with no records) for reproduction doc.name of `paper`."""
    n = len(doc.planned)
    doc.title = f"{doc.name}: not measured"
    doc.intro = (f"`vobench reproduce {doc.name}` planned {n} jobs and stopped before the first of them wrote a "
                 "record, so no table of the paper could be rebuilt and no claim judged.")
    # The Conditions say "Incomplete: 0 of N planned jobs have a record" and which (Doc._finish).
    t = doc.table("Planned jobs without a record", ["data set", "suite", "orderer or probe", "views", "sizes",
                                                    "threads", "jobs", "record"])
    groups = {}
    for j in doc.missing:
        groups.setdefault((doc.row_label(j), j.get("suite"), _plan.job_unit(j)), []).append(j)
    for (row, suite, unit), js in groups.items():
        views = [j["view_index"] for j in js if type(j.get("view_index")) is int]
        sizes = sorted({_plan.key_size(j) or f"{j['w']}x{j['h']}" for j in js if j.get("w")})  # a fitted job: its entry
        threads = sorted({j.get("threads") for j in js if j.get("threads") is not None})
        t.row(row, suite, unit, _plan.ranges(views) if views else "-", ", ".join(sizes) or "-",
              ", ".join(map(str, threads)) or "-", len(js), "not measured")
    doc.claim(f"every claim of {doc.name} ({paper}): none can be computed without records",
              ours=None, paper=None, criterion=f"not measured: 0 of {n} planned jobs have a record", holds=None)
    return doc
