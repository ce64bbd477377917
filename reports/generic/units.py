"""Numbers for people: bytes in KiB/MiB/GiB, times in µs/ms/s, three significant digits."""
import math


def sig(v, digits=3):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "–"
    if isinstance(v, int):
        return f"{v:,}"
    if v == 0:
        return "0"
    if abs(v) >= 1000:  # 2,070 rather than 2.07e+03
        return f"{v:,.0f}"
    return f"{v:.{digits}g}"


def human_bytes(n):
    if n is None:
        return "–"
    for unit, size in (("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)):
        if abs(n) >= size:
            return f"{n / size:.3g} {unit}"
    return f"{int(n)} B"


def human_seconds(s):
    if s is None:
        return "–"
    if s == 0:
        return "0 s"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if abs(s) >= scale:
            return f"{s / scale:.3g} {unit}"
    return f"{s / 1e-9:.3g} ns"


def time_unit(max_seconds):
    """(label, factor) for an axis whose largest value is max_seconds: value * factor."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if max_seconds >= scale:
            return unit, 1.0 / scale
    return "ns", 1e9
