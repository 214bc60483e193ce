#!/usr/bin/env python3
"""The analog's HDF5 file (report Section D; docs/analog.md): a run of
decks/analog_undamped.deck with --h5 writes /analog/case_1 (t, theta1, theta1dot,
theta2, theta2dot in rad and rad/s, the separation in in) every 1 ms to 0.125 s and
the deck as /input/deck; checked here independently of the program: theta2 = omega t
(m v rho = I0 omega) up to the 60-degree stop, theta1's rate the derivative of theta1,
the separation from the angles by hand, the first contact between 0.064 and 0.065 s.

    analog_h5_check.py HSRI2D DECKS_DIR WORK_DIR
"""
import math
import pathlib
import subprocess
import sys

import h5py

exe, decks, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
work.mkdir(parents=True, exist_ok=True)
h5 = work / "analog.h5"
lst = work / "analog.lst"
subprocess.run([exe, str(decks / "analog_undamped.deck"), "-o", str(lst), "--h5", str(h5)], check=True)
failures = []


def check(what, ok):
    if not ok:
        failures.append(what)


with h5py.File(h5, "r") as f:
    d = f["analog/case_1"][:]
    deck = "\n".join(f["input/deck"].asstr()[:])
    check("the deck is in /input/deck", "*ANALOG" in deck)
    check("126 rows", d.shape == (126, 6))
    omega = 110.0 / (9.80665 / 0.0254) * 20 * 17.6 * 17.0 / 117.0
    for t, th1, r1, th2, r2, gap in d:
        expected2 = min(omega * t, math.radians(60.0))
        check(f"theta2 at {t}", abs(th2 - expected2) < 1e-12)
        a = (0.0 + 38 * math.sin(th2), 38 * math.cos(th2))          # the rear head
        # its signed distance from the front body's line (hip at (34, 0)), negative past it
        dist = (a[0] - 34.0) * -math.cos(th1) + a[1] * math.sin(th1)
        check(f"separation at {t}: {gap} vs {dist}", gap <= dist + 1e-9)
    rows = {round(t * 1000): (th1, r1) for t, th1, r1, *_ in d}
    for k in range(1, 125):
        fd = (rows[k + 1][0] - rows[k - 1][0]) / 0.002
        check(f"theta1dot at {k} ms", abs(fd - rows[k][1]) < 0.02 * omega)
    first = next(t for t, *_, gap in d if gap <= 0)
    check(f"first contact row {first}", abs(first - 0.065) < 1e-9)
    check("no contact at 0.064 s", d[64, 5] > 0)

for f in failures:
    print("FAILED", f)
print(f"analog HDF5: {len(failures)} failures")
sys.exit(1 if failures else 0)
