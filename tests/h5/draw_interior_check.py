#!/usr/bin/env python3
"""tools/draw-interior on the timing deck's interior (tools/bench/
interior_driver.deck: seat back, padded lower panel and its edge, toeboard,
floor): the SVG names every resolved surface, draws the flat ones as
segments from (X, Y) to their far end as the listing gives them (their
length and direction checked against the deck's D and PSI), and the
occupant's seven joints.

Usage: draw_interior_check.py HSRI2D TOOL DECK WORKDIR
"""
import math
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
# the flat surfaces as segments: length D and direction PSI + 180 deg (from
# (X'', Y'') towards the far end) at the drawing's 10 px per inch, y down
segments = re.findall(r'<line x1="([-.0-9]+)" y1="([-.0-9]+)" x2="([-.0-9]+)" y2="([-.0-9]+)" '
                      r'stroke="black" stroke-width="3"/>', text)
drawn = sorted((round(math.hypot(float(x2) - float(x1), float(y2) - float(y1)) / 10.0, 1),
                round(math.degrees(math.atan2(float(y2) - float(y1), float(x1) - float(x2))), 0))
               for x1, y1, x2, y2 in segments)
flat = sorted([(12.0, 95.0), (10.0, 45.0), (20.0, -80.0)])    # the deck's D, PSI of surfaces 5, 6, 9
if drawn != flat:
    fail(f"flat surfaces drawn as (D, PSI) {drawn}, expected {flat}")
# a bad deck: the tool says so and fails
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, os.path.join(work, "missing.deck"), "-o", out],
                   capture_output=True, text=True)
if p.returncode == 0:
    fail("a missing deck did not fail")
print(f"{NAME}: PASS ({len(labels)} surfaces, {len(joints)} joints)")
