#!/usr/bin/env python3
"""Writes tests/mme/sled: the body-only (sled) deck's pulse as an ISO-MME
data set (ISO/TS 13499), made by hand for the tests of *PULSEMME.

Channel 1 (10VEHCCG0000ACXP, g): the deck's 21 knots of -20 sin(pi t/T)
sampled every 5.37 ms exactly at the knots, from 2 samples before the
event's time zero, then zeros: the same table as the deck's cards.
Channel 2 (10VEHCRS0000ACXP, m/s**2): the same piecewise-linear pulse every
0.537 ms, in m/s**2 (10 significant digits), with one NOVALUE sample inside
the pulse (bridged linearly: on the line, so the same function).
Run once; the files are committed (python3 tests/mme/make_sled_set.py).
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))
KNOTS = [0.0, -3.1287, -6.1803, -9.0798, -11.7557, -14.1421, -16.1803, -17.8201, -19.0211,
         -19.7538, -20.0, -19.7538, -19.0211, -17.8201, -16.1803, -14.1421, -11.7557, -9.0798,
         -6.1803, -3.1287, 0.0]
STEP = 0.00537   # s, the deck's knot spacing
G = 9.80665      # m/s**2


def header(code, name, unit, dt, t1, n):
    rows = [("Channel code", code), ("Laboratory channel code", code), ("Name of the channel", name),
            ("Location", code[2:12]), ("Direction", code[14]), ("Channel frequency class", "NOVALUE"),
            ("Reference system", "local"), ("Sampling interval", dt), ("Unit", unit),
            ("Time of first sample", t1), ("Number of samples", str(n)), ("Dimension", "AC"),
            ("Data status", "ok")]
    return "".join("%-28s:%s\n" % row for row in rows)


def main():
    chan = os.path.join(HERE, "sled", "CHANNEL")
    os.makedirs(chan, exist_ok=True)
    with open(os.path.join(HERE, "sled", "sled.mme"), "w") as f:
        for key, value in [("Data format", "ISO-MME"), ("Version", "1.6"), ("Test number", "sled"),
                           ("Test type", "sled, 30 mph 20 g half-sine (hsri2d's body-only deck)"),
                           ("Laboratory name", "hsri2d tests (made by hand)"),
                           ("Comments", "Time zero: the start of the pulse")]:
            f.write("%-28s:%s\n" % (key, value))
    with open(os.path.join(chan, "sled.chn"), "w") as f:
        f.write("%-28s:%s\n" % ("Instrumentation standard", "SAEJ211"))
        f.write("%-28s:%s\n" % ("Number of channels", "2"))
        f.write("%-28s:%s\n" % ("Name of channel 001", "10VEHCCG0000ACXP / vehicle CG, x, at the knots"))
        f.write("%-28s:%s\n" % ("Name of channel 002", "10VEHCRS0000ACXP / vehicle, x, every 0.537 ms"))
    # channel 1: two samples before zero, the 21 knots, zeros to 0.2148 s
    values = [0.0, 0.0] + KNOTS + [0.0] * 20
    with open(os.path.join(chan, "sled.001"), "w") as f:
        f.write(header("10VEHCCG0000ACXP", "vehicle CG x", "g", "0.00537", "-0.01074", len(values)))
        f.writelines("%s\n" % repr(v) for v in values)
    # channel 2: ten samples a knot interval, linear between the knots, m/s**2
    fine = []
    for k in range(401):
        i, j = divmod(k, 10)
        a = KNOTS[i] + (KNOTS[i + 1] - KNOTS[i]) * j / 10.0 if i < 20 else 0.0
        fine.append("%.9e" % (a * G))
    fine[57] = "NOVALUE"
    with open(os.path.join(chan, "sled.002"), "w") as f:
        f.write(header("10VEHCRS0000ACXP", "vehicle x", "m/s**2", "0.000537", "0", len(fine)))
        f.writelines("%s\n" % v for v in fine)


if __name__ == "__main__":
    main()
