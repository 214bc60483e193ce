#!/usr/bin/env python3
"""--mme DIR: a run's time histories as an ISO-MME data set (docs/pulse.md,
"The run as an ISO-MME data set").

usage: mme_output.py HSRI2D DECK WORKDIR

Runs DECK (a belted deck) with a vertical part added to its pulse, with --mme
and --h5, then checks the data set against the HDF5 file's /channels (the
10 kHz records the FMVSS 208 table filters): the index's channels and codes,
each channel's header (code, unit, dimension, unfiltered with its SAE J211-1
class stated, sampling interval and time of first sample = /channels/time's
(the head's /channels/head_time's, 20 kHz),
number of samples = its sample lines), its values in ISO's units and signs
(the vehicle's and the head's and chest's x and z accelerations in g, z down,
and resultants; the neck's axial force and moment; both femurs' axial
force, compression negative; the chest's deflection, compression negative;
each belt section's tension in N) to the 10 digits written; and, where the
print times fall on the grid, the channels against the print records. A second run into the same folder is refused
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
        t_print = f["time"][:]
        vehicle = f["vehicle"][:]
        acc = f["acceleration"][:]
        lap = f["effects/lap_belt/force"][:].reshape(-1)
        torso = f["effects/torso_belt/force"][:]
        ch = {k: f["channels/" + k][:] for k in f["channels"]}
        classes = {k: f["channels/" + k].attrs.get("filter_class") for k in f["channels"]}
    t = ch["time"].reshape(-1)
    th = ch["head_time"].reshape(-1)          # the head's 20 kHz grid
    head, chest, neck = ch["head_acceleration"], ch["chest_acceleration"], ch["neck_loads"]
    belts, veh = ch["belt_forces"], ch["vehicle_acceleration"]
    # code: (unit, dimension, the SAE J211-1 class, the values from /channels
    # in ISO's units and signs: z down, neck Fz + tension and My + flexion,
    # femur and chest compression -)
    expected = {
        "10VEHCCG0000ACX0": ("g", "AC", 60, veh[:, 0]),
        "10VEHCCG0000ACZ0": ("g", "AC", 60, -veh[:, 1]),
        "11HEAD000000ACX0": ("g", "AC", 1000, head[:, 0]),
        "11HEAD000000ACZ0": ("g", "AC", 1000, -head[:, 1]),
        "11HEAD000000ACR0": ("g", "AC", 1000, np.hypot(head[:, 0], head[:, 1])),
        "11CHST000000ACX0": ("g", "AC", 180, chest[:, 0]),
        "11CHST000000ACZ0": ("g", "AC", 180, -chest[:, 1]),
        "11CHST000000ACR0": ("g", "AC", 180, np.hypot(chest[:, 0], chest[:, 1])),
        "11NECKUP0000FOZ0": ("N", "FO", 1000, neck[:, 0]),   # J211's class of neck forces
        "11NECKUP0000MOY0": ("Nm", "MO", 600, neck[:, 1]),
        "11FEMRLE0000FOZ0": ("N", "FO", 600, -ch["femur_force"].reshape(-1)),
        "11FEMRRI0000FOZ0": ("N", "FO", 600, -ch["femur_force"].reshape(-1)),
        "11CHST000000DSX0": ("mm", "DS", 180, -ch["chest_deflection"].reshape(-1)),
        "11SEBE0000B6FO00": ("N", "FO", 60, belts[:, 0]),
        "11SEBE0000B3FO00": ("N", "FO", 60, belts[:, 1]),
        "11SEBE0000B4FO00": ("N", "FO", 60, belts[:, 2]),
    }
    if sorted(names.values()) != sorted(expected):
        fail("channels %s, expected %s" % (sorted(names.values()), sorted(expected)))
    if classes["belt_forces"] != ["CFC 60"] and list(classes["belt_forces"]) != ["CFC 60"]:
        fail("/channels/belt_forces filter_class %s" % classes["belt_forces"])
    if np.max(np.abs(vehicle[:, 7])) < G_STD:
        fail("the vertical pulse did not reach the run")
    dt = t[1] - t[0]
    n = len(t)
    if abs(dt - 1e-4) > 1e-15 or t[0] != 0.0:
        fail("/channels/time: first %g, interval %g; expected 0 and 0.1 ms" % (t[0], dt))
    if abs(th[1] - th[0] - 5e-5) > 1e-15 or th[0] != 0.0:
        fail("/channels/head_time: first %g, interval %g; expected 0 and 0.05 ms" % (th[0], th[1] - th[0]))
    for number, code in sorted(names.items()):
        header, samples = header_and_samples(os.path.join(dset, "CHANNEL", "run1." + number))
        unit, dimension, cfc, values = expected[code]
        grid = th if code[2:6] == "HEAD" else t
        if header["Channel code"] != code or header["Unit"] != unit or header["Dimension"] != dimension:
            fail("channel %s: header %s" % (number, header))
        if code[-1] != "0" or header["Channel frequency class"] != "NOVALUE" or \
                header["Comments"] != "unfiltered; filter at CFC %d (SAE J211-1)" % cfc:
            fail("channel %s: not stated unfiltered with its class %d: %s" % (number, cfc, header))
        step = grid[1] - grid[0]
        if abs(float(header["Sampling interval"]) - step) > 1e-15 or float(header["Time of first sample"]) != grid[0]:
            fail("channel %s: interval %s, first %s; its grid's %g, %g" %
                 (number, header["Sampling interval"], header["Time of first sample"], step, grid[0]))
        if int(header["Number of samples"]) != len(samples) or len(samples) != len(grid):
            fail("channel %s: %s samples in its header, %d in the file, %d on its grid" %
                 (number, header["Number of samples"], len(samples), len(grid)))
        scale = max(1.0, float(np.max(np.abs(values))))
        worst = float(np.max(np.abs(samples - values))) / scale
        if worst > 1e-8:
            fail("channel %s (%s): off /channels by %.3g of its largest" % (number, code, worst))
    # the 10 kHz channels agree with the print records where their times meet
    # (the print times fall on the grid): the vehicle, the head's and chest's
    # resultants, the belts' tensions (lb in the records)
    at = np.rint(t_print / dt).astype(int)
    at = at[at < n]
    m = len(at)
    ah = np.rint(t_print[:m] / (th[1] - th[0])).astype(int)
    for label, sampled, printed in (
            ("vehicle x", veh[at, 0], vehicle[:m, 6] / G_STD),
            ("vehicle y", veh[at, 1], vehicle[:m, 7] / G_STD),
            ("head", np.hypot(head[ah, 0], head[ah, 1]), acc[:m, 0] / G_STD),
            ("chest", np.hypot(chest[at, 0], chest[at, 1]), acc[:m, 1] / G_STD),
            ("lap belt", belts[at, 0], lap[:m] * LB_TO_N),
            ("torso belt upper", belts[at, 1], torso[:m, 0] * LB_TO_N),
            ("torso belt lower", belts[at, 2], torso[:m, 1] * LB_TO_N)):
        worst = float(np.max(np.abs(sampled - printed))) / max(1.0, float(np.max(np.abs(printed))))
        if worst > 1e-9:
            fail("%s: the 10 kHz channel is off the print records by %.3g of its largest" % (label, worst))
    if np.max(belts[:, 0]) < 100.0:
        fail("the lap belt never pulled (%g N): the test shows nothing" % np.max(belts[:, 0]))
    print("OK: %d channels of %d samples agree with /channels and, at %d print times, with the records"
          % (len(names), n, m))

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
