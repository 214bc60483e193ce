"""A second run aimed at the same --h5 path never corrupts the first one's
file: neither a file another process is reading (HDF5 used to truncate it,
then fail to lock it) nor one a run is still writing (both runs now write
their own temporary file and rename it over the target when done).

Usage: second_run_same_h5.py HSRI2D DECK_DIRECTORY WORK_DIRECTORY
"""
import glob
import os
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

NAME = "io_second_run_same_h5"


def fail(message):
    print(f"{NAME}: FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def run(exe, *args):
    p = subprocess.run([exe, *args], capture_output=True, text=True, timeout=120)
    for bad in ("Fortran runtime", "Backtrace", "Segmentation", "Program received"):
        if bad in p.stderr:
            fail(f"{' '.join(args)}: a crash reached the user:\n{p.stderr}")
    return p


def check_complete(path, what):
    """The file opens and its series have one row per time."""
    with h5py.File(path, "r") as f:
        rows = f["time"].shape[0]
        for name in ("body/z", "acceleration", "energy/summary"):
            if f[name].shape[0] != rows:
                fail(f"{what}: {name} has {f[name].shape[0]} rows, /time {rows}")
        return f.attrs["title"], rows


def main():
    exe, decks, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    os.chdir(work)

    # 1. The first run's file, held open by a reader while a second run
    #    writes a different case to the same path.
    p = run(exe, os.path.join(decks, "free_fall.deck"), "-o", "first.lst", "--h5", "out.h5")
    if p.returncode != 0:
        fail(f"the first run failed: {p.stderr}")
    reader = h5py.File("out.h5", "r")
    title = reader.attrs["title"]
    time_before = reader["time"][()]
    p = run(exe, os.path.join(decks, "joint_torque.deck"), "-o", "second.lst", "--h5", "out.h5")
    if p.returncode != 0:
        fail(f"the second run failed (status {p.returncode}): {p.stderr}")
    # Everything the reader reads now is the first run's, intact.
    if reader.attrs["title"] != title:
        fail("the reader's file changed its title")
    if not np.array_equal(reader["time"][()], time_before):
        fail("the reader's /time changed")
    z = reader["body/z"][()]
    if z.shape[0] != time_before.shape[0] or not np.all(np.isfinite(z)):
        fail("the reader's /body/z is damaged")
    reader.close()
    new_title, _ = check_complete("out.h5", "the second run's file")
    if new_title == title:
        fail("out.h5 still holds the first run after the second one succeeded")

    # 2. Two runs writing the same path at once: each writes its own
    #    temporary file; the target ends up complete, from one of them.
    with open("long.deck", "w") as f:
        f.write("*TIME\n         1.0    0.0001    0.0005   1.0E-06        10   1.0E-07   1.0E-09\n")
    first = subprocess.Popen([exe, "@default", "long.deck", "-o", "a.lst", "--h5", "same.h5"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while not glob.glob("same.h5.*.part") and not os.path.exists("same.h5"):
        if first.poll() is not None or time.monotonic() > deadline:
            break
        time.sleep(0.005)
    second = run(exe, os.path.join(decks, "free_fall.deck"), "-o", "b.lst", "--h5", "same.h5")
    first_err = first.communicate(timeout=120)[1]
    if first.returncode != 0 or second.returncode != 0:
        fail(f"concurrent runs: statuses {first.returncode} and {second.returncode}:\n{first_err}\n{second.stderr}")
    final_title, rows = check_complete("same.h5", "the file two runs wrote at once")
    print(f"{NAME}: concurrent runs left a complete file ({rows} rows of '{final_title}')")
    left = glob.glob("*.part")
    if left:
        fail(f"temporary files left: {left}")
    print(f"{NAME}: PASS")


if __name__ == "__main__":
    main()
