"""Cook, Max, Silva, Williams (SXMPVO): the tables, claims and figures of the cook-*
reproductions, from stored records only (docs/pipeline.md). Paper numbers: cook.json."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from vobtables import metrics as m  # noqa: E402
from vobtables import paper as P  # noqa: E402
from vobtables import images as img  # noqa: E402
from papers.cook_common import (PHASES, at_size, by_row, command, finish_figure, fitted, machine, mb,  # noqa: E402
                                label, paper_table, size_entry, size_name, size_note, views_violating,
                                window_text)


# --- Table 1 ----------------------------------------------------------------------------------

def table1(records, paper, doc):
    doc.title = "Cook et al. Table 1: parameters of the analysis"
    doc.intro = (command("cook-table1", records) + ": n cells, b exterior faces, a = projected exterior-face "
                 "area in pixels (pixel centres covered, summed over faces).")
    t = doc.table(f"Ours: parameters, {window_text(records)} (a and w*h: mean over "
                  f"{len({r['view_index'] for r in records})} views)",
                  ["data set", "n", "n/log2 n", "b", "a", "w*h"])
    below = []
    for row, recs in by_row(records):
        n, b = recs[0]["n"], recs[0]["b"]
        nlog = round(n / math.log2(n))
        t.row(row, n, nlog, b, round(m.mean(recs, lambda r: r.get("a"))), round(m.mean(recs, lambda r: r["w"] * r["h"])))
        below.append(b < nlog)
    t.notes = (size_note(records, "nothing: the default already runs Table 1's six helices and the paper's 1.5M-cell gap meshes") +
               " Gap meshes: block of 6 tets per hex, gaps empty slabs across z (Cook 5.2).")
    paper_table(doc, paper["table1"], "Paper, Table 1",
                "Typed in from the paper's Table 1 (image sizes per data set).")
    prow = paper["table1"]["rows"]
    # The suite asks helix for each paper helix's n and b (`cells`, `faces`): ours within 5%?
    for name, pn, _, pb, *_ in (r for r in prow if r[0].startswith("helix")):
        recs = [r for r in records if r.get("dataset_spec", {}).get("name") == "helix" and
                r["dataset_spec"].get("set", {}).get("cells") == pn and r["dataset_spec"]["set"].get("faces") == pb]
        dn = db = None
        if recs:
            dn, db = recs[0]["n"] / pn - 1, recs[0]["b"] / pb - 1
        doc.claim(f"our helix for {name} has the paper's n and b (relative differences; "
                  + ("not run at this scale" if not recs else f"ours n = {recs[0]['n']:,}, b = {recs[0]['b']:,}") + ")",
                  ours=None if not recs else f"n {dn:+.2%}, b {db:+.2%}", paper=f"n = {pn}, b = {pb}",
                  criterion="abs(n / paper n - 1) <= 5% and abs(b / paper b - 1) <= 5%",
                  holds=None if not recs else (abs(dn) <= 0.05 and abs(db) <= 0.05),
                  scope={"row": label({"dataset_spec": {"name": "helix", "set": {"cells": pn, "faces": pb}}})})
    doc.claim("typically b is below n/log2 n, so sorting the exterior faces is O(n) (share of data sets)",
              ours=sum(below) / len(below), paper=sum(r[3] < r[2] for r in prow) / len(prow),
              criterion="ours >= 0.5", holds=sum(below) / len(below) >= 0.5, scope={"row": doc.row_labels()})


# --- Table 3 ----------------------------------------------------------------------------------

def table3(records, paper, doc):
    doc.title = "Cook et al. Table 3: SXMPVO's four phases"
    views = sorted({r["view_index"] for r in records})
    nviews = len(views)
    win = window_text(records)
    doc.intro = (command("cook-table3", records) + f": sxmpvo on helices with Table 1's n and b and on real meshes, "
                 f"{nviews} views, {win} (Table 1's w*h per data set).")
    ours = doc.table(f"Ours: seconds per frame, {win} (mean over the views where every phase and the total were "
                     f"recorded, of the {nviews} views asked; median of {records[0]['repeats']} runs)",
                     ["data set", "n", "views matched", "I", "II", "III", "IV", "total", "oracle (views violating)"],
                     size_note(records, "helix 1.0M, 2.37M, 3.57M and 4.5M (the 4.5M helix needs about 4 GB)"))
    paper_table(doc, paper["table3"], f"Paper, Table 3 ({machine(paper, 'onyx')})", "Image sizes of Table 1.")
    shares = doc.table("Share of each phase in the total (%): ours, then the paper's (computed from Table 3)",
                       ["data set", "I %", "II %", "III %", "IV %", "largest phase"],
                       decimals={c: 1 for c in ("I %", "II %", "III %", "IV %")})
    # Each data set's phases and total over the same views (matched views): a view that lacks one of them
    # is left out of every column of the row, and a row with fewer views than asked leaves the claims
    # below not measured.
    matched, short = {}, {}
    for row, recs in by_row(records):
        expected = m.expected_keys(recs, views)
        means, common, lacking = m.matched_means({**{p: (recs, m.phase(p)) for p in PHASES},
                                                  "total": (recs, m.frame_seconds)}, expected)
        matched[row] = (means, [r for r in recs if m.match_key(r) in common], m.matched_text(common, expected))
        if lacking:
            short[row] = [f"{len(common)} of {len(expected)} views matched"]
    for row, (means, _, _) in matched.items():
        ph = [means[p] for p in PHASES]
        tot = sum(v for v in ph if v is not None) or None
        pc = [None if v is None or not tot else 100 * v / tot for v in ph]
        big = max(range(4), key=lambda i: pc[i] or 0)
        shares.row(f"ours: {row}", *pc, ["I", "II", "III", "IV"][big])
    p3 = paper["table3"]
    for j, col in enumerate(p3["columns"][1:], start=1):
        vals = [P.value(r[j]) for r in p3["rows"][:4]]
        tot = P.value(p3["rows"][4][j])
        pc = [100 * v / tot for v in vals]
        shares.row(f"paper (computed): {col}", *pc, ["I", "II", "III", "IV"][max(range(4), key=lambda i: pc[i])])
    counts = doc.table("Ours: PN relations and A-buffer (matched views)",
                       ["data set", "a (entries)", "head insertion rate", "PN pairs", "PN relations",
                        "found at head", "moved to front", "tie reorders", "unpaired"])
    mem = doc.table("Ours: memory per structure (MB; matched views)",
                    ["data set", "mesh", "faces+planes", "MPVO arrays", "A-buffer", "PN lists", "exterior list"])
    mp = paper["memory"]
    mem.notes = (f"Paper, helix3.5 (3.57M cells): vertices {mp['MB']['vertices']} MB, cells {mp['MB']['cells']} MB, "
                 f"face structures {mp['MB']['face structures']} MB; A-buffer {mp['MB']['A-buffer at 375x450']} MB at "
                 f"375x450 (a = {mp['a at 375x450']:,}) and {mp['MB']['A-buffer at 1M pixels']} MB at 1M pixels "
                 f"(a = {mp['a at 1M pixels']:,}); PN structures {mp['MB']['PN structures']} MB (per-cell list pointers, "
                 f"{mp['PN dependencies']:,} dependencies); exterior face list {mp['MB']['exterior face list']} MB; "
                 f"total {mp['MB']['SXMPVO total']} MB. Our A-buffer entry is 16 bytes (double depth, cell and facing, "
                 "next) plus a 4-byte head per pixel; PN lists are a 4-byte head per cell plus 8 bytes per relation, "
                 "plus their CSR copy.")
    rates = []
    for row, recs in by_row(records):
        means, recs_m, views_cell = matched[row]
        c = lambda k: m.mean(recs_m, m.counter(k))  # noqa: E731
        ours.row(row, recs[0]["n"], views_cell, *[means[p] for p in PHASES], means["total"], views_violating(recs))
        counts.row(row, c("abuffer_entries"), c("head_insertion_rate"), c("pn_pairs"), c("pn_relations"),
                   c("pn_found_at_head"), c("pn_moved_to_front"), c("tie_reorders"), c("unpaired_entries"))
        mem.row(row, mb(m.mean(recs_m, lambda r: m.get(r, "bytes.scene"))), mb(c("bytes_faces")), mb(c("bytes_mpvo")),
                mb(c("bytes_abuffer")), mb(c("bytes_pn")), mb(c("bytes_exterior")))
        rates += m.values(recs, m.counter("head_insertion_rate"))
    if short:
        ours.notes += (" Rows with fewer matched views than asked: " +
                       "; ".join(f"{row} ({v[0]})" for row, v in short.items()) + ".")
    # 'any view' and 'every view' are judged only when every data set has every view asked.
    why = m.short_rows_reason(short)
    low = min(rates) if rates and not short else None
    doc.claim("insertions into the PIX lists occur at the head more than 99 percent of the time (lowest rate, any view)",
              ours=low, paper=paper["claims"]["head insertion rate"], criterion="ours > 0.99" + why,
              holds=None if low is None else low > 0.99, scope={"row": doc.row_labels()})
    bad = None if short else views_violating(records)
    doc.claim("SXMPVO's order passes the oracle on every view (views violating)", ours=bad, paper=0,
              criterion="ours == 0" + why, holds=None if bad is None else bad == 0, scope={"row": doc.row_labels()})


# --- Table 4 ----------------------------------------------------------------------------------

ORDERERS4 = (("sxmpvo", "SXMPVO"), ("mpvonc", "MPVONC"), ("vtk-centroid", "vtk-centroid"))
PAIR4 = ["sxmpvo", "mpvonc"]  # what the SXMPVO/MPVONC claims read (vtk-centroid is only shown)


def table4(records, paper, doc):
    name = records[0].get("reproduction", "cook-table4")
    cond = "the paper's conditions" if fitted(records) else "our condition, not the paper's"
    doc.title = f"Cook et al. Table 4: SXMPVO against MPVONC by mesh size ({cond})"
    doc.intro = command(name, records) + ": sxmpvo, mpvonc and vtk-centroid in the same run, same views."
    w, h = records[0]["w"], records[0]["h"]
    # Every orderer of every data set is measured on the same views: a mean or a ratio is shown
    # only over all of them, never over fewer (or over different ones for two orderers).
    views = sorted({r["view_index"] for r in records})
    nviews = len(views)
    ours = doc.table(f"Ours ({cond}): seconds per frame, {window_text(records)} (mean of {nviews} views, "
                     f"median of {records[0]['repeats']} runs)",
                     ["data set", "n", "SXMPVO", "MPVONC", "vtk-centroid", "SXMPVO/MPVONC", "SXMPVO/VTK"])
    rows, recs_of = [], {}
    expected = {}
    for row, recs in by_row(records):
        expected[row] = m.expected_keys(recs, views)
        t, why = {}, {}
        for o, _ in ORDERERS4:
            t[o], why[o] = m.complete_mean(m.select(recs, orderer=o), m.frame_seconds, expected[row])
        rows.append((row, recs[0]["n"], t, why))
        recs_of[row] = recs
        ours.row(row, recs[0]["n"], *[why[o] or t[o] for o, _ in ORDERERS4],
                 m.ratio(t["sxmpvo"], t["mpvonc"]), m.ratio(t["sxmpvo"], t["vtk-centroid"]))
    if any(w for _, _, _, why in rows for w in why.values()):
        ours.title = ours.title[:-1] + "; where an orderer lacks views of a data set, its cell says so)"
    helices = sorted((r for r in rows if r[0].startswith("helix")), key=lambda r: r[1])  # sizes may come out of order
    # Each orderer's line over its own records: one orderer's missing records never hide another's.
    lines = {}
    for o, who in ORDERERS4:
        pts = [(n, t[o]) for _, n, t, _ in helices if t[o] is not None]
        gaps = [f"{who} on {row}: {'no records' if why[o] == 'not measured' else why[o]}"
                for row, _, _, why in helices if why[o]]
        # Judged (and drawn, and noted) only over every helix size, and at least 3 of them.
        reason = ("; ".join(gaps) if gaps else
                  f"{len(pts)} helix size{'' if len(pts) == 1 else 's'}" if len(pts) < 3 else "")
        lines[o] = (pts, None if reason else m.fit_line([p[0] for p in pts], [p[1] for p in pts]), reason)
    fs, fn = lines["sxmpvo"][1], lines["mpvonc"][1]
    ours.notes = size_note(records, "helix 1.0M-4.5M")
    fitted_text = [f"{who} %.3g us per cell (r^2 = %.4f)" % (lines[o][1]["slope"] * 1e6, lines[o][1]["r2"])
                   for o, who in ORDERERS4[:2] if lines[o][1]]
    if fitted_text:
        ours.notes += " Linear fit over the helices: " + ", ".join(fitted_text) + "."
    p = paper["table4"]
    pt = doc.table(f"Paper, Table 4 ({machine(paper, 'onyx')})", ["n", "SXMPVO", "MPVONC", "ratio (computed)"],
                   "Image sizes of Table 1 (about 170k pixels); the ratio is computed from the paper's two columns.")
    pq = {n: P.value(sx) / P.value(nc) for n, sx, nc in p["rows"]}
    for n, sx, nc in p["rows"]:
        pt.row(n, sx, nc, "%.2f" % pq[n])
    # 'For data sets with more than 100,000 cells ... at about the same speed as the MPVONC heuristic':
    # the paper calls ratios up to its largest such ratio (0.60 / 0.35 = 1.71 at 187,395 cells) 'about the same'.
    about = paper["claims"]["about as fast as mpvonc"]
    above = about["cells above"]
    hi = max(q for n, q in pq.items() if n > above)
    hi_n = max((n for n in pq if n > above), key=lambda n: pq[n])
    # One claim per Table 4 mesh above 100,000 cells (our helix with the paper's n; measured or not, so
    # none drops out with its records), then any other mesh we measured above it (the gap mesh, helices
    # of --full that Table 4 does not list).
    def cells_of(row):
        spec = recs_of[row][0].get("dataset_spec") or {}
        return (spec.get("set") or {}).get("cells") if spec.get("name") == "helix" else None

    listed, judged_rows = [], set()
    for pn in sorted(k for k in pq if k > above):
        hit = [r for r in rows if cells_of(r[0]) == pn]
        listed.append(hit[0] if hit else (f"helix {pn / 1e6:.3g}M", pn, None, None))
        judged_rows.update(r[0] for r in hit[:1])
    listed += [r for r in rows if r[1] > above and r[0] not in judged_rows]
    for row, n, t, why in listed:
        if t is None:
            q = v = None
            missing = f"no records of a helix with the paper's n = {n:,}"
        else:
            q, v = m.ratio(t["sxmpvo"], t["mpvonc"]), m.ratio(t["sxmpvo"], t["vtk-centroid"])
            missing = "; ".join(f"{who} {why[o]}" for o, who in ORDERERS4[:2] if why[o])
        near = min(pq, key=lambda k: abs(k - n))
        doc.claim(f"SXMPVO at about the same speed as MPVONC for more than {above:,} cells: SXMPVO/MPVONC on {row} "
                  f"({'not run' if t is None else f'n = {n:,}'}; SXMPVO/vtk-centroid = "
                  f"{'-' if v is None else '%.2f' % v})",
                  ours=q, paper=f"{pq[near]:.2f} at n = {near:,} (Table 4)",
                  criterion=f"ours <= {hi:.2f} (the largest ratio the paper calls about the same: Table 4 at n = {hi_n:,})"
                  + (f"; not measured: {missing}" if missing else ""),
                  holds=None if q is None else q <= hi, scope={"row": row, "orderer": PAIR4})
        # Table 4's ratios from 1M cells on are 1.01 to 1.20: issue 16 asks for that band at every size above
        # 100k, on the mean and on the worst view, which is stricter than the paper's own 1.71.
        worst = None if q is None else max(view_ratios(recs_of[row], expected[row]).values())
        n_text = f"n = {n:,}" if t is not None else "not run"
        doc.claim(f"our check, not a claim of the paper (issue 16): SXMPVO/MPVONC within Table 4's large-mesh band "
                  f"on {row} ({n_text}), mean over views and worst view "
                  f"({'-' if worst is None else '%.2f' % worst})",
                  ours=q, paper=f"{min(pq[k] for k in pq if k >= 1000000):.2f} to "
                  f"{max(pq[k] for k in pq if k >= 1000000):.2f} (Table 4, n >= 1,000,000)",
                  criterion="ours <= 1.20 and worst view <= 1.20" + (f"; not measured: {missing}" if missing else ""),
                  holds=None if q is None or worst is None else (q <= 1.2 and worst <= 1.2),
                  scope={"row": row, "orderer": PAIR4})
    smallest, unpaired = min_view_ratio(records, expected)
    doc.claim("SXMPVO is always slower than MPVONC, for every data set and view (smallest SXMPVO/MPVONC over "
              "data sets and views)", ours=smallest,
              paper=f"{min(pq.values()):.2f} (smallest ratio in Table 4); {paper['claims']['always slower']}",
              criterion="ours > 1" + (f"; not measured: {'; '.join(unpaired)}" if unpaired else ""),
              holds=None if smallest is None else smallest > 1, scope={"orderer": PAIR4})
    # 'The time for both MPVONC and SXMPVO grows approximately linearly in the number of cells.'
    for o, who in ORDERERS4[:2]:
        pts, f, reason = lines[o]
        doc.claim(f"{who} time grows approximately linearly in the number of cells (helices; least-squares line "
                  + ("-" if not f or reason else f"{f['slope'] * 1e6:.3g} us per cell, intercept {f['intercept']:.3g} s")
                  + ")",
                  ours=None if not f or reason else f["r2"], paper="grows approximately linearly",
                  criterion="r^2 of the line >= 0.95 over at least 3 helix sizes"
                  + (f"; not measured: {reason}" if reason else ""),
                  holds=None if not f or reason else f["r2"] >= 0.95,
                  scope={"orderer": o, "row": doc.row_labels(lambda row: row.startswith("helix"))})
    if any(pts for pts, _, _ in lines.values()):
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        xmax = max(n for pts, _, _ in lines.values() for n, _ in pts)
        for o, who in ORDERERS4:
            pts = lines[o][0]
            if pts:
                ax.plot([x for x, _ in pts], [y for _, y in pts], "o-", label=who)
        for f in (fs, fn):
            if f:
                ax.plot([0, xmax], [f["intercept"], f["intercept"] + f["slope"] * xmax], ":", color="grey")
        finish_figure(doc, fig, ax, "cells n (helix)",
                      "seconds per frame (%s)" % ("fitted windows" if fitted(records) else f"{w}x{h}"),
                      f"SXMPVO vs MPVONC by mesh size (fits dotted; {cond})",
                      f"{name}-time-by-n.png", "time against n over the helices (each orderer where all its "
                      "views were measured), with linear fits")


def view_ratios(recs, expected):
    """{match key: SXMPVO / MPVONC frame time} over the keys of one data set measured by both."""
    out = {}
    for k in sorted(expected, key=str):
        sx = [r for r in m.select(recs, orderer="sxmpvo") if m.match_key(r) == k]
        nc = [r for r in m.select(recs, orderer="mpvonc") if m.match_key(r) == k]
        q = m.ratio(m.mean(sx, m.frame_seconds), m.mean(nc, m.frame_seconds))
        if q is not None:
            out[k] = q
    return out


def min_view_ratio(records, expected):
    """(the smallest SXMPVO / MPVONC frame time over every data set and expected view, or None;
    what lacks a side: ['ROW: no SXMPVO record at views V, ...']). expected: {row: match keys}."""
    out, unpaired = [], []
    for row, recs in by_row(records):
        got = view_ratios(recs, expected[row])
        out += got.values()
        for o, who in ORDERERS4[:2]:
            have = {m.match_key(r) for r in m.select(recs, orderer=o) if m.frame_seconds(r) is not None}
            lost = sorted({k[0] for k in expected[row] - have}, key=str)
            if lost:
                unpaired.append(f"{row}: no {who} record at view{'s' if len(lost) > 1 else ''} "
                                + ", ".join(map(str, lost)))
    return (min(out) if out and not unpaired else None), unpaired


# --- Tables 2 and 5 ---------------------------------------------------------------------------

def table2_5(records, paper, doc):
    doc.title = "Cook et al. Tables 2 and 5: SXMPVO time against image size"
    doc.intro = command("cook-table2-5", records)
    sizes = sorted({size_entry(r) for r in records}, key=lambda s: s[0] * s[1])
    nviews = len({r["view_index"] for r in records})
    ours = doc.table(f"Ours: SXMPVO seconds per frame (mean of {nviews} views; phase III in brackets)",
                     ["data set", "n"] + [size_name(*s) for s in sizes] + ["oracle (views violating)"])
    checked = sorted({size_entry(r) for r in records if "oracle" in r}, key=lambda s: s[0] * s[1])
    ours.notes = (size_note(records, "the 1.485M helix (default 450k)") + " The oracle checks every view up to "
                  + (size_name(*checked[-1]) if checked else "no size") + " pixels.")
    series, growing = [], []
    for row, recs in by_row(records):
        cells, times = [], []
        for w, h in sizes:
            at = at_size(recs, (w, h))
            tot, ph3 = m.mean(at, m.frame_seconds), m.mean(at, m.phase(PHASES[2]))
            cells.append("-" if tot is None else "%.3f (%.3f)" % (tot, ph3))
            times.append(tot)
        ours.row(row, recs[0]["n"], *cells, views_violating(recs))
        series.append((row, times))
        if None not in times and len(times) > 1:
            growing.append(times[-1] > times[0])
    p2 = paper["table2"]
    paper_table(doc, p2, f"Paper, Table 2 (SXMPVO on the {machine(paper, 'onyx')}; BSP-XMPVO on a 333 MHz PowerPC)", "")
    paper_table(doc, paper["table5"], f"Paper, Table 5 ({machine(paper, 'p4')})",
                "Window size matched to the data set's bounding box; " +
                ("ours too, at each column's pixel count." if fitted(records) else "ours are square."))
    doc.claim("SXMPVO time grows with image size (data sets slower at the largest size than at the smallest)",
              ours=sum(growing), paper="larger in every row of Tables 2 and 5",
              criterion=f"ours == {len(growing)} (every data set measured at every size)",
              holds=all(growing) if growing else None, scope={"row": doc.row_labels()})
    shares = []
    for row, recs in by_row(records):
        lo_s, hi_s = sizes[0], sizes[-1]
        a_, b_ = at_size(recs, lo_s), at_size(recs, hi_s)
        dt = None if not a_ or not b_ else m.mean(b_, m.frame_seconds) - m.mean(a_, m.frame_seconds)
        d3 = None if not a_ or not b_ else m.mean(b_, m.phase(PHASES[2])) - m.mean(a_, m.phase(PHASES[2]))
        if dt and d3 is not None and len(sizes) > 1:
            shares.append((row, d3 / dt))
    low = min(shares, key=lambda x: x[1]) if shares else None
    # Its scope: the smallest and largest size planned, so a size never reached leaves it not measured.
    ends = sorted(set(sizes) | {size_entry(j) for j in doc.planned if j.get("w")}, key=lambda s: s[0] * s[1])
    doc.claim("the change in timing with image size is due almost entirely to Phase III (lowest share of phase III "
              "in the change from the smallest to the largest size" + (f", on {low[0]})" if low else ")"),
              ours=low[1] if low else None, paper=p2["note"],
              criterion="ours >= 0.8 on every data set ('almost entirely': at least 80% of the change)",
              holds=None if low is None else low[1] >= 0.8,
              scope={"size": ["%dx%d" % ends[0], "%dx%d" % ends[-1]]})
    bad = views_violating(records)
    # The oracle runs in the suite "checked" only (the 2M column has none).
    doc.claim("SXMPVO's order passes the oracle at every checked size (views violating)", ours=bad, paper=0,
              criterion="ours == 0", holds=bad == 0, scope={"suite": "checked"})
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for row, times in series:
        ax.plot([w * h for w, h in sizes], times, "o-", label=row)
    finish_figure(doc, fig, ax, "image size (pixels)", "SXMPVO seconds per frame", "SXMPVO time against image size",
                  "cook-table2-5.png", "SXMPVO time against image size")


# --- Table 6 ----------------------------------------------------------------------------------

def table6(records, paper, doc):
    doc.title = "Cook et al. Table 6: tiny cells against image size"
    doc.intro = command("cook-table6", records)
    sides = sorted({m.get(r, "result.side") for r in records})
    view = records[0]["result"]["view_index"]
    t = doc.table(f"Ours: tiny cells (no pixel centre), view {view} of 14",
                  ["data set", "n"] + [size_name(s, s) for s in sides])
    t.notes = (size_note(records, "the 1.485M helix and 1.5M gap mesh") +
               (" Windows fitted to the bounding box at each column's pixel count, as the paper's."
                if all(m.get(r, "result.fit") for r in records) else
                " Square images; the whole bounding sphere is in view, so the mesh covers a smaller share of the "
                "image than the paper's windows fitted to the bounding box."))
    helix_tiny, helix_lacking, shrinking, lacking = [], [], [], []
    for row, recs in by_row(records):
        counts = [m.get((m.select(recs, **{"result.side": s}) or [{}])[0], "result.tiny_cells") for s in sides]
        t.row(row, recs[0]["n"], *counts)
        absent = [size_name(s, s) for s, c in zip(sides, counts) if c is None]
        if row.startswith("helix"):
            helix_tiny += [c for c in counts if c is not None]
            helix_lacking += [f"{row} at {x}" for x in absent]
        if absent:
            lacking.append(f"{row} at {', '.join(absent)}")
        else:
            shrinking.append(all(a >= b for a, b in zip(counts, counts[1:])))
    paper_table(doc, paper["table6"], "Paper, Table 6")
    # A data set or size without its count leaves the claim not measured (said), never judged on the rest.
    doc.claim("the helix has no tiny cells at any image size (most tiny cells over sizes)",
              ours=max(helix_tiny) if helix_tiny and not helix_lacking else None, paper=0,
              criterion="ours == 0" + (f"; not measured: no count for {'; '.join(helix_lacking)}" if helix_lacking
                                       else "" if helix_tiny else "; not measured: no helix"),
              holds=max(helix_tiny) == 0 if helix_tiny and not helix_lacking else None,
              scope={"row": doc.row_labels(lambda row: row.startswith("helix"))})
    reason = ("no count for " + "; ".join(lacking) if lacking else
              f"{len(sides)} image size{'' if len(sides) == 1 else 's'}" if len(sides) < 2 else "")
    doc.claim("fewer tiny cells at larger images (data sets whose count never grows with size)",
              ours=None if reason else sum(shrinking), paper="never more at a larger size, in every row of Table 6",
              criterion=f"ours == {len(shrinking) + len(lacking)} (every data set measured at every size)"
              + (f"; not measured: {reason}" if reason else ""),
              holds=None if reason or not shrinking else all(shrinking), scope={"row": doc.row_labels()})


# --- Fig. 11 ----------------------------------------------------------------------------------

def fig11(records, paper, doc):
    doc.title = "Cook et al. Fig. 11: time against exterior-face area"
    doc.intro = (command("cook-fig11", records) + f": gap meshes with 0 to 95 gaps. Paper ({machine(paper, 'onyx')}): "
                 "time linear in a, for 1.5M cells and up to 1,000,000 exterior faces at 375x450.")
    w, h = records[0]["w"], records[0]["h"]
    t = doc.table(f"Ours: SXMPVO at {w}x{h}, mesh turned 45 degrees about x and y",
                  ["gaps", "n", "b", "a", "SXMPVO s", "III s", "MPVONC s", "head insertion rate", "PN relations", "oracle"])
    views = sorted({r["view_index"] for r in records})
    pts, lacking = [], []
    for _, recs in m.group(records, lambda r: int(r["dataset_spec"]["set"]["gaps"])):
        sx, nc = m.select(recs, orderer="sxmpvo"), m.select(recs, orderer="mpvonc")
        gaps = int(recs[0]["dataset_spec"]["set"]["gaps"])
        # Each mesh's values over all its views, else the cell says what is missing (no mean over fewer).
        expected = m.expected_keys(recs, views)
        a, why_a = m.complete_mean(sx, m.counter("abuffer_entries"), expected)
        ts, why_s = m.complete_mean(sx, m.frame_seconds, expected)
        tn, why_n = m.complete_mean(nc, m.frame_seconds, expected)
        whole = not why_s
        ok = None if not sx or "oracle" not in sx[0] else ("violations" if views_violating(sx) else "ok")
        t.row(gaps, recs[0]["n"], recs[0]["b"], why_a or a, why_s or ts,
              m.mean(sx, m.phase(PHASES[2])) if whole else None, why_n or tn,
              m.mean(sx, m.counter("head_insertion_rate")) if whole else None,
              m.mean(sx, m.counter("pn_relations")) if whole else None, ok)
        if a is not None and ts is not None:
            pts.append((gaps, a, ts, tn))
        else:
            lacking.append(f"{gaps} gaps: SXMPVO " + ("time " + why_s if why_s else "a " + why_a))
    pts.sort()
    f = m.fit_line([p[1] for p in pts], [p[2] for p in pts])
    # Fewer than 3 meshes, or a mesh without its SXMPVO time or a, cannot be judged: not measured.
    reason = "; ".join(lacking) if lacking else (f"{len(pts)} mesh{'' if len(pts) == 1 else 'es'}"
                                                 if len(pts) < 3 else "")
    judged = bool(f) and not reason
    t.notes = size_note(records, "the paper's 1.5M-cell meshes (50x50x100 hexes; default 20x20x100 = 240k cells)")
    if judged:
        t.notes += (" Linear fit of SXMPVO time against a: %.3g us per pixel entry, intercept %.3g s, r^2 = %.4f."
                    % (f["slope"] * 1e6, f["intercept"], f["r2"]))
    doc.claim("the time to sort the cells is a linear function of the projected exterior-face area a (least-squares "
              "line of SXMPVO time against a: " + ("-" if not judged else "%.3g us per pixel entry, intercept %.3g s"
                                                   % (f["slope"] * 1e6, f["intercept"])) + f"; {len(pts)} meshes)",
              ours=f["r2"] if judged else None, paper="a linear function of the projected area (Fig. 11)",
              criterion="r^2 of the line >= 0.95 and slope > 0, over at least 3 meshes"
              + (f"; not measured: {reason}" if reason else ""),
              holds=(f["r2"] >= 0.95 and f["slope"] > 0) if judged else None, scope={"orderer": "sxmpvo"})
    if pts:
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        ax.plot([p[1] for p in pts], [p[2] for p in pts], "o", label="SXMPVO")
        nc_pts = [p for p in pts if p[3] is not None]
        ax.plot([p[1] for p in nc_pts], [p[3] for p in nc_pts], "s", label="MPVONC", alpha=0.6)
        if judged:
            amax = max(p[1] for p in pts)
            ax.plot([0, amax], [f["intercept"], f["intercept"] + f["slope"] * amax], "-", color="grey",
                    label="fit: %.3g us/pixel entry, r$^2$=%.3f" % (f["slope"] * 1e6, f["r2"]))
        for p in pts[::4]:
            ax.annotate("%d gaps" % p[0], (p[1], p[2]), fontsize=7)
        finish_figure(doc, fig, ax, "projected exterior-face area a (pixels)", f"seconds per frame ({w}x{h})", "Time against exterior-face area (gap series)",
                      "cook-fig11.png", "SXMPVO and MPVONC time against a, with the linear fit")


# --- Fig. 8 -----------------------------------------------------------------------------------

def fig8(records, paper, doc):
    doc.title = "Cook et al. Fig. 8: the helix with MPVONC and SXMPVO orders"
    s1 = [r for r in records if m.get(r, "oracle.supersample", 1) == 1]
    s4 = [r for r in records if m.get(r, "oracle.supersample", 1) == 4]
    n, w, h = records[0]["n"], records[0]["w"], records[0]["h"]
    doc.intro = (command("cook-fig8", records) + f": helix of {n} cells and {records[0]['b']} exterior faces (paper: "
                 "3.57M and 91,400; --full; at this size a misordered cell is large enough to change its pixels), "
                 "14 views. Paper: MPVONC shows errors (green inner cells over pink outer ones), SXMPVO none.")
    t = doc.table(f"Oracle per view, {window_text(s1)} (S = 1; SXMPVO also at S = 4)",
                  ["view", "MPVONC violating pixels", "MPVONC fragments", "MPVONC pixels off (image)",
                   "SXMPVO violating pixels", "SXMPVO pixels off (image)", "SXMPVO S=4 violating samples",
                   "MPVONC/SXMPVO pixels differing (8-bit PNGs, > 1 step)"])
    one = lambda rs, o, v: (m.select(rs, orderer=o, view_index=v) or [None])[0]  # noqa: E731
    worst, worst_px, nc_bad, sx_bad = None, (-1, -1), 0, 0
    for v in sorted({r["view_index"] for r in s1}):
        sx, nc, sx4 = one(s1, "sxmpvo", v), one(s1, "mpvonc", v), one(s4, "sxmpvo", v)
        differing = None
        if sx and nc and sx.get("images") and nc.get("images"):
            a, b = img.load_png(doc, nc["images"]["order"]), img.load_png(doc, sx["images"]["order"])
            if a is not None and b is not None:
                differing = int(img.differing(a, b).sum())
        g = lambda r, k: m.get(r, k) if r else None  # noqa: E731
        t.row(v, g(nc, "oracle.violating_pixels"), g(nc, "oracle.violating_fragments"),
              g(nc, "image_error.pixels_off"), g(sx, "oracle.violating_pixels"), g(sx, "image_error.pixels_off"),
              g(sx4, "oracle.violating_pixels"), differing)
        vp = g(nc, "oracle.violating_pixels")
        # The figure's view: most pixels differing in the images (what shows), then most violating.
        if vp is not None and (differing or 0, vp) > worst_px:
            worst, worst_px = v, (differing or 0, vp)
        nc_bad += bool(vp)
        sx_bad += bool(g(sx, "oracle.violating_pixels"))
    t.notes = (f"Images of view {worst} (the view where the two images differ in most pixels): (a) SXMPVO order, "
               "(b) MPVONC order, "
               "(c) white where they differ by more than one 8-bit step (in the stored PNGs: the last column "
               "counts these; a lower bound on the C++ reproduction's float test, which counted a difference above "
               "1/255 and so equalled MPVONC's pixels off wherever SXMPVO's image is exact), the SXMPVO image dimly "
               "behind, (d) the MPVONC image with those pixels marked red. "
               "S = 4 counts violations between pixel centres: SXMPVO promises nothing there.")
    sx, nc = one(s1, "sxmpvo", worst), one(s1, "mpvonc", worst)
    if sx and nc and sx.get("images") and nc.get("images"):
        doc.image(img.relative(doc, sx["images"]["order"]), "(a) SXMPVO order")
        doc.image(img.relative(doc, nc["images"]["order"]), "(b) MPVONC order")
        a, b = img.load_png(doc, nc["images"]["order"]), img.load_png(doc, sx["images"]["order"])
        if a is not None and b is not None:
            img.write_difference(doc, "cook-fig8c-difference.png", a, b)
            doc.image("cook-fig8c-difference.png", "(c) where the two orders' images differ")
            img.write_marked(doc, "cook-fig8d-marked.png", a, b, grow=2)
            doc.image("cook-fig8d-marked.png", "(d) MPVONC order, the differing pixels marked red (grown by 2 pixels)")
    nviews = len({r["view_index"] for r in s1})
    doc.claim("MPVONC misorders the helix (views with violating pixels)", ours=nc_bad,
              paper="(b) MPVONC order: green inner cells wrongly occlude pink outer ones",
              criterion="ours > 0", holds=nc_bad > 0 if nviews else None,
              scope={"suite": "orders", "orderer": "mpvonc"})
    shown = m.get(nc, "image_error.pixels_off") if nc else None
    share = None if shown is None else 100.0 * shown / (w * h)
    doc.claim(f"MPVONC's errors are visible in the image of the shown view {worst} (ours: % of the {w}x{h} image's "
              f"pixels where MPVONC's image is off the exact one by more than 1/255; {shown} pixels)", ours=share,
              paper="(c) white where the images differ: visible regions", criterion="ours >= 0.1 (at least 0.1% of "
              "the image, a region a reader can see, not scattered pixels)",
              holds=None if share is None else share >= 0.1, scope={"suite": "orders"})  # the view is chosen over both
    doc.claim("SXMPVO orders the helix correctly at pixel centres (views with violating pixels)", ours=sx_bad,
              paper=0, criterion="ours == 0", holds=sx_bad == 0 if nviews else None,
              scope={"suite": "orders", "orderer": "sxmpvo"})


# A data set's row label, for the records and for planned jobs without one (build_tables.py).
ROW_OF = label

TABLES = {
    "cook-table1": table1,
    "cook-table3": table3,
    "cook-table4": table4,
    "cook-table4-512": table4,
    "cook-table2-5": table2_5,
    "cook-table6": table6,
    "cook-fig11": fig11,
    "cook-fig8": fig8,
}
