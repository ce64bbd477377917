#!/usr/bin/python3
"""Krishnan et al.'s exactness claims for the OpenGL backends, judged under the gl sampling
rule (reports/papers/krishnan.py), from hand-made records: a frame fails on a violation off
the rule's cycles, passes with violations only on them (no more than any order has), is not
judged when its snapped cells overlap (input_fault), and a claim with nothing judged reads
"not measured".

usage: check_gl_rule_claims.py REPORTS_DIR
"""
import os
import sys

REPORTS = sys.argv[1]
sys.path.insert(0, REPORTS)
sys.path.insert(0, os.path.join(REPORTS, "papers"))
import krishnan  # noqa: E402
from vobtables.doc import Doc  # noqa: E402


def fail(why):
    sys.exit(f"check_gl_rule_claims: {why}")


def rec(fragments=0, pixels=0, cycles=None, fault=False, raster="gl"):
    r = {"raster": raster, "row": "helix", "w": 64, "h": 64,
         "oracle": {"violating_fragments": fragments, "violating_pixels": pixels}}
    if cycles is not None:
        r["oracle"]["rule_cycles"] = cycles
    if fault:
        r["input_fault"] = "cells 1 and 2 overlap"
    return r


ON_CYCLES = {"avoidable_fragments": 0, "excess": 0, "unbounded": False, "cycle_pixels": 1}
OFF_CYCLES = {"avoidable_fragments": 2, "excess": 0, "unbounded": False, "cycle_pixels": 1}


def verdict(records):
    doc = Doc("t", "t")
    krishnan._gl_rule_claim(doc, records, "claim", "paper", "table1-gl-rule")
    return doc.claims[0]["holds"], doc.claims[0]["ours"], doc.claims[0]["criterion"]


cases = [
    ("clean frames", [rec(), rec()], True, 0),
    ("violations on the rule's cycles only", [rec(), rec(3, 1, ON_CYCLES)], True, 0),
    ("a violation off the rule's cycles", [rec(), rec(5, 2, OFF_CYCLES)], False, 1),
    ("a violation with no cycle split", [rec(4, 2)], False, 1),
    ("overlapping snapped cells are not judged", [rec(), rec(9, 9, fault=True)], True, 0),
    ("nothing judged", [rec(9, 9, fault=True)], None, None),
    ("no records", [], None, None),
]
for name, records, holds, ours in cases:
    got = verdict(records)
    if got[0] != holds or got[1] != ours:
        fail(f"{name}: holds {got[0]}, ours {got[1]}; expected {holds}, {ours} ({got[2]})")
if "1 not judged" not in verdict(cases[4][1])[2]:
    fail("the criterion must say how many frames were not judged")
# The tables judged at exact pixel centres never see the gl rule's records, and back.
mixed = [rec(), rec(raster="exact"), {"row": "x"}]
if len(krishnan._under_gl_rule(mixed)) != 1 or len(krishnan._under_exact_rule(mixed)) != 2:
    fail("records are not split by their sampling rule")
print(f"check_gl_rule_claims: {len(cases)} cases")
