"""Rows of the generic report: one per (scene, revision, orderer), medians over its views.

One verdict per record: `oracle` (on the order, or with `"judged": "composited"` on what the
orderer composites). A record without `oracle` (or null) was not checked: it counts as
neither failing nor exact, and its error is None, never 0."""
import collections
import statistics

from . import limits
from .load import revision, run_of

# Records older than the one-verdict change: HAVS's own per-pixel count stood in for the
# oracle's verdict on the cell order it returns (their `oracle` judged that derived order).
OLD_OWN_VIOLATIONS = "havs_violating_pixels"


def scene_key(r):
    return f"{r['dataset']} @ {r['w']}x{r['h']}"


def checked(r):
    return isinstance(r.get("oracle"), dict)


def judged(r):
    """'order', 'composited', or None (not checked)."""
    if not checked(r):
        return None
    o = r["oracle"]
    if "judged" in o:
        return o["judged"]
    return "composited" if OLD_OWN_VIOLATIONS in r.get("counters", {}) else "order"


def violating_pixels(r):
    """The verdict's violating pixels; None when not checked. Overlapping cells (the
    oracle's input_fault): no visibility order exists, so the violations are the input's."""
    if not checked(r):
        return None
    if "input_fault" in r:
        return 0
    o = r["oracle"]
    if "judged" not in o and OLD_OWN_VIOLATIONS in r.get("counters", {}):
        return int(r["counters"][OLD_OWN_VIOLATIONS])
    return int(o.get("violating_pixels", 0))


def error_fraction(r):
    v = violating_pixels(r)
    cov = r["oracle"].get("covered_pixels") if checked(r) else None
    if v is None or not cov:
        return None
    return v / cov


def claim(r):
    c = r.get("claims", {})
    return "object" if c.get("object_exact") else ("image" if c.get("image_exact") else "heuristic")


def verdict_text(row):
    """'2/14 failing', '0/14 failing', 'not checked', or both for a partly checked row."""
    if row["checked_views"] == 0:
        return "not checked"
    text = f"{row['failing_views']}/{row['checked_views']} failing"
    if row["checked_views"] < row["views"]:
        text += f", {row['views'] - row['checked_views']} not checked"
    if row["judged"] == "composited":
        text += " (composited)"
    if row["input_faults"]:
        text += f" (+{row['input_faults']} input faults)"
    return text


def algo_key(r):
    """An orderer measured under several thread counts (a suite's "threads": [1, 0]) gets a
    row per count: (spec, threads)."""
    return (r["algorithm"], r.get("threads"))


def summarise(recs):
    groups = collections.OrderedDict()
    for r in recs:
        groups.setdefault((scene_key(r), revision(r), algo_key(r)), []).append(r)
    # Runs that measured the same view again (a rerun with other settings, two files merged)
    # get a row each; runs that complete each other (a resumed run) share one.
    split = collections.OrderedDict()
    for (scene, rev, algo), rs in groups.items():
        runs = collections.defaultdict(set)
        for r in rs:
            runs[r.get("view_index")].add(run_of(r))
        if any(len(v) > 1 for v in runs.values()):
            for r in rs:
                split.setdefault((scene, rev, algo, run_of(r)), []).append(r)
        else:
            split[(scene, rev, algo, None)] = rs
    rows = []
    for (scene, rev, (algo, threads), run), rs in split.items():
        times = [r["total"]["median"] for r in rs]
        chk = [r for r in rs if checked(r)]
        errs = [e for e in (error_fraction(r) for r in chk) if e is not None]
        rmse = [r["image_error"]["rmse"] for r in rs if "image_error" in r]
        phases = collections.OrderedDict()
        for r in rs:
            for name, v in r["phases"].items():
                phases.setdefault(name, []).append(v["median"])
        views = collections.Counter(r.get("view_index") for r in rs)
        per_view = collections.defaultdict(list)
        for r in rs:
            per_view[r.get("view_index")].append(r["total"]["median"])
        rows.append({
            "scene": scene, "dataset": rs[0]["dataset"], "dataset_spec": rs[0].get("dataset_spec"),
            "w": rs[0]["w"], "h": rs[0]["h"], "revision": rev,
            "runs": sorted({run_of(r) for r in rs}), "run": run, "algorithm": algo, "threads": threads,
            "hosts": sorted({str(r.get("host") or (r.get("context") or {}).get("host_name") or "?") for r in rs}),
            "n": rs[0]["n"],
            "b": rs[0].get("b"), "views": len(rs),
            "repeated_views": sum(1 for c in views.values() if c > 1),
            "seconds": statistics.median(times),
            # Per view (median over that view's records): ratios against a reference use common views only.
            "_view_seconds": {v: statistics.median(t) for v, t in per_view.items()},
            "prepare_s": rs[0]["prepare"]["seconds"],
            "checked_views": len(chk),
            "judged": judged(chk[0]) if chk else None,
            "err": statistics.mean(errs) if errs else None,
            "failing_views": sum(1 for r in chk if violating_pixels(r) > 0),
            "input_faults": sum(1 for r in rs if "input_fault" in r),
            "violating_pixels": sum(violating_pixels(r) for r in chk) if chk else None,
            "max_k": max((r["oracle"].get("max_k", 0) for r in chk), default=None),
            "rmse": statistics.mean(rmse) if rmse else None,
            # A compositing orderer's derived cell order, judged too: shown labelled, never as the verdict.
            "cell_order_px": (sum(r["oracle_cell_order"].get("violating_pixels", 0) for r in rs
                                  if isinstance(r.get("oracle_cell_order"), dict))
                              if any(isinstance(r.get("oracle_cell_order"), dict) for r in rs) else None),
            "cycles": max(r["cycles"]["count"] for r in rs),
            "exact": claim(rs[0]),
            # The sampling rule an image claim holds under (gl: what llvmpipe draws), beside it in the table.
            "exact_under": (rs[0].get("claims") or {}).get("image_exact_under"),
            "phases": {k: statistics.median(v) for k, v in phases.items()},
            "bytes": rs[0]["bytes"]["orderer"] + rs[0]["bytes"]["derived"],
            # The working set streamed once at the run's triad rate (limits.py).
            **limits.row_fields(rs),
        })
        rows[-1]["frame_over_stream"] = limits.frame_over_stream(rows[-1])
    # A scene with several thread counts labels its rows with theirs (figures.label).
    counts = collections.defaultdict(set)
    for row in rows:
        counts[row["scene"]].add(row["threads"])
    for row in rows:
        row["multi_threads"] = len(counts[row["scene"]]) > 1
    # Ratios against a reference under the same thread count (and scene: data set and size), over the views
    # both measured: medians over the same views, never over different view sets.
    base = {(r["scene"], r["revision"], r["run"], r["algorithm"], r["threads"]): r for r in rows}
    for row in rows:
        for ref in ("mpvonc", "vtk-centroid"):
            b = base.get((row["scene"], row["revision"], row["run"], ref, row["threads"])) or base.get(
                (row["scene"], row["revision"], None, ref, row["threads"]))
            q, views = vs_reference(row, b)
            row["vs_" + ref] = q
            # [views compared, views either measured] when they differ; None when the view sets agree.
            row["vs_" + ref + "_views"] = views
        row["verdict"] = verdict_text(row)
    # One orderer's rows of several revisions side by side.
    first_scene, first_algo = {}, {}
    for r in rows:
        first_scene.setdefault(r["scene"], len(first_scene))
        first_algo.setdefault(r["algorithm"], len(first_algo))
    rows.sort(key=lambda r: (first_scene[r["scene"]], first_algo[r["algorithm"]], r["threads"] or 0))
    return rows


def vs_reference(row, ref):
    """(row time / reference time over the views both measured, None or [common, all] when their view
    sets differ). No reference row: (None, None)."""
    if ref is None:
        return None, None
    mine, theirs = row["_view_seconds"], ref["_view_seconds"]
    common = [v for v in mine if v in theirs]
    every = set(mine) | set(theirs)
    views = None if len(common) == len(every) else [len(common), len(every)]
    if not common:
        return None, views
    a = statistics.median(mine[v] for v in common)
    b = statistics.median(theirs[v] for v in common)
    return (a / b if b > 0 else None), views


def vs_text(row, ref, sig):
    """The 'vs REF' cell: the ratio, and 'incomplete: N of M views' when only some views are common."""
    q, views = row["vs_" + ref], row.get("vs_" + ref + "_views")
    if views is None:
        return sig(q)
    return (f"{sig(q)} " if q is not None else "") + f"(incomplete: {views[0]} of {views[1]} views)"


def thread_pairs(rows):
    """Orderers measured under several thread counts on one scene: (scene, revision, run,
    algorithm, rows by thread count ascending), the fewest and most threads side by side."""
    groups = collections.OrderedDict()
    for r in rows:
        if r["threads"] is not None:
            groups.setdefault((r["scene"], r["revision"], r["run"], r["algorithm"]), []).append(r)
    return [(*k, sorted(rs, key=lambda r: r["threads"])) for k, rs in groups.items() if len(rs) > 1]
