"""XMPVO (Silva et al.), BSP-XMPVO (Comba et al.) and Cook et al.'s Table 2, which puts both
beside SXMPVO: the tables of xmpvo-scaling, xmpvo-stability and cook-table2, from records
only (docs/pipeline.md)."""
import re

import matplotlib.pyplot as plt

from vobtables import metrics as m
from vobtables import paper as P
from papers.cook_common import fitted, size_entry, window_text


def command(records):
    r = records[0]
    scale = r.get("scale", "default")
    return f"`vobench reproduce {r['reproduction']}" + ("" if scale == "default" else f" --{scale}") + "`"


def frames_text(records):
    """'median of 3 frames after a warm-up', as the records were measured."""
    reps, warm = records[0]["repeats"], records[0]["warmup"]
    after = "" if warm == 0 else (" after a warm-up" if warm == 1 else f" after {warm} warm-up frames")
    return f"median of {reps} frames{after}"


def failing_views(records):
    return sum(1 for r in records if m.get(r, "oracle.violating_fragments", 0) > 0)


def oracle_cell(records):
    if not records:
        return "not measured"
    return f"{failing_views(records)} of {len(records)} views violate"


def of(records, orderer):
    return [r for r in records if r.get("orderer") == orderer]


# --- xmpvo-scaling ---------------------------------------------------------------------------

def scaling_figure(rows, fits, size, doc):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    ax = axes[0]
    for key, name, style in (("xmpvo", "XMPVO per view", "o-"), ("bsp", "BSP-XMPVO per view", "s-"),
                             ("bsp_prepare", "BSP-XMPVO preprocessing (BSP build)", "^--"),
                             ("sxmpvo", "SXMPVO per view", "x:")):
        pts = [(r["b"], r[key]) for r in rows if r.get(key) is not None]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, label=name)
    ax.set_xlabel(f"exterior faces b (gap series, {size})")
    ax.set_ylabel("seconds (log scale)")
    ax.set_yscale("log")
    ax.set_title("Time against b")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_xlim(left=0)
    ax = axes[1]
    for key, name, style in (("xmpvo", "XMPVO", "o"), ("bsp", "BSP-XMPVO", "s")):
        pts = [(r["b"] ** 2, r[key]) for r in rows if r.get(key) is not None]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, label=name + " per view")
            f = fits.get(key)
            if f:
                xs = [0, max(p[0] for p in pts)]
                ax.plot(xs, [f["intercept"] + f["slope"] * x for x in xs], "-", color="grey", alpha=0.6)
    ax.set_xlabel("b^2")
    ax.set_ylabel("seconds per view")
    ax.set_title("Per-view time against b^2 (least-squares lines)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    fig.tight_layout()
    doc.figure(fig, "xmpvo-scaling.png", "time against b; per-view time against b^2")


def scaling(records, paper, doc):
    doc.title = "XMPVO and BSP-XMPVO: time against the number of exterior faces b"
    doc.intro = (command(records) + ": the gap series (Cook et al. 5.2) at a fixed number of cells; more gaps, "
                 "more exterior faces. XMPVO's per-view cost is O(n + b^2) in the worst case (Silva et al.); "
                 "BSP-XMPVO moves work into a view-independent BSP build and pays per view for beam queries.")
    first = records[0]
    s = first["dataset_spec"]["set"]
    size = f"{s['nx']}x{s['ny']}x{s['nz']} hexes, {first['n']} tets"
    t = doc.table(f"Ours: gap series ({size}), {first['w']}x{first['h']}, Cook's Fig. 11 view "
                  "(mesh turned 45 degrees about x and y)",
                  ["gaps", "b", "XMPVO s/view", "BSP build s", "BSP-XMPVO s/view", "tree work s", "glue s",
                   "SXMPVO s/view", "BSP nodes", "depth", "fragment growth", "relations BSP / XMPVO",
                   "oracle BSP / XMPVO"])
    rows = []
    views = sorted({r["view_index"] for r in records})
    for _, recs in m.group(records, "row"):
        bsp, xm, sx = of(recs, "bsp-xmpvo"), of(recs, "xmpvo"), of(recs, "sxmpvo")
        # Each orderer's per-view time over every view of the mesh, else None and why (no mean over fewer).
        expected = m.expected_keys(recs, views)
        (txm, wxm), (tbsp, wbsp), (tsx, wsx) = (m.complete_mean(o, m.frame_seconds, expected) for o in (xm, bsp, sx))
        row = {"gaps": recs[0]["dataset_spec"]["set"]["gaps"], "b": recs[0]["b"],
               "xmpvo": txm, "bsp": tbsp,
               "bsp_prepare": m.mean(bsp, lambda r: m.get(r, "prepare.phases.BSP build")),
               "sxmpvo": tsx, "why": {"xmpvo": wxm, "bsp": wbsp, "sxmpvo": wsx}}
        rel_bsp, rel_xm = m.mean(bsp, m.counter("relations")), m.mean(xm, m.counter("relations"))
        relations = ("-" if rel_bsp is None else f"{rel_bsp:.0f}") + " / " + ("-" if rel_xm is None else f"{rel_xm:.0f}")
        t.row(row["gaps"], row["b"], wxm or txm, row["bsp_prepare"], wbsp or tbsp,
              m.mean(bsp, m.phase("tree work")), m.mean(bsp, m.phase("glue")), wsx or tsx,
              m.mean(bsp, m.counter("bsp_nodes")), m.mean(bsp, m.counter("bsp_depth")),
              m.mean(bsp, m.counter("fragment_growth")), relations, oracle_cell(bsp) + " / " + oracle_cell(xm))
        rows.append(row)
    bs = [r["b"] for r in rows]
    b2 = [b * b for b in bs]
    fits, notes = {}, []
    have = {k: all(r[k] is not None for r in rows) for k in ("bsp", "xmpvo")}
    fit = {}
    for key in ("bsp", "xmpvo"):
        if have[key]:
            fit[key] = (m.fit_line(bs, [r[key] for r in rows]), m.fit_line(b2, [r[key] for r in rows]))
            if fit[key][1]:
                fits[key] = fit[key][1]
    notes.append("b = exterior faces (triangles here). BSP build = the prepare phase 'BSP build' alone (unique faces "
                 "and planes are shared with every MPVO-family orderer). Per-view times: "
                 f"{frames_text(records)}. ")
    for key, name in (("bsp", "BSP-XMPVO"), ("xmpvo", "XMPVO")):
        f1, f2 = fit.get(key, (None, None))
        if f1 and f2:
            notes.append(f"{name} per view against b: r^2 = {f1['r2']:.3f} (line in b), {f2['r2']:.3f} (line in b^2).")
            notes.append(" " if key == "bsp" else "")
    t.notes = "".join(notes).rstrip()

    def reason(key, name):
        """Why a line cannot be judged: a gap mesh without the orderer's time on all its views, or fewer
        than 3 values of b."""
        lacking = [f"{r['gaps']} gaps ({r['why'][key]})" for r in rows if r[key] is None]
        if lacking:
            return f"; not measured: {name} at {', '.join(lacking)}"
        return f"; not measured: {len(rows)} value{'' if len(rows) == 1 else 's'} of b" if len(rows) < 3 else ""

    f1, f2 = fit.get("bsp", (None, None))
    why = reason("bsp", "BSP-XMPVO")
    f1, f2 = (None, None) if why else (f1, f2)
    doc.claim("BSP-XMPVO's per-view time has a quasi-quadratic term that shows up in practice (Cook et al., section "
              "5.1): a line in b^2 fits better than a line in b" +
              (f" (r^2 {f2['r2']:.3f} in b^2, {f1['r2']:.3f} in b; line in b^2: intercept {f2['intercept']:.3g} s)"
               if f1 and f2 else ""),
              ours=f2["r2"] if f2 else None, paper="a quasi-quadratic term, which seems to show up in practice",
              criterion="r^2 (line in b^2) > r^2 (line in b), over at least 3 values of b (ours: r^2 in b^2)" + why,
              holds=None if not (f1 and f2) else f2["r2"] > f1["r2"], scope={"orderer": "bsp-xmpvo"})
    g1, g2 = fit.get("xmpvo", (None, None))
    why = reason("xmpvo", "XMPVO")
    g1, g2 = (None, None) if why else (g1, g2)
    doc.claim("XMPVO's per-view time is O(n + b^2) (Silva et al., worst case; n fixed here): a line in b^2 fits it "
              "with r^2 >= 0.95" + (f" (r^2 {g2['r2']:.3f} in b^2, {g1['r2']:.3f} in b; intercept "
                                    f"{g2['intercept']:.3g} s, slope {g2['slope']:.3g} s per b^2)" if g1 and g2 else ""),
              ours=g2["r2"] if g2 else None, paper=paper["xmpvo-scaling"]["xmpvo_per_view"],
              criterion="r^2 (line in b^2) >= 0.95 and slope > 0, over at least 3 values of b (ours: r^2 in b^2)" + why,
              holds=None if not (g1 and g2) else g2["r2"] >= 0.95 and g2["slope"] > 0, scope={"orderer": "xmpvo"})
    scaling_figure(rows, fits, size, doc)


# --- xmpvo-stability -------------------------------------------------------------------------

def stability(records, paper, doc):
    doc.title = "XMPVO: double against exact predicates on the hard cases"
    doc.intro = command(records)
    probes = [r for r in records if r.get("probe") == "xmpvo-stability"]
    dis = doc.table("Decisions where plain doubles disagree with the exact predicate (summed over views)",
                    ["data set", "views", "arrow signs", "disagree", "facing", "disagree",
                     "edge-pair crossings", "disagree", "sides at vertices", "disagree"])
    verdict = doc.table("Oracle verdict of the order built from each kind of sign",
                        ["data set", "views", "exact: failing views", "exact: violating pixels",
                         "double: failing views", "double: violating pixels", "cycles exact",
                         "cycles double", "undecided face pairs"])
    sizes = set()
    for row, recs in m.group(probes, "row"):
        r = recs[-1]["result"]
        sizes.add(r.get("size"))
        dis.row(row, r["views"], r["arrows"], r["disagree_arrows"], r["facing"], r["disagree_facing"],
                r["crossings"], r["disagree_crossings"], r["sides"], r["disagree_sides"])
        verdict.row(row, r["views"], r["exact_failing_views"], r["exact_violating_pixels"],
                    r["double_failing_views"], r["double_violating_pixels"], r["exact_cycles"],
                    r["double_cycles"], r["undecided"])
    # Silva et al.: XMPVO is an exact visibility ordering of acyclic meshes.
    acyclic = [recs[-1]["result"] for _, recs in m.group(probes, "row") if recs[-1]["result"]["exact_cycles"] == 0]
    bad = sum(r["exact_failing_views"] for r in acyclic) if acyclic else None
    doc.claim(f"XMPVO with exact predicates orders every acyclic mesh exactly (failing views with exact signs, over "
              f"the {len(acyclic)} data sets without a visibility cycle)", ours=bad,
              paper="an exact visibility ordering for acyclic polyhedral meshes (Silva et al.)",
              criterion="ours == 0", holds=None if bad is None else bad == 0, scope={"probe": "xmpvo-stability"})
    views = max((m.get(r, "result.views", 0) for r in probes), default=0)
    dis.notes = ("Arrow signs: MPVO's double value n.eye + d of every face against the exact sign; the "
                 "double is checked only within its error bound, outside it the two agree by the bound "
                 "(MpvoCore's double_sign_wrong). Facing: eye_side of each exterior face. Edge-pair "
                 "crossings: the proper-crossing verdict of each candidate edge pair. Sides at vertices: "
                 "every side of a projected edge evaluated in the ray queries (coverage and wedges).")
    verdict.notes = ("`exact` is xmpvo:predicates=compare (decides with the exact signs, identical to the "
                     "default); `double` is xmpvo:predicates=double (every sign above in plain doubles, "
                     "MPVO arrows without the error bound; the depth order of two faces stays exact). "
                     f"Hard cases use their own cameras; the others {views} Fibonacci views; "
                     f"{', '.join(sorted(s for s in sizes if s))}, S = 1. "
                     "The touching-* cases are blocks meeting face to face with duplicated nodes: their "
                     "interface faces are coplanar exterior faces, ordered by face_pairs.h's coplanar_order "
                     "(the last column counts face pairs left undecided, 0 on valid input).")


# --- cook-table2 -----------------------------------------------------------------------------

def pixels_label(p):
    return f"{p / 1e6:.3g}M" if p >= 1e6 else f"{p / 1e3:.0f}k"


def phases_text(records):
    names = sorted({k for r in records for k in r.get("phases", {})})
    return ", ".join(f"{k} {m.mean(records, m.phase(k)):.3g}" for k in names)


def bsp_counters_text(bsp):
    c = {k: m.mean(bsp, m.counter(k)) or 0.0 for k in
         ("bsp_nodes", "bsp_depth", "fragment_growth", "beam_queries", "nodes_visited", "early_stops", "bytes_bsp")}
    return (f"BSP nodes {c['bsp_nodes']:.0f}, depth {c['bsp_depth']:.0f}, fragment growth {c['fragment_growth']:.3g}"
            f", beams {c['beam_queries']:.0f}, nodes visited {c['nodes_visited']:.0f}, early stops {c['early_stops']:.0f}"
            f", BSP bytes {c['bytes_bsp'] / 1048576.0:.3g} MB")


def stands_for(row):
    """The paper's data set a row stands in for, from the suite's label: 'tet-femur (for bluntfin)'
    and 'helix 600 (tiny, for bluntfin)' -> 'bluntfin'; None when the label names none."""
    g = re.search(r"\bfor ([^(),]+?)\)\s*$", row or "")
    return g.group(1) if g else None


# The suites the SXMPVO / BSP-XMPVO claims read: BSP-XMPVO and SXMPVO at the smallest image.
SXMPVO_OVER_BSP = ["bsp-xmpvo", "sxmpvo-170k"]


def cook_table2(records, paper, doc):
    p = paper["cook-table2"]
    labels = [pixels_label(x) for x in p["pixels"]]
    doc.title = "Cook et al. Table 2: BSP-XMPVO and XMPVO beside SXMPVO"
    orderer_recs = [r for r in records if "orderer" in r]
    # Our rows paired with the paper's by the data set each stands in for (cook-table2.json's "data set",
    # named in the suite's label), never by position: a data set without records is its own row.
    by_name = {}
    for row, recs in m.group(orderer_recs, "row"):
        by_name.setdefault(stands_for(row), []).append((row, recs))
    paired = [(pr, by_name.get(pr["data set"], [])) for pr in p["rows"]]
    known = {pr["data set"] for pr in p["rows"]}
    unpaired = [g for name, gs in by_name.items() if name not in known for g in gs]
    stand_ins = [f"{row}, {recs[0]['n']:,} cells, for {pr['data set']}'s {pr['n']:,}"
                 for pr, gs in paired for row, recs in gs]
    stand_ins += [f"{row} (stands in for none of the paper's rows)" for row, _ in unpaired]
    doc.intro = command(records) + ". Stand-ins: " + ("; ".join(stand_ins) or "none measured") + "."
    bsp_all = of(orderer_recs, "bsp-xmpvo")
    nviews = len({r["view_index"] for r in bsp_all}) if bsp_all else 0
    total_views = bsp_all[0]["views"] if bsp_all else 14
    ours = doc.table(f"Ours: seconds per view (mean of {nviews} views of {total_views})",
                     ["data set", "n", "b", "BSP-XMPVO prep.", "BSP-XMPVO", "XMPVO"] +
                     [f"SXMPVO {x}" for x in labels] +
                     [f"oracle at {labels[0]}: BSP-XMPVO / XMPVO / SXMPVO"])
    detail = doc.table("Ours: phases and counters of the object-space orderers (per view, mean)",
                       ["data set", "orderer", "phases (s)", "relations", "other counters"])
    sx_sizes = []
    # The paper's rows in its order, each with our stand-in's rows or one row saying why there are none;
    # then rows that stand in for none of the paper's.
    for pr, gs in paired + [(None, [g]) for g in unpaired]:
        if pr and not gs:
            name = pr["data set"]
            cell = "not run" if name in p.get("not_run", {}) else "not measured"
            ours.row(f"{name}: {cell}", pr["n"], pr["b"], *([cell] * (len(ours.columns) - 3)))
            detail.row(name, "-", cell, None, p["not_run"][name] if cell == "not run"
                       else f"no records of a stand-in for {name}")
        for row, recs in gs:
            bsp, xm, sx = of(recs, "bsp-xmpvo"), of(recs, "xmpvo"), of(recs, "sxmpvo")
            # By the suite's size entry: with fitted windows each view has its own w x h.
            by_pixels = sorted(m.group(sx, lambda r: size_entry(r)[0] * size_entry(r)[1]), key=lambda g: g[0])
            sx_sizes = ["%dx%d" % size_entry(g[1][0]) for g in by_pixels]
            sx_times = [m.mean(g[1], m.frame_seconds) for g in by_pixels]
            sx_times += [None] * (len(labels) - len(sx_times))
            first = by_pixels[0][1] if by_pixels else []
            ours.row(row, recs[0]["n"], recs[0]["b"], m.mean(bsp, m.prepare_seconds), m.mean(bsp, m.frame_seconds),
                     m.mean(xm, m.frame_seconds), *sx_times[:len(labels)],
                     oracle_cell(bsp) + " / " + oracle_cell(xm) + " / " + oracle_cell(first))
            detail.row(row, "bsp-xmpvo", phases_text(bsp), m.mean(bsp, m.counter("relations")), bsp_counters_text(bsp))
            if xm:
                detail.row(row, "xmpvo", phases_text(xm), m.mean(xm, m.counter("relations")), "")
    # 'In addition to being faster, the SXMPVO algorithm has the following advantages over BSP-XMPVO'.
    # Both sides over the same views (every view of the reproduction), else not measured; a data set the
    # paper times BSP-XMPVO on but we have no records of is not measured too, never left out.
    all_views = {r["view_index"] for r in orderer_recs}
    for pr, row, recs in [(pr, row, recs) for pr, gs in paired for row, recs in gs or [(None, None)]]:
        pq = m.ratio(P.value(pr["sxmpvo"][0]), P.value(pr["bsp_xmpvo"]))
        if recs is None:
            if pr["data set"] not in p.get("not_run", {}):
                doc.claim(f"SXMPVO is faster than BSP-XMPVO per view for {pr['data set']} (ours: SXMPVO at the "
                          "smallest image / BSP-XMPVO, seconds per view)", ours=None,
                          paper="-" if pq is None else f"{pr['sxmpvo'][0]} / {pr['bsp_xmpvo']} = {pq:.2f} "
                          "(different machines)",
                          criterion=f"ours < 1; not measured: no records of a stand-in for {pr['data set']}",
                          holds=None, scope={"row": doc.row_labels(lambda r, d=pr["data set"]: stands_for(r) == d)})
            continue
        bsp = of(recs, "bsp-xmpvo")
        sx = of(recs, "sxmpvo")
        small = min((size_entry(r) for r in sx), key=lambda e: e[0] * e[1], default=None)
        sx_small = [r for r in sx if size_entry(r) == small]
        lacking = []
        for name, rs in (("BSP-XMPVO", bsp), ("SXMPVO", sx_small)):
            have = {r["view_index"] for r in rs if m.frame_seconds(r) is not None} & all_views
            if have != all_views:
                lacking.append(f"{name} {m.views_text(len(have), len(all_views))}")
        q = None if lacking else m.ratio(m.mean(sx_small, m.frame_seconds), m.mean(bsp, m.frame_seconds))
        doc.claim(f"SXMPVO is faster than BSP-XMPVO per view on {row} (for {pr['data set']}; ours: SXMPVO at the "
                  "smallest image / BSP-XMPVO, seconds per view)", ours=q,
                  paper="-" if pq is None else f"{pr['sxmpvo'][0]} / {pr['bsp_xmpvo']} = {pq:.2f} (different machines)",
                  criterion="ours < 1" + (f"; not measured: {'; '.join(lacking)}" if lacking else ""),
                  holds=None if q is None else q < 1, scope={"row": row, "suite": SXMPVO_OVER_BSP})
    win = window_text(bsp_all) if bsp_all else "-"
    full = records[0].get("scale") == "full"
    sx_any = of(orderer_recs, "sxmpvo")
    ours.notes = ("BSP-XMPVO prep. = its whole prepare (unique faces, face planes, BSP build). BSP-XMPVO and XMPVO "
                  "are object-space orderers: their per-view time does not depend on the image, so they are timed "
                  f"once per view ({win}; " +
                  ("3 repeats" if full else "1 frame after a warm-up for BSP-XMPVO, 1 frame for XMPVO; --full repeats") +
                  f"). SXMPVO: {frames_text(sx_any) if sx_any else 'median of 3 frames after a warm-up'} per view and "
                  f"size ({', '.join(sx_sizes)}" + (", each window fitted to the bounding box at that pixel count"
                                                    if fitted(sx_any) else "") +
                  f"). The oracle checks every orderer on the same views ({win}).")
    machines = paper["machines"]
    pt = doc.table(f"Paper, {p['table']} (SXMPVO on the {machines[p['machines']['SXMPVO']]}; BSP-XMPVO on a "
                   f"{machines[p['machines']['BSP-XMPVO']]}; {p['units']})",
                   ["data set", "n", "BSP-XMPVO"] + [f"SXMPVO {x}" for x in labels])
    for pr in p["rows"]:
        pt.row(pr["data set"], pr["n"], pr["bsp_xmpvo"], *pr["sxmpvo"])
    pt.notes = ("; ".join(f"{pr['data set']}: b = {pr['b']:,}" + (" exterior faces" if i == 0 else "")
                          for i, pr in enumerate(p["rows"])) +
                f" ({p['b_source']}). {p['notes']}")


TABLES = {"xmpvo-scaling": scaling, "xmpvo-stability": stability, "cook-table2": cook_table2}
