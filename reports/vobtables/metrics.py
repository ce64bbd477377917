"""Metrics: functions of stored records. Nothing here measures."""
import statistics


def select(records, **where):
    """Records whose fields equal the given values (dotted names reach into objects:
    select(rs, **{"parameters.k": 2}))."""
    out = []
    for r in records:
        if all(get(r, k.replace("__", ".")) == v for k, v in where.items()):
            out.append(r)
    return out


def get(r, dotted, default=None):
    cur = r
    for part in dotted.split("."):
        if not isinstance(cur, dict) or part not in cur:
            return default
        cur = cur[part]
    return cur


def group(records, field):
    """[(value, records)] in first-seen order; `field` is a dotted name or a function."""
    keyf = field if callable(field) else (lambda r: get(r, field))
    groups = {}
    for r in records:
        groups.setdefault(keyf(r), []).append(r)
    return list(groups.items())


def values(records, metric):
    return [v for v in (metric(r) for r in records) if v is not None]


def mean(records, metric):
    v = values(records, metric)
    return statistics.mean(v) if v else None


def median(records, metric):
    v = values(records, metric)
    return statistics.median(v) if v else None


def total(records, metric):
    v = values(records, metric)
    return sum(v) if v else None


def maximum(records, metric):
    v = values(records, metric)
    return max(v) if v else None


# --- per-record metrics -------------------------------------------------------------------

def frame_seconds(r):
    """Median per-frame order time of the record's repeats."""
    return get(r, "total.median")


def phase(name):
    return lambda r: get(r, f"phases.{name}.median")


def counter(name):
    return lambda r: get(r, f"counters.{name}")


def oracle(name):
    return lambda r: get(r, f"oracle.{name}")


def result(dotted):
    """A value of a probe record's result."""
    return lambda r: get(r, f"result.{dotted}")


def prepare_seconds(r):
    return get(r, "prepare.seconds")


def violating_pixels(r):
    """The verdict's violating pixels (`oracle`: for an orderer that composites itself, on what
    it composited); 0 when the input has overlapping cells (not the orderer's fault). Records
    older than the one verdict judged HAVS's derived cell order there: its own count wins."""
    if "input_fault" in r:
        return 0
    if get(r, "oracle.judged") is None and get(r, "counters.havs_violating_pixels") is not None:
        return int(get(r, "counters.havs_violating_pixels"))
    return get(r, "oracle.violating_pixels")


def failing(r):
    v = violating_pixels(r)
    return None if v is None else int(v > 0)


def ratio(a, b):
    return None if a is None or b in (None, 0) else a / b


def fit_line(x, y):
    """Least squares y = intercept + slope * x, with r^2 (1 when y does not vary); None for
    fewer than two points or constant x."""
    n = len(x)
    if n < 2:
        return None
    sx, sy = sum(x), sum(y)
    sxx, sxy, syy = sum(v * v for v in x), sum(a * b for a, b in zip(x, y)), sum(v * v for v in y)
    d = n * sxx - sx * sx
    if d == 0:
        return None
    slope = (n * sxy - sx * sy) / d
    intercept = (sy - slope * sx) / n
    ss_tot = syy - sy * sy / n
    ss_res = sum((b - intercept - slope * a) ** 2 for a, b in zip(x, y))
    return {"slope": slope, "intercept": intercept, "r2": 1 - ss_res / ss_tot if ss_tot > 0 else 1.0}


# --- matched records: what two orderers' numbers may be compared on ------------------------

def size_of(r):
    """The suite's size entry of a record (the WxH part of its key; with fitted windows the
    record's w and h differ per view), else its w x h."""
    for part in str(r.get("key", "")).split("|"):
        a, x, b = part.partition("x")
        if x and a.isdigit() and b.isdigit():
            return part
    return f"{r.get('w')}x{r.get('h')}"


def match_key(r):
    """What records of two orderers must share to be compared: the view, the size entry and
    the thread count (the data set is the caller's group)."""
    return (r.get("view_index"), size_of(r), r.get("threads"))


def expected_keys(group, views=None):
    """Every (view, size, threads) a data set's records cover: the set each orderer of it is
    expected to have (a suite gives every orderer of a data set the same views). With `views`
    (every view index of the reproduction, when all its suites measure the same views), each
    of those views at each of the group's sizes and thread counts, so a view missing for every
    orderer of one data set counts as missing too. Records that say which views their suite
    asked (`views_asked`) add those, so a view lost by every orderer of the run counts too."""
    keys = {match_key(r) for r in group}
    if views is not None:
        keys |= {(v, s, t) for v in views for _, s, t in keys}
    # at the record's own size and threads: two suites of one reproduction may ask other views
    keys |= {(v, size_of(r), r.get("threads")) for r in group for v in (r.get("views_asked") or ())}
    return keys


def views_text(have, of):
    """A cell or reason for a mean that would cover fewer views than expected."""
    return "not measured" if have == 0 else f"incomplete: {have} of {of} views"


def complete_mean(recs, metric, expected):
    """(mean over recs, None) when recs cover every expected key and the metric is known on
    each; else (None, 'incomplete: N of M views' / 'not measured'), never a mean over fewer."""
    have = {match_key(r) for r in recs if metric(r) is not None} & set(expected)
    if not expected or have != set(expected):
        return None, views_text(len(have), len(expected))
    return mean(recs, metric), None


def matched_means(sides, expected, key=match_key):
    """Means of the sides compared in one row over their matched views: the keys (default
    match_key; `view_of` when the sides differ in size) at which every side has its metric.
    sides: {name: (records, metric)}; expected: the keys the reproduction asks the row for.
    Returns (means {name: mean over the matched keys, or None when none match}, the matched
    keys, what lacks views: ['NAME incomplete: N of M views', ...], empty when every side has
    every expected key)."""
    expected = set(expected)
    have = {name: {key(r) for r in rs if metric(r) is not None} & expected for name, (rs, metric) in sides.items()}
    common = set.intersection(*have.values()) if have else set()
    means = {name: mean([r for r in rs if key(r) in common], metric) if common else None
             for name, (rs, metric) in sides.items()}
    lacking = [f"{name} {views_text(len(h), len(expected))}" for name, h in have.items() if h != expected]
    return means, common, lacking


def view_of(r):
    """The view alone as a match key (sides of a row measured at different sizes)."""
    return r.get("view_index")


def matched_text(matched, expected):
    """A row's 'views matched' cell: '3 of 3'."""
    return f"{len(matched)} of {len(expected)}"


def short_rows_reason(short):
    """The criterion's tail for a claim that depends on rows with fewer matched views than the
    reproduction asks for ({row: lacking}), else ''."""
    if not short:
        return ""
    return "; not measured: " + "; ".join(f"{row}: {', '.join(lack)}" for row, lack in short.items())
