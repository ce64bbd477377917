"""The generic report's figures (Debian's matplotlib): speed against error, phase bars,
scaling. Each figure is saved at its full size; the page shows it at full column width and
links to the file."""
import collections
import colorsys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
import numpy as np  # noqa: E402

from .units import time_unit  # noqa: E402

DPI = 100
MARKERS = {"object": ("o", "claims object-space exactness"), "image": ("D", "claims image-space exactness"),
           "heuristic": ("s", "heuristic (no exactness claim)")}
# Size parameters of the built-in generators: a scaling series varies these and keeps the rest.
SIZE_KEYS = {"cells", "faces", "nx", "ny", "nz", "n", "scale", "size", "resolution"}


def palette(n):
    """n distinct colours: tab20, tab20b, tab20c (60), beyond that evenly spaced hues at
    alternating lightness."""
    base = [plt.get_cmap(m)(i) for m in ("tab20", "tab20b", "tab20c") for i in range(20)]
    if n <= 10:
        return [plt.get_cmap("tab10")(i) for i in range(n)]
    if n <= len(base):
        return base[:n]
    return [colorsys.hls_to_rgb(i / n, 0.35 + 0.3 * (i % 3) / 2, 0.75) for i in range(n)]


def _save(fig, out):
    fig.savefig(out, dpi=DPI, bbox_inches="tight", metadata={"Software": None})
    plt.close(fig)


def label(row, revisions):
    return (row["algorithm"] + (f" ({row['threads']} threads)" if row.get("multi_threads") else "")
            + (f" @ {row['revision']}" if len(revisions) > 1 else "")
            + (f" [run {row['run']}]" if row.get("run") else ""))


def marker_legend(ax, claims, loc):
    handles = [Line2D([], [], ls="", marker=MARKERS[c][0], color="0.3", markersize=8, label=MARKERS[c][1])
               for c in ("object", "image", "heuristic") if c in claims]
    return ax.legend(handles=handles, title="marker shape", fontsize=9, title_fontsize=9, **loc)


def speed_error(scene, rows, out):
    """Checked rows on the error axis (violating pixels, % of covered); rows without an
    oracle verdict on a separate band labelled "not checked", never at zero."""
    revs = sorted({r["revision"] for r in rows})
    cols = dict(zip([label(r, revs) for r in rows], palette(len(rows))))
    chk = [r for r in rows if r["err"] is not None]
    unchk = [r for r in rows if r["err"] is None]
    unit, f = time_unit(max(r["seconds"] for r in rows))
    if unchk:
        fig, (ax, band) = plt.subplots(2, 1, figsize=(10, 6.2), sharex=True,
                                       gridspec_kw={"height_ratios": [5, 1], "hspace": 0.08})
    else:
        fig, ax = plt.subplots(figsize=(10, 5.4))
        band = None
    for r in chk:
        ax.scatter([r["seconds"] * f], [r["err"] * 100], marker=MARKERS[r["exact"]][0], s=70,
                   color=cols[label(r, revs)], edgecolor="k", linewidth=0.5, label=label(r, revs), zorder=3)
        ax.annotate(label(r, revs), (r["seconds"] * f, r["err"] * 100), xytext=(5, 5), textcoords="offset points",
                    fontsize=7, rotation=30, color="0.25")
    if chk:
        pts = [(r["seconds"], r["err"]) for r in chk]
        front = pareto(pts)
        ax.plot([pts[i][0] * f for i in front], [pts[i][1] * 100 for i in front], "k--", lw=0.8,
                label="Pareto front (checked)")
        # Exact orderers sit on 0: a margin below keeps their markers whole.
        ax.set_ylim(-0.004, max(1.0, 100 * max(e for _, e in pts)) * 6)  # room for labels
    else:
        ax.text(0.5, 0.5, "no orderer of this scene was checked by the oracle", transform=ax.transAxes,
                ha="center", va="center", color="0.4")
    ax.set_xscale("log")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.set_ylabel("violating pixels\n(% of covered, mean over views)")
    ax.set_title(f"speed against error: {scene}", fontsize=11)
    ax.grid(True, which="both", alpha=0.3)
    if band is not None:
        for r in unchk:
            band.scatter([r["seconds"] * f], [0], marker=MARKERS[r["exact"]][0], s=70, color=cols[label(r, revs)],
                         edgecolor="k", linewidth=0.5, label=label(r, revs), zorder=3)
            band.annotate(label(r, revs), (r["seconds"] * f, 0), xytext=(5, 5), textcoords="offset points",
                          fontsize=7, rotation=30, color="0.25")
        band.set_yticks([])
        band.set_ylabel("not checked\n(no oracle)", rotation=0, ha="right", va="center")
        band.set_facecolor("#eeeeee")
        band.grid(True, axis="x", which="both", alpha=0.3)
        band.set_xlabel(f"median time per frame ({unit}, log)")
    else:
        ax.set_xlabel(f"median time per frame ({unit}, log)")
    handles, labels = [], []
    for a in (ax, band) if band is not None else (ax,):
        h, lab = a.get_legend_handles_labels()
        handles += h
        labels += lab
    leg = ax.legend(handles, labels, fontsize=9, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                    borderaxespad=0, title="orderer", title_fontsize=9)
    ax.add_artist(leg)
    marker_legend(ax, {r["exact"] for r in rows}, {"loc": "lower left", "bbox_to_anchor": (1.02, 0.0),
                                                   "borderaxespad": 0})
    _save(fig, out)


def pareto(points):
    """Indices of points not dominated in (time, error), both minimised, by time."""
    front = []
    for i, (t, e) in enumerate(points):
        if not any((t2 <= t and e2 <= e) and (t2 < t or e2 < e) for j, (t2, e2) in enumerate(points) if j != i):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def phases(scene, rows, out):
    """Stacked median phase times per orderer; one colour per phase name (no repeats), the
    legend to the right of the bars."""
    revs = sorted({r["revision"] for r in rows})
    names = []
    for r in rows:
        for p in r["phases"]:
            if p not in names:
                names.append(p)
    unit, f = time_unit(max(sum(r["phases"].values()) for r in rows) or 1e-9)
    cols = palette(len(names))
    height = max(1.4, 0.5 + 0.36 * len(rows))
    fig, (ax, share) = plt.subplots(2, 1, figsize=(10, 2 * height + 1.2),
                                    gridspec_kw={"hspace": 0.35})
    ylabels = [label(r, revs) for r in rows]
    totals = [sum(r["phases"].values()) or 1e-30 for r in rows]
    for k, p in enumerate(names):
        for a, scale in ((ax, [f] * len(rows)), (share, [100 / t for t in totals])):
            left = [s * sum(r["phases"].get(q, 0) for q in names[:k]) for r, s in zip(rows, scale)]
            a.barh(ylabels, [s * r["phases"].get(p, 0) for r, s in zip(rows, scale)], left=left, color=cols[k],
                   label=p if a is ax else None, edgecolor="white", linewidth=0.3)
    for y, t in enumerate(totals):  # short bars stay readable by their number
        ax.text(f * t, y, f"  {f * t:.3g} {unit}", va="center", fontsize=8)
    ax.set_xlim(0, 1.18 * f * max(totals))
    ax.set_xlabel(f"median time per frame ({unit}), by phase")
    ax.set_title(f"phases: {scene}", fontsize=11)
    share.set_xlim(0, 100)
    share.set_xlabel("share of each orderer's time (%), by phase")
    for a in (ax, share):
        a.invert_yaxis()
        a.grid(True, axis="x", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, title="phase",
              ncol=1 if len(names) <= 30 else 2)
    _save(fig, out)


def series_key(row):
    """(family, variant, size): rows of one series differ only in their size parameters."""
    spec = row.get("dataset_spec") or {}
    family = spec.get("name") or row["dataset"].split("(")[0]
    variant = ",".join(f"{k}={v}" for k, v in sorted((spec.get("set") or {}).items()) if k not in SIZE_KEYS)
    return family, variant, f"{row['w']}x{row['h']}"


def slope(pts):
    """Fitted exponent s of t ~ n^s (least squares in log-log)."""
    x = np.log([p[0] for p in pts])
    y = np.log([p[1] for p in pts])
    return float(np.polyfit(x, y, 1)[0])


def scaling(rows, out):
    """Time against n, one panel per (family, variant, image size), one line per orderer
    (and revision), fitted log-log slope in the legend. False when no series has two n."""
    revs = sorted({r["revision"] for r in rows})
    panels = collections.OrderedDict()
    for r in rows:
        panels.setdefault(series_key(r), collections.defaultdict(dict))[label(r, revs)][r["n"]] = r["seconds"]
    panels = {k: {a: sorted(v.items()) for a, v in s.items() if len(v) >= 2} for k, s in panels.items()}
    panels = {k: s for k, s in panels.items() if s}
    if not panels:
        return False
    names = sorted({a for s in panels.values() for a in s})
    cols = dict(zip(names, palette(len(names))))
    unit, f = time_unit(max(t for s in panels.values() for pts in s.values() for _, t in pts))
    fig, axes = plt.subplots(len(panels), 1, figsize=(10, 4.2 * len(panels)), squeeze=False)
    for ax, ((family, variant, size), s) in zip(axes[:, 0], sorted(panels.items())):
        for a, pts in sorted(s.items()):
            ax.plot([p[0] for p in pts], [p[1] * f for p in pts], "o-", color=cols[a],
                    label=f"{a}: slope {slope(pts):.2f} ({len(pts)} sizes)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("primitives n (log)")
        ax.set_ylabel(f"median time per frame ({unit}, log)")
        ax.set_title(f"{family}{' (' + variant + ')' if variant else ''} at {size}", fontsize=11)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0,
                  title="orderer: log-log slope", title_fontsize=8)
    fig.tight_layout()
    _save(fig, out)
    return True


