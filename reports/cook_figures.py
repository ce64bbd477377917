#!/usr/bin/python3
"""Figures of the Cook et al. (SXMPVO) reproductions: cook_figures.py DATA.json OUT_DIR.

DATA.json is written by harness/cli/experiments/cook.cpp; its "kind" picks the figure:
table4 (time against n with linear fits), table2-5 (time against image size),
fig11 (time against exterior-face area a, with the fitted line). Run with Debian's
/usr/bin/python3, which sees python3-matplotlib."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def table4(d, ax):
    rows = [r for r in d["rows"] if r["label"].startswith("helix")]
    n = [r["n"] for r in rows]
    for key, name in (("sxmpvo", "SXMPVO"), ("mpvonc", "MPVONC"), ("vtk", "vtk-centroid")):
        ax.plot(n, [r[key] for r in rows], "o-", label=name)
    for key in ("fit_sxmpvo", "fit_mpvonc"):
        f = d[key]
        ax.plot([0, max(n)], [f["intercept"], f["intercept"] + f["slope"] * max(n)], ":", color="grey")
    ax.set_xlabel("cells n (helix)")
    ax.set_ylabel("seconds per frame (512x512)")
    ax.set_title("SXMPVO vs MPVONC by mesh size (fits dotted)")


def table25(d, ax):
    for r in d["rows"]:
        ax.plot(d["pixels"], r["times"], "o-", label=r["label"])
    ax.set_xlabel("image size (pixels)")
    ax.set_ylabel("SXMPVO seconds per frame")
    ax.set_title("SXMPVO time against image size")


def fig11(d, ax):
    a = [r["a"] for r in d["rows"]]
    ax.plot(a, [r["sxmpvo"] for r in d["rows"]], "o", label="SXMPVO")
    ax.plot(a, [r["mpvonc"] for r in d["rows"]], "s", label="MPVONC", alpha=0.6)
    f = d["fit"]
    ax.plot([0, max(a)], [f["intercept"], f["intercept"] + f["slope"] * max(a)], "-", color="grey",
            label="fit: %.3g us/pixel entry, r$^2$=%.3f" % (f["slope"] * 1e6, f["r2"]))
    for r in d["rows"][::4]:
        ax.annotate("%d gaps" % r["gaps"], (r["a"], r["sxmpvo"]), fontsize=7)
    ax.set_xlabel("projected exterior-face area a (pixels)")
    ax.set_ylabel("seconds per frame (450x375)")
    ax.set_title("Time against exterior-face area (gap series)")


def main():
    data_path, out_dir = sys.argv[1], sys.argv[2]
    with open(data_path) as fh:
        d = json.load(fh)
    draw = {"table4": table4, "table2-5": table25, "fig11": fig11}[d["kind"]]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    draw(d, ax)
    ax.set_ylim(bottom=0)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    name = {"table4": "cook-table4", "table2-5": "cook-table2-5", "fig11": "cook-fig11"}[d["kind"]]
    fig.savefig(os.path.join(out_dir, name + ".png"), dpi=120)


if __name__ == "__main__":
    main()
