"""vobench's own speed targets (issue 16), not a paper's: the tables and claims of the
speed-targets reproduction, from records only (docs/pipeline.md). Each target is one entry of
TARGETS; its verdict is computed from the records of its suite, per dataset, over every view
measured (a target holds on a dataset only when it holds at each of its views)."""
from vobtables import metrics as m
from vobtables.conditions import conditions

ISSUE = "issue 16"

# Orderers are named by their records' "algorithm" (the spec as the suite gives it), datasets
# by their "row"; a target is judged on its datasets only (the tiny scale's meshes are shown in
# the tables, their claims read "not measured").
# kind "ratio": time(num) / time(den) per view, each the median of the record's frames;
# kind "prepare": the record's prepare seconds (once per dataset);
# kind "rate": cells per second of the orderer's frame, at the given thread count.
TARGETS = [
    {"suite": "sxmpvo-mpvonc", "kind": "ratio", "num": "sxmpvo", "den": "mpvonc", "at_most": 1.2,
     "datasets": ["helix(cells=1000000)", "helix(cells=1485000,faces=59500)"],
     "what": "SXMPVO / MPVONC", "target": "at most 1.2 on the 1M- and 1.5M-cell helices at 512x512, one thread"},
    {"suite": "xmpvo-sxmpvo", "kind": "ratio", "num": "xmpvo", "den": "sxmpvo", "at_most": 10.0, "datasets": ["helix(cells=200000)"],
     "what": "XMPVO / SXMPVO per view", "target": "at most 10 on the 200k-cell helix at 512x512, one thread"},
    {"suite": "shuffled-1m", "kind": "ratio", "num": "sxmpvo", "den": "vtk-centroid", "at_most": 1.5,
     "datasets": ["helix(cells=1000000,shuffle=1)"],
     "what": "SXMPVO / vtk-centroid",
     "target": "at most 1.5 on a generated 1M-cell mesh with its cells shuffled, one thread"},
    {"suite": "centroid-peer", "kind": "ratio", "num": "vtk-centroid", "den": "centroid", "at_least": 10.0,
     "datasets": ["helix(cells=1003520,faces=41472)"],
     "what": "vtk-centroid / centroid", "target": "at least 10 (centroid 10 times faster) on 1M cells, one thread"},
    {"suite": "bsp-prepare", "kind": "prepare", "algorithm": "bsp-xmpvo", "below": 2.0, "datasets": ["tet-femur"],
     "what": "BSP-XMPVO preprocessing (seconds)", "target": "under 2 s on tet-femur, one thread"},
    {"suite": "havs-k2", "kind": "rate", "algorithm": "havs:k=2,analyze=false", "threads": 2, "at_least": 2.0e6,
     "datasets": ["helix(cells=200000)"],
     "what": "software HAVS frame at k = 2 (cells per second)",
     "target": "at least 2 M cells/s on the 200k-cell helix at 512x512 with 2 threads"},
]


def number(v):
    return f"{int(v):,}" if float(v).is_integer() else f"{v:g}"


def bound_text(t):
    if "at_most" in t:
        return f"<= {number(t['at_most'])}"
    if "at_least" in t:
        return f">= {number(t['at_least'])}"
    return f"< {number(t['below'])}"


def meets(t, value):
    if value is None:
        return None
    if "at_most" in t:
        return value <= t["at_most"]
    if "at_least" in t:
        return value >= t["at_least"]
    return value < t["below"]


def worst(t, values):
    """The value that decides the target over several views: the largest against an upper
    bound, the smallest against a lower one."""
    return max(values) if "at_least" not in t else min(values)


def view_values(t, recs):
    """[(view, value, detail)] of one dataset's records, in view order; value None where a
    record the target needs is missing."""
    out = []
    for view, rs in sorted(m.group(recs, "view_index"), key=lambda kv: kv[0]):
        if t["kind"] == "ratio":
            a = m.median(m.select(rs, algorithm=t["num"]), m.frame_seconds)
            b = m.median(m.select(rs, algorithm=t["den"]), m.frame_seconds)
            out.append((view, m.ratio(a, b), (a, b)))
        elif t["kind"] == "prepare":
            p = m.median(m.select(rs, algorithm=t["algorithm"]), m.prepare_seconds)
            out.append((view, p, (p,)))
        else:
            mine = [r for r in m.select(rs, algorithm=t["algorithm"]) if r.get("threads") == t["threads"]]
            s = m.median(mine, m.frame_seconds)
            n = mine[0].get("n") if mine else None
            out.append((view, None if s in (None, 0) or n is None else n / s, (s, n)))
    return out


def columns(t):
    if t["kind"] == "ratio":
        return ["dataset", "view", f"{t['num']} ms", f"{t['den']} ms", "ratio", "target", "met"]
    if t["kind"] == "prepare":
        return ["dataset", "view", "prepare s", "target", "met"]
    return ["dataset", "view", "frame ms", "cells", "cells/s", "target", "met"]


def row_cells(t, value, detail):
    ms = [None if v is None else v * 1e3 for v in detail]
    if t["kind"] == "ratio":
        return [ms[0], ms[1], value]
    if t["kind"] == "prepare":
        return [value]
    return [ms[0], detail[1], value]


def yes_no(b):
    return "not measured" if b is None else ("yes" if b else "NO")


def speed_targets(records, numbers, doc):
    doc.title = "vobench's speed targets (issue 16)"
    doc.intro = ("vobench's own targets from issue 16, not claims of a paper: each is computed from the records of "
                 "one run (ratios from orderers measured in turn frame by frame, one thread unless said), and holds "
                 "on a dataset only when it holds at every view measured. The gmsh-meshed target (SXMPVO at most 1.5 "
                 "times vtk-centroid on component8.step at -clmax 0.4) needs gmsh and its demo files: "
                 "tests/benchmarks/gmsh-component8.sh OUT.jsonl.")
    doc.conditions = conditions(records, {"machine": "none (these are vobench's own targets)"})
    for t in TARGETS:
        recs = [r for r in records if str(r.get("suite")).split("/")[-1] == t["suite"]]
        table = doc.table(f"{t['what']}: {t['target']}", columns(t),
                          f"Suite {t['suite']} of this reproduction; "
                          + ("the preprocessing is timed once per dataset (the record's prepare seconds)."
                             if t["kind"] == "prepare" else "times are the median of each record's frames."),
                          decimals={"ratio": 3})
        rows = dict(m.group(recs, lambda r: r.get("row") or r.get("dataset")))
        for row, rs in rows.items():
            for view, value, detail in view_values(t, rs):
                table.row(row, view, *row_cells(t, value, detail), bound_text(t), yes_no(meets(t, value)))
        for row in t["datasets"]:
            vals = view_values(t, rows.get(row, []))
            measured = [v for _, v, _ in vals]
            missing = not measured or any(v is None for v in measured)
            decisive = None if missing else worst(t, measured)
            elsewhere = sorted(k for k in rows if k != row)
            why = ("" if measured and not missing else " (a view lacks a record)" if measured
                   else f" (not run on {row}; measured on {', '.join(elsewhere)})" if elsewhere else " (not run)")
            doc.claim(f"{ISSUE}: {t['what']}: {t['target']}. On {row}"
                      + (f", the worst of {len(vals)} views" if len(vals) > 1 else ", one view" if vals else ""),
                      ours=decisive, paper=f"{ISSUE}: {bound_text(t)}",
                      criterion=f"every view {bound_text(t)}{why}", holds=meets(t, decisive),
                      scope={"suite": t["suite"], "row": row})  # two targets may share a data set


TABLES = {"speed-targets": speed_targets}
