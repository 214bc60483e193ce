#!/usr/bin/env python3
"""The deck's messages and echo as a user sees them (issue 14, items 16,
22, 23, 24).

usage: deck_messages.py CASE HSRI2D WORKDIR

  echo_card_numbers  a deck of more than 100,000 lines: the echo's card
                     numbers widen, never asterisks (docs/usage.md)
  escaped_names      a deck whose name holds a newline and a tab: the
                     listing's DECK and echo lines and the messages show
                     it escaped, each on one line
  pulse_from_fd      a deck read from /dev/fd/N (as bash's <(...) gives it)
                     names a relative *PULSEFILE: it is found in the
                     current directory, not under /dev/fd/
  bad_card_once      a card with a tab: one problem, with its group and
                     card number, and nothing after it
"""
import os
import shutil
import subprocess
import sys

FORBIDDEN = ("Fortran runtime", "Backtrace", "Error termination", "Segmentation", "Program received")


def run(exe, args, cwd, pass_fds=()):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, pass_fds=pass_fds, timeout=300)
    err = p.stderr.decode("utf-8", "replace")
    for bad in FORBIDDEN:
        if bad in err:
            fail(f"{bad!r} reached the user:\n{err}")
    return p.returncode, p.stdout.decode("utf-8", "replace"), err


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def expect(condition, message):
    if not condition:
        fail(message)


def problems(err):
    """The problem lines of a deck error (not the program's own lines)."""
    return [line for line in err.splitlines() if line and not line.startswith("hsri2d:")]


def echo_card_numbers(exe, work):
    deck = os.path.join(work, "long.deck")
    with open(deck, "w") as f:
        f.write("*TIME\n        0.01\n")
        f.write("$ a comment\n" * 100_005)
    status, _, err = run(exe, ["@default", "long.deck", "-o", "long.lst"], work)
    expect(status == 0, f"status {status}: {err}")
    with open(os.path.join(work, "long.lst"), encoding="utf-8") as f:
        listing = f.read().splitlines()
    echo = [line for line in listing if "long.deck:" in line]
    expect(len(echo) > 100_000, f"{len(echo)} echo lines of long.deck")
    expect(not any("*****" in line for line in listing), "a number printed as asterisks")
    numbered = [line for line in echo if line.split()[0] == "100003"]
    expect(len(numbered) == 1, "no echo line numbered 100003")
    expect(all(len(line) <= 132 for line in listing), "a listing line over 132 columns")


def escaped_names(exe, work):
    name = "a\nb\tc.deck"
    with open(os.path.join(work, name), "w") as f:
        f.write("*TIME\n        0.01\n")
    status, _, err = run(exe, ["@default", name, "-o", "names.lst"], work)
    expect(status == 0, f"status {status}: {err}")
    with open(os.path.join(work, "names.lst"), encoding="utf-8") as f:
        listing = f.read().splitlines()
    expect(" DECK    a\\nb\\tc.deck" in listing, "no escaped DECK line")
    echo = [line for line in listing if "a\\nb\\tc.deck:" in line]
    expect(len(echo) == 2, f"{len(echo)} escaped echo lines, expected 2")
    expect(not any(line.startswith("b") for line in listing), "a line split at the name's newline")
    with open(os.path.join(work, name), "w") as f:
        f.write("*TIME\n       abc\n")
    status, _, err = run(exe, ["--check", "@default", name], work)
    expect(status == 2, f"status {status}: {err}")
    lines = problems(err)
    expect(len(lines) == 1 and lines[0].startswith("a\\nb\\tc.deck:2: *TIME card 1, field TMAX (columns 3-12)"),
           f"the problem is not one escaped line:\n{err}")


def pulse_from_fd(exe, work):
    with open(os.path.join(work, "pulse.csv"), "w") as f:
        f.write("t, xddot\n0, 0\n0.01, -5\n0.02, 0\n")
    read_end, write_end = os.pipe()
    os.write(write_end, b"*PULSEFILE\npulse.csv\n*TIME\n        0.01\n")
    os.close(write_end)
    try:
        status, _, err = run(exe, ["@default", f"/dev/fd/{read_end}", "-o", "fd.lst"], work, pass_fds=(read_end,))
    finally:
        os.close(read_end)
    expect(status == 0, f"status {status}: {err}")
    with open(os.path.join(work, "fd.lst"), encoding="utf-8") as f:
        listing = f.read().splitlines()
    expect(" PULSE   pulse.csv" in listing, "the listing does not use ./pulse.csv")


def bad_card_once(exe, work):
    with open(os.path.join(work, "tab.deck"), "w") as f:
        f.write("*TIME\n        0.1\t0.0001\n")
    status, _, err = run(exe, ["--check", "@default", "tab.deck"], work)
    expect(status == 2, f"status {status}: {err}")
    lines = problems(err)
    expect(lines == ["tab.deck:2: *TIME card 1: tab character in column 12; cards have fixed columns, use spaces"],
           f"not the one problem expected:\n{err}")


CASES = {f.__name__: f for f in (echo_card_numbers, escaped_names, pulse_from_fd, bad_card_once)}


def main():
    case, exe, work = sys.argv[1], os.path.realpath(sys.argv[2]), os.path.join(sys.argv[3], sys.argv[1])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    CASES[case](exe, work)
    print(case + ": ok")


if __name__ == "__main__":
    main()
