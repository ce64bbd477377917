"""A reproduction's document: tables (ours beside the paper's), claims computed by an
explicit criterion, figures; written as NAME.md, NAME.json and NAME.html, deterministically
(the same records give the same bytes)."""
import html
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import plan as _plan  # noqa: E402


def fmt(v):
    """A table cell: 3 significant digits, integers as integers, None as '-'."""
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "-"
        if v == math.floor(v) and abs(v) < 1e15:
            return str(int(v))
        return f"{v:.3g}"
    return str(v)


def column_formats(rows, ncols):
    """One format per column, so a column's numbers share their precision: fixed decimals
    giving 3 significant digits to the column's smallest non-zero float (at most 6), or 3
    significant digits per cell when the floats span more than 4 decades."""
    out = []
    for i in range(ncols):
        fl = [abs(r[i]) for r in rows if isinstance(r[i], float) and math.isfinite(r[i])]
        frac = [v for v in fl if v != math.floor(v)]
        nz = [v for v in fl if v > 0]
        if not frac or not nz:
            out.append(None)
        elif max(nz) / min(nz) > 1e4:
            out.append("g")
        else:
            out.append(max(0, min(6, 2 - math.floor(math.log10(min(nz))))))
    return out


def cell(v, f):
    """A cell in its column's format (see column_formats)."""
    if f is None or not isinstance(v, float) or not math.isfinite(v):
        return fmt(v)
    return f"{v:.3g}" if f == "g" else f"{v:.{f}f}"


def _wrap(text, width):
    words, lines, cur = text.split(), [], ""
    for wd in words:
        if cur and len(cur) + 1 + len(wd) > width:
            lines.append(cur)
            cur = wd
        else:
            cur = f"{cur} {wd}".strip()
    return lines + ([cur] if cur else [])


def _clean(v):
    """JSON-safe: NaN and infinities become null."""
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


class Table:
    def __init__(self, title, columns, notes="", decimals=None):
        self.title, self.columns, self.notes, self.rows = title, list(columns), notes, []
        self.decimals = dict(decimals or {})  # column -> fixed decimals, instead of column_formats' choice

    def formats(self):
        auto = column_formats(self.rows, len(self.columns))
        return [self.decimals.get(c, f) for c, f in zip(self.columns, auto)]

    def row(self, *cells):
        if len(cells) != len(self.columns):
            raise ValueError(f"table '{self.title}': row has {len(cells)} cells for {len(self.columns)} columns")
        self.rows.append([_clean(c) for c in cells])
        return self


# Counts the images that did not load into <body data-broken-images> (tests/reports reads it).
BROKEN_IMAGES_SCRIPT = """<script>
window.addEventListener('load', function () {
  var imgs = document.images, broken = 0;
  for (var i = 0; i < imgs.length; i++)
    if (!imgs[i].complete || imgs[i].naturalWidth === 0) broken++;
  document.body.setAttribute('data-images', imgs.length);
  document.body.setAttribute('data-broken-images', broken);
});
</script>"""


def _anchor(k, text):
    return f"s{k}-" + "".join(c if c.isalnum() else "-" for c in text.lower())[:40].strip("-")


def _md(text):
    """A Markdown table cell: a literal '|' would end the cell."""
    return str(text).replace("|", "\\|")


def _same_data_set(r):
    """What a record and a planned job of one data set share: the suite's row and the recipe."""
    return (r.get("row"), json.dumps(r.get("dataset_spec"), sort_keys=True))


class Doc:
    def __init__(self, name, title, intro="", context=None, out_dir="."):
        self.name, self.title, self.intro, self.context = name, title, intro, context
        self.out_dir = out_dir
        self.conditions = ""  # machines, threads, repeats and warm-up, stand-ins (vobtables.conditions)
        self.tables, self.claims, self.figures = [], [], []
        # The reproduction's planned jobs and those without a record (set_plan); a claim whose
        # scope covers one of the missing is "not measured" (claim), a data set with no record
        # at all still gets its row (_finish), and the Conditions say which are missing.
        self.planned, self.missing, self.records = [], [], []
        self.row_of = None  # a record's or planned job's row label (None: its "row", else its data set)
        self._finished = False

    def set_plan(self, records, plans, reproduction=None):
        """The reproduction's records and the results file's plan lines (vobtables.plan)."""
        self.records = list(records)
        self.planned = _plan.planned_jobs(plans, reproduction)
        self.missing = _plan.missing_jobs(records, plans, reproduction)

    def row_label(self, r):
        if self.row_of is not None:
            try:
                return self.row_of(r)
            except (KeyError, TypeError, ValueError):
                # A planned job lacks what the script's label reads (cook's gap rows read n): the
                # label of a record of the same data set, so a claim scoped to that row covers it.
                same = self._record_labels().get(_same_data_set(r))
                if same is not None:
                    return same
        return _plan.job_row(r)

    def _record_labels(self):
        """{data set of a record (_same_data_set): its label}, once per set of records."""
        if getattr(self, "_labels_of", (None,))[0] is not self.records:
            labels = {}
            for rec in self.records:
                try:
                    labels.setdefault(_same_data_set(rec), self.row_of(rec))
                except (KeyError, TypeError, ValueError):
                    pass
            self._labels_of = (self.records, labels)
        return self._labels_of[1]

    def missing_in(self, scope=None):
        """The planned jobs without a record that fall in `scope` (vobtables.plan.in_scope)."""
        return [j for j in self.missing if _plan.in_scope(j, scope, self.row_label)]

    def row_labels(self, where=None):
        """Row labels of the records and the planned jobs (those passing `where`), records' first:
        a claim over all rows lists them in its scope, a row planned but never reached included."""
        out = []
        for r in self.records + self.planned:
            row = self.row_label(r)
            if row not in out and (where is None or where(row)):
                out.append(row)
        return out

    def missing_rows(self):
        """Row labels of planned data sets with no record at all, in plan order."""
        have = {self.row_label(r) for r in self.records}
        out = []
        for j in self.missing:
            row = self.row_label(j)
            if row not in have and row not in out:
                out.append(row)
        return out

    def _finish(self):
        """Once, before writing: the Conditions say which planned jobs have no record, and each
        table whose rows are our data sets gets a "not measured" row for a planned data set
        with no record."""
        if self._finished:
            return
        self._finished = True
        if not self.missing:
            return
        text = _plan.describe(self.missing, self.planned, self.row_label)
        if not self.records:  # stopped before its first record
            text = f"0 of {len(self.planned)} planned jobs have a record. " + text
        self.conditions = (self.conditions.rstrip() + " " if self.conditions else "") + (
            "Incomplete: " + text + " Claims over them are not measured.")
        rows = self.missing_rows()
        have = {self.row_label(r) for r in self.records}
        for t in self.tables:
            if not t.rows or len(t.columns) < 2:
                continue
            firsts = [r[0] for r in t.rows if isinstance(r[0], str)]
            if any(f in have for f in firsts):
                prefix = ""
            elif any(f.startswith("ours: ") and f[6:] in have for f in firsts):
                prefix = "ours: "
            else:
                continue
            for row in rows:
                if prefix + row not in firsts:
                    t.rows.append([prefix + row, "not measured"] + [None] * (len(t.columns) - 2))

    def table(self, title, columns, notes="", decimals=None):
        t = Table(title, columns, notes, decimals)
        self.tables.append(t)
        return t

    def claim(self, claim, ours, paper, criterion, holds, scope=None):
        """`holds` is computed from the numbers by `criterion` (a bool), or None when a
        record it needs is missing ("not measured"). `scope`: what the claim is about (a dict
        of row, orderer, view, size, threads; vobtables.plan.in_scope), None for the whole
        reproduction; when a planned job in it has no record the claim is not measured, its
        `ours` left out, and the criterion says which jobs are missing."""
        if holds is not None and not isinstance(holds, bool):
            raise TypeError(f"claim '{claim}': holds must be a bool or None, not {type(holds).__name__}")
        lost = self.missing_in(scope)
        if lost:
            rows = sorted({self.row_label(j) for j in lost})
            criterion = (f"{criterion}; not measured: {len(lost)} planned job(s) without a record "
                         f"({', '.join(rows[:6])}{' ...' if len(rows) > 6 else ''})")
            holds, ours = None, None
        self.claims.append({"claim": claim, "holds": holds, "ours": _clean(ours),
                            "paper": _clean(paper), "criterion": criterion})

    def figure(self, fig, file_name, caption=""):
        """Saves a matplotlib figure beside the document (deterministic PNG metadata)."""
        path = os.path.join(self.out_dir, file_name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        fig.savefig(path, dpi=100, metadata={"Software": None})
        plt.close(fig)
        self.figures.append({"file": file_name, "caption": caption})

    def image(self, file_name, caption="", key=None):
        """An image a probe or the runner wrote (path relative to the output folder), shown as
        a figure with the caption as its title inside the image and, with `key` (a list of
        (label, (r, g, b)) in [0, 1]), a colour key. Without the file, the caption alone."""
        src = os.path.join(self.out_dir, file_name)
        if not os.path.exists(src):
            self.figures.append({"file": file_name, "caption": caption})
            return
        import matplotlib.image as mpimg
        from matplotlib.patches import Patch
        pic = mpimg.imread(src)
        h, w = pic.shape[:2]
        scale = 5.0 / max(w, h)
        fig, ax = plt.subplots(figsize=(max(w * scale, 3.0) + (2.2 if key else 0), h * scale + 0.7))
        ax.imshow(pic, interpolation="nearest")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_xlabel(f"{w} x {h} pixels", fontsize=8)
        ax.set_title("\n".join(_wrap(caption, 60)), fontsize=8)
        if key:
            ax.legend(handles=[Patch(facecolor=c, edgecolor="k", label=lab) for lab, c in key], fontsize=7,
                      loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, title="colour key",
                      title_fontsize=7)
        fig.tight_layout()
        stem = os.path.splitext(file_name)[0].replace(os.sep, "-")
        self.figure(fig, os.path.join("labelled", stem + ".png"), caption)

    # --- writing ---------------------------------------------------------------------------

    def to_json(self):
        self._finish()
        return {"reproduction": self.name, "title": self.title, "intro": self.intro,
                "conditions": self.conditions, "context": self.context,
                "tables": [{"title": t.title, "columns": t.columns,
                            "rows": [dict(zip(t.columns, r)) for r in t.rows], "notes": t.notes}
                           for t in self.tables],
                "claims": self.claims, "figures": self.figures}

    def to_markdown(self):
        self._finish()
        out = [f"# {self.title}", ""]
        if self.intro:
            out += [self.intro, ""]
        if self.conditions:
            out += ["**Conditions.** " + self.conditions, ""]
        for t in self.tables:
            out += [f"## {t.title}", "", "| " + " | ".join(_md(c) for c in t.columns) + " |",
                    "|" + "---|" * len(t.columns)]
            fs = t.formats()
            out += ["| " + " | ".join(_md(cell(c, f)) for c, f in zip(r, fs)) + " |" for r in t.rows]
            if t.notes:
                out += ["", t.notes]
            out.append("")
        if self.claims:
            out += ["## Claims", "", "| claim | holds | ours | paper | criterion |", "|---|---|---|---|---|"]
            for c in self.claims:
                verdict = "not measured" if c["holds"] is None else ("holds" if c["holds"] else "does not hold")
                out.append(f"| {_md(c['claim'])} | {verdict} | {_md(fmt(c['ours']))} | {_md(fmt(c['paper']))} | "
                           f"{_md(c['criterion'])} |")
            out.append("")
        for f in self.figures:
            out += [f"![{f['caption']}]({f['file']})", ""]
        if self.context:
            out += ["## Machine", "", "```", json.dumps(self.context, indent=1, sort_keys=True), "```", ""]
        return "\n".join(out)

    def to_html(self):
        """The page: a table of contents, tables, claims, then each figure at full column width
        linked to its full-size file."""
        self._finish()
        e = html.escape
        sections = [(_anchor(k, t.title), t.title) for k, t in enumerate(self.tables)]
        sections += [("claims", "Claims")] if self.claims else []
        sections += [("figures", "Figures")] if self.figures else []
        sections += [("machine", "Machine")] if self.context else []
        out = ["<!doctype html><html><head><meta charset='utf-8'>",
               f"<title>{e(self.title)}</title>",
               "<style>body{font-family:sans-serif;max-width:70em;margin:2em auto;padding:0 1em;line-height:1.4}"
               "table{border-collapse:collapse;margin:1em 0;font-size:13px}td,th{border:1px solid #ccc;"
               "padding:2px 8px;text-align:right}th{background:#f3f3f3}td:first-child{text-align:left}"
               ".no{color:#b00}.yes{color:#070}.nm{color:#888}figure{margin:1.5em 0}"
               "figure img{width:100%;border:1px solid #ddd}figcaption{font-size:13px}"
               ".row{display:flex;flex-wrap:wrap;gap:12px}figure.pic{margin:0;max-width:100%}"
               "figure.pic img{width:auto;max-width:100%}"
               "nav{background:#f7f7f7;border:1px solid #ddd;padding:.5em 1em;font-size:14px}"
               ".scroll{overflow-x:auto}</style></head><body>",
               f"<h1>{e(self.title)}</h1>"]
        if len(sections) > 1:
            out.append("<nav><b>Contents</b><ul>" + "".join(f"<li><a href='#{a}'>{e(t)}</a></li>"
                                                            for a, t in sections) + "</ul></nav>")
        if self.intro:
            out.append(f"<p>{e(self.intro)}</p>")
        if self.conditions:
            out.append(f"<p><b>Conditions.</b> {e(self.conditions)}</p>")
        for k, t in enumerate(self.tables):
            out.append(f"<h2 id='{_anchor(k, t.title)}'>{e(t.title)}</h2><div class='scroll'><table><tr>"
                       + "".join(f"<th>{e(c)}</th>" for c in t.columns) + "</tr>")
            fs = t.formats()
            for r in t.rows:
                out.append("<tr>" + "".join(f"<td>{e(cell(c, f))}</td>" for c, f in zip(r, fs)) + "</tr>")
            out.append("</table></div>")
            if t.notes:
                out.append(f"<p>{e(t.notes)}</p>")
        if self.claims:
            out.append("<h2 id='claims'>Claims</h2><table><tr><th>claim</th><th>holds</th><th>ours</th>"
                       "<th>paper</th><th>criterion</th></tr>")
            for c in self.claims:
                cls, word = (("nm", "not measured") if c["holds"] is None
                             else (("yes", "holds") if c["holds"] else ("no", "does not hold")))
                out.append(f"<tr><td>{e(c['claim'])}</td><td class='{cls}'>{word}</td><td>{e(fmt(c['ours']))}</td>"
                           f"<td>{e(fmt(c['paper']))}</td><td>{e(c['criterion'])}</td></tr>")
            out.append("</table>")
        if self.figures:
            out.append("<h2 id='figures'>Figures</h2>")
        for k, f in enumerate(self.figures):
            # Plots at full column width; labelled images (doc.image) at their own size, side by side.
            pic = f["file"].startswith("labelled")
            if pic and (k == 0 or not self.figures[k - 1]["file"].startswith("labelled")):
                out.append("<div class='row'>")
            out.append(f"<figure{' class=pic' if pic else ''}><a href='{e(f['file'])}'><img src='{e(f['file'])}' "
                       f"alt='{e(f['caption'])}'></a><figcaption>{e(f['caption'])} (click for full size)"
                       "</figcaption></figure>")
            if pic and (k + 1 == len(self.figures) or not self.figures[k + 1]["file"].startswith("labelled")):
                out.append("</div>")
        if self.context:
            out.append("<h2 id='machine'>Machine</h2><pre>" + e(json.dumps(self.context, indent=1, sort_keys=True))
                       + "</pre>")
        out += [BROKEN_IMAGES_SCRIPT, "</body></html>"]
        return "\n".join(out)

    def write(self):
        os.makedirs(self.out_dir, exist_ok=True)
        for ext, text in (("md", self.to_markdown()), ("json", json.dumps(self.to_json(), indent=1) + "\n"),
                          ("html", self.to_html())):
            path = os.path.join(self.out_dir, f"{self.name}.{ext}")
            tmp = path + ".tmp"
            with open(tmp, "w") as f:
                f.write(text)
            os.replace(tmp, path)
        return os.path.join(self.out_dir, f"{self.name}.md")
