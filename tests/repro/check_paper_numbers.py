#!/usr/bin/python3
"""Paper numbers, digit for digit (issue 13): every number in reports/papers/*.json is stored as
the paper prints it (integers as numbers, everything else as its printed text), occurs in the
paper's text file, and appears unchanged in the tables built from records; every cell of a
paper column in those tables is one of the paper's printed numbers.

usage: check_paper_numbers.py DIR   (DIR holds the NAME.json documents of the reproductions,
                                     built from records: the repro.summary test's folder)
"""
import glob
import json
import os
import re
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "reports"))
from vobtables import fmt  # noqa: E402
from vobtables.paper import _NUM  # noqa: E402

TEXTS = {"botha": "botha-post-ip-pbtf.txt", "cook": "cook-max-silva-williams-sxmpvo.txt",
         "havs": "callahan-et-al-havs.txt", "krishnan": "krishnan-silva-wei-stencil-layering.txt",
         "xmpvo": "cook-max-silva-williams-sxmpvo.txt"}
PAPERS_TXT = os.environ.get("VOB_PAPERS", "/work/shared/papers")
# Keys whose numbers are not the paper's measurements: table and figure numbers, our own
# parameters (frame counts, block sizes, pixel counts of the column labels), thresholds read
# from the text ("cells above"), and HAVS Table 5, which we transcribe but do not reproduce.
META = {"number", "table", "figure", "frames", "block_sizes", "best_block", "pixels", "views",
        "columns", "layers", "max_speedup", "speedup_over_xmpvo", "cells above"}
NOT_SHOWN = {("havs", "table5"), ("cook", "fig11"), ("cook", "claims"), ("havs", "claims"), ("cook", "memory"),
             ("botha", "interleaving"), ("krishnan", "fig2"), ("krishnan", "fig3"), ("krishnan", "xmpvo")}


def leaves(o, path=()):
    if isinstance(o, dict):
        for k, v in o.items():
            yield from leaves(v, path + (k,))
    elif isinstance(o, list):
        for v in o:
            yield from leaves(v, path)
    else:
        yield path, o


def numeric(v):
    if isinstance(v, bool):
        return False
    return isinstance(v, (int, float)) or (isinstance(v, str) and bool(_NUM.match(v)))


def in_text(printed, text):
    tok = re.escape(printed.replace(",", ""))
    return re.search(r"(?<![\d.])" + tok + r"(?![\d])", text) is not None


def main():
    out_dir = sys.argv[1]
    errors, checked, shown = [], 0, 0
    docs = {}
    for f in sorted(glob.glob(os.path.join(out_dir, "*.json"))):
        try:
            d = json.load(open(f))
        except ValueError:
            continue
        if isinstance(d, dict) and "reproduction" in d and "tables" in d:
            docs[d["reproduction"]] = d
    for pj in sorted(glob.glob(os.path.join(ROOT, "reports", "papers", "*.json"))):
        paper = os.path.basename(pj)[:-5]
        numbers = json.load(open(pj))
        txt_path = os.path.join(PAPERS_TXT, TEXTS[paper])
        if not os.path.exists(txt_path):  # the papers' texts are not in the repository
            print(f"note: {txt_path} missing: {paper}.json's numbers are checked against the tables only")
        text = open(txt_path).read() if os.path.exists(txt_path) else None
        text = None if text is None else re.sub(r"(?<=\d),(?=\d{3})", "", text)
        mine = [d for d in docs.values() if PAPER_OF.get(d["reproduction"]) == paper]
        cells, prose = set(), []
        for d in mine:
            for t in d["tables"]:
                prose.append(t.get("notes") or "")
                for row in t["rows"]:
                    cells.update(fmt(v) for v in row.values())
            prose += [str(c.get("paper")) for c in d["claims"]] + [d.get("intro") or ""]
        prose = re.sub(r"(?<=\d),(?=\d{3})", "", "\n".join(prose))
        printed_set = set()
        for path, v in leaves(numbers):
            if not numeric(v) or any(k in META for k in path):
                continue
            checked += 1
            if isinstance(v, float):
                errors.append(f"{paper}.json {'.'.join(path)}: {v!r} is a float; store the paper's printed text")
                continue
            p = str(v)
            printed_set.add(p)
            if text is not None and not in_text(p, text):
                errors.append(f"{paper}.json {'.'.join(path)}: {p!r} does not occur in {TEXTS[paper]}")
            if (paper, path[0]) in NOT_SHOWN or not mine:
                continue
            shown += 1
            if p not in cells and not in_text(p, prose):
                errors.append(f"{paper}.json {'.'.join(path)}: {p!r} is in no table cell or note of "
                              + ", ".join(sorted(d["reproduction"] for d in mine)))
        # Paper columns hold the paper's numbers only.
        for d in mine:
            for t in d["tables"]:
                paper_table = t["title"].startswith("Paper")
                for col in t["columns"][1:]:
                    if "(computed)" in col or not (paper_table or col.lower().startswith("paper")):
                        continue
                    for row in t["rows"]:
                        v = row.get(col)
                        if v is None or not numeric(v):
                            continue
                        if isinstance(v, float) or fmt(v) not in printed_set:
                            errors.append(f"{d['reproduction']}: table '{t['title']}', column '{col}': {v!r} is "
                                          f"not a printed number of {paper}.json")
    for e in errors:
        print("FAIL", e)
    print(f"paper numbers: {checked} checked against the texts, {shown} against {len(docs)} documents' tables; "
          f"{len(errors)} errors")
    sys.exit(1 if errors or not docs else 0)


PAPER_OF = {}  # reproduction -> paper, from the reproduction files


if __name__ == "__main__":
    # Which paper each document belongs to: the records say it; the documents do not, so
    # read the reproduction files.
    for f in glob.glob(os.path.join(ROOT, "datasets", "suites", "**", "*.json"), recursive=True):
        try:
            r = json.load(open(f))
        except ValueError:
            continue
        if isinstance(r, dict) and r.get("reproduction"):
            PAPER_OF[r["reproduction"]] = r.get("paper")
    main()
