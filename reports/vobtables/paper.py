"""The paper's numbers as printed. reports/papers/PAPER.json keeps integers as numbers and
every other number as the text the paper prints ("0.60", "10.98", "2331 K", "57%"), so a
table shows it digit for digit (tests/repro/check_paper_numbers.py checks this); `value`
reads one for arithmetic."""
import re

_NUM = re.compile(r"^\s*([-+]?[0-9][0-9,]*(?:\.[0-9]+)?)\s*(K|M|million|%|percent)?\s*$")
_SCALE = {None: 1.0, "K": 1e3, "M": 1e6, "million": 1e6, "%": 0.01, "percent": 0.01}


def value(v):
    """A paper number as a float: 12 -> 12.0, "0.60" -> 0.6, "2331 K" -> 2331000.0,
    "57%" -> 0.57, "15 million" -> 1.5e7; None, "n/a" and other text -> None."""
    if v is None or isinstance(v, bool):
        return None
    if isinstance(v, (int, float)):
        return float(v)
    g = _NUM.match(str(v))
    if not g:
        return None
    return float(g.group(1).replace(",", "")) * _SCALE[g.group(2)]


def printed(v):
    """The paper's text of a number (integers without thousands separators)."""
    return "-" if v is None else str(v)
