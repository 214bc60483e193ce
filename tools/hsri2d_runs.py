"""What tools/convergence and tools/work-precision share to run hsri2d: the
deck's fields as docs/deck-format.md gives their columns, override decks'
numbers, the runs under way (ended with the tool), the listing's integration
figures, print-time grids and option parsing. Imported, never run."""
import argparse
import os
import re
import subprocess
import threading


class ToolError(Exception):
    """A failure of the tool itself (not a measured result): exit status 2."""


class Field:
    """A field's columns (1-based, inclusive), as docs/deck-format.md gives them."""

    def __init__(self, first, last):
        self.first, self.last = first, last

    def get(self, card):
        return card[self.first - 1:self.last].strip()

    def put(self, card, text):
        width = self.last - self.first + 1
        if len(text) > width:
            raise ToolError(f"'{text}' does not fit in columns {self.first}-{self.last}")
        card = card.ljust(80)
        return card[:self.first - 1] + text.rjust(width) + card[self.last:]


NOUT, NINT = Field(43, 52), Field(53, 62)                                             # *OPTIONS
TMAX, DT, DTPRINT, CTOL = Field(3, 12), Field(13, 22), Field(23, 32), Field(33, 42)  # *TIME
RTOL, ATOL = Field(53, 62), Field(63, 72)                                             # *TIME
ASTART, EBFAIL = Field(3, 12), Field(33, 42)                                          # *NUMERICS
# what a blank *TIME field means (docs/deck-format.md)
TIME_BLANK = {"TMAX": 0.2, "DT": 1e-4, "DTPRINT": 0.005, "CTOL": 1e-6, "RTOL": 1e-7, "ATOL": 1e-9}


def number_text(x):
    """x as a number of at most 10 characters that reads back exactly."""
    for text in [repr(float(x))] + [f"{x:.{d}E}" for d in range(0, 9)]:
        text = text.upper().replace("E-0", "E-").replace("E+0", "E+")
        if len(text) <= 10 and float(text) == float(x):
            return text
    raise ToolError(f"{x!r} cannot be written exactly in a 10-column field")


def group_card(lines, name):
    """The first data card of the last *NAME group of a deck, or None."""
    card, found = None, False
    for line in lines:
        if line.startswith("*"):
            header = line.split()[0].upper() if line.split() else ""
            found = header == "*" + name
            if found:
                card = ""            # the group is there; its card may be missing
            continue
        if found and card == "" and line.strip() and not line.startswith("$"):
            card = line.rstrip("\r\n")
    return card or None


def tidy(x):
    """x without the rounding of the arithmetic that made it (12 digits)."""
    return float(f"{x:.12g}")


def multiple(a, b):
    """Whether a is a whole multiple of b (to rounding)."""
    n = round(a / b)
    return n >= 1 and abs(a - n * b) <= 1e-9 * a


class Children:
    """The runs of hsri2d under way, so that the tool's end (a signal, a
    failure) ends them too: killing the tool leaves no run behind."""

    def __init__(self):
        self.lock, self.procs, self.stopping = threading.Lock(), set(), False

    def run(self, args):
        """(status, standard error, CPU seconds user + system) of one run."""
        with self.lock:
            if self.stopping:
                raise ToolError("stopped")
            p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            self.procs.add(p)
        try:
            err = p.stderr.read()
            _, status, usage = os.wait4(p.pid, 0)
            p.returncode = os.waitstatus_to_exitcode(status)
            p.stderr.close()
        finally:
            with self.lock:
                self.procs.discard(p)
        return p.returncode, err.decode(errors="replace"), usage.ru_utime + usage.ru_stime

    def stop(self):
        with self.lock:
            self.stopping = True
            for p in self.procs:
                if p.returncode is None:
                    p.terminate()


CHILDREN = Children()


class Stopped(Exception):
    """A signal (SIGINT, SIGTERM, SIGHUP) stopped the tool."""


def on_signal(signum, frame):
    CHILDREN.stop()
    raise Stopped(signum)


def integration_figures(listing):
    """The summary's end and the INTEGRATION section's counts."""
    out = {}
    patterns = {"t_end": r"ended at t =\s*(\S+) s", "accepted": r"accepted steps\s+(\d+)",
                "rejected": r"rejected steps\s+(\d+)", "evaluations": r"right-hand-side evaluations\s+(\d+)",
                "restarts": r"restarts after a jump\s+(\d+)", "h_min": r"step size from\s+(\S+)",
                "located": r"switches located\s+(\d+)"}
    for key, pattern in patterns.items():
        m = re.search(pattern, listing)
        out[key] = float(m.group(1)) if m else None
    m = re.search(r"ended at t =\s*\S+ s: (.*)", listing)
    out["end_reason"] = m.group(1).strip() if m else None
    out["energy_failed"] = "THE ENERGY BALANCE FAILED" in listing
    return out


def on_grid(times, grid):
    """{k: row} for the rows whose time is k * grid (to rounding)."""
    rows = {}
    for i, t in enumerate(times):
        k = int(round(t / grid))
        if abs(t - k * grid) <= 1e-9 * max(grid, abs(t)):
            rows[k] = i
    return rows


def number_list(text):
    """An option's comma-separated positive numbers."""
    try:
        values = [float(x) for x in text.split(",") if x.strip()]
    except ValueError as e:
        raise argparse.ArgumentTypeError(f"not a list of numbers: {text}") from e
    if not values or any(not v > 0 for v in values):
        raise argparse.ArgumentTypeError(f"expected positive numbers: {text}")
    return values
