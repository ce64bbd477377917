#!/usr/bin/python3
"""The timing part of every table's conditions (reports/vobtables/conditions.py) from hand-made
records: records whose orderers took turns frame by frame (suite "interleave", records
"interleaved": true) say so, the others do not, and a mix of both is given as two settings
with their counts.

usage: check_conditions_timing.py REPORTS_DIR
"""
import sys

sys.path.insert(0, sys.argv[1])
from vobtables.conditions import timing  # noqa: E402

TURNS = "taking turns frame by frame"


def fail(why):
    sys.exit(f"check_conditions_timing: {why}")


def rec(interleaved=None, probe=False):
    r = {"repeats": 3, "warmup": 1, "threads": 1}
    if interleaved is not None:
        r["interleaved"] = interleaved
    if probe:
        r["probe"] = "machine-limits"
    return r


plain = timing([rec(), rec(False)])
if TURNS in plain or "orderer records (2)" not in plain:
    fail(f"plain records: {plain!r}")
turns = timing([rec(True), rec(True), rec(True)])
if TURNS not in turns or "orderer records (3)" not in turns:
    fail(f"interleaved records: {turns!r}")
mixed = timing([rec(True), rec(), rec(), rec(probe=True)])
parts = mixed.split("; ")
if len(parts) != 3:
    fail(f"a mix should give three settings: {mixed!r}")
with_turns = [p for p in parts if TURNS in p]
if len(with_turns) != 1 or not with_turns[0].startswith("orderer records (1)"):
    fail(f"only the one interleaved record takes turns: {mixed!r}")
if not any(p.startswith("orderer records (2)") and TURNS not in p for p in parts):
    fail(f"the two plain records: {mixed!r}")
print("check_conditions_timing: ok")
