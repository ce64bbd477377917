"""The parts of a generic report page: the runs header, a scene's table and figures, the
scene index."""
import collections
import os

from . import figures, gallery
from .rows import scene_key, thread_pairs, vs_text
from .units import human_bytes, human_seconds, sig
from vobtables.conditions import shared_host_warning


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s)


def runs_header(page, recs):
    """Every revision and run the records come from: rows are never merged across revisions.
    Context fields newer records carry (threads, load average, library versions) when present."""
    by_rev = collections.OrderedDict()
    for r in recs:
        c = r.get("context") or {}
        e = by_rev.setdefault(c.get("git_sha") or "?", collections.defaultdict(set))
        e["runs"].add(r.get("run_id") or c.get("date") or "?")
        e["dates"].add(c.get("date") or "?")
        e["machines"].add(f"{c.get('cpu', '?')} ({c.get('num_cpus', '?')} CPUs"
                          + (f", {c['mhz']:.0f} MHz" if isinstance(c.get("mhz"), (int, float)) else "") + ")")
        e["builds"].add(f"{c.get('compiler', '?')}, {c.get('build_type', '?')}")
        e["threads"].add(str(r.get("threads", c.get("threads", "?"))))
        if isinstance(c.get("load_avg"), list) and c["load_avg"]:
            e["load"].add(f"{c['load_avg'][0]:.2f}")
        a = c.get("allocation")
        if isinstance(a, dict):
            e["alloc"].add("2 MiB pages" if a.get("huge_pages") else "4 KiB pages" + (f" ({a['why_off']})" if a.get("why_off") else ""))
        if isinstance(c.get("libraries"), dict):
            e["libs"].add(", ".join(f"{k} {v}" for k, v in sorted(c["libraries"].items())))
        e["records"].add(id(r))
    page.heading(2, "Revisions and runs")
    rows = [[rev, str(len(e["runs"])), ", ".join(sorted(e["dates"])), "; ".join(sorted(e["machines"])),
             "; ".join(sorted(e["builds"])), ", ".join(sorted(e["threads"])),
             ", ".join(sorted(e["load"])) or "–", "; ".join(sorted(e["alloc"])) or "not recorded",
             str(len(e["records"]))] for rev, e in by_rev.items()]
    page.table(["revision (git)", "runs", "dates", "machine", "build", "threads", "load at start",
                "large blocks", "records"], rows)
    for rev, e in by_rev.items():
        if e["libs"]:
            page.para(f"Libraries ({rev}): " + "; ".join(sorted(e["libs"])) + ".")
    warning = shared_host_warning(recs)
    if warning:
        page.para(warning.strip())
    if len(by_rev) > 1:
        page.para(f"Records of {len(by_rev)} revisions: every table keeps one row per revision (column "
                  "'revision'); nothing is averaged across revisions.")


VERDICT_NOTE = ("claim: object = object-space exact, image = image-space exact (image (gl): under the gl "
                "sampling rule, what llvmpipe draws; judged as such only in runs with raster gl), heuristic = no claim. "
                "verdict: views with at least one violating pixel / views the oracle checked "
                "(composited = judged on what the orderer composites); not checked = measured without "
                "the oracle (no error is known, so none is plotted). Times are medians over views of each "
                "view's median over repeats; memory is the orderer's and its derived structures'.")


def scene_table(page, rows, revisions):
    multi = len({r["revision"] for r in rows}) > 1  # this scene's rows, not the whole report's
    by_run = any(r["run"] for r in rows)
    derived = any(r["cell_order_px"] is not None for r in rows)
    head = (["orderer", "claim"] + (["revision"] if multi else []) + (["run"] if by_run else []) +
            ["threads", "views", "time/frame", "vs mpvonc", "vs vtk-centroid", "prepare", "verdict",
             "violating px, summed over views (mean % covered)"] +
            (["derived cell order px"] if derived else []) +
            ["max k", "image RMSE", "cycles", "memory"])
    out, classes = [], []
    for r in rows:
        views = str(r["views"]) + (f" ({len(r['runs'])} runs)" if len(r["runs"]) > 1 else "")
        if r["repeated_views"]:
            views += f" ({r['repeated_views']} measured more than once)"
        nc = r["checked_views"] == 0
        # The count itself (summed over the checked views), so table, caption and `check` agree.
        err = ("not checked" if r["err"] is None and nc else
               "–" if r["err"] is None else f"{r['violating_pixels']:,} ({sig(100 * r['err'])}%)")
        claimed = r["exact"] + (f" ({r['exact_under']})" if r["exact"] == "image" and r.get("exact_under") not in (None, "exact") else "")
        cells = ([r["algorithm"], claimed] + ([r["revision"]] if multi else []) +
                 ([r["run"] or "all"] if by_run else []) +
                 [str(r["threads"]) if r["threads"] is not None else "?", views, human_seconds(r["seconds"]), vs_text(r, "mpvonc", sig), vs_text(r, "vtk-centroid", sig),
                  human_seconds(r["prepare_s"]), r["verdict"], err] +
                 ([sig(r["cell_order_px"]) if r["cell_order_px"] is not None else "–"] if derived else []) +
                 [sig(r["max_k"]) if r["max_k"] is not None else "–", sig(r["rmse"]), sig(r["cycles"]),
                  human_bytes(r["bytes"])])
        cls = [None] * len(cells)
        vi = head.index("verdict")
        cls[vi] = "nc" if nc else ("bad" if r["failing_views"] else None)
        cls[vi + 1] = "nc" if nc else None
        out.append(cells)
        classes.append(cls)
    page.table(head, out, classes)
    if by_run:
        page.para("run: runs that measured the same views again are not merged; each has its own row.")
    if derived:
        page.para("derived cell order px: the oracle's count on the cell order a compositing orderer "
                  "returns (labelled 'derived cell order'); its verdict is the 'verdict' column.")


def threads_table(page, rows):
    """A parallel orderer's time with the fewest and with the most threads, and their ratio
    (the speed-up), so a ratio between orderers never silently compares 2 cores with 1."""
    pairs = thread_pairs(rows)
    if not pairs:
        return
    multi = len({p[1] for p in pairs}) > 1
    by_run = any(p[2] for p in pairs)
    out = []
    for scene, rev, run, algo, rs in pairs:
        lo, hi = rs[0], rs[-1]
        ratio = lo["seconds"] / hi["seconds"] if hi["seconds"] > 0 else None
        out.append([algo] + ([rev] if multi else []) + ([run or "all"] if by_run else []) +
                  [f"{lo['threads']} / {hi['threads']}", human_seconds(lo["seconds"]), human_seconds(hi["seconds"]),
                   f"{sig(ratio)}x" if ratio is not None else "–",
                   human_seconds(lo["prepare_s"]), human_seconds(hi["prepare_s"])])
    page.table(["orderer"] + (["revision"] if multi else []) + (["run"] if by_run else []) +
               ["threads (fewest / most)", "time/frame, fewest threads", "time/frame, most threads",
                "speed-up", "prepare, fewest", "prepare, most"], out)
    page.para("Threads: the same views measured under each thread count of the suite (\"threads\": [1, 0]; "
              "0 = all cores, shown as the count in effect); speed-up = time with the fewest threads / time "
              "with the most.")


def make_figures(scene, rows, out_dir):
    f1 = f"figures/speed_error_{slug(scene)}.png"
    f2 = f"figures/phases_{slug(scene)}.png"
    figures.speed_error(scene, rows, os.path.join(out_dir, f1))
    figures.phases(scene, rows, os.path.join(out_dir, f2))
    return f1, f2


def scene_section(page, scene, rows, recs, figs, out_dir, revisions, note=False):
    r0 = rows[0]
    page.heading(2, scene)
    page.para(f"{r0['dataset']}: n = {r0['n']:,} primitives"
              + (f", b = {r0['b']:,} boundary faces" if r0.get("b") else "")
              + f", {r0['w']}x{r0['h']} pixels, {len(rows)} rows.")
    scene_table(page, rows, revisions)
    threads_table(page, rows)
    if note:
        page.para(VERDICT_NOTE)
    page.figure(figs[0], "speed against error",
                "Speed against error: mean violating pixels over checked views against median time per "
                "frame; marker shape = exactness claim, colour = orderer; grey band = not checked.")
    page.figure(figs[1], "phases", "Median time per frame split by phase (top: time; bottom: share of each "
                "orderer's time), one colour per phase.")
    gallery.add(page, [r for r in recs if scene_key(r) == scene], out_dir, revisions)


def scene_index(page, scenes, rows, href):
    """One link per scene page (numbered as in the overview), with its size, rows, how many
    orderers fail or were not checked, and the fastest orderer with no violation."""
    items = []
    for k, s in enumerate(scenes):
        sr = [r for r in rows if r["scene"] == s]
        fail = sum(1 for r in sr if r["failing_views"])
        nc = sum(1 for r in sr if r["checked_views"] == 0)
        ok = [r for r in sr if r["checked_views"] and not r["failing_views"]]
        best = min(ok, key=lambda r: r["seconds"]) if ok else None
        items.append((f"S{k + 1}: {s}", href(s),
                      f"(n = {sr[0]['n']:,}; {len(sr)} rows; {fail} failing in some view; {nc} not checked"
                      + (f"; fastest with no violation: {best['algorithm']}, {human_seconds(best['seconds'])})"
                         if best else ")")))
    page.link_list(items)


def overview(page, scenes, rows):
    """Orderer x scene: median time per frame, marked when it fails in some view (✗) or was
    not checked (?), so one table answers which orderer to choose."""
    revs = sorted({r["revision"] for r in rows})
    multi_threads = len({r["threads"] for r in rows}) > 1
    keys = list(dict.fromkeys((r["algorithm"], r["revision"], r["run"], r["threads"]) for r in rows))
    cell = {(r["algorithm"], r["revision"], r["run"], r["threads"], r["scene"]): r for r in rows}
    out, classes = [], []
    for algo, rev, run, threads in keys:
        line = [figures.label({"algorithm": algo, "revision": rev, "run": run, "threads": threads,
                               "multi_threads": multi_threads}, revs)]
        cls = [None]
        for s in scenes:
            r = cell.get((algo, rev, run, threads, s))
            if r is None:  # no record of this orderer on this scene
                line.append("not measured")
                cls.append("nc")
                continue
            mark = " ?" if r["checked_views"] == 0 else (" ✗" if r["failing_views"] else "")
            line.append(human_seconds(r["seconds"]) + mark)
            cls.append("nc" if mark == " ?" else ("bad" if mark else None))
        out.append(line)
        classes.append(cls)
    page.table(["orderer"] + [f"S{k + 1}" for k in range(len(scenes))], out, classes)
    page.para("Median time per frame per scene (S1, S2, ... as listed below); ✗ = violating pixels in some "
              "checked view, ? = not checked, no mark = no violation in any checked view; not measured = no "
              "record of that orderer on that scene.")
