#!/usr/bin/env python3
"""tools/bench/eval-cost (issue 16 section 4's figures, docs/performance.md):
the frame measurement's deck, the default deck with its *TIME card's TMAX,
DT and DTPRINT rewritten, is a deck the program runs as meant (0.02 s, a
print time every 1e-4 s: 201 records), with the card's other fields kept.
The callgrind part needs valgrind, which CI does not install; it is not run.

  eval_cost_check.py HSRI2D TOOL DECKS WORKDIR
"""
import os
import runpy
import subprocess
import sys

exe, tool, decks, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
mod = runpy.run_path(tool, run_name="eval_cost")
dense = os.path.join(work, "dense.deck")
mod["time_card_deck"](os.path.join(decks, "default.deck"), dense, ["0.02", "0.0001", "0.0001"])
src = open(os.path.join(decks, "default.deck")).read().splitlines()
out = open(dense).read().splitlines()
changed = [(a, b) for a, b in zip(src, out) if a != b]
assert len(src) == len(out) and len(changed) == 1, changed
old, new = changed[0]
assert new[32:] == old[32:], (old, new)          # CTOL CITER RTOL ATOL kept
assert new.split()[:3] == ["0.02", "0.0001", "0.0001"], new
lst = os.path.join(work, "dense.lst")
p = subprocess.run([exe, dense, "-o", lst], capture_output=True, text=True)
assert p.returncode == 0, p.stderr
text = open(lst).read()
# the listing's time column: the last record at 0.02 s, one every 1e-4 s
assert "0.02000" in text and "0.00010" in text, "the dense deck's print times are not in its listing"
print("eval-cost's dense deck: one card changed, runs, prints every 1e-4 s to 0.02 s")
