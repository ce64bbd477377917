"""A page of the generic report written twice, as Markdown and as HTML, from one list of
blocks: headings (with anchors for the table of contents), paragraphs, tables, figures
(full column width, linked to the full-size file) and image rows (each image links to its
file). Every HTML page ends with a small script that counts the images that did not load
into `data-broken-images` on <body> (the browser test reads it)."""
import html
import re

from vobtables.doc import BROKEN_IMAGES_SCRIPT

E = html.escape

CSS = """body{font-family:sans-serif;max-width:1150px;margin:1em auto;padding:0 1em;line-height:1.4}
table{border-collapse:collapse;font-size:12.5px;margin:.5em 0 1em}td,th{border:1px solid #ccc;padding:3px 7px;
text-align:right;white-space:nowrap}td:first-child,th:first-child{text-align:left}th{background:#f3f3f3;white-space:normal;vertical-align:bottom}
.nc{color:#777;font-style:italic}.bad{color:#b00}figure{margin:1em 0}figure img{width:100%;border:1px solid #ddd}
figcaption{font-size:13px;color:#333}.row{display:flex;gap:8px;flex-wrap:wrap;margin:.3em 0 1.2em}
.row figure{flex:0 0 calc(25% - 6px);min-width:180px;margin:0}.row img{image-rendering:pixelated}
nav.toc{background:#f7f7f7;border:1px solid #ddd;padding:.5em 1em;font-size:14px}nav.toc ul{margin:.2em 0}
.scroll{overflow-x:auto}"""

SCRIPT = BROKEN_IMAGES_SCRIPT


def anchor(text):
    return re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "section"


class Page:
    def __init__(self, title):
        self.title = title
        self.md = [f"# {title}", ""]
        self.html = [f"<h1>{E(title)}</h1>"]
        self.toc = []  # (level, text, id)
        self.ids = set()

    def heading(self, level, text, toc=True):
        a = anchor(text)
        while a in self.ids:
            a += "-x"
        self.ids.add(a)
        if toc:
            self.toc.append((level, text, a))
        self.md += [f"{'#' * level} {text}", ""]
        self.html.append(f"<h{level} id='{a}'>{E(text)}</h{level}>")

    def para(self, text, md=None, raw_html=None):
        self.md += [text if md is None else md, ""]
        self.html.append(f"<p>{raw_html if raw_html is not None else E(text)}</p>")

    def link_list(self, items):
        """items: (text, href, note)."""
        for text, href, note in items:
            self.md.append(f"- [{text}]({href}){' ' + note if note else ''}")
        self.md.append("")
        self.html.append("<ul>" + "".join(f"<li><a href='{E(h)}'>{E(t)}</a> {E(n or '')}</li>" for t, h, n in items)
                         + "</ul>")

    def table(self, header, rows, classes=None):
        """rows: lists of strings; classes: per row, per cell, an optional CSS class."""
        self.md += ["| " + " | ".join(c.replace("|", "\\|") for c in header) + " |", "|" + "---|" * len(header)]
        self.md += ["| " + " | ".join(str(c).replace("|", "\\|") for c in r) + " |" for r in rows]
        self.md.append("")
        out = ["<div class='scroll'><table><tr>" + "".join(f"<th>{E(c)}</th>" for c in header) + "</tr>"]
        for k, r in enumerate(rows):
            cls = (classes or [None] * len(rows))[k] or [None] * len(r)
            out.append("<tr>" + "".join((f'<td class="{c}">' if c else "<td>") + f"{E(str(v))}</td>"
                                        for v, c in zip(r, cls)) + "</tr>")
        out.append("</table></div>")
        self.html.append("\n".join(out))

    def figure(self, src, alt, caption=""):
        self.md += [f"![{alt}]({src})", ""] + ([caption, ""] if caption else [])
        self.html.append(f"<figure><a href='{E(src)}'><img src='{E(src)}' alt='{E(alt)}'></a>"
                         f"<figcaption>{E(caption or alt)} (click for full size)</figcaption></figure>")

    def image_row(self, items, caption="", md_caption=None):
        """items: (src or None, label). A missing file is named, never linked."""
        self.md.append(" ".join(f"![{lab}]({src})" if src else f"({lab}: no image)" for src, lab in items if lab))
        self.md += ["", md_caption or caption, ""] if (md_caption or caption) else [""]
        if caption:
            self.html.append(f"<p>{caption if md_caption is not None else E(caption)}</p>")
        cells = []
        for src, lab in items:
            if not lab:  # a spacer keeping columns aligned
                cells.append("<figure></figure>")
            elif src:
                cells.append(f"<figure><a href='{E(src)}'><img src='{E(src)}' alt='{E(lab)}'></a>"
                             f"<figcaption>{E(lab)}</figcaption></figure>")
            else:
                cells.append(f"<figure><figcaption class='nc'>{E(lab)}: no image</figcaption></figure>")
        self.html.append("<div class='row'>" + "".join(cells) + "</div>")

    def markdown(self):
        return "\n".join(self.md).rstrip("\n") + "\n"

    def to_html(self, toc=True, nav=""):
        parts = ["<!doctype html><html><head><meta charset='utf-8'>",
                 f"<title>{E(self.title)}</title><style>{CSS}</style></head><body>"]
        if nav:
            parts.append(nav)
        parts.append(self.html[0])
        if toc and self.toc:
            lines, level = ["<nav class='toc'><b>Contents</b><ul>"], min(lv for lv, _, _ in self.toc)
            for lv, text, a in self.toc:
                pad = "&nbsp;" * 4 * (lv - level)
                lines.append(f"<li style='list-style:none'>{pad}<a href='#{a}'>{E(text)}</a></li>")
            lines.append("</ul></nav>")
            parts.append("\n".join(lines))
        parts += self.html[1:]
        if nav:
            parts.append(nav)
        parts += [SCRIPT, "</body></html>"]
        return "\n".join(parts) + "\n"
