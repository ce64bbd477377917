#!/usr/bin/python3
"""vobench compare BASE.jsonl NEW.jsonl (after Google Benchmark's tools/compare.py).

Matches the orderer records of two results files by their key without its settings parts
(docs/pipeline.md "Jobs and keys"), and prints per (algorithm, dataset, view, size) the
time ratio new/base of the median total, a two-sided Mann-Whitney U test on the per-repeat
samples, the same per phase, and the oracle's violating pixels on both sides.

Exit 1 on a regression, each named on stderr:
  - an orderer claiming exactness (claims object_exact or image_exact) going from zero to
    any violating pixel;
  - a heuristic whose violating pixels grow by more than --pixel-growth (fraction, 0.10)
    AND by more than --pixel-slack pixels (10);
  - a slowdown of the median total beyond --threshold (0.10 = 10%) and beyond --min-ms
    (0.05 ms: frames of microseconds shift by tens of percent on a busy machine) with
    U-test p < --alpha (0.05). When the sample counts cannot reach p < alpha (e.g. 3 against 3) the row says
    so and is not flagged.
  - a base record with no counterpart in new (an orderer, data set or view that stopped
    producing results), unless --allow-missing (new is meant to be a subset).
Exit 0 otherwise; exit 2 on bad input (one line: file, line, reason), when no record
matches (nothing was compared), or when matched records were made with different settings
(repeats, warm-up, threads, oracle, supersample, image error, parameters) unless
--allow-different-settings.
"""
import argparse
import html
import json
import math
import os
import re
import sys
import signal  # noqa: E402

# Ctrl-C during `vobench reproduce` stops the script as it stops vobench, without a traceback.
signal.signal(signal.SIGINT, signal.SIG_DFL)

# Key parts that are settings, not identity (jobs.cpp); "s1" is the old supersample part.
SETTING_PART = re.compile(r"^(r\d+w\d+|oracle|nooracle|ss\d+|s\d+|imgerr|t\d+|rgl|interleaved)$")


class BadInput(Exception):
    pass


def load(path):
    """(records, contexts) of one results file; BadInput names file, line and reason."""
    recs, ctx = [], {}
    try:
        f = open(path)
    except OSError as e:
        raise BadInput(f"{path}: cannot be read ({e.strerror})")
    with f:
        for n, raw in enumerate(f, 1):
            if not raw.strip():
                continue
            try:
                r = json.loads(raw)
            except json.JSONDecodeError as e:
                if not raw.endswith("\n") and recs + list(ctx):  # after complete lines: torn by a killed writer
                    print(f"compare: note: {path}: line {n}: an incomplete last line left out", file=sys.stderr)
                    continue
                raise BadInput(f"{path}: line {n}: not JSON ({e.msg})")
            if not isinstance(r, dict) or not isinstance(r.get("key"), str):
                raise BadInput(f"{path}: line {n}: not a results record (no string \"key\")")
            if r.get("type") == "context":
                ctx[r.get("run_id")] = r.get("context") or {}
                continue
            if r.get("type") == "plan":  # a suite's plan (the jobs it meant to measure), not a record
                continue
            if "probe" in r:
                continue
            total = r.get("total")
            if not isinstance(total, dict) or not isinstance(total.get("median"), (int, float)):
                raise BadInput(f"{path}: line {n}: orderer record without a number total.median")
            for name, p in (r.get("phases") or {}).items():
                if not isinstance(p, dict) or not isinstance(p.get("median"), (int, float)):
                    raise BadInput(f"{path}: line {n}: phase {name!r} without a number median")
            r["_line"] = n
            recs.append(r)
    if not recs:
        raise BadInput(f"{path}: holds no orderer records")
    return recs, ctx


def identity(key):
    return "|".join(p for p in key.split("|") if not SETTING_PART.match(p))


def settings(r):
    """What must be equal for two records to be compared."""
    parts = [p for p in r["key"].split("|") if SETTING_PART.match(p)]
    return {"repeats": r.get("repeats"), "warmup": r.get("warmup"), "threads": r.get("threads"),
            "oracle": "oracle" in r and r["oracle"] is not None,
            "supersample": next((p for p in parts if re.match(r"^s{1,2}\d+$", p)), None),
            "image_error": "image_error" in r, "parameters": r.get("parameters"),
            "raster": r.get("raster") or "exact",  # records before the gl rule sampled exactly
            "interleaved": bool(r.get("interleaved"))}


def samples(t):
    s = t.get("samples") if isinstance(t, dict) else None
    return [float(x) for x in s] if isinstance(s, list) and s else None


def min_p(n1, n2):
    """The smallest two-sided p the exact U test can give with these sample counts."""
    return 2.0 / math.comb(n1 + n2, n1)


def u_test(a, b, alpha):
    """(p or None, note)."""
    if not a or not b:
        return None, "no samples (records before schema 2)"
    if min_p(len(a), len(b)) >= alpha:
        return None, f"{len(a)} vs {len(b)} samples cannot reach p<{alpha:g}"
    from scipy.stats import mannwhitneyu
    if len(set(a) | set(b)) == 1:
        return 1.0, ""
    return float(mannwhitneyu(b, a, alternative="two-sided").pvalue), ""


def pixels(r):
    o = r.get("oracle")
    if not isinstance(o, dict) or not isinstance(o.get("violating_pixels"), (int, float)):
        return None
    return int(o["violating_pixels"])


def exact(r):
    c = r.get("claims") or {}
    return bool(c.get("object_exact") or c.get("image_exact"))


def label(r):
    threads = f" {r['threads']} threads" if r.get("threads") else ""
    return f"{r.get('algorithm')} on {r.get('dataset')} view {r.get('view_index')} {r.get('w')}x{r.get('h')}{threads}"


def ms(s):
    return f"{s * 1e3:.3f}"


def pair_up(base, new):
    """[(b, n)] matched by key, then by identity; and the unmatched of each side."""
    by_key = {r["key"]: r for r in new}
    pairs, rest_b = [], []
    for b in base:
        n = by_key.pop(b["key"], None)
        (pairs.append((b, n)) if n else rest_b.append(b))
    by_id = {}
    for n in by_key.values():
        by_id.setdefault(identity(n["key"]), []).append(n)
    only_base = []
    for b in rest_b:
        cands = by_id.get(identity(b["key"]))
        (pairs.append((b, cands.pop(0))) if cands else only_base.append(b))
    only_new = [n for c in by_id.values() for n in c]
    return pairs, only_base, only_new


def compare(base, new, a):
    """(markdown lines, regressions, settings differences)."""
    pairs, only_base, only_new = pair_up(base, new)
    diffs = []
    for b, n in pairs:
        sb, sn = settings(b), settings(n)
        for k in sb:
            if sb[k] != sn[k]:
                diffs.append(f"{label(b)}: {k} {json.dumps(sb[k])} in base, {json.dumps(sn[k])} in new")
    regress = []
    rows, prow = [], []
    for b, n in pairs:
        tb, tn = b["total"]["median"], n["total"]["median"]
        ratio = tn / tb if tb > 0 else (1.0 if tn == 0 else float("inf"))
        p, note = u_test(samples(b["total"]), samples(n["total"]), a.alpha)
        verdict = ""
        if ratio > 1 + a.threshold and (tn - tb) * 1e3 < a.min_ms:
            verdict = f"slower by < {a.min_ms:g} ms (noise floor)"
        elif ratio > 1 + a.threshold:
            if p is not None and p < a.alpha:
                verdict = "SLOWER"
                regress.append(f"{label(b)}: {ratio:.2f}x slower (median {ms(tb)} -> {ms(tn)} ms, p={p:.3g})")
            elif p is None:
                verdict = "slower? (untested)"
        elif ratio < 1 - a.threshold and (tb - tn) * 1e3 >= a.min_ms and p is not None and p < a.alpha:
            verdict = "faster"
        pb, pn = pixels(b), pixels(n)
        if pb is None or pn is None:
            corr = "not checked" if pb is None and pn is None else f"{pb if pb is not None else 'not checked'} -> " \
                   f"{pn if pn is not None else 'not checked'}"
        else:
            corr = f"{pb} -> {pn}"
            if exact(n) and pb == 0 and pn > 0:
                regress.append(f"{label(b)}: claims exactness, now {pn} violating pixels (was 0)")
                corr += " REGRESSION"
            elif not exact(n) and pn > pb * (1 + a.pixel_growth) and pn - pb > a.pixel_slack:
                regress.append(f"{label(b)}: violating pixels {pb} -> {pn} (more than +{a.pixel_growth:.0%} "
                               f"and +{a.pixel_slack} pixels)")
                corr += " REGRESSION"
            elif pn != pb:
                corr += " (better)" if pn < pb else " (worse, within threshold)"
        rows.append([label(b), ms(tb), ms(tn), f"{ratio:.3f}", "-" if p is None else f"{p:.3g}",
                     verdict or note, corr])
        for ph in b.get("phases") or {}:
            qn = (n.get("phases") or {}).get(ph)
            if not qn:
                continue
            qb = b["phases"][ph]
            r = qn["median"] / qb["median"] if qb["median"] > 0 else float("inf")
            pp, pnote = u_test(samples(qb), samples(qn), a.alpha)
            prow.append([label(b), ph, ms(qb["median"]), ms(qn["median"]), f"{r:.3f}",
                         "-" if pp is None else f"{pp:.3g}", pnote])
    md = ["# vobench compare", "", f"base: `{a.base}` ({len(base)} orderer records); "
          f"new: `{a.new}` ({len(new)}); {len(pairs)} matched, {len(only_base)} only in base, "
          f"{len(only_new)} only in new.", "",
          f"Regression: slowdown > {a.threshold:.0%} and > {a.min_ms:g} ms with U-test p < {a.alpha:g}; "
          f"an exact orderer "
          f"from 0 to any violating pixel; a heuristic's violating pixels + more than "
          f"{a.pixel_growth:.0%} and {a.pixel_slack} pixels. Times in ms (median of the repeats).", ""]
    md += table(["record", "base ms", "new ms", "new/base", "p (U test)", "time", "violating pixels"], rows)
    md += ["", "## Phases", ""] + table(["record", "phase", "base ms", "new ms", "new/base", "p", "note"], prow)
    for title, lst in (("Only in base", only_base), ("Only in new", only_new)):
        if lst:
            md += ["", f"## {title}", ""] + [f"- {label(r)} (`{r['key']}`)" for r in lst]
    if only_base and not a.allow_missing:
        regress.append(f"{len(only_base)} base record(s) missing from new (first: {label(only_base[0])}); "
                       f"--allow-missing if new is meant to be a subset")
    md += ["", "## Verdict", ""] + ([f"- REGRESSION: {r}" for r in regress] or ["No regression."])
    return md, regress, diffs


def table(head, rows):
    esc = lambda c: str(c).replace("|", "\\|")  # noqa: E731
    return ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)] + \
           ["| " + " | ".join(esc(c) for c in r) + " |" for r in rows]


def to_html(md):
    out, in_table = ["<!doctype html><meta charset=utf-8><title>vobench compare</title>",
                     "<style>td,th{border:1px solid #ccc;padding:2px 6px}table{border-collapse:collapse}</style>"], False
    for line in md:
        if line.startswith("|"):
            cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
            if set(line) <= set("|-"):
                continue
            tag = "th" if not in_table else "td"
            if not in_table:
                out.append("<table>")
                in_table = True
            out.append("<tr>" + "".join(f"<{tag}>{html.escape(c)}</{tag}>" for c in cells) + "</tr>")
            continue
        if in_table:
            out.append("</table>")
            in_table = False
        if line.startswith("#"):
            lvl = len(line) - len(line.lstrip("#"))
            out.append(f"<h{lvl}>{html.escape(line.lstrip('#').strip())}</h{lvl}>")
        elif line.startswith("- "):
            out.append(f"<p>&bull; {html.escape(line[2:])}</p>")
        elif line:
            out.append(f"<p>{html.escape(line)}</p>")
    return "\n".join(out + (["</table>"] if in_table else [])) + "\n"


def main():
    ap = argparse.ArgumentParser(prog="vobench compare", description=__doc__.splitlines()[0])
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("-o", "--output", help="also write FILE.md or FILE.html")
    ap.add_argument("--threshold", type=float, default=0.10, help="slowdown fraction (0.10)")
    ap.add_argument("--alpha", type=float, default=0.05, help="U-test significance (0.05)")
    ap.add_argument("--min-ms", type=float, default=0.05,
                    help="a slowdown smaller than this many ms per frame is not flagged (0.05)")
    ap.add_argument("--pixel-growth", type=float, default=0.10, help="heuristic pixel growth fraction (0.10)")
    ap.add_argument("--pixel-slack", type=int, default=10, help="heuristic pixel growth in pixels (10)")
    ap.add_argument("--allow-different-settings", action="store_true")
    ap.add_argument("--allow-missing", action="store_true", help="base records absent from new are not a regression")
    a = ap.parse_args()
    try:
        base, _ = load(a.base)
        new, _ = load(a.new)
    except BadInput as e:
        print(f"compare: {e}", file=sys.stderr)
        return 2
    if not pair_up(base, new)[0]:
        print(f"compare: nothing to compare: none of the {len(new)} orderer records of {a.new} matches one of the "
              f"{len(base)} of {a.base}", file=sys.stderr)
        return 2
    md, regress, diffs = compare(base, new, a)
    if diffs and not a.allow_different_settings:
        print(f"compare: refused: records made with different settings ({len(diffs)}), first: {diffs[0]}; "
              f"use --allow-different-settings to compare anyway", file=sys.stderr)
        return 2
    if diffs:
        md[4:4] = ["Settings differ (allowed): " + "; ".join(diffs[:5]) + ("; ..." if len(diffs) > 5 else ""), ""]
    print("\n".join(md))
    if a.output:
        text = to_html(md) if a.output.endswith((".html", ".htm")) else "\n".join(md) + "\n"
        try:
            os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
            with open(a.output, "w") as f:
                f.write(text)
        except OSError as e:
            print(f"compare: {a.output}: cannot be written ({e.strerror})", file=sys.stderr)
            return 2
    for r in regress:
        print(f"compare: regression: {r}", file=sys.stderr)
    return 1 if regress else 0


if __name__ == "__main__":
    sys.exit(main())
