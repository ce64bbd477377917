"""HAVS (Callahan et al. 2005): tables, claims and figures of the reproductions havs-table1,
havs-table2, havs-table3-4, havs-k-tradeoff and havs-gl, from their records only
(docs/pipeline.md). Reproduction files: datasets/suites/havs/*.json; the paper's numbers:
reports/papers/havs.json.

Rows of the mesh tables are labelled 'OURS (PAPER)' by the reproduction files; the name in
parentheses picks the paper's row.
"""
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from vobtables import metrics as m  # noqa: E402
from vobtables import paper as P  # noqa: E402

SORTS = [("shell", "shellsort"), ("heap", "heapsort (std::make_heap + sort_heap)"),
         ("quick", "quicksort (std::sort)"), ("stable", "std::stable_sort"),
         ("radix", "LSD radix sort (4 x 8 bits)")]


# The colours of havs::k_needed_image (algorithms/havs/havs_frame.cpp), as in the paper's Fig. 6.
KMAP_KEY = [("k <= 2", (0.1, 0.8, 0.1)), ("2 < k <= 6", (1.0, 0.8, 0.1)), ("k > 6", (1.0, 0.1, 0.1)),
            ("no fragment", (0.0, 0.0, 0.0))]


def command(records):
    """The command that made these records, with its scale."""
    r = records[0] if records else {}
    scale = r.get("scale", "default")
    return f"`vobench reproduce {r.get('reproduction')}" + ("" if scale == "default" else f" --{scale}") + "`"


def probes(records, name):
    return [r for r in records if r.get("probe") == name]


def orderer_records(records):
    return [r for r in records if "probe" not in r]


def image(r, name):
    """An image a probe wrote: the runner moves result.images into the record's images."""
    return m.get(r, f"images.{name}") or m.get(r, f"result.images.{name}")


def paper_name(row):
    """'gap (f117)' -> 'f117'; None without parentheses."""
    g = re.search(r"\(([^()]*)\)\s*$", row or "")
    return g.group(1) if g else None


def short_name(row):
    return (row or "").split(" (")[0]


def ms(s):
    return None if s is None else s * 1e3


def inv(s):
    return None if not s else 1 / s


def ratio(a, b):
    return m.ratio(a, b)


def paper_rows(doc, paper, key, columns, names, notes=""):
    """The paper's whole table (every row, as printed), so no row of it is dropped when our
    stand-ins cover only some of its meshes."""
    p = paper[key]
    t = doc.table(f"Paper, Table {p['number']}: {p['title']}", ["paper's mesh", "our stand-in"] + names,
                  notes or p.get("comment", ""))
    ours = {v: k for k, v in paper["stand_ins"].items() if k != "comment"}
    for mesh, cells in p["rows"].items():
        t.row(mesh, ours.get(mesh, "-"), *[cells.get(c) for c in columns])


# --- havs-table1 ------------------------------------------------------------------------

def table1(records, paper, doc):
    doc.title = "HAVS Table 1: CPU sorting"
    doc.intro = (command(records) + ": five sorts of the same one million (float, id) "
                 "pairs in one run, then the face and cell sorts of a 1M-cell mesh.")
    p1 = paper["table1"]["ms"]
    sorts = {m.get(r, "parameters.sort"): r for r in probes(records, "havs-sorts")}
    rec0 = next(iter(sorts.values()), {})
    n = m.get(rec0, "result.n")
    reps = len(m.get(rec0, "result.samples_s", []) or [])
    ours = {key: ms(m.get(sorts.get(key, {}), "result.median_s")) for key, _ in SORTS}
    radix, quick = ours["radix"], ours["quick"]
    t = doc.table(f"Table 1: sorting {n:,} floats (with their int32 ids), median of {reps} after "
                  f"{rec0.get('warmup')} warm-up sort(s)" if n else
                  "Table 1: sorting floats (with their int32 ids)",
                  ["algorithm", "ours (ms)", "M keys/s", "paper (ms)", "ours / radix", "paper / radix (computed)"],
                  paper["machine_note"] + " Single thread. Keys uniform in [-1000, 1000], seed "
                  + str(m.get(rec0, "result.seed", 1)) + ".")
    for key, name in SORTS:
        o, pp = ours[key], p1.get(key)
        t.row(name, o, None if not o or not n else n / (o * 1e3), pp, ratio(o, radix),
              ratio(pp, p1["radix"]) if pp is not None else None)
    unsorted = [k for k, r in sorts.items() if m.get(r, "result.sorted") is False]
    if unsorted:
        t.notes += " NOT SORTED by: " + ", ".join(unsorted) + "."

    mesh = orderer_records(records)
    r0 = mesh[0] if mesh else {}
    t2 = doc.table(f"Sorting a {r0.get('n', 0):,}-cell {r0.get('row', 'gap')} mesh (one view, median of "
                   f"{r0.get('repeats')} frames after {r0.get('warmup')} warm-up)",
                   ["orderer", "primitives", "phase", "ms", "M primitives/s"],
                   "std::stable_sort appears in the first table on the same 1M keys. VTK's sorter "
                   "(vtkCellCenterDepthSort) computes cell centres and depths and sorts with std::sort "
                   "inside its single timed phase.")
    for r in mesh:
        prims = m.get(r, "counters.havs_faces") if r.get("orderer") == "havs" else r.get("n")
        for name, v in sorted((r.get("phases") or {}).items()):
            if name == "k-buffer":  # Table 1 is about sorting
                continue
            s = v["median"]
            t2.row(r["algorithm"], prims, name, s * 1e3, prims / s * 1e-6 if s and prims else None)

    # The paper's Table 1: quicksort 281 ms, radix 64 ms, so radix is 281 / 64 = 4.39 times faster.
    paper_q = ratio(P.value(p1["quick"]), P.value(p1["radix"]))
    lo, hi = paper_q / 2, paper_q * 2
    q_over_r = ratio(quick, radix)
    doc.claim("radix sort about 4.4 times faster than quicksort on one million floats (quicksort time / radix time)",
              q_over_r, f"{p1['quick']} ms / {p1['radix']} ms = {paper_q:.2f}",
              f"{lo:.2f} <= ours <= {hi:.2f} (the paper's ratio within a factor of 2)",
              None if q_over_r is None else lo <= q_over_r <= hi, scope={"probe": "havs-sorts"})
    # Section 5.1: 'our current sorting technique can sort upward of 15 million faces per second'.
    # The quantity: faces of a mesh through HAVS's cpu sort (centroid distances + radix sort).
    fps_claim = paper["claims"]["faces_per_second"]
    bar = P.value(fps_claim["value"])
    hv = [r for r in mesh if r.get("orderer") == "havs"]
    faces, sort_s = (m.get(hv[0], "counters.havs_faces"), m.get(hv[0], "phases.cpu sort.median")) if hv else (None, None)
    faces_s = ratio(faces, sort_s)
    doc.claim("HAVS's cpu sort sorts upward of 15 million faces per second (ours: faces of the mesh / median cpu "
              "sort time, one thread)", None if faces_s is None else faces_s / 1e6, fps_claim["printed"],
              f"ours >= {bar / 1e6:g} (million faces per second)", None if faces_s is None else faces_s >= bar,
              scope={"orderer": "havs"})


# --- havs-table2 ------------------------------------------------------------------------

def table2(records, paper, doc):
    doc.title = "HAVS Table 2: k-buffer analysis"
    doc.intro = (command(records) + " (`--full` for paper-sized helix and zoo). Fig. 6-style "
                 "maps of the view with most k > 2 pixels: green k <= 2, yellow 2 < k <= 6, red k > 6.")
    recs = probes(records, "havs-analysis")
    nviews = max((len(m.get(r, "result.views", [])) for r in recs), default=0)
    size = "x".join(map(str, m.get(recs[0], "result.size", []))) if recs else "-"
    t = doc.table(f"Table 2: k-buffer analysis, maximum over {nviews} views at {size}",
                  ["mesh (paper's)", "cells", "fragments", "Max A", "Max k", "k > 2", "k > 6",
                   "paper fragments", "paper Max A", "paper Max k", "paper k > 2", "paper k > 6"],
                  paper["machine_note"] +
                  " Fragments = face fragments at pixel centres (our faces are unique: a shared face "
                  "is rasterized once, as in HAVS). k of a pixel = 1 + the largest number of earlier-"
                  "arrived fragments farther than one fragment: the k-buffer entries it needs to "
                  "composite the exact segment sequence (proved in algorithms/havs/kbuffer.h, tested "
                  "in test_havs). Columns are maxima over the views, as in the paper. Our meshes "
                  "are stand-ins: sizes differ from the paper's (see cells).")
    rows = paper["table2"]["rows"]
    for r in recs:
        views = m.get(r, "result.views", [])

        def vmax(key):
            return max((v[key] for v in views), default=None)

        pp = rows.get(paper_name(r.get("row")), {})
        t.row(r.get("row"), r.get("n"), vmax("fragments"), vmax("max_list"), vmax("max_k"), vmax("k_gt_2"),
              vmax("k_gt_6"), pp.get("fragments"), pp.get("max_a"), pp.get("max_k"), pp.get("k_gt_2"),
              pp.get("k_gt_6"))
        kmap = image(r, "kmap")
        if kmap:
            doc.image(kmap, f"{r.get('row')}: k needed, view {m.get(r, 'result.worst_view')} "
                            "(the view with most k > 2 pixels)", key=KMAP_KEY)
    # Table 2: pixels needing k > 6 are few: at most 1,683 of 7,223,435 fragments (torso) in the paper.
    shares = {k: P.value(v["k_gt_6"]) / P.value(v["fragments"]) for k, v in rows.items()}
    worst_p = max(shares, key=shares.get)
    for r in recs:
        views = m.get(r, "result.views", [])
        frag = max((v["fragments"] for v in views), default=None)
        k6 = max((v["k_gt_6"] for v in views), default=None)
        share = ratio(k6, frag)
        doc.claim(f"k = 6 suffices almost everywhere on {r.get('row')}: pixels needing k > 6 per fragment "
                  f"(maxima over the views: {k6} of {frag})", None if share is None else 100 * share,
                  f"{100 * shares[worst_p]:.3f}% at most ({rows[worst_p]['k_gt_6']} of {rows[worst_p]['fragments']}, "
                  f"{worst_p})", f"ours <= {100 * shares[worst_p]:.3f} (%, the paper's largest share)",
                  None if share is None else share <= shares[worst_p], scope={"row": r.get('row')})
    paper_rows(doc, paper, "table2", ["fragments", "max_a", "max_k", "k_gt_2", "k_gt_6"],
               ["fragments", "Max A", "Max k", "k > 2", "k > 6"])


# --- havs-table3-4 ----------------------------------------------------------------------

def table34(records, paper, doc):
    doc.title = "HAVS Tables 3 and 4: render performance"
    doc.intro = command(records) + " (`--full` for paper-sized helix and zoo, and 3 repeats)."
    recs = orderer_records(records)
    # Every mesh is measured at k = 2 and k = 6 on the same views: a mean or a ratio is shown only
    # over all of them, never over fewer (or over different views for the two k).
    views = sorted({r.get("view_index") for r in recs}, key=str)
    nviews = len(views)
    size = f"{recs[0].get('w')}x{recs[0].get('h')}" if recs else "-"
    t3 = doc.table(f"Table 3: k-buffer (fragment phase) per frame, mean over {nviews} views at {size}",
                   ["mesh (paper's)", "cells", "k=2 fps", "k=2 cells/s", "k=6 fps", "k=6 cells/s",
                    "paper k=2 fps", "paper k=2 cells/s", "paper k=6 fps", "paper k=6 cells/s"])
    t4 = doc.table(f"Table 4: total per frame with k = 2 (cpu sort + k-buffer), mean over {nviews} views",
                   ["mesh (paper's)", "cpu sort ms", "k-buffer ms", "total ms", "fps", "cells/s",
                    "paper CPU ms", "paper GPU ms", "paper total ms", "paper fps", "paper cells/s"],
                   "cpu sort = face centroid distances + LSD radix sort, single thread.")
    p3, p4 = paper["table3"]["rows"], paper["table4"]["rows"]
    # The paper's meshes in its order, each under our stand-in's label (havs.json stand_ins), measured
    # or not, so no row or claim of the paper drops out when its records are missing; then any other rows.
    groups = m.group(recs, "row")
    ours_of = {v: k for k, v in paper["stand_ins"].items() if k not in ("comment", "why")}
    meshes = []
    for pm in p3:
        found = [(row, rs) for row, rs in groups if paper_name(row) == pm]
        meshes.append(found[0] if found else (f"{ours_of.get(pm, '?')} ({pm})", []))
    meshes += [(row, rs) for row, rs in groups if paper_name(row) not in p3]
    values = {}
    for row, rs in meshes:
        expected = m.expected_keys(rs, views)
        by_k = {k: [r for r in rs if m.get(r, "parameters.k") == k] for k in (2, 6)}
        kb, why = {}, {}
        for k in (2, 6):
            kb[k], why[k] = m.complete_mean(by_k[k], m.phase("k-buffer"), expected)
            if not rs:
                why[k] = "no records"
        sort2, why_sort = m.complete_mean(by_k[2], m.phase("cpu sort"), expected)
        cells = rs[0].get("n") if rs else None
        values[row] = (cells, kb, why)
        a, b = p3.get(paper_name(row), {}), p4.get(paper_name(row), {})
        t3.row(row, cells, why[2] or inv(kb[2]), ratio(cells, kb[2]), why[6] or inv(kb[6]), ratio(cells, kb[6]),
               a.get("k2_fps"), a.get("k2_cells_s"), a.get("k6_fps"), a.get("k6_cells_s"))
        tot = None if sort2 is None or kb[2] is None else sort2 + kb[2]
        t4.row(row, why[2] if not rs else (why_sort or ms(sort2)), why[2] or ms(kb[2]), ms(tot), inv(tot),
               ratio(cells, tot), b.get("cpu_ms"), b.get("gpu_ms"), b.get("total_ms"), b.get("fps"), b.get("cells_s"))
    r0 = recs[0] if recs else {}
    timed = (f"Median of {r0.get('repeats')} frames per view after {r0.get('warmup')} warm-up frame(s), "
             f"threads {r0.get('threads')}; analysis off.")
    # Table 3: k = 6 costs the paper 1.22 (spx2) to 2.20 (f117) times k = 2's GPU time (fps ratios).
    pr = {name: P.value(v["k2_fps"]) / P.value(v["k6_fps"]) for name, v in p3.items()}
    lo, hi = min(pr.values()), max(pr.values())
    for row, _ in meshes:
        _, kb, why = values[row]
        q = ratio(kb[6], kb[2])
        missing = "; ".join(f"k={k} {why[k]}" for k in (2, 6) if why[k] and why[k] != "no records")
        missing = "no records" if why[2] == "no records" else missing
        pq = pr.get(paper_name(row))
        doc.claim(f"k = 6 is slower than k = 2 on {row}, by the paper's factor (k-buffer time k=6 / k=2)", q,
                  "-" if pq is None else f"{pq:.2f} ({paper_name(row)}; paper range {lo:.2f} to {hi:.2f})",
                  f"{lo:.2f} <= ours <= {hi:.2f} (the range of Table 3's fps(k=2) / fps(k=6) over its five meshes)"
                  + (f"; not measured: {missing}" if missing else ""),
                  None if q is None else lo <= q <= hi, scope={"row": row})
    # 'between one and six million cells per second': every mesh of the paper's, each over all its views.
    rates = {row: ratio(values[row][0], values[row][1][2]) for row, _ in meshes}
    have = [x for x in rates.values() if x is not None]
    lacking = [f"{row} ({values[row][2][2]})" for row, x in rates.items() if x is None]
    cps = paper["claims"]["cells_per_second"]
    doc.claim("the fragment-level sorting renders between one and six million cells per second (ours: k = 2 "
              "k-buffer phase, lowest and highest over the meshes, million cells/s)",
              None if not have else f"{min(have) / 1e6:.3f} to {max(have) / 1e6:.3f}"
              + (f" on {len(have)} of {len(rates)} meshes" if lacking else ""), cps["printed"],
              "1 <= ours <= 6 for every mesh (million cells per second)"
              + (f"; not measured: {'; '.join(lacking)}" if lacking else ""),
              None if not have or lacking else all(1e6 <= x <= 6e6 for x in have), scope={"orderer": "havs:k=2"})
    paper_rows(doc, paper, "table3", ["cells", "k2_fps", "k2_cells_s", "k6_fps", "k6_cells_s"],
               ["cells", "k=2 fps", "k=2 cells/s", "k=6 fps", "k=6 cells/s"])
    paper_rows(doc, paper, "table4", ["cpu_ms", "gpu_ms", "total_ms", "fps", "cells_s"],
               ["CPU ms", "GPU ms", "total ms", "fps", "cells/s"])
    t3.notes = (paper["machine_note"] + " Paper's Table 3 is the GPU part (rasterize, fragment program, "
                "composite, glFinish); ours is the software k-buffer phase, parallel over bands of rows "
                "on this machine's cores. " + timed)


# --- havs-k-tradeoff --------------------------------------------------------------------

def _error(r):
    """(violating pixels, covered pixels, image RMSE): the record's one verdict (HAVS: what it
    composited, "judged": "composited"); HAVS records older than that verdict: its counters."""
    c = r.get("counters") or {}
    if m.get(r, "oracle.judged") == "composited":
        return (r["oracle"]["violating_pixels"], r["oracle"]["covered_pixels"],
                m.get(r, "image_error.rmse", c.get("havs_image_rmse", 0.0)))
    if "havs_violating_pixels" in c:
        return c["havs_violating_pixels"], c["havs_covered_pixels"], c["havs_image_rmse"]
    return (m.get(r, "oracle.violating_pixels", 0), m.get(r, "oracle.covered_pixels", 0),
            m.get(r, "image_error.rmse", 0.0))


def k_tradeoff(records, paper, doc):
    doc.title = "HAVS: time against error as k grows"
    doc.intro = command(records) + ": reproduction file datasets/suites/havs/k-tradeoff.json."
    acc = {}
    for r in orderer_records(records):
        vp, cov, rmse = _error(r)
        a = acc.setdefault((r["dataset"], r["algorithm"]), {"t": 0, "n": 0, "vp": 0, "cov": 0, "rmse": 0,
                                                            "k": m.get(r, "parameters.k")})
        a["t"] += r["total"]["median"]
        a["n"] += 1
        a["vp"] += vp
        a["cov"] += cov
        a["rmse"] += rmse
    t = doc.table("Speed against error (means over the views)",
                  ["mesh", "orderer", "ms/frame", "violating pixels", "% of covered", "image RMSE"],
                  "HAVS rows: pixels whose composited segment sequence differs from the exact (A-buffer) "
                  "one, and the k-buffer image against exact-order compositing of the same segments. Cell "
                  "orderers: the oracle's violating pixels and render_in_order against render_exact. "
                  "Times: HAVS = cpu sort + k-buffer (it renders); cell orderers = ordering only.")
    for (ds, alg), a in sorted(acc.items()):
        t.row(ds, alg, a["t"] / a["n"] * 1e3, a["vp"] / a["n"], 100 * a["vp"] / max(a["cov"], 1), a["rmse"] / a["n"])

    meshes = sorted({ds for ds, _ in acc})
    # HAVS's curve per mesh: (k, ms/frame, % of covered pixels with an error), by k.
    curves = {ds: sorted((a["k"], a["t"] / a["n"] * 1e3, 100 * a["vp"] / max(a["cov"], 1))
                         for (d, alg), a in acc.items() if d == ds and alg.startswith("havs"))
              for ds in meshes}
    if meshes:
        fig, axes = plt.subplots(1, len(meshes), figsize=(4.2 * len(meshes), 4), squeeze=False)
        for ax, ds in zip(axes[0], meshes):
            for (d, alg), a in sorted(acc.items()):
                if d == ds and not alg.startswith("havs"):
                    ax.plot([a["t"] / a["n"] * 1e3], [100 * a["vp"] / max(a["cov"], 1)], "o", label=alg)
            h = curves[ds]
            if h:
                ax.plot([x[1] for x in h], [x[2] for x in h], "-s", color="k", label="havs (k)")
                for k, tm, e in h:
                    ax.annotate(f"k={k}", (tm, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
            ax.set_title(ds, fontsize=9)
            ax.set_xlabel("time per frame (ms)")
            ax.set_ylabel("% of covered pixels with an ordering error")
            ax.set_ylim(bottom=0)
            ax.set_xlim(left=0)
            ax.legend(fontsize=7)
        ks = sorted({k for h in curves.values() for k, _, _ in h})
        fig.suptitle("HAVS: time per frame against ordering error, k = " + ", ".join(map(str, ks)) +
                     " beside the other orderers", fontsize=10)
        fig.tight_layout()
        doc.figure(fig, "havs-k-tradeoff.png", "per mesh: time per frame against the share of covered "
                   "pixels with an ordering error; HAVS joined in order of k")
    # The paper's trade-off: a larger k buys fewer errors. Judged only when every mesh has every k of the
    # run on every view (a mesh or k missing, or a k on fewer views, would judge 'every mesh' on less).
    recs = orderer_records(records)
    views = sorted({r.get("view_index") for r in recs}, key=str)
    havs_algs = sorted({alg for _, alg in acc if alg.startswith("havs")})
    lacking = []
    for ds in meshes:
        mine = [r for r in recs if r["dataset"] == ds]
        expected = m.expected_keys(mine, views)
        for alg in havs_algs:
            have = {m.match_key(r) for r in mine if r["algorithm"] == alg}
            if have != expected:
                lacking.append(f"{ds} {alg}: {m.views_text(len(have), len(expected))}")
    reason = "; ".join(lacking) if lacking else ("" if len(havs_algs) >= 2 else
                                                 f"{len(havs_algs)} value{'' if len(havs_algs) == 1 else 's'} of k")
    pairs = [(h[0][2], h[-1][2]) for h in curves.values() if len(h) >= 2]
    worst = None if reason else max((last - first for first, last in pairs), default=None)
    doc.claim("a larger k buffer leaves fewer pixels wrong: the largest k has no more erroneous pixels than the "
              "smallest, on every mesh (ours: largest increase, % of covered pixels)", worst,
              "Table 2: fewer pixels need k > 6 than k > 2 on every mesh",
              "ours <= 0" + (f"; not measured: {reason}" if reason else ""),
              None if worst is None else worst <= 0, scope={"orderer": "havs"})


# --- havs-gl ----------------------------------------------------------------------------

GL_NOTES = (
    "Times are per frame ({timing}) and include, for GL, building the index buffer, both passes, glFinish "
    "and the float readback; the cpu sort is not included (same for both). Differing = pixels with a "
    "channel differing after rounding to 8 bits. Race-changed pixels = pixels where a batched GL frame "
    "differs at 8 bits from the serialized GL frame of the same inputs. Pixels with other coverage = "
    "pixels whose fragment count differs between GL and the harness rasterizer used by the software "
    "k-buffer (llvmpipe snaps vertices to 1/256 pixel, so a pixel centre that close to an edge can go to "
    "the neighbouring face or to neither); \"of which other coverage\" counts the serialized-vs-software "
    "differing pixels that are among them (a pixel centre that moves to the neighbouring face keeps its "
    "count and is not among them). A coverage change can change a k-buffer decision (which entry leaves) "
    "and so a pixel by several levels at small k; differences of one level are rounding (float "
    "accumulation order, double dot products). Difference images (images/*-diff.png): white where the GL "
    "image differs from the software one by more than 1/255.")
LLVMPIPE_NOTE = (
    " Why no race on llvmpipe: Mesa's llvmpipe bins the triangles into 64x64-pixel tiles and each tile's "
    "command list is executed by one rasterizer thread in submission order (lp_rast.c: rasterize_scene -> "
    "rasterize_bin -> tri_rasterize_bin), so two fragments of one pixel are never shaded at the same time "
    "and the shader's read-modify-write is serialized in draw order, with or without interlock. The race "
    "of Fig. 5 needs hardware that shades fragments of one pixel concurrently; the serialized mode is the "
    "race-free reference for such hardware. LP_NUM_THREADS: {threads}.")


def gl(records, paper, doc):
    doc.title = "HAVS: the k-buffer as an OpenGL fragment shader (OSMesa) against the software k-buffer"
    recs = probes(records, "havs-gl")
    ok = [r for r in recs if m.get(r, "result.available")]
    down = [r for r in recs if m.get(r, "result.available") is False]
    gl_desc = (f"{m.get(ok[0], 'result.gl_version')}, {m.get(ok[0], 'result.gl_renderer')}" if ok else
               f"not available ({m.get(down[0], 'result.reason')})" if down else "not measured")
    doc.intro = (
        command(records) + " (`--full`: 14 views, paper-sized helix and zoo). The same "
        "face order (CPU radix sort) goes through the software k-buffer (algorithms/havs/kbuffer.h, TBB over "
        "bands of rows) and through the GL 4.5 core shader k-buffer (algorithms/havs/gl/gl_kbuffer.h: image "
        "load/store, no fragment-shader interlock), drawn in one call (batched, the paper's way) and in "
        "race-free runs of faces with disjoint pixel rectangles separated by glMemoryBarrier (serialized). "
        f"GL: {gl_desc}.")
    reps = recs[0].get("repeats", 1) if recs else 1
    timing = (f"median of {reps} after a warm-up" if reps > 1 else
              "one timed frame after a warm-up (the tiny scale only)")
    ts = doc.table("Per mesh and k (sums over the views; time ratio of the sums)",
                   ["mesh (paper's)", "cells", "faces", "k", "sw ms/frame", "gl ms/frame", "gl / sw",
                    "gl serialized ms/frame", "covered pixels", "pixels with other coverage", "gl vs sw differing",
                    "serialized vs sw differing", "of which by > 1/255", "of which other coverage",
                    "race-changed pixels", "max diff (1/255)"], GL_NOTES.format(timing=timing))
    size = "x".join(map(str, m.get(recs[0], "result.size", []))) if recs else "-"
    tv = doc.table(f"Per view and k: software k-buffer against the GL shader k-buffer ({size})",
                   ["mesh", "view", "k", "sw ms", "gl ms", "gl / sw", "gl serialized ms", "serialized draws",
                    "sw fragments", "gl fragments", "pixels with other coverage", "gl vs sw: pixels differing",
                    "max diff", "RMS", "serialized vs sw: pixels differing", "of which by > 1/255",
                    "of which other coverage", "serialized max diff", "race-changed pixels"],
                   "Columns as above, per view.")
    order = []
    for r in ok:
        if r.get("row") not in order:
            order.append(r.get("row"))
    ok.sort(key=lambda r: (order.index(r.get("row")), m.get(r, "parameters.k", m.get(r, "result.k"))))
    tot_race = tot_ser = tot_cov = 0
    for r in ok:
        res = r["result"]
        vs = res["views"]
        nv = max(len(vs), 1)

        def s(key):
            return sum(m.get(v, key, 0) for v in vs)

        sw, glb, ser = s("software_s"), s("gl_batched_s"), s("gl_serialized_s")
        race, d_ser, cov = s("race_changed_pixels"), s("serialized_vs_sw.differing"), s("covered_pixels")
        mx = max([max(v["gl_vs_sw"]["max"], v["serialized_vs_sw"]["max"]) for v in vs], default=None)
        ts.row(r.get("row"), res.get("cells", r.get("n")), res["faces"], res["k"], sw / nv * 1e3, glb / nv * 1e3,
               ratio(glb, sw), ser / nv * 1e3, cov, s("coverage_differing_pixels"), s("gl_vs_sw.differing"),
               d_ser, s("serialized_vs_sw.differing_by_more_than_1"),
               s("serialized_vs_sw_differing_with_coverage_difference"), race, mx)
        tot_race, tot_ser, tot_cov = tot_race + race, tot_ser + d_ser, tot_cov + cov
        for v in vs:
            tv.row(short_name(r.get("row")), v["view"], res["k"], v["software_s"] * 1e3, v["gl_batched_s"] * 1e3,
                   ratio(v["gl_batched_s"], v["software_s"]), v["gl_serialized_s"] * 1e3, v["serialized_draws"],
                   v["software_fragments"], v["gl_fragments"], v["coverage_differing_pixels"],
                   v["gl_vs_sw"]["differing"], v["gl_vs_sw"]["max"], v["gl_vs_sw"]["rms"],
                   v["serialized_vs_sw"]["differing"], v["serialized_vs_sw"]["differing_by_more_than_1"],
                   v["serialized_vs_sw_differing_with_coverage_difference"], v["serialized_vs_sw"]["max"],
                   v["race_changed_pixels"])
        first = vs[0]["view"] if vs else None
        for kind in ("gl", "diff"):
            f = image(r, f"{kind}-v{first}")
            if f:
                doc.image(f, f"{r.get('row')}, view {first}, k={res['k']}: " +
                          ("GL image (batched)" if kind == "gl" else "GL against software, white > 1/255"))
    if ok:
        threads = m.get(ok[0], "result.lp_num_threads")
        ts.notes += LLVMPIPE_NOTE.format(threads=threads or "unset (one rasterizer thread per CPU)")
    renderer = m.get(ok[0], "result.gl_renderer") if ok else "the GL renderer"
    doc.claim(f"our check, not a claim of the paper: no race-changed pixel on {renderer} (ours: race-changed pixels over {tot_cov} covered "
              "pixel-frames; the paper's Fig. 5 shows races on its GPU)",
              tot_race if ok else None, None, "ours == 0", (tot_race == 0) if ok else None, scope={"probe": "havs-gl"})
    share = 100 * tot_ser / tot_cov if ok and tot_cov else None
    doc.claim("our check, not a claim of the paper: serialized GL k-buffer equals the software k-buffer at 8 bits on at least 99% of the covered "
              f"pixels (ours: % differing, {tot_ser} of {tot_cov})", share, None, "ours <= 1",
              None if not ok else tot_ser * 100 <= tot_cov, scope={"probe": "havs-gl"})


TABLES = {"havs-table1": table1, "havs-table2": table2, "havs-table3-4": table34,
          "havs-k-tradeoff": k_tradeoff, "havs-gl": gl}
