#!/usr/bin/env python3
"""tools/draw-interior on the timing deck's interior (tools/bench/
interior_driver.deck: seat back, padded lower panel and its edge, toeboard,
floor): the SVG names every resolved surface, draws the flat ones as
segments from (X, Y) to their far end as the listing gives them (their
length and direction checked against the deck's D and PSI), the
occupant's seven joints, and the body points' contact arcs where f.1 puts
them. A deck whose run fails numerically (status 3) is drawn the same
(issue 14, item 27); an output that is one of the inputs (a deck, through a
link, or standard input) is refused with status 1 and the deck left as it
was (item 9); a symbolic link given as the output stays, its target written.

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
# the body points' contact arcs (f.1): the ten circles, the head's rho'_4 = 6.1 in from
# the neck along the head at theta_4 = 85 deg with r_4 = 3.9 in (decks/body_only.deck's
# arcs and posture), the hand at L_6 = 13.7 in from the elbow
circle = r'<circle cx="([-.0-9]+)" cy="([-.0-9]+)" r="([-.0-9]+)"[^>]*><title>{}</title>'
arcs = re.findall(r"<title>(arc [0-9]+)</title>", text)
if sorted(arcs) != sorted(f"arc {i}" for i in (1, 2, 3, 4, 5, 6, 7, 8, 10, 11)):
    fail(f"arcs {arcs}")
neck = [float(v) for v in re.search(circle.format("neck"), text).groups()]
head = [float(v) for v in re.search(circle.format("arc 4"), text).groups()]
elbow = [float(v) for v in re.search(circle.format("elbow"), text).groups()]
hand = [float(v) for v in re.search(circle.format("arc 10"), text).groups()]
dist = math.hypot(head[0] - neck[0], head[1] - neck[1]) / 10.0
angle = math.degrees(math.atan2(neck[1] - head[1], head[0] - neck[0]))
if abs(dist - 6.1) > 0.02 or abs(angle - 85.0) > 0.5 or abs(head[2] / 10.0 - 3.9) > 0.01:
    fail(f"head arc at {dist:.2f} in, {angle:.1f} deg from the neck, radius {head[2] / 10.0}")
if abs(math.hypot(hand[0] - elbow[0], hand[1] - elbow[1]) / 10.0 - 13.7) > 0.02:
    fail("the hand is not L_6 from the elbow")
# a bad deck: the tool says so and fails
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, os.path.join(work, "missing.deck"), "-o", out],
                   capture_output=True, text=True)
if p.returncode == 0:
    fail("a missing deck did not fail")

# a run that ends in a numerical failure (an energy-balance tolerance no run
# meets: status 3) is drawn: the drawing needs only t = 0
tight = os.path.join(work, "tight.deck")
with open(tight, "w") as f:
    f.write("*NUMERICS\n" + "1.0E-12".rjust(32) + "\n")
failing = subprocess.run([hsri2d, deck, tight, "-o", os.devnull], capture_output=True)
if failing.returncode != 3:
    fail(f"the deck with EBTOL = 1e-12 ends with status {failing.returncode}, not 3: the test needs another deck")
out3 = os.path.join(work, "failing.svg")
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, deck, tight, "-o", out3], capture_output=True, text=True)
if p.returncode != 0:
    fail(f"a run ending with status 3 was not drawn: status {p.returncode}: {p.stderr}")
if open(out3, encoding="utf-8").read() != text:
    fail("the drawing of the failing run differs from the drawing at t = 0")

# an output that is an input is refused, the input untouched
mine = os.path.join(work, "mine.deck")
deck_text = open(deck, encoding="utf-8").read()
with open(mine, "w", encoding="utf-8") as f:
    f.write(deck_text)
link = os.path.join(work, "link.svg")
if os.path.lexists(link):
    os.unlink(link)
os.symlink("mine.deck", link)
for args, stdin, what in (([mine, "-o", mine], None, "-o the deck"),
                          ([mine, "-o", link], None, "-o a link to the deck"),
                          (["-", "-o", mine], mine, "-o the deck on standard input"),
                          (["-", "-o", "/dev/stdin"], mine, "-o /dev/stdin, the deck on standard input")):
    with open(stdin or os.devnull, "rb") as f:
        p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, *args], stdin=f, capture_output=True, text=True)
    if p.returncode != 1 or "refusing to overwrite" not in p.stderr:
        fail(f"{what}: status {p.returncode}, expected 1 and a refusal: {p.stderr}")
    if open(mine, encoding="utf-8").read() != deck_text:
        fail(f"{what}: the deck was changed")
if not os.path.islink(link):
    fail("link.svg is no longer a symbolic link")

# the deck from standard input is drawn like the deck from its file
out_stdin = os.path.join(work, "stdin.svg")
with open(mine, "rb") as f:
    p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, "-", "-o", out_stdin], stdin=f,
                       capture_output=True, text=True)
if p.returncode != 0 or open(out_stdin, encoding="utf-8").read() != text:
    fail(f"the deck on standard input was not drawn as from its file: status {p.returncode}: {p.stderr}")

# a symbolic link to nothing yet as the output: the link stays, its target is written
dangling = os.path.join(work, "dangling.svg")
drawn = os.path.join(work, "drawn.svg")
for path in (dangling, drawn):
    if os.path.lexists(path):
        os.unlink(path)
os.symlink("drawn.svg", dangling)
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, deck, "-o", dangling], capture_output=True, text=True)
if p.returncode != 0 or not os.path.islink(dangling) or not os.path.isfile(drawn):
    fail(f"-o a dangling link: status {p.returncode}, the link {'kept' if os.path.islink(dangling) else 'replaced'}")
if [n for n in os.listdir(work) if n.endswith(".part")]:
    fail("a temporary file was left")
# -o - writes the drawing on standard output, not a file named "-"
p = subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, deck, "-o", "-"], capture_output=True, text=True,
                   cwd=work)
if p.returncode != 0 or not p.stdout.startswith("<svg") or os.path.exists(os.path.join(work, "-")):
    fail(f"-o -: status {p.returncode}, stdout {'an SVG' if p.stdout.startswith('<svg') else 'not an SVG'}")
print(f"{NAME}: PASS ({len(labels)} surfaces, {len(joints)} joints, {len(arcs)} arcs)")
