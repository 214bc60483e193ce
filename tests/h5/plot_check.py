"""tools/plot (issue 18): each picture rendered from a shipped deck's HDF5
file (the program run here), named after the run, not empty and of its
format; a filtered series plotted when the file has one; an existing file
kept without --force and replaced with it; no temporary file left; every
error one line, status 1, no Python traceback.

    plot_check.py HSRI2D PLOT DECKS_DIR WORKDIR
"""
import math
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

hsri2d, plot, decks, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def tool(*args):
    p = subprocess.run([sys.executable, plot, *args], capture_output=True, text=True, cwd=work)
    return p.returncode, p.stderr


def picture(path, magic):
    """The file exists, holds more than its header, and starts as its format does."""
    if not os.path.isfile(path) or os.path.getsize(path) < 1000:
        return False
    with open(path, "rb") as f:
        return f.read(len(magic)) == magic


PNG, GIF = b"\x89PNG\r\n\x1a\n", b"GIF8"

try:
    import matplotlib  # noqa: F401
except ImportError:
    sys.exit("tools/plot needs matplotlib (Debian package python3-matplotlib; tools/setup installs it)")

# the belted sled (seat, lap and torso belts, no interior) and the default deck (the driver's interior)
for deck in ("sled_belted", "default"):
    h5 = os.path.join(work, deck + ".h5")
    p = subprocess.run([hsri2d, deck + ".deck", "-o", os.devnull, "--h5", h5], cwd=decks, capture_output=True)
    if p.returncode != 0:
        sys.exit(f"hsri2d {deck}.deck failed ({p.returncode}): {p.stderr.decode()}")
    status, err = tool("motion", h5, "--times", "0", "0.05", "0.1", "--dpi", "60")
    check(status == 0 and picture(os.path.join(work, f"{deck}-motion.png"), PNG),
          f"{deck}: motion gives {deck}-motion.png ({err.strip()})")
    status, err = tool("history", h5, "--dpi", "60")
    check(status == 0 and picture(os.path.join(work, f"{deck}-history.png"), PNG),
          f"{deck}: history gives {deck}-history.png ({err.strip()})")

h5 = os.path.join(work, "sled_belted.h5")
try:
    import PIL.Image
    status, err = tool("animate", h5, "--dpi", "40", "--fps", "20")
    gif = os.path.join(work, "sled_belted-animation.gif")
    check(status == 0 and picture(gif, GIF), f"animate gives sled_belted-animation.gif ({err.strip()})")
    with h5py.File(h5, "r") as f:
        records = f["time"].shape[0]
    frames = PIL.Image.open(gif).n_frames if os.path.isfile(gif) else 0
    check(frames == records, f"the animation has a frame per print time ({frames} of {records})")
except ImportError:
    status, err = tool("animate", h5)
    check(status == 1 and "python3-pil" in err, "without PIL, animate says which package it needs")

# mp4 only with ffmpeg
status, err = tool("animate", h5, "-o", "run.mp4", "--dpi", "40")
if shutil.which("ffmpeg"):
    check(status == 0 and os.path.getsize(os.path.join(work, "run.mp4")) > 1000, "an MP4 with ffmpeg")
else:
    check(status == 1 and "ffmpeg" in err and not os.path.exists(os.path.join(work, "run.mp4")),
          "no ffmpeg: an MP4 is refused, saying why")

# an existing file is kept without --force, replaced with it
target = os.path.join(work, "sled_belted-motion.png")
before = open(target, "rb").read()
status, err = tool("motion", h5, "--times", "0.02", "--dpi", "60")
check(status == 1 and "exists; --force replaces it" in err and open(target, "rb").read() == before,
      "an existing picture is not replaced without --force")
status, err = tool("motion", h5, "--times", "0.02", "--dpi", "60", "--force")
check(status == 0 and open(target, "rb").read() != before, "--force replaces it")
status, err = tool("history", h5, "-o", h5)
check(status == 1 and "refusing" in err, "the run's own file is never the output")

# the 10 kHz channels (issue 18 section 1) are plotted raw and J211-filtered; the
# filter is the program's: a CFC 180 chest channel of a step, filtered, is met half
# way at the step and ends at its level (the forward-backward pass: no phase)
status, err = tool("history", h5, "--dpi", "60", "-o", os.path.join(work, "channels-history.png"), "--force")
check(status == 0 and "head filtered (CFC 1000): /channels/head_acceleration" in err
      and "chest filtered (CFC 180): /channels/chest_acceleration" in err
      and picture(os.path.join(work, "channels-history.png"), PNG),
      "the head's and chest's 10 kHz channels are plotted raw and filtered")
import importlib.machinery, importlib.util
loader = importlib.machinery.SourceFileLoader("hsri2d_plot", plot)
spec = importlib.util.spec_from_loader("hsri2d_plot", loader)
module = importlib.util.module_from_spec(spec)
loader.exec_module(module)
step = np.where(np.arange(2001) >= 1000, 1.0, 0.0)
y = module.j211(step, 180.0, 1e-4)
check(abs(y[1000] - 0.5) < 0.05 and abs(y[0]) < 1e-9 and abs(y[-1] - 1.0) < 1e-9
      and abs(y[1000 + 30] + y[999 - 30] - 1.0) < 1e-9,
      "J211 in tools/plot: a step met half way at its time, antisymmetric about it, settled at its ends")

# the seat as each frame's time has it (issue 18): the rigid beam (its y_g and
# gamma) and the non-rigid beams (delta_A, w, z) move in the pictures; their t = 0
# line is the scene's cushion line; a file without those series draws the seat at
# t = 0 and says so; the spring seat's cushion does not move
for deck, form in (("sled_rigid_seat", 2), ("sled_beam_seat", 3), ("sled_belted", 1)):
    h5 = os.path.join(work, deck + ".h5")
    if not os.path.exists(h5):
        p = subprocess.run([hsri2d, deck + ".deck", "-o", os.devnull, "--h5", h5], cwd=decks, capture_output=True)
        if p.returncode != 0:
            sys.exit(f"hsri2d {deck}.deck failed ({p.returncode}): {p.stderr.decode()}")
    run = module.Run(h5, 1)
    scene = module.frame_geometry(run)[2]
    seat, series = module.seat_columns(scene), module.seat_series(run)
    first, _, moved0 = module.seat_lines(seat, series, 0)
    last = [module.seat_lines(seat, series, r)[0] for r in range(run.t.size)]
    shift = max(float(np.max(np.abs(lines[0][1] - first[0][1]))) for lines in last)
    tan = math.tan(seat["gamma_o"])
    on_line = float(np.max(np.abs(first[0][1] - (seat["y_line"] + (first[0][0] - seat["x_line"]) * tan))))
    check(int(seat["form"]) == form and moved0, f"{deck}: the seat's form {form} and its motion in the file")
    if form == 1:
        check(shift == 0.0, f"{deck}: the spring seat's cushion line does not move")
    else:
        # (the beam seat's beam 1 at t = 0 is already lowered by the body's weight)
        check(shift > 1.0 and (form == 3 or on_line < 1e-12),
              f"{deck}: the seat moves with the run (by up to {shift:.2f} in), from the cushion line at t = 0 "
              f"({on_line:.2g} in off it)")
        status, err = tool("motion", h5, "--times", "0.1", "--dpi", "50", "-o", os.path.join(work, deck + "-seat.png"))
        check(status == 0 and picture(os.path.join(work, deck + "-seat.png"), PNG), f"{deck}: its motion picture")
        # without the series that move it: the t = 0 seat, labelled so
        bare = os.path.join(work, deck + "-bare.h5")
        shutil.copy(h5, bare)
        with h5py.File(bare, "a") as f:
            for name in ("effects/seat/beam", "effects/seat/loads"):
                if name in f:
                    del f[name]
        run = module.Run(bare, 1)
        lines, _, moved = module.seat_lines(seat, module.seat_series(run), run.t.size - 1)
        check(not moved and np.allclose(lines[0][1], seat["y_line"] + (lines[0][0] - seat["x_line"]) * tan),
              f"{deck}: a file without the seat's series draws it at t = 0")
        status, err = tool("motion", bare, "--times", "0.1", "--dpi", "50", "-o",
                           os.path.join(work, deck + "-bare.png"))
        check(status == 0, f"{deck}: ... and still draws ({err.strip()})")

# errors: one line each, status 1, never a traceback
with open(os.path.join(work, "text.h5"), "w") as f:
    f.write("not HDF5\n")
with h5py.File(os.path.join(work, "other.h5"), "w") as f:
    f["x"] = [1.0]
with h5py.File(os.path.join(work, "old.h5"), "w") as f:
    f.attrs["program"] = "hsri2d"
    f["time"] = [0.0, 0.1]
cases = [("motion", "missing.h5", "missing.h5: no such file"),
         ("history", "text.h5", "not an HDF5 file"),
         ("animate", "other.h5", "not an hsri2d HDF5 file"),
         ("motion", "old.h5", "has no /joints/x"),
         ("history", "old.h5", "has no /acceleration")]
for picture_name, name, expected in cases:
    status, err = tool(picture_name, os.path.join(work, name))
    check(status == 1 and expected in err and "Traceback" not in err and len(err.strip().splitlines()) == 1,
          f"{picture_name} {name}: \"{expected}\", status 1, one line")
status, err = tool("motion", h5, "--times", "9")
check(status == 1 and "outside the run" in err, "a time outside the run")
status, err = tool("nonsense", h5)
check(status == 2 and "Traceback" not in err, "a bad command line: status 2")

left = [n for n in os.listdir(work) if ".part" in n]
check(not left, f"no temporary file left ({left})")
if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("tools/plot: every picture and every refusal as expected")
