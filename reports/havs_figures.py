"""Figures of the HAVS reproductions (run by `vobench reproduce havs-k-tradeoff`).

usage: havs_figures.py havs-k-tradeoff OUT_DIR
Reads OUT_DIR/results.jsonl and writes OUT_DIR/havs-k-tradeoff.png: per mesh, time per frame
against the fraction of covered pixels with an ordering error. HAVS points (its own k-buffer
error, counters havs_*) are joined in order of k; the cell orderers use the oracle's
violating pixels of their cell order.
"""
import json
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def error_fraction(r):
    c = r.get("counters", {})
    if "havs_violating_pixels" in c:
        return c["havs_violating_pixels"] / max(c["havs_covered_pixels"], 1)
    o = r["oracle"]
    return o["violating_pixels"] / max(o["covered_pixels"], 1)


def k_tradeoff(out_dir):
    recs = load(os.path.join(out_dir, "results.jsonl"))
    by = defaultdict(lambda: defaultdict(list))
    for r in recs:
        by[r["dataset"]][r["algorithm"]].append(r)
    names = sorted(by)
    fig, axes = plt.subplots(1, len(names), figsize=(4.2 * len(names), 4), squeeze=False)
    for ax, ds in zip(axes[0], names):
        havs = []
        for alg, rs in sorted(by[ds].items()):
            t = 1e3 * sum(r["total"]["median"] for r in rs) / len(rs)
            e = 100 * sum(error_fraction(r) for r in rs) / len(rs)
            if alg.startswith("havs"):
                havs.append((rs[0]["parameters"]["k"], t, e))
            else:
                ax.plot([t], [e], "o", label=alg)
        havs.sort()
        if havs:
            ax.plot([h[1] for h in havs], [h[2] for h in havs], "-s", color="k", label="havs (k)")
            for k, t, e in havs:
                ax.annotate(f"k={k}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_title(ds, fontsize=9)
        ax.set_xlabel("time per frame (ms)")
        ax.set_ylabel("% of covered pixels with an ordering error")
        ax.set_ylim(bottom=0)
        ax.set_xlim(left=0)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "havs-k-tradeoff.png"), dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] != "havs-k-tradeoff":
        sys.exit("usage: havs_figures.py havs-k-tradeoff OUT_DIR")
    k_tradeoff(sys.argv[2])
