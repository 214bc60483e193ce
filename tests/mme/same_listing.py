#!/usr/bin/env python3
"""A shipped deck run with its pulse given as an ISO-MME data set reproduces
the same deck with the pulse on cards (*PULSEMME; docs/pulse.md).

usage: same_listing.py HSRI2D DECK OVERLAY EXPECTED_SOURCE WORKDIR

Runs DECK alone and DECK followed by OVERLAY (a deck whose *PULSEMME replaces
the *PULSE cards), then compares the two listings from the page "INITIAL
STATE AND ACCELERATIONS" to the end (the input pages differ by the echo and
the pulse table), page headers left out: every number the same to one unit
of its last printed digit (the interpolation's tolerance: the data set's
samples lie on the cards' piecewise-linear table, written to 10 digits), all
text the same. The first listing page must name the data set's channel
(EXPECTED_SOURCE). Exit status 0 when they agree.
"""
import os
import re
import subprocess
import sys

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([EeDd][-+]?\d+)?$")


def run(exe, decks, out):
    proc = subprocess.run([exe] + decks + ["-o", out], capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit("FAIL: %s exited with %d: %s" % (" ".join(decks), proc.returncode, proc.stderr))
    with open(out) as f:
        return f.read()


def results(text):
    lines = text.split("\n")
    first = [k for k, line in enumerate(lines) if "INITIAL STATE AND ACCELERATIONS" in line]
    if not first:
        sys.exit("FAIL: no INITIAL STATE page")
    return [line for line in lines[first[0]:] if "HSRI-2D" not in line]


def last_digit_unit(token):
    mantissa, _, exponent = token.upper().replace("D", "E").partition("E")
    places = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 10.0 ** (-places + (int(exponent) if exponent else 0))


def main():
    exe, deck, overlay, expected, work = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    cards = run(exe, [deck], os.path.join(work, "cards.lst"))
    mme = run(exe, [deck, overlay], os.path.join(work, "mme.lst"))
    head = mme.split("\n")[:20]
    if not any(expected in line for line in head):
        sys.exit("FAIL: the listing does not name the pulse's data set (%s):\n%s" % (expected, "\n".join(head)))
    a, b = results(cards), results(mme)
    if len(a) != len(b):
        sys.exit("FAIL: %d result lines from the cards, %d from the data set" % (len(a), len(b)))
    n_numbers = 0
    worst = 0.0
    for k, (la, lb) in enumerate(zip(a, b)):
        ta, tb = la.split(), lb.split()
        if len(ta) != len(tb):
            sys.exit("FAIL: result line %d differs:\n  %s\n  %s" % (k + 1, la, lb))
        for x, y in zip(ta, tb):
            if NUMBER.match(x) and NUMBER.match(y):
                n_numbers += 1
                unit = max(last_digit_unit(x), last_digit_unit(y))
                diff = abs(float(x.replace("D", "E")) - float(y.replace("D", "E")))
                worst = max(worst, diff / unit)
                if diff > unit * (1.0 + 1e-9):
                    sys.exit("FAIL: result line %d: %s against %s:\n  %s\n  %s" % (k + 1, x, y, la, lb))
            elif x != y:
                sys.exit("FAIL: result line %d: %s against %s:\n  %s\n  %s" % (k + 1, x, y, la, lb))
    print("OK: %d result lines, %d numbers; largest difference %.2f of a last digit" % (len(a), n_numbers, worst))


if __name__ == "__main__":
    main()
