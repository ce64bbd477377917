"""The image gallery of one scene: the views where some orderer violates (each view's exact
image once, then per violating orderer its image, the colour difference and the violation
map with the count), plus one clean view per scene."""
import collections
import html
import os

from .load import image_path, revision
from .rows import checked, judged, violating_pixels
from .units import sig


def link(path, html_dir):
    """An image's link relative to the page's folder, or None when the file is missing."""
    if not path or not os.path.exists(path):
        return None
    return os.path.relpath(path, html_dir)


def caption(r):
    """Text of a gallery caption (HTML-escaped parts joined by the caller)."""
    v = violating_pixels(r)
    if v is None:
        text = "not checked (no oracle verdict)"
    else:
        cov = r["oracle"].get("covered_pixels")
        text = f"{v:,} violating pixels" + (f" ({100 * v / cov:.3g}% of {cov:,} covered)" if cov else "")
        if judged(r) == "composited":
            text += ", judged on what it composites"
    d = r.get("oracle_cell_order")
    if isinstance(d, dict) and "violating_pixels" in d:
        text += f"; derived cell order: {d['violating_pixels']:,} violating pixels"
    ie = r.get("image_error")
    if ie:
        text += f"; colour difference: {ie.get('pixels_off', 0):,} pixels off, RMSE {sig(ie.get('rmse'))}"
    return text


def views(recs):
    """(view index, revision) -> that view's records with images, in file order."""
    out = collections.OrderedDict()
    for r in recs:
        if r.get("images"):
            out.setdefault((r.get("view_index"), revision(r)), []).append(r)
    return out


def add(page, recs, html_dir, revisions):
    """Gallery of one scene's records into page; returns the number of views shown."""
    by_view = views(recs)
    if not by_view:
        return 0
    bad = [k for k, rs in by_view.items() if any((violating_pixels(r) or 0) > 0 for r in rs)]
    clean = [k for k in by_view if k not in bad][:1]
    shown = bad + clean
    page.heading(3, f"Images: {recs[0]['dataset']} @ {recs[0]['w']}x{recs[0]['h']}")
    page.para(f"{len(bad)} of {len(by_view)} imaged views have violations; "
              + ("they are shown" if bad else "none has") + (", with one clean view." if clean else ".")
              + " Violation map: the exact image with the pixels the verdict counts as violating marked.")
    for view, rev in shown:
        rs = by_view[(view, rev)]
        title = f"view {view}" + (f" @ {rev}" if len(revisions) > 1 else "")
        failing = [r for r in rs if (violating_pixels(r) or 0) > 0]
        ok = [r["algorithm"] for r in rs if violating_pixels(r) == 0]
        unchk = [r["algorithm"] for r in rs if not checked(r)]
        exact = (link(image_path(rs[0], "exact"), html_dir), f"{title}: exact (oracle) image")
        note = []
        if ok:
            note.append("no violation: " + ", ".join(ok))
        if unchk:
            note.append("not checked: " + ", ".join(unchk))
        page.para(f"{title}: " + ("; ".join(note) if note else f"{len(failing)} orderer(s) with violations") + ".")
        if not failing:
            page.image_row([exact])
        for k, r in enumerate(failing):
            # The exact image once per view: at the head of its first row.
            items = [exact if k == 0 else (None, "")] + [
                (link(image_path(r, "order"), html_dir), f"{r['algorithm']}: its order"),
                (link(image_path(r, "diff"), html_dir), "colour difference")]
            text = caption(r)
            if "violations" in (r.get("images") or {}):
                items.append((link(image_path(r, "violations"), html_dir), "violating pixels marked"))
            else:  # older records: the colour difference may look blank although pixels violate
                text += "; no violation map in this record"
            page.image_row(items, caption=f"<b>{html.escape(r['algorithm'])}</b>, {title}: {html.escape(text)}",
                           md_caption=f"**{r['algorithm']}**, {title}: {text}")
    return len(shown)
