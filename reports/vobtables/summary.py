"""The claims summary of a folder holding several reproductions' records (`vobench reproduce
all`, `vobench report DIR`): every claim of every table built, with its experiment, ours,
the paper's, the criterion and the verdict, and the counts. Built from the documents that
build_tables.py has just made from the records, so it is a function of the records alone."""
import html
import json
import os

from .doc import fmt

VERDICT = {True: "holds", False: "does not hold", None: "not measured"}
PAPERS = {"botha": "Botha and Post 2005 (IP-PBTF)", "cook": "Cook, Max, Silva, Williams 2004 (SXMPVO)",
          "havs": "Callahan et al. 2005 (HAVS)", "krishnan": "Krishnan, Silva, Wei 2001",
          "xmpvo": "Cook et al. 2004 Table 2, Silva et al. 1998, Comba et al. 1999 (XMPVO, BSP-XMPVO)",
          "vobench": "vobench's own speed targets (issue 16), not a paper's"}


def counts(rows):
    c = {v: 0 for v in VERDICT.values()}
    for r in rows:
        c[r["verdict"]] += 1
    return c


def title_of(docs, scale):
    """What the folder holds: the reproductions and their papers (never 'every paper' for a folder
    holding some of them)."""
    papers = list(dict.fromkeys(p for p, _ in docs))
    named = [PAPERS.get(p, p) for p in papers if p != "vobench"] + (
        ["vobench's speed targets"] if "vobench" in papers else [])
    holds = named[0] if len(named) == 1 else "; ".join(named[:-1]) + " and " + named[-1]
    n = len(docs)
    return (f"vobench: the claims of {n} reproduction{'' if n == 1 else 's'}: {holds}"
            + ("" if scale == "default" else f" ({scale} scale)"))


def write_summary(docs, out_dir, scale):
    """docs: [(paper, Doc)] in build order; writes claims-summary.md, .json and .html (summary.json is the generic report's)."""
    rows = []
    for paper, doc in docs:
        for c in doc.claims:
            rows.append({"paper": paper, "experiment": doc.name, "claim": c["claim"], "verdict": VERDICT[c["holds"]],
                         "holds": c["holds"], "ours": c["ours"], "paper value": c["paper"],
                         "criterion": c["criterion"]})
    total = counts(rows)
    per_paper = [(p, counts([r for r in rows if r["paper"] == p])) for p in sorted({r["paper"] for r in rows})]
    title = title_of(docs, scale)
    intro = (f"{len(rows)} claims from {len(docs)} reproductions: {total['holds']} hold, {total['does not hold']} do "
             f"not hold, {total['not measured']} not measured (a record they need is missing, or too few to apply the "
             "criterion: each says which). Every verdict is "
             "computed from the records by the criterion shown; each experiment's page (EXPERIMENT.md) has the "
             "tables, the stand-ins and the machines.")
    if scale == "tiny":
        intro += " Tiny scale: sizes far below the papers'; the verdicts only show the pipeline works."
    data = {"title": title, "scale": scale, "counts": total,
            "papers": [{"paper": p, "name": PAPERS.get(p, p), "counts": c} for p, c in per_paper],
            "claims": [{k: v for k, v in r.items() if k != "verdict"} for r in rows]}
    md = [f"# {title}", "", intro, "", "| paper | holds | does not hold | not measured |", "|---|---|---|---|"]
    md += [f"| {PAPERS.get(p, p)} | {c['holds']} | {c['does not hold']} | {c['not measured']} |" for p, c in per_paper]
    md += [f"| all | {total['holds']} | {total['does not hold']} | {total['not measured']} |", "",
           "| claim | experiment | ours | paper | criterion | verdict |", "|---|---|---|---|---|---|"]
    md += [f"| {r['claim']} | [{r['experiment']}]({r['experiment']}.md) | {fmt(r['ours'])} | {fmt(r['paper value'])} | "
           f"{r['criterion']} | {r['verdict']} |" for r in rows]
    e = html.escape
    cls = {"holds": "yes", "does not hold": "no", "not measured": "nm"}
    h = ["<!doctype html><html><head><meta charset='utf-8'>", f"<title>{e(title)}</title>",
         "<style>body{font-family:sans-serif;max-width:90em;margin:2em auto}table{border-collapse:collapse}"
         "td,th{border:1px solid #ccc;padding:2px 6px}.no{color:#b00}.yes{color:#070}.nm{color:#888}</style>"
         "</head><body>", f"<h1>{e(title)}</h1><p>{e(intro)}</p><table><tr><th>paper</th><th>holds</th>"
         "<th>does not hold</th><th>not measured</th></tr>"]
    h += [f"<tr><td>{e(PAPERS.get(p, p))}</td><td>{c['holds']}</td><td>{c['does not hold']}</td>"
          f"<td>{c['not measured']}</td></tr>" for p, c in per_paper]
    h.append(f"<tr><td>all</td><td>{total['holds']}</td><td>{total['does not hold']}</td>"
             f"<td>{total['not measured']}</td></tr></table>")
    h.append("<table><tr><th>claim</th><th>experiment</th><th>ours</th><th>paper</th><th>criterion</th>"
             "<th>verdict</th></tr>")
    h += [f"<tr><td>{e(r['claim'])}</td><td><a href='{e(r['experiment'])}.html'>{e(r['experiment'])}</a></td>"
          f"<td>{e(fmt(r['ours']))}</td><td>{e(fmt(r['paper value']))}</td><td>{e(r['criterion'])}</td>"
          f"<td class='{cls[r['verdict']]}'>{r['verdict']}</td></tr>" for r in rows]
    h.append("</table></body></html>")
    for name, text in (("claims-summary.md", "\n".join(md) + "\n"), ("claims-summary.json", json.dumps(data, indent=1) + "\n"),
                       ("claims-summary.html", "\n".join(h) + "\n")):
        path = os.path.join(out_dir, name)
        with open(path + ".tmp", "w") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
    return os.path.join(out_dir, "claims-summary.md")
