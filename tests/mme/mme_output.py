#!/usr/bin/env python3
"""--mme DIR: a run's time histories as an ISO-MME data set (docs/pulse.md,
"The run as an ISO-MME data set").

usage: mme_output.py HSRI2D DECK WORKDIR

Runs DECK (a belted deck) with a vertical part added to its pulse, with --mme
and --h5, then checks the data set
against the HDF5 file: the index's channels and codes, each channel's
header (code, unit, dimension, sampling interval = the print interval,
number of samples = its sample lines = the print records), its values
(the vehicle's x acceleration in g, its z with ISO's sign, the head's and
chest's resultant accelerations in g, each belt section's tension in N, to
the 10 digits written). A second run into the same folder is refused
(status 4, nothing written, the data set unchanged); the program reads its
own data set back as a pulse (*PULSEMME).
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

G_STD = 9.80665 / 0.0254      # in/s^2
LB_TO_N = 4.4482216152605


def fail(message):
    sys.exit("FAIL: " + message)


def header_and_samples(path):
    header, samples = {}, []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not samples and ":" in line:
                key, _, value = line.partition(":")
                header[key.strip()] = value.strip()
            else:
                samples.append(float(line))
    return header, np.array(samples)


def main():
    exe, deck, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "out"))
    dset = os.path.join(work, "out", "run1")
    h5 = os.path.join(work, "run1.h5")
    # the deck's pulse with a vertical part, so that the z channel's sign shows
    vertical = os.path.join(work, "vertical.deck")
    with open(vertical, "w") as f:
        f.write("*PULSE\n")
        for t, x, y in ((0.0, 0.0, 0.0), (0.05, -20.0, 5.0), (0.1, 0.0, 0.0)):
            f.write("  %10.4f%10.4f%10.4f\n" % (t, x, y))
    proc = subprocess.run([exe, deck, vertical, "--mme", dset, "--h5", h5, "-o", os.path.join(work, "run1.lst")],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        fail("the run exited with %d: %s" % (proc.returncode, proc.stderr))

    chn_header, _ = header_and_samples(os.path.join(dset, "CHANNEL", "run1.chn"))
    names = {k[len("Name of channel "):]: v.split(" / ")[0] for k, v in chn_header.items()
             if k.startswith("Name of channel ")}
    if int(chn_header["Number of channels"]) != len(names):
        fail("the index counts %s channels and names %d" % (chn_header["Number of channels"], len(names)))
    if not os.path.exists(os.path.join(dset, "run1.mme")):
        fail("no run1.mme")

    with h5py.File(h5, "r") as f:
        t = f["time"][:]
        vehicle = f["vehicle"][:]
        acc = f["acceleration"][:]
        lap = f["effects/lap_belt/force"][:]
        torso = f["effects/torso_belt/force"][:]
    expected = {
        "10VEHCCG0000ACX0": ("g", "AC", vehicle[:, 6] / G_STD),
        "10VEHCCG0000ACZ0": ("g", "AC", -vehicle[:, 7] / G_STD),
        "11HEAD000000ACR0": ("g", "AC", acc[:, 0] / G_STD),
        "11CHST000000ACR0": ("g", "AC", acc[:, 1] / G_STD),
        "11SEBE0000B6FO00": ("N", "FO", lap.reshape(-1) * LB_TO_N),
        "11SEBE0000B3FO00": ("N", "FO", torso[:, 0] * LB_TO_N),
        "11SEBE0000B4FO00": ("N", "FO", torso[:, 1] * LB_TO_N),
    }
    if sorted(names.values()) != sorted(expected):
        fail("channels %s, expected %s" % (sorted(names.values()), sorted(expected)))
    if np.max(np.abs(vehicle[:, 7])) < G_STD:
        fail("the vertical pulse did not reach the run")
    dt = t[1] - t[0]
    n = len(t)
    if abs(t[-1] - (t[0] + (n - 1) * dt)) > 1e-9:
        n -= 1     # a last record off the print grid is left out
    for number, code in sorted(names.items()):
        header, samples = header_and_samples(os.path.join(dset, "CHANNEL", "run1." + number))
        unit, dimension, values = expected[code]
        if header["Channel code"] != code or header["Unit"] != unit or header["Dimension"] != dimension:
            fail("channel %s: header %s" % (number, header))
        if abs(float(header["Sampling interval"]) - dt) > 1e-12 or float(header["Time of first sample"]) != 0.0:
            fail("channel %s: interval %s, first %s; the print interval is %g" %
                 (number, header["Sampling interval"], header["Time of first sample"], dt))
        if int(header["Number of samples"]) != len(samples) or len(samples) != n:
            fail("channel %s: %s samples in its header, %d in the file, %d print records" %
                 (number, header["Number of samples"], len(samples), n))
        scale = max(1.0, float(np.max(np.abs(values[:n]))))
        worst = float(np.max(np.abs(samples - values[:n]))) / scale
        if worst > 1e-8:
            fail("channel %s (%s): off the HDF5 file's values by %.3g of its largest" % (number, code, worst))
    print("OK: %d channels of %d samples agree with the HDF5 file" % (len(names), n))

    # a second run into the same folder: refused before anything is written
    before = {p: open(os.path.join(dset, "CHANNEL", p), "rb").read() for p in os.listdir(os.path.join(dset, "CHANNEL"))}
    second = os.path.join(work, "run2.lst")
    proc = subprocess.run([exe, deck, "--mme", dset, "-o", second], capture_output=True, text=True)
    if proc.returncode != 4 or "exists; it is not overwritten" not in proc.stderr:
        fail("a second run into the data set: status %d, %s" % (proc.returncode, proc.stderr))
    if os.path.exists(second):
        fail("the refused run wrote its listing")
    proc = subprocess.run([exe, "--check", deck, "--mme", dset], capture_output=True, text=True)
    if proc.returncode != 4 or "exists; it is not overwritten" not in proc.stderr:
        fail("--check of a folder holding a data set: status %d, %s" % (proc.returncode, proc.stderr))
    proc = subprocess.run([exe, "--outputs", deck, "--mme", dset], capture_output=True, text=True)
    if proc.returncode != 1 or "--mme would be ignored" not in proc.stderr:
        fail("--outputs with --mme: status %d, %s" % (proc.returncode, proc.stderr))
    after = {p: open(os.path.join(dset, "CHANNEL", p), "rb").read() for p in os.listdir(os.path.join(dset, "CHANNEL"))}
    if before != after:
        fail("the refused run changed the data set")
    # a channel file alone in the way (the .mme and index gone) is refused too, when the run begins
    os.remove(os.path.join(dset, "run1.mme"))
    os.remove(os.path.join(dset, "CHANNEL", "run1.chn"))
    proc = subprocess.run([exe, deck, "--mme", dset, "-o", second], capture_output=True, text=True)
    if proc.returncode != 4 or "run1.001 exists; it is not overwritten" not in proc.stderr:
        fail("a channel file in the way: status %d, %s" % (proc.returncode, proc.stderr))
    if os.path.exists(os.path.join(dset, "run1.mme")):
        fail("the refused run wrote the .mme file")

    # the program reads its own data set back as a pulse
    with open(os.path.join(work, "readback.deck"), "w") as f:
        f.write("*PULSEMME\nout/run2/run2.mme\n10VEHCCG0000ACX0\n")
    proc = subprocess.run([exe, deck, "--mme", os.path.join(work, "out", "run2"), "-o", os.path.join(work, "run2b.lst")],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        fail("a run into a new folder: %d %s" % (proc.returncode, proc.stderr))
    proc = subprocess.run([exe, "--check", deck, os.path.join(work, "readback.deck")], capture_output=True, text=True)
    if proc.returncode != 0:
        fail("the data set read back as a pulse: %d %s" % (proc.returncode, proc.stderr))
    print("OK: refused into an existing data set; read back as a pulse")


if __name__ == "__main__":
    main()
