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
- Adversarial listings keep to 132 columns, wrapping what is longer on
  indented lines without losing a character (issue 14, 21): a deck and a
  pulse file at paths of some 300 characters with many warnings naming them,
  the belts' COUPLING = ALL; and every archived listing (tests/listings).
- Extreme but legal values print no asterisks (issue 14, 22): a pulse table
  of 100,000 rows, the table's limit (its index widens); joints, vehicle and
  pulse at the ends of their ranges.
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
    extras = [[]]
    # (an analog deck of Section D has no *OPTIONS: its one listing is checked)
    if "*OPTIONS" in open(os.path.join(decks, deck)).read().upper():
        write("nout3.deck", nout3_options(os.path.join(decks, deck)))
        extras.append(["nout3.deck"])
    for extra in extras:
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

# 4. long lines wrapped, never cut (issue 14, 21)
def wrapped_text(path, start):
    """The line starting with `start` and its continuation lines (indented
    9 columns), joined without their indentation."""
    lines = open(path).read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith(start):
            text = line
            for more in lines[i + 1:]:
                if not more.startswith(" " * 9) or more[9:10] == " ":
                    break
                text += more[9:]
            return text
    return None


deep = os.path.join(os.path.abspath(work), "long_" + "d" * 90, "e" * 90, "f" * 60)
os.makedirs(deep, exist_ok=True)
long_deck = os.path.join(deep, "a_deck_with_a_long_name_" + "g" * 20 + ".deck")
# the default deck in it for a passenger without belts (its belts and the driver's
# surfaces unused: warnings naming
# the file), its pulse from a CSV file in the long directory, a short run
write(os.path.join(deep, "pulse_with_a_long_name.csv"), "t, xddot\n0, -20\n0.1, -20\n0.11, 0\n")
default_text = open(os.path.join(decks, "default.deck")).read()
lines = default_text.splitlines()
header = next(i for i, l in enumerate(lines) if l.upper().startswith("*OPTIONS"))
data = next(i for i in range(header + 1, len(lines)) if lines[i].strip() and not lines[i].startswith("$"))
lines[data] = card(2, 0, 1, 2, 3, 2).rstrip("\n")
write(long_deck, "\n".join(lines) + "\n")
write(os.path.join(deep, "more.deck"), "*PULSEFILE\npulse_with_a_long_name.csv\n*TIME\n" + card("0.02"))
p = run(long_deck, os.path.join(deep, "more.deck"), "-o", "long.lst")
if p.returncode != 0:
    fail(f"the long path: status {p.returncode}: {p.stderr[:300]}")
else:
    for problem in listing_problems("long.lst"):
        fail("the long path: " + problem)
    text = open("long.lst").read()
    if text.count(" WARNING ") < 2:
        fail("the long path: expected warnings naming the deck in the listing")
    if max(len(l) for l in text.splitlines()) < 120:
        fail("the long path: no line came near the width: the test tests nothing")
    joined = wrapped_text("long.lst", " DECK    " + long_deck[:20])
    if joined != " DECK    " + long_deck:
        fail(f"the long path: the DECK line is not the path wrapped: {joined!r}")
    joined = wrapped_text("long.lst", " PULSE   ")
    if joined is None or "pulse_with_a_long_name.csv" not in joined.replace(" ", ""):
        fail(f"the long path: the PULSE line lost the file's name: {joined!r}")
write("coupling.deck", "*BELTOPTIONS\n" + card("ALL") + "*TIME\n" + card("0.02"))
p = run("@default", "coupling.deck", "-o", "coupled.lst")
if p.returncode != 0:
    fail(f"COUPLING = ALL: status {p.returncode}: {p.stderr[:300]}")
else:
    for problem in listing_problems("coupled.lst"):
        fail("COUPLING = ALL: " + problem)

listings = os.path.join(os.path.dirname(os.path.abspath(decks)), "tests", "listings")
for name in sorted(os.listdir(listings)):
    if name.endswith(".lst"):
        for problem in listing_problems(os.path.join(listings, name)):
            fail("archived: " + problem)

# 5. extreme but legal values (issue 14, 22): 100,000 pulse rows
rows = "".join(card(f"{k * 1e-6:.6f}", -20) for k in range(100000))
write("pulse100k.deck", "*PULSE\n" + rows + "*TIME\n" + card("0.01", "", "0.01"))
p = run(body_only, "pulse100k.deck", "-o", "pulse100k.lst")
if p.returncode != 0:
    fail(f"100,000 pulse rows: status {p.returncode}: {p.stderr[:300]}")
else:
    for problem in listing_problems("pulse100k.lst"):
        fail("100,000 pulse rows: " + problem)
    if not re.search(r"^100000 +0\.1", open("pulse100k.lst").read(), re.M):
        fail("100,000 pulse rows: the last row's index is not printed as 100000")

# ... and parameters at the ends of their ranges (the listing's tables before
# the run; the run itself may well fail, status 3, its listing delivered)
body_lines = open(body_only).read().splitlines()
first = next(i for i, l in enumerate(body_lines) if l.upper().startswith("*JOINTS"))
joint_cards = [l.ljust(72) for l in body_lines[first + 1:] if l.strip() and not l.startswith("$")][:7]
# the stiffnesses, friction and its velocity limit at their largest, the stop angles as they were
joints = "".join(c[:2] + "%10s" % "1.0E+12" * 3 + c[32:52] + "%10s" % "1.0E+12" * 2 + "\n" for c in joint_cards)
write("extreme.deck", "*JOINTS\n" + joints + "*VEHICLE\n" + card("1.0E+12", "1.0E+12", -100000, 100000, -90, -100000)
      + "*PULSE\n" + card(0, -10000, 10000, "-1.0E+08") + card(1000, 10000, -10000, "1.0E+08")
      + "*TIME\n" + card("0.001", "", "0.001"))
p = run(body_only, "extreme.deck", "-o", "extreme.lst")
if p.returncode not in (0, 3):
    fail(f"extreme values: status {p.returncode}: {p.stderr[:300]}")
else:
    for problem in listing_problems("extreme.lst"):
        fail("extreme values: " + problem)

if failures:
    sys.exit(1)
print("runs_as_a_user: PASS")
