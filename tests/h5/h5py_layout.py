"""The HDF5 file as h5py 3 reads it (format_version 3, docs/usage.md):
root attributes, every dataset's columns/units/description as Python str,
/time 1-D, string datasets readable with .asstr().

Usage: h5py_layout.py HSRI2D WORK_DIRECTORY
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

NAME = "h5py_layout"


def fail(message):
    print(f"{NAME}: FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def is_str_list(value):
    return isinstance(value, np.ndarray) and value.ndim == 1 and all(isinstance(v, str) for v in value)


def main():
    exe, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    os.chdir(work)
    p = subprocess.run([exe, "-o", "run.lst", "--h5", "run.h5"], capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        fail(f"the run failed: {p.stderr}")
    version = subprocess.run([exe, "--version"], capture_output=True, text=True).stdout.split()[-1]

    with h5py.File("run.h5", "r") as f:
        a = f.attrs
        if int(a["format_version"]) != 3:
            fail(f"format_version is {a['format_version']!r}, expected 3")
        for key, want in (("program", "hsri2d"), ("version", version)):
            if not isinstance(a[key], str) or a[key] != want:
                fail(f"root attribute {key} is {a[key]!r}, expected the str {want!r}")
        for key in ("title", "units"):
            if not isinstance(a[key], str) or not a[key]:
                fail(f"root attribute {key} is {a[key]!r}, expected a non-empty str")

        rows = f["time"].shape
        if len(rows) != 1:
            fail(f"/time has shape {rows}, expected 1-D")
        n = rows[0]
        t = f["time"][()]
        if n < 2 or t[0] != 0.0 or not np.all(np.diff(t) > 0):
            fail("/time does not start at 0 and increase")

        datasets = []
        f.visititems(lambda name, obj: datasets.append(name) if isinstance(obj, h5py.Dataset) else None)
        for name in ("time", "body/z", "events/time", "events/kind", "events/index", "events/text", "input/deck"):
            if name not in datasets:
                fail(f"/{name} is missing")
        for name in datasets:
            d = f[name]
            ncols = 1 if d.ndim == 1 else d.shape[1]
            for key in ("columns", "units"):
                value = d.attrs.get(key)
                if not is_str_list(value) or len(value) != ncols:
                    fail(f"/{name} attribute {key} is {value!r}, expected {ncols} str")
            description = d.attrs.get("description")
            if not isinstance(description, str) or not description:
                fail(f"/{name} attribute description is {description!r}, expected a non-empty str")
            if name.startswith("channels/"):
                # the FMVSS 208 table's channels: their own 10 kHz grid, /channels/time
                # (the head's 20 kHz, /channels/head_time)
                grid = "channels/head_time" if name.endswith(("head_acceleration", "head_time")) else "channels/time"
                if d.shape[0] != f[grid].shape[0]:
                    fail(f"/{name} has {d.shape[0]} rows, /{grid} {f[grid].shape[0]}")
            elif d.ndim == 2 and not name.startswith(("summary/", "scene/")) and d.shape[0] != n:
                fail(f"/{name} has {d.shape[0]} rows, /time {n}")

        # every effect's contribution to b, and the summary's maxima with their times
        forces = [name for name in datasets if name.startswith("effects/") and name.endswith("/generalized_force")]
        if not forces:
            fail("no /effects/<name>/generalized_force series")
        for name in forces:
            if f[name].shape != (n, 10):
                fail(f"/{name} has shape {f[name].shape}, expected ({n}, 10)")
        maxima = f["summary/maxima"]
        columns = list(maxima.attrs["columns"])
        if maxima.shape[0] != 1 or "head_acceleration" not in columns:
            fail(f"/summary/maxima is {maxima.shape} with columns {columns}")
        if f["summary/maxima_time"].shape != maxima.shape:
            fail("/summary/maxima_time does not match /summary/maxima")
        head = maxima[0, columns.index("head_acceleration")]
        if not head >= f["acceleration"][:, 0].max():
            fail("the summary's head acceleration is below the largest printed one")

        # the acceleration criteria (docs/injury.md): one row, HIC15 <= HIC36,
        # the HIC window inside its limit and on the run
        crit = f["summary/injury_criteria"]
        ccols = list(crit.attrs["columns"])
        if crit.shape != (1, 9) or ccols[0] != "head_hic15":
            fail(f"/summary/injury_criteria is {crit.shape} with columns {ccols}")
        row = dict(zip(ccols, crit[0, :]))
        if not 0.0 <= row["head_hic15"] <= row["head_hic36"]:
            fail(f"HIC15 {row['head_hic15']} and HIC36 {row['head_hic36']} out of order")
        if not 0.0 <= row["head_hic15_t2"] - row["head_hic15_t1"] <= 0.015 + 1e-12:
            fail("the HIC15 window is longer than 15 ms")
        if row["chest_clip3ms"] > maxima[0, columns.index("chest_acceleration")] / (9.80665 / 0.0254) + 1e-9:
            fail("the chest's 3 ms clip exceeds its largest acceleration")
        # the joint reactions at print times
        for name in ("joints/tension", "joints/shear"):
            if f[name].shape != (n, 7):
                fail(f"/{name} has shape {f[name].shape}, expected ({n}, 7)")

        deck = f["input/deck"].asstr()[()]
        if len(deck) == 0 or not all(isinstance(line, str) for line in deck):
            fail("/input/deck does not read as str with .asstr()")
        if not any(line.startswith("*TIME") for line in deck):
            fail("/input/deck does not hold the deck")
        text = f["events/text"].asstr()[()]
        if text.shape != f["events/time"].shape:
            fail("/events/text does not read with .asstr()")
        # each event says in HDF5 what the listing's summary says (one description)
        if len(text) == 0:
            fail("the default deck's run records no event (it has undesired contacts)")
        with open("run.lst", encoding="utf-8") as lst:
            listing = lst.read()
        for t, line in zip(f["events/time"][()], text):
            if f"t ={t:10.5f} s   {line.rstrip()}" not in listing:
                fail(f"event {line.rstrip()!r} at t = {t} is not in the listing's summary")
    check_utf8_comment(exe)
    print(f"{NAME}: PASS ({len(datasets)} datasets, {n} rows)")


def check_utf8_comment(exe):
    """The documented recipe, f["input/deck"].asstr()[:], on a deck whose comment
    holds UTF-8 gives back its lines (the dataset was typed ASCII: UnicodeDecodeError)."""
    deck = subprocess.run([exe, "--default-deck"], capture_output=True, text=True, check=True).stdout
    comment = "$ crash pulse \u00e0 la SAE J211 \u2014 \u0394v = 48 km/h"
    with open("utf8.deck", "w", encoding="utf-8") as out:
        out.write(comment + "\n" + deck)
    p = subprocess.run([exe, "utf8.deck", "-o", "utf8.lst", "--h5", "utf8.h5"],
                       capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        fail(f"the run of a deck with a UTF-8 comment failed: {p.stderr}")
    with h5py.File("utf8.h5", "r") as f:
        try:
            lines = f["input/deck"].asstr()[:]
        except UnicodeDecodeError as e:
            fail(f'f["input/deck"].asstr()[:] raised {e}')
        if lines[0] != comment:
            fail(f"/input/deck's first line is {lines[0]!r}, expected {comment!r}")
        if [line.rstrip() for line in lines[1:]] != [line.rstrip() for line in deck.splitlines()]:
            fail("/input/deck does not hold the deck's lines")
        f["events/text"].asstr()[:]


if __name__ == "__main__":
    main()
