"""Whole runs as a user makes them (issue 5, section 5).

Usage: run_checks.py HSRI2D DECK_DIRECTORY WORK_DIRECTORY

- A head spun at 1e6 deg/s with RK4 at the default step (the body-only deck,
  decks/body_only.deck): the energy balance is off by about half the peak
  kinetic energy. The run ends with status 3,
  says why on standard error and in the listing; with *NUMERICS EBFAIL =
  CONTINUE it runs to its end (status 0) and is flagged in both.
- No number in any listing is printed as asterisks, and no line of any
  listing (every shipped deck, with NOUT = 3 too) is wider than 132 columns.
- NBODY = 2 warns, on standard error and in the listing, that the occupant
  position changes nothing without *SURFACES (the body-only deck).
"""
import os
import re
import subprocess
import sys

exe, decks, work = sys.argv[1], sys.argv[2], sys.argv[3]
body_only = os.path.join(os.path.abspath(decks), "body_only.deck")
os.makedirs(work, exist_ok=True)
os.chdir(work)
failures = []


def fail(message):
    failures.append(message)
    print("runs_as_a_user: FAIL: " + message)


def run(*args):
    p = subprocess.run([exe, *args], capture_output=True, text=True, timeout=600)
    for bad in ("Fortran runtime", "Backtrace", "Error termination", "SIG"):
        if bad in p.stderr:
            fail(f"{' '.join(args)}: a runtime error reached the user: {p.stderr[:300]}")
    return p


def write(name, text):
    with open(name, "w") as f:
        f.write(text)


def card(*fields, index=""):
    """A data card: the index in columns 1-2, fields of ten columns from 3."""
    return f"{index:>2}" + "".join(f"{x:>10}" for x in fields) + "\n"


def listing_problems(path):
    """Lines wider than 132 columns; numbers printed as asterisks."""
    problems = []
    in_echo = False
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n").lstrip("\f")
            if len(line) > 132:
                problems.append(f"{path}:{number}: {len(line)} columns")
            if line.startswith("INPUT DECK"):
                in_echo = True
            elif line.startswith(("PARAMETERS", "RUN")):
                in_echo = False
            # the deck echo shows the cards as written (group headers start with *)
            if not in_echo and "**" in line:
                problems.append(f"{path}:{number}: asterisks: {line.strip()[:80]}")
    return problems


# 1. results that mean nothing
write("spin.deck", "*INITIAL\n" + "".join(card(t, r, index=i + 1) for i, (t, r) in enumerate(
    [(125, 0), (110, 0), (105, 0), (85, "1.0E+06"), (-44, 0), (22, 0), (15, 0), (-60, 0)])))
p = run(body_only, "spin.deck", "-o", "spin.lst")
if p.returncode != 3:
    fail(f"the spun head: status {p.returncode}, expected 3")
if "EBTOL" not in p.stderr or "energy balance" not in p.stderr:
    fail(f"the spun head: standard error does not say why: {p.stderr[:300]}")
if os.path.exists("spin.lst"):
    text = open("spin.lst").read()
    if "THE ENERGY BALANCE FAILED" not in text:
        fail("the spun head: the listing is not flagged")
    for problem in listing_problems("spin.lst"):
        fail("the spun head: " + problem)
else:
    fail("the spun head: no listing delivered with status 3")

write("continue.deck", "*NUMERICS\n" + card("", "", "", "CONTINUE"))
p = run(body_only, "spin.deck", "continue.deck", "-o", "spin_on.lst")
if p.returncode != 0:
    fail(f"the spun head with EBFAIL = CONTINUE: status {p.returncode}, expected 0: {p.stderr[:300]}")
text = open("spin_on.lst").read() if os.path.exists("spin_on.lst") else ""
if "THE ENERGY BALANCE FAILED" not in text:
    fail("the spun head with EBFAIL = CONTINUE: the listing is not flagged")
if "ended at t =   0.20000 s: time" not in text:
    fail("the spun head with EBFAIL = CONTINUE: the run did not reach TMAX")
if "hsri2d: warning: the energy balance failed" not in p.stderr:
    fail(f"the spun head with EBFAIL = CONTINUE: no warning on standard error: {p.stderr[:300]}")
for problem in listing_problems("spin_on.lst"):
    fail("the spun head with EBFAIL = CONTINUE: " + problem)

# 2. every shipped deck, and with NOUT = 3 (its own *OPTIONS card, NOUT set to 3): 132 columns,
# no asterisks
def nout3_options(path):
    lines = open(path).read().splitlines()
    header = next(i for i, l in enumerate(lines) if l.upper().startswith("*OPTIONS"))
    data = next(l for l in lines[header + 1:] if l.strip() and not l.startswith("$"))
    data = data.ljust(72)
    return "*OPTIONS\n" + data[:42] + "%10d" % 3 + data[52:].rstrip() + "\n"
for deck in sorted(os.listdir(decks)):
    if not deck.endswith(".deck"):
        continue
    write("nout3.deck", nout3_options(os.path.join(decks, deck)))
    for extra in ([], ["nout3.deck"]):
        out = deck + ("_nout3" if extra else "") + ".lst"
        p = run(os.path.join(decks, deck), *extra, "-o", out)
        if p.returncode != 0:
            fail(f"{deck} {' '.join(extra)}: status {p.returncode}: {p.stderr[:300]}")
            continue
        for problem in listing_problems(out):
            fail(problem)

# 3. an option that changes nothing here says so
write("passenger.deck", "*OPTIONS\n" + card(2, 0, 1, 1, 2, 2))
p = run(body_only, "passenger.deck", "-o", "passenger.lst")
if p.returncode != 0:
    fail(f"NBODY = 2: status {p.returncode}")
if not re.search(r"hsri2d: warning: .*NBODY = 2.*changes nothing", p.stderr):
    fail(f"NBODY = 2: no warning on standard error: {p.stderr[:300]}")
if "WARNING" not in open("passenger.lst").read():
    fail("NBODY = 2: no warning in the listing")

if failures:
    sys.exit(1)
print("runs_as_a_user: PASS")
