#!/usr/bin/python3
"""vobench report: results (JSONL) -> Markdown + HTML with matplotlib figures.

Per scene: a table (human units, "not checked" for records without the oracle, one row per
revision), speed against error (unchecked rows on a separate band), phase bars, and a
gallery of the views with violations; across scenes: scaling per (family, variant, size).
More than PAGE_SCENES scenes: report.html is an index linking one page per scene. The
Markdown (report.md, NAME.md) is one document. Parts live in reports/generic/. Run with
Debian's /usr/bin/python3 (python3-matplotlib)."""
import argparse
import collections
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generic import figures, limits, sections, vtk_render  # noqa: E402
from generic.load import load, revision  # noqa: E402
from generic.page import Page, anchor  # noqa: E402
from generic.rows import summarise  # noqa: E402
from vobtables import plan as vplan  # noqa: E402
import signal  # noqa: E402

# Ctrl-C during `vobench reproduce` stops the script as it stops vobench, without a traceback.
signal.signal(signal.SIGINT, signal.SIG_DFL)

PAGE_SCENES = 6  # more scenes: an index page and one page per scene


def scene_file(k):
    return f"scene-{k + 1:02d}.html"


def build(a):
    plans, keys = [], set()
    recs, probes = load(a.results, plans, keys)
    # Planned jobs without a record (docs/pipeline.md "Incomplete data"): the runs' plan lines
    # of this reproduction (--name), or of every run.
    planned = vplan.planned_jobs(plans, a.name or None)
    missing = [j for j in planned if j.get("key") not in keys]
    if not recs and not probes:
        sys.exit("report: no records")
    if not recs:
        print("report: only probe records: no generic report")
        return
    out = a.out
    os.makedirs(os.path.join(out, "figures"), exist_ok=True)
    rows = summarise(recs)
    scenes = list(collections.OrderedDict((r["scene"], 1) for r in rows))
    revisions = sorted({revision(r) for r in recs})
    figs = {s: sections.make_figures(s, [r for r in rows if r["scene"] == s], out) for s in scenes}
    scaled = figures.scaling(rows, os.path.join(out, "figures/scaling.png"))
    includes = []
    for inc in a.include:
        with open(inc) as f:
            includes.append(f.read())

    def front(page):
        page.para(f"{len(recs)} orderer records, {len(scenes)} scenes, {len(revisions)} revision(s)"
                  + (f" ({probes} probe records are left to the paper tables)." if probes else "."))
        for text in includes:
            page.para(text)
        if missing:
            lost = sorted({vplan.job_row(j) for j in missing} - {r.get("row") or r.get("dataset") for r in recs})
            page.para("Conditions. Incomplete: " + vplan.describe(missing, planned)
                      + (f" Not measured at all (no scene section): {', '.join(lost)}." if lost else "")
                      + " Rows and figures below cover only the jobs that have a record.",
                      md="**Conditions.** Incomplete: " + vplan.describe(missing, planned)
                      + (f" Not measured at all (no scene section): {', '.join(lost)}." if lost else "")
                      + " Rows and figures below cover only the jobs that have a record.")
        sections.runs_header(page, recs)
        page.heading(2, "How to read the tables")
        page.para(sections.VERDICT_NOTE)
        limits.section(page, rows, recs)

    def scaling(page):
        vtk_render.section(page, out, a.results)  # vobench-vtk render runs beside the results
        if scaled:
            page.heading(2, "Scaling")
            page.figure("figures/scaling.png", "time against n",
                        "Median time per frame against n, one panel per dataset family, variant and image "
                        "size; the legend gives each line's fitted log-log slope (time ~ n^slope).")

    # One Markdown document with everything (NAME.md is rebuilt byte for byte by `vobench report`).
    full = Page(a.title)
    front(full)
    if len(scenes) > 1:
        full.heading(2, "Overview")
        sections.overview(full, scenes, rows)
        sections.scene_index(full, scenes, rows, lambda s: "#" + anchor(s))
    for s in scenes:
        sections.scene_section(full, s, [r for r in rows if r["scene"] == s], recs, figs[s], out, revisions)
    scaling(full)
    pages = {}
    if len(scenes) <= a.page_scenes:
        pages["report.html"] = full.to_html()
    else:
        index = Page(a.title)
        front(index)
        index.heading(2, "Overview")
        sections.overview(index, scenes, rows)
        index.heading(2, "Scenes")
        index.para(f"{len(scenes)} scenes, one page each (table, figures, images):")
        sections.scene_index(index, scenes, rows, lambda s: scene_file(scenes.index(s)))
        scaling(index)
        pages["report.html"] = index.to_html()
        for k, s in enumerate(scenes):
            p = Page(f"{a.title}: {s}")
            sections.scene_section(p, s, [r for r in rows if r["scene"] == s], recs, figs[s], out, revisions, note=True)
            prev = f"<a href='{scene_file(k - 1)}'>previous scene</a> · " if k > 0 else ""
            nxt = f" · <a href='{scene_file(k + 1)}'>next scene</a>" if k + 1 < len(scenes) else ""
            nav = f"<p>{prev}<a href='report.html'>index</a>{nxt} (scene {k + 1} of {len(scenes)})</p>"
            pages[scene_file(k)] = p.to_html(nav=nav)
    text = full.markdown()
    write_atomic(os.path.join(out, "report.md"), text)
    for name, body in pages.items():
        write_atomic(os.path.join(out, name), body)
    clean = [{k: v for k, v in r.items() if k != "dataset_spec" and not k.startswith("_")} for r in rows]
    write_atomic(os.path.join(out, "summary.json"), json.dumps(clean, indent=1) + "\n")
    if a.name:
        write_atomic(os.path.join(out, a.name + ".md"), text)
        write_atomic(os.path.join(out, a.name + ".html"), pages["report.html"])
        write_atomic(os.path.join(out, a.name + ".json"),
                     json.dumps({"experiment": a.name, "rows": clean}, indent=1) + "\n")
    print(f"report: {len(recs)} records, {len(scenes)} scenes -> {out}/report.md, report.html"
          + (f" and {len(pages) - 1} scene pages" if len(pages) > 1 else ""))


def write_atomic(path, text):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("results", nargs="+")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="vobench report")
    ap.add_argument("--include", action="append", default=[], help="Markdown files to put first")
    ap.add_argument("--name", help="also write NAME.md, NAME.html and NAME.json (the rows) for reproduce")
    ap.add_argument("--page-scenes", type=int, default=PAGE_SCENES,
                    help=f"more scenes than this: an index page and one page per scene (default {PAGE_SCENES})")
    build(ap.parse_args())


if __name__ == "__main__":
    main()
