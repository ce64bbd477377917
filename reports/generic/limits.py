"""How far each orderer is from the machine's limit: its frame time beside the time to stream
its working set once at the STREAM-triad bandwidth its run measured (the context's
`machine_limits`, harness/bench/machine_limits.h) at the record's thread count.

Working set = the record's `bytes`: orderer + scene + derived, everything a frame may read.
Streaming it once is a floor only for a frame that touches every byte it holds; a frame that
reads less can come in under it (ratio < 1). Computed here from the stored records; a run
without the measurement, or one that did not measure the record's thread count, is
"not measured", never a guess."""
import statistics

from .units import human_bytes, human_seconds, sig

NOT_MEASURED = "not measured"


def limits_of(r):
    """The run context's machine_limits of a record, or None."""
    ml = (r.get("context") or {}).get("machine_limits")
    return ml if isinstance(ml, dict) else None


def rate(r, kind, field):
    """The context's `kind` ("triad" or "gather") `field` at the record's thread count, or None."""
    ml = limits_of(r)
    threads = r.get("threads", (r.get("context") or {}).get("threads"))
    if ml is None or threads is None:
        return None
    for e in ml.get(kind) or []:
        if e.get("threads") == threads and isinstance(e.get(field), (int, float)) and e[field] > 0:
            return float(e[field])
    return None


def triad_rate(r):
    return rate(r, "triad", "bytes_per_second")


def working_set(r):
    b = r.get("bytes") or {}
    return sum(int(b.get(k) or 0) for k in ("orderer", "scene", "derived"))


def stream_seconds(r):
    """Seconds to stream the record's working set once at its run's triad rate, or None."""
    bw = triad_rate(r)
    return working_set(r) / bw if bw else None


def row_fields(rs):
    """The bandwidth columns of one report row (records `rs`: its views): medians over the
    records whose run measured the limit at their thread count."""
    measured = [r for r in rs if stream_seconds(r) is not None]
    ws = statistics.median(working_set(r) for r in rs)
    llc = [limits_of(r).get("llc_bytes") for r in measured]
    if not measured:
        return {"working_set": ws, "triad_bps": None, "stream_s": None, "stream_views": 0, "fits_llc": None}
    return {"working_set": ws,
            # Read from the cache rather than memory: faster than the triad's rate.
            "fits_llc": all(isinstance(c, int) and 0 < ws <= c for c in llc),
            "triad_bps": statistics.median(triad_rate(r) for r in measured),
            "stream_s": statistics.median(stream_seconds(r) for r in measured),
            "stream_views": len(measured)}


def frame_over_stream(row):
    s = row.get("stream_s")
    return row["seconds"] / s if s else None


def per_second(v, unit):
    return f"{v / 1e9:.3g} G{unit}/s" if v >= 1e9 else f"{v / 1e6:.3g} M{unit}/s"


def runs_table(page, recs):
    """The limits each run measured (one row per run and thread count)."""
    runs = {}
    for r in recs:
        runs.setdefault(r.get("run_id") or (r.get("context") or {}).get("date") or "?", limits_of(r))
    out = []
    for run, ml in runs.items():
        if ml is None:
            out.append([run, "–", NOT_MEASURED, NOT_MEASURED, NOT_MEASURED, "–", "–"])
            continue
        gathers = {e.get("threads"): e for e in ml.get("gather") or []}
        # Fresh memory's first touch, on 4 KiB / 2 MiB pages (one thread; older runs lack it).
        ft = ml.get("first_touch") or {}
        small, huge = ft.get("small_pages_bytes_per_second"), ft.get("huge_pages_bytes_per_second")
        touch = (f"{per_second(small, 'B')} / {per_second(huge, 'B')}" if small and huge else NOT_MEASURED)
        for e in ml.get("triad") or []:
            g = gathers.get(e.get("threads"), {})
            out.append([run, str(e.get("threads")), per_second(e["bytes_per_second"], "B"),
                        per_second(g["gathers_per_second"], "") if g.get("gathers_per_second") else NOT_MEASURED,
                        touch, human_bytes(ml.get("triad_bytes_per_pass")), human_seconds(ml.get("seconds"))])
    page.table(["run", "threads", "triad bandwidth", "random gathers", "first touch (4 KiB / 2 MiB pages)",
                "triad arrays", "measured in"], out)


def section(page, rows, recs):
    """The bandwidth table: every row's frame time beside its streaming time and their ratio."""
    page.heading(2, "Against the machine's limits")
    page.para("Each run measures this machine's STREAM-triad bandwidth (a[i] = b[i] + s*c[i], 24 bytes "
              "counted per element, over arrays much larger than the last-level cache: 4x by default) and its "
              "random-gather rate "
              "(sum of x[idx[i]] over distinct random positions), best of a few repetitions, at 1 thread "
              "and all threads the run may use:")
    runs_table(page, recs)
    multi = len({r["revision"] for r in rows}) > 1
    # Records of several machines or runs: each row says whose it is (two hosts' rows look alike otherwise).
    where = (len({h for r in rows for h in r.get("hosts", [])}) > 1 or len({x for r in rows for x in r["runs"]}) > 1)
    out, classes = [], []
    for r in rows:
        ratio = frame_over_stream(r)
        nm = r["stream_s"] is None
        out.append([r["algorithm"], r["scene"]] + ([r["revision"]] if multi else []) +
                   ([", ".join(r.get("hosts", [])) + " / " + (r["run"] or ", ".join(r["runs"]))] if where else []) +
                   [str(r["threads"]) if r["threads"] is not None else "?", human_seconds(r["seconds"]),
                    human_bytes(r["working_set"]) + (" (fits in LLC)" if r.get("fits_llc") else ""),
                    NOT_MEASURED if nm else per_second(r["triad_bps"], "B"),
                    NOT_MEASURED if nm else human_seconds(r["stream_s"]),
                    NOT_MEASURED if nm else sig(ratio)])
        classes.append([None] * (len(out[-1]) - 3) + ["nc" if nm else None] * 3)
    page.table(["orderer", "scene"] + (["revision"] if multi else []) + (["host / run"] if where else []) +
               ["threads", "time/frame", "working set", "triad at these threads", "stream once",
                "frame / stream"], out, classes)
    ratios = [(frame_over_stream(r), r) for r in rows if frame_over_stream(r) is not None]
    worst = max(ratios, key=lambda t: t[0]) if ratios else None
    page.para("working set: the record's bytes (orderer + scene + derived structures); stream once: working "
              "set / triad bandwidth at the record's thread count, from its own run; frame / stream: how many "
              "times longer a frame takes than streaming what it holds once (below 1: the frame reads less "
              "than it holds, or, marked 'fits in LLC', reads it from the last-level cache, faster than "
              "from memory). " + (f"Largest: {sig(worst[0])} ({worst[1]['algorithm']} on {worst[1]['scene']}, "
                                    f"{worst[1]['threads']} thread{'' if worst[1]['threads'] == 1 else 's'})." if worst else
                                    "No row has a measured limit (runs without `machine_limits`)."))
