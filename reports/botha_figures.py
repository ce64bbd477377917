#!/usr/bin/python3
"""Figures of the Botha and Post (IP-PBTF) reproductions: botha_figures.py DATA.json OUT_DIR.

DATA.json is written by harness/cli/experiments/botha.cpp; its "kind" picks the figure:
table1 (ordering throughput per volume and ordering), violations (violating pixels per view
of btf, wbtf, pbtf, ip-pbtf, one panel per volume). Run with Debian's /usr/bin/python3,
which sees python3-matplotlib."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ORDERS = ["btf", "wbtf", "pbtf", "ip-pbtf", "distance-sort"]


def table1(d, out):
    vols = list(dict.fromkeys(r["volume"] for r in d["rows"]))
    fig, ax = plt.subplots(figsize=(10, 4.5))
    w = 0.8 / len(ORDERS)
    for k, o in enumerate(ORDERS):
        vals = [next((r["mvoxels_per_s"] for r in d["rows"] if r["volume"] == v and r["ordering"] == o), 0) for v in vols]
        ax.bar([i + k * w for i in range(len(vols))], vals, w, label=o)
    ax.set_xticks([i + 0.4 - w / 2 for i in range(len(vols))])
    ax.set_xticklabels([v.split(":")[-1].strip() for v in vols], fontsize=8)
    ax.set_ylabel("ordering throughput (Mvoxels/s)")
    ax.set_title("Botha and Post Table 1: ordering alone, 512x512 close-ups")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "botha-table1.png"), dpi=110)


def violations(d, out):
    vols = d["volumes"]
    fig, axes = plt.subplots(1, len(vols), figsize=(4.5 * len(vols), 4), squeeze=False)
    for ax, v in zip(axes[0], vols):
        views = range(len(v["views"]))
        for o in ORDERS[:4]:
            ax.plot(views, [max(c[o], 0.5) for c in v["views"]], "o-", label=o, markersize=3)
        ax.set_yscale("log")
        ax.set_xlabel("view")
        ax.set_title(v["label"], fontsize=9)
    axes[0][0].set_ylabel("violating pixels (0 drawn at 0.5)")
    axes[0][0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "botha-violations.png"), dpi=110)


def main():
    with open(sys.argv[1]) as f:
        d = json.load(f)
    {"table1": table1, "violations": violations}[d["kind"]](d, sys.argv[2])


if __name__ == "__main__":
    main()
