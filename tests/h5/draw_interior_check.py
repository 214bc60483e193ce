#!/usr/bin/env python3
"""tools/draw-interior on the timing deck's interior (tools/bench/
interior_driver.deck: seat back, padded lower panel and its edge, toeboard,
floor): the SVG names every resolved surface, draws the flat ones as
segments from (X, Y) to their far end as the listing gives them, and the
occupant's seven joints.

Usage: draw_interior_check.py HSRI2D TOOL DECK WORKDIR
"""
import os
import re
import subprocess
import sys

NAME = "draw_interior"


def fail(message):
    print(f"{NAME}: FAIL: {message}")
    sys.exit(1)


hsri2d, tool, deck, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
out = os.path.join(work, "interior.svg")
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, deck, "-o", out], capture_output=True, text=True)
if p.returncode != 0:
    fail(f"status {p.returncode}: {p.stderr}")
text = open(out, encoding="utf-8").read()
labels = re.findall(r"<text[^>]*>([^<]*)</text>", text)
expected = ["5 lower panel", "6 toeboard", "9 seat back", "12 floor", "25 lower panel edge"]
if sorted(labels) != sorted(expected):
    fail(f"surfaces {labels}, expected {expected}")
joints = re.findall(r"<title>([a-z]+)</title>", text)
if sorted(joints) != sorted(["hip", "lspine", "uspine", "neck", "shoulder", "elbow", "knee"]):
    fail(f"joints {joints}")
if text.count('stroke-width="3"') < 3:
    fail("fewer than three flat surfaces drawn as segments")
# a bad deck: the tool says so and fails
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, os.path.join(work, "missing.deck"), "-o", out],
                   capture_output=True, text=True)
if p.returncode == 0:
    fail("a missing deck did not fail")
print(f"{NAME}: PASS ({len(labels)} surfaces, {len(joints)} joints)")
