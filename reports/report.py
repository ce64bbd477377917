#!/usr/bin/python3
"""vobench report: results (JSONL) -> Markdown + HTML with matplotlib figures.

Figures: speed against error per scene (with the Pareto front), stacked phase bars per
scene, time against size where a dataset family has several sizes, and an image gallery of
the records that carry images. Run with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import argparse
import collections
import html
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vobtables import load_records  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def scene_key(r):
    return f"{r['dataset']} @ {r['w']}x{r['h']}"


# Orderers that composite themselves (HAVS fixes the order per pixel in its k-buffer) report
# their own per-pixel violations, judged against the oracle's exact sequences; those stand in
# for the oracle's verdict on the cell order they return.
OWN_VIOLATIONS = "havs_violating_pixels"


def violating_pixels(r):
    # Overlapping cells (the oracle's input_fault): no visibility order exists, so the
    # violations are the input's, not the orderer's.
    if "input_fault" in r:
        return 0
    c = r.get("counters", {})
    if OWN_VIOLATIONS in c:
        return int(c[OWN_VIOLATIONS])
    return r.get("oracle", {}).get("violating_pixels", 0)


def error_fraction(r):
    o = r.get("oracle")
    if not o or not o.get("covered_pixels"):
        return None
    return violating_pixels(r) / o["covered_pixels"]


def summarise(recs):
    """Rows per (scene, algorithm): medians over views."""
    groups = collections.OrderedDict()
    for r in recs:
        groups.setdefault((scene_key(r), r["algorithm"]), []).append(r)
    rows = []
    for (scene, algo), rs in groups.items():
        times = [r["total"]["median"] for r in rs]
        errs = [e for e in (error_fraction(r) for r in rs) if e is not None]
        rmse = [r["image_error"]["rmse"] for r in rs if "image_error" in r]
        phases = collections.OrderedDict()
        for r in rs:
            for name, v in r["phases"].items():
                phases.setdefault(name, []).append(v["median"])
        rows.append({
            "scene": scene, "dataset": rs[0]["dataset"], "algorithm": algo, "n": rs[0]["n"],
            "b": rs[0].get("b"), "views": len(rs),
            "ms": 1e3 * statistics.median(times),
            "prepare_s": rs[0]["prepare"]["seconds"],
            "err": statistics.mean(errs) if errs else None,
            "failing_views": sum(1 for r in rs if violating_pixels(r) > 0),
            "input_faults": sum(1 for r in rs if "input_fault" in r),
            "violating_pixels": sum(violating_pixels(r) for r in rs),
            "max_k": max((r.get("oracle", {}).get("max_k", 0) for r in rs), default=0),
            "rmse": statistics.mean(rmse) if rmse else None,
            "cycles": max(r["cycles"]["count"] for r in rs),
            "exact": r_claims(rs[0]),
            "phases": {k: 1e3 * statistics.median(v) for k, v in phases.items()},
            "bytes": rs[0]["bytes"]["orderer"] + rs[0]["bytes"]["derived"],
        })
    by_scene = collections.defaultdict(dict)
    for row in rows:
        by_scene[row["scene"]][row["algorithm"]] = row
    for row in rows:
        for ref in ("mpvonc", "vtk-centroid"):
            base = by_scene[row["scene"]].get(ref)
            row["vs_" + ref] = row["ms"] / base["ms"] if base and base["ms"] > 0 else None
    return rows


def r_claims(r):
    c = r.get("claims", {})
    return "object" if c.get("object_exact") else ("image" if c.get("image_exact") else "heuristic")


def fmt(v, digits=3):
    if v is None:
        return "–"
    if isinstance(v, float):
        if v == 0:
            return "0"
        return f"{v:.{digits}g}"
    return str(v)


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s)


def pareto(points):
    """Indices of points not dominated in (time, error), both minimised."""
    front = []
    for i, (t, e) in enumerate(points):
        if not any((t2 <= t and e2 <= e) and (t2 < t or e2 < e) for j, (t2, e2) in enumerate(points) if j != i):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def fig_speed_error(scene, rows, out):
    pts = [(r["ms"], r["err"] if r["err"] is not None else 0.0) for r in rows]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for r, (t, e) in zip(rows, pts):
        marker = "o" if r["exact"] != "heuristic" else "s"
        ax.scatter([t], [e * 100], marker=marker, s=50, label=r["algorithm"])
    front = pareto(pts)
    ax.plot([pts[i][0] for i in front], [pts[i][1] * 100 for i in front], "k--", lw=0.8, label="Pareto front")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_ylim(0, max(1.0, 100 * max(e for _, e in pts)) * 1.8)  # exact orderers sit on 0
    ax.set_xlabel("median time per frame (ms, log)")
    ax.set_ylabel("violating pixels (% of covered, mean over views)")
    ax.set_title(f"speed against error: {scene}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def fig_phases(scene, rows, out):
    fig, ax = plt.subplots(figsize=(6.4, 0.5 + 0.45 * len(rows)))
    names = []
    for r in rows:
        for p in r["phases"]:
            if p not in names:
                names.append(p)
    cmap = plt.get_cmap("tab20")
    for k, p in enumerate(names):
        left = [sum(r["phases"].get(q, 0) for q in names[:k]) for r in rows]
        ax.barh([r["algorithm"] for r in rows], [r["phases"].get(p, 0) for r in rows], left=left,
                color=cmap(k % 20), label=p)
    ax.set_xlabel("median time per frame (ms)")
    ax.set_title(f"phases: {scene}", fontsize=9)
    ax.legend(fontsize=6, loc="lower right")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def fig_scaling(rows, out):
    series = collections.defaultdict(list)
    for r in rows:
        family = r["dataset"].split("(")[0]
        series[(family, r["algorithm"])].append((r["n"], r["ms"]))
    series = {k: sorted(v) for k, v in series.items() if len({n for n, _ in v}) >= 2}
    if not series:
        return False
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for (family, algo), pts in sorted(series.items()):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"{algo} on {family}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("primitives n")
    ax.set_ylabel("median time per frame (ms)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("results", nargs="+")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="vobench report")
    ap.add_argument("--include", action="append", default=[], help="Markdown files to put first")
    ap.add_argument("--name", help="also write NAME.md and NAME.json (the rows) for reproduce")
    a = ap.parse_args()
    recs = [r for p in a.results for r in load_records(p, who="report")]
    if not recs:
        sys.exit("report: no records")
    # Probe records (docs/pipeline.md) feed the paper tables, not this report.
    recs = [r for r in recs if "probe" not in r]
    if not recs:
        print("report: only probe records: no generic report")
        return
    os.makedirs(os.path.join(a.out, "figures"), exist_ok=True)
    rows = summarise(recs)
    scenes = list(collections.OrderedDict((r["scene"], 1) for r in rows))
    md = [f"# {a.title}", ""]
    ctx = recs[-1].get("context", {})
    md.append(f"Machine: {ctx.get('cpu', '?')} ({ctx.get('num_cpus', '?')} threads), {ctx.get('compiler', '?')}, "
              f"{ctx.get('build_type', '?')} build, git {ctx.get('git_sha', '?')}, {ctx.get('date', '?')}. "
              f"{len(recs)} records.")
    md.append("")
    for inc in a.include:
        with open(inc) as f:
            md += [f.read(), ""]
    body_imgs = {}
    for scene in scenes:
        srows = [r for r in rows if r["scene"] == scene]
        f1 = f"figures/speed_error_{slug(scene)}.png"
        f2 = f"figures/phases_{slug(scene)}.png"
        fig_speed_error(scene, srows, os.path.join(a.out, f1))
        fig_phases(scene, srows, os.path.join(a.out, f2))
        body_imgs[scene] = (f1, f2)
        md += [f"## {scene}", "",
               "| algorithm | claim | n | views | ms/frame | vs mpvonc | vs vtk-centroid | prepare s | "
               "failing views | violating px (% covered) | max k | image RMSE | cycles | bytes |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in srows:
            faults = f" (+{r['input_faults']} input faults)" if r["input_faults"] else ""
            md.append(f"| {r['algorithm']} | {r['exact']} | {r['n']} | {r['views']} | {fmt(r['ms'])} | "
                      f"{fmt(r['vs_mpvonc'])} | {fmt(r['vs_vtk-centroid'])} | {fmt(r['prepare_s'])} | "
                      f"{r['failing_views']}/{r['views']}{faults} | "
                      f"{fmt(None if r['err'] is None else 100 * r['err'])} | {r['max_k']} | "
                      f"{fmt(r['rmse'])} | {r['cycles']} | {r['bytes']} |")
        md += ["", f"![speed against error]({f1})", "", f"![phases]({f2})", ""]
    if fig_scaling(rows, os.path.join(a.out, "figures/scaling.png")):
        md += ["## Scaling", "", "![time against n](figures/scaling.png)", ""]
    gallery = [r for r in recs if "images" in r]
    if gallery:
        md += ["## Images (order | exact | difference)", ""]
        for r in gallery:
            im = r["images"]
            rel = [os.path.relpath(im[k], a.out) for k in ("order", "exact", "diff")]
            o = r.get("oracle", {})
            md.append(f"**{r['algorithm']}** on {r['dataset']}, view {r['view_index']}: "
                      f"{o.get('violating_pixels', '?')} violating pixels, "
                      f"RMSE {fmt(r.get('image_error', {}).get('rmse'))}")
            md.append("")
            md.append(" ".join(f"![{k}]({p})" for k, p in zip(("order", "exact", "diff"), rel)))
            md.append("")
    text = "\n".join(md) + "\n"
    write_atomic(os.path.join(a.out, "report.md"), text)
    write_atomic(os.path.join(a.out, "report.html"), to_html(a.title, text))
    write_atomic(os.path.join(a.out, "summary.json"), json.dumps(rows, indent=1) + "\n")
    if a.name:
        write_atomic(os.path.join(a.out, a.name + ".md"), text)
        write_atomic(os.path.join(a.out, a.name + ".json"), json.dumps({"experiment": a.name, "rows": rows}, indent=1) + "\n")
    print(f"report: {len(recs)} records, {len(scenes)} scenes -> {a.out}/report.md, report.html")


def to_html(title, md):
    """A small Markdown subset (headings, tables, images, paragraphs) to HTML."""
    out = [f"<!doctype html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>",
           "<style>body{font-family:sans-serif;max-width:1200px;margin:auto}table{border-collapse:collapse;"
           "font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px}img{max-width:32%}</style></head><body>"]
    lines = md.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("#"):
            level = len(line) - len(line.lstrip("#"))
            out.append(f"<h{level}>{html.escape(line[level:].strip())}</h{level}>")
        elif line.startswith("|"):
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append([c.strip() for c in lines[i].strip("|").split("|")])
                i += 1
            out.append("<table>")
            for k, r in enumerate(rows):
                if k == 1 and all(set(c) <= set("-: ") for c in r):
                    continue
                tag = "th" if k == 0 else "td"
                out.append("<tr>" + "".join(f"<{tag}>{html.escape(c)}</{tag}>" for c in r) + "</tr>")
            out.append("</table>")
            continue
        elif "![" in line:
            parts = []
            for chunk in line.split("!["):
                if "](" in chunk:
                    alt, rest = chunk.split("](", 1)
                    src = rest.split(")", 1)[0]
                    parts.append(f"<img alt='{html.escape(alt)}' src='{html.escape(src)}'>")
            out.append("<p>" + " ".join(parts) + "</p>")
        elif line.strip():
            out.append(f"<p>{html.escape(line).replace('**', '')}</p>")
        i += 1
    out.append("</body></html>")
    return "\n".join(out)


def write_atomic(path, text):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


if __name__ == "__main__":
    main()
