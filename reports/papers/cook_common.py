"""What the cook-* table scripts share (reports/papers/cook.py): row labels, the size of a
record's image (the suite's size entry, also for fitted windows), notes and figure finishing."""
import re
import textwrap

from vobtables import metrics as m

PHASES = ["I create partial order", "II sort exterior faces", "III scan faces and add dependencies", "IV DFS"]
# Square images of about the paper's pixel counts (Tables 2, 5 and 6).
SIZE_NAMES = {412: "170k", 592: "350k", 837: "700k", 1025: "1.05M", 1414: "2M"}
MIB = 1024.0 * 1024.0


# --- rows and helpers -----------------------------------------------------------------------

def label(r):
    """The C++ reproductions' row labels, from the dataset recipe."""
    spec = r.get("dataset_spec") or {}
    name, s = spec.get("name"), spec.get("set") or {}
    if name == "helix":
        return "helix %.3gM" % (float(s["cells"]) / 1e6)
    if name == "gap":
        paper_size = (int(s.get("nx", 50)), int(s.get("ny", 50)), int(s.get("nz", 100))) == (50, 50, 100)
        return "gap %d" % int(s.get("gaps", 0)) + ("" if paper_size else " (%dk)" % round(r["n"] / 1000))
    if name == "zoo":
        scale = int(s.get("scale", 1))
        return "zoo" if scale == 1 else "zoo x%d" % scale
    return r.get("row") or r.get("dataset")


def by_row(records):
    return m.group(records, label)


def scale_of(records):
    return records[0].get("scale", "default") if records else "default"


def command(name, records):
    sc = scale_of(records)
    return f"`vobench reproduce {name}" + {"full": " --full", "tiny": " --tiny"}.get(sc, "") + "`"


def size_note(records, opt_in):
    sc = scale_of(records)
    if sc == "full":
        return "Run with --full: the paper's sizes."
    if sc == "tiny":
        return "Tiny scale (--tiny, the CTest check): sizes far below the paper's; the numbers only show the table builds."
    return "Default sizes; --full adds " + opt_in + "."


def fitted(records):
    """Records whose windows were fitted to the bounding box (suite "fit": the paper's rule)."""
    return bool(records) and all("|fit" in r["key"] for r in records)


def window_text(records):
    """The image size of a set of records: W x H, or the fitted windows' pixel counts."""
    if not fitted(records):
        return "%dx%d" % (records[0]["w"], records[0]["h"])
    px = sorted({r["w"] * r["h"] for r in records})
    return ("windows fitted to the bounding box, %s pixels" %
            ("%d" % px[0] if len(px) == 1 else "%d to %d" % (px[0], px[-1])))


def views_violating(recs):
    """Views whose order the oracle rejects (records without the oracle count as none)."""
    return sum(m.values(recs, m.failing))


def mb(v):
    return None if v is None else v / MIB


def paper_table(doc, p, title, notes=None):
    t = doc.table(title, p["columns"], notes if notes is not None else p.get("note", ""))
    for row in p["rows"]:
        t.row(*row)
    return t


def machine(paper, key):
    return paper["machines"][key]


def finish_figure(doc, fig, ax, xlabel, ylabel, title, file_name, caption):
    """Labels, title, axes from zero, grid and legend; then the figure is saved beside the document."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    # Wrapped and smaller than the axis labels, so a long title stays inside the figure.
    ax.set_title("\n".join(textwrap.wrap(title, 60)), fontsize=10)
    ax.set_ylim(bottom=0)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    doc.figure(fig, file_name, caption)


def size_entry(r):
    """The suite's size entry (W, H) of an orderer record, from its key: with "fit" the record's w and h
    are the fitted window's, the entry is the pixel budget (W*H) the paper's table names."""
    for part in r["key"].split("|"):
        hit = re.fullmatch(r"(\d+)x(\d+)", part)
        if hit:
            return int(hit.group(1)), int(hit.group(2))
    return r["w"], r["h"]


def at_size(recs, size):
    return [r for r in recs if size_entry(r) == size]


def size_name(w, h):
    """A square size entry by the paper's pixel count ("170k"), any other as WxH."""
    return SIZE_NAMES.get(w, f"{w}x{h}") if w == h else f"{w}x{h}"
