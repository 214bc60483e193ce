#!/usr/bin/env python3
"""Feed hsri2d malformed and extreme decks, check them and run them, and check
that every process ends as the program promises (docs/usage.md): never with a
Fortran runtime error, a backtrace, a signal or a hang.

usage: fuzz_decks.py HSRI2D WORKDIR DECK [DECK ...]

Each deck (fixed hostile inputs made from the first DECK, then random
mutations of every DECK) is first checked with --check, which must end with
status 0 (valid) or 2 (deck error; 4 for the unreadable inputs). Every deck
the check accepts is then run - the whole simulation, listing and, for a
share of the runs, the HDF5 file - which must end with status 0 (success) or 3
(numerical failure, with its message). Status 2 after an accepted check would
mean the check and the run disagree, and 4 that the work directory could not
be written: both are failures, as are statuses 1 and any other, a signal, a
run without a message on standard error when it fails, or a forbidden text
(FORBIDDEN) on standard error or output.

Long runs. A valid deck may ask for up to 1e9 steps (TMAX/DT), which a
mutation of TMAX, DT or the tolerances can produce. Every second accepted
deck is therefore run with a second deck that replaces its *TIME group by a
short run (CAP_DECK; a later group replaces the earlier one): those runs
must end within RUN_TIMEOUT, otherwise it is a hang and a failure. The other
decks run with their own *TIME; one that is still running after RUN_TIMEOUT
is stopped and counted as a long run, not a failure (it asked for a long run,
which the program does by design), and is then run again with CAP_DECK,
which must end in time like any other capped run. So every accepted deck is
run to its end at least once, and the time stays bounded.
"""
import os
import random
import subprocess
import sys
import time

FORBIDDEN = ("Fortran runtime", "Backtrace", "Error termination", "ERROR STOP",
             "Segmentation", "Program received", "SIGSEGV", "SIGFPE", "SIGBUS",
             "SIGILL", "SIGABRT", "floating-point exception", "Floating-point exception")

# random mutations of each base deck: of its text, and of its values only
# (FUZZ_MUTATIONS and FUZZ_SEED in the environment change them for a longer
# search by hand; the test uses these)
TEXT_MUTATIONS_PER_DECK = int(os.environ.get("FUZZ_MUTATIONS", 150))
VALUE_MUTATIONS_PER_DECK = int(os.environ.get("FUZZ_MUTATIONS", 150))
DEFAULT_SEED = 20261122
SEED = int(os.environ.get("FUZZ_SEED", DEFAULT_SEED))
CHECK_TIMEOUT = 20.0   # s; a --check reads a deck and builds the model, nothing more
RUN_TIMEOUT = 3.0      # s; a capped run takes under 0.1 s (Debug build)

# Failures found by this test in code the deck reader's owners do not own,
# reported (issue 5, section 5) and left visible: each is printed as a known
# failure on every run instead of failing the test. Remove an entry once fixed.
# (None now: the free-fall deck's segment started at -1000 deg/s under NINT = 3,
# which ground through the joints' Coulomb friction, runs since the friction
# slides on its dead band's edges, issue 15, D-4b.)
# Each is known by what its mutated deck holds, not by its name: the names depend on
# every base deck's text, as the random stream runs through them in order.
KNOWN_FAILURES = [
]


def known_failure(work, failure):
    """The KNOWN_FAILURES entry a failure ("name: message") is, or None."""
    name = failure.split(":")[0]
    for prefix, line, reason in KNOWN_FAILURES:
        if name.startswith(prefix):
            try:
                with open(os.path.join(work, name + ".deck"), encoding="latin-1") as f:
                    if line in f.read():
                        return prefix, line, reason
            except OSError:
                pass
    return None


CAP_DECK = """$ fuzz_decks.py: a short run in place of the mutated deck's time controls
*TIME
        0.01    0.0001     0.005
"""

# Values written into a numeric field: limits of the card table, zero, signs,
# tiny and huge magnitudes, malformed numbers.
FIELD_VALUES = ("0.", "-0.", "1.", "-1.", "1.E-12", "1.E12", "-1.E12", "999999.", "1.E-9",
                "1000.", "-360.", "360.", "1.E300", "1.D-4", "2.5E+1", "+7", "0.0001",
                "5", "3", "4", "1.E-30", ".5", "-.5", "1.0E", "E5", "1..", "")


def cases(base_lines, rnd):
    """Yield (name, bytes): fixed hostile inputs made from one deck."""
    base = "\n".join(base_lines) + "\n"
    yield "empty", b""
    yield "newlines_only", b"\n\n\n"
    yield "binary", bytes(rnd.randrange(256) for _ in range(4096))
    yield "nul_bytes", b"*TIME\n\0\0\0\0\n"
    yield "one_huge_line", b"*TIME\n" + b"9" * 1_000_000 + b"\n"
    yield "many_groups", ("*TITLE\nx\n" * 5000).encode()
    yield "truncated_mid_card", base.encode()[: len(base) // 2 + 7]
    yield "no_final_newline", base.rstrip("\n").encode()
    yield "crlf", base.replace("\n", "\r\n").encode()
    yield "utf8_title", base.replace("DEFAULT", "DÉFAUT").encode("utf-8")
    yield "utf8_comments", base.replace("$ ", "$ ÉÀ—€𝄞 ").encode("utf-8")
    yield "utf8_same_width", base.replace("$ ", "$é").encode("utf-8")
    yield "utf8_80_characters", (base + "$" + "é" * 40 + "€" * 39 + "\n").encode("utf-8")
    yield "utf8_bom", b"\xef\xbb\xbf" + base.encode()
    yield "latin1_comment", base.replace("$ ", "$ é ").encode("latin-1")
    yield "nan_inf", base.replace("0.2 ", "NaN ").replace("386.", "Inf ").encode()
    yield "huge_numbers", base.replace("0.0001", "9.9E+99").encode()
    yield "tiny_step", base.replace("0.0001", "1.0E-30").encode()
    yield "header_only", b"*SEGMENTS\n*JOINTS\n*INITIAL\n"
    yield "stars", b"*\n**\n* \n"


def is_data_card(line):
    return line.strip() != "" and line[:1] not in ("*", "$")


def mutate(base_lines, rnd):
    """One random mutation of a deck: 1 to 6 edits of its cards."""
    lines = list(base_lines)
    data = [i for i, line in enumerate(lines) if is_data_card(line)]
    for _ in range(rnd.randint(1, 6)):
        i = rnd.randrange(len(lines))
        op = rnd.randrange(9)
        line = lines[i]
        if op == 0 and line:                      # one character changed
            j = rnd.randrange(len(line))
            line = line[:j] + chr(rnd.randrange(32, 127)) + line[j + 1:]
        elif op == 1:                             # card cut short
            line = line[: rnd.randrange(len(line) + 1)]
        elif op == 2:                             # card shifted right
            line = " " * rnd.randint(1, 15) + line
        elif op == 3:                             # junk appended
            line = line + " " * rnd.randint(0, 20) + "".join(
                rnd.choice("0123456789.-+E ") for _ in range(rnd.randint(1, 30)))
        elif op == 4:                             # card repeated
            lines.insert(i, line)
        elif op == 5:                             # card removed
            del lines[i]
            continue
        elif op == 6:                             # a non-ASCII character or byte
            j = rnd.randrange(len(line) + 1)
            ch = rnd.choice(["é", "—", "€", "𝄞", "\ufeff"]).encode("utf-8").decode("latin-1")
            if rnd.random() < 0.3:
                ch = chr(rnd.randrange(128, 256))
            line = line[:j] + ch + line[j:]
        else:                                     # a numeric field of a data card rewritten
            if not data:
                continue
            i = rnd.choice(data)
            if i >= len(lines):
                continue
            line = lines[i].ljust(72)
            k = rnd.randint(1, 7)
            value = rnd.choice(FIELD_VALUES)
            line = (line[: 10 * k - 8] + value.rjust(10)[:10] + line[10 * k + 2:]).rstrip()
        lines[i] = line
    return ("\n".join(lines) + "\n").encode("latin-1")


def mutate_values(base_lines, rnd):
    """One to three numbers of data cards set to an extreme but well-formed
    value in the same field (nine columns wide, so that it cannot touch the
    field before): the deck often stays valid, and its run is what is tried."""
    lines = list(base_lines)
    data = [i for i, line in enumerate(lines) if is_data_card(line)]
    for _ in range(rnd.randint(1, 3)):
        i = rnd.choice(data)
        line = lines[i].ljust(72)
        given = [k for k in range(1, 8) if line[10 * k - 8: 10 * k + 2].strip()]
        if not given:
            continue
        k = rnd.choice(given)
        try:
            value = float(line[10 * k - 8: 10 * k + 2].replace("D", "E"))
        except ValueError:
            continue                              # a word (LINEAR, LOWER, ...)
        choice = rnd.randrange(4)
        if choice == 0:
            value *= 10.0 ** rnd.randint(-6, 6)
        elif choice == 1:
            value = -value
        elif choice == 2:
            value = 0.0
        else:
            value = rnd.choice([1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9]) * rnd.choice([1, -1])
        text = f"{value:.2E}"
        lines[i] = (line[: 10 * k - 8] + text.rjust(10) + line[10 * k + 2:]).rstrip()
    return ("\n".join(lines) + "\n").encode("latin-1")


class Fuzz:
    def __init__(self, exe, work):
        self.exe = exe
        self.work = work
        self.failures = []
        self.check_status = {}
        self.run_status = {}
        self.long_runs = []
        self.n_check = 0
        self.n_run = 0
        self.n_h5 = 0
        self.slowest = (0.0, "")
        self.cap = os.path.join(work, "cap.deck")
        with open(self.cap, "w", encoding="ascii") as f:
            f.write(CAP_DECK)

    def process(self, name, args, timeout):
        """Run hsri2d; None on timeout, else (status, stderr text)."""
        start = time.monotonic()
        try:
            p = subprocess.run([self.exe] + args, capture_output=True, timeout=timeout, cwd=self.work)
        except subprocess.TimeoutExpired:
            return None
        elapsed = time.monotonic() - start
        if elapsed > self.slowest[0]:
            self.slowest = (elapsed, name)
        err = p.stderr.decode("latin-1")
        out = p.stdout.decode("latin-1")
        for bad in FORBIDDEN:
            if bad in err or bad in out:
                self.failures.append(f"{name}: '{bad}' reached the user: hsri2d {' '.join(args)}\n{err}")
                break
        if p.returncode < 0:
            self.failures.append(f"{name}: killed by signal {-p.returncode}: hsri2d {' '.join(args)}\n{err}")
        elif p.returncode != 0 and not err.strip():
            self.failures.append(f"{name}: exit status {p.returncode} without a message")
        return p.returncode, err

    def deck(self, name, data):
        path = os.path.join(self.work, name + ".deck")
        with open(path, "wb") as f:
            f.write(data)
        self.n_check += 1
        result = self.process(name, ["--check", path], CHECK_TIMEOUT)
        if result is None:
            self.failures.append(f"{name}: --check gave no answer within {CHECK_TIMEOUT} s")
            return
        status, err = result
        self.check_status[status] = self.check_status.get(status, 0) + 1
        if status not in (0, 2, 4):
            self.failures.append(f"{name}: --check ended with status {status}\n{err}")
        if status != 0:
            return
        # the whole run: capped for every second accepted deck
        capped = self.n_run % 2 == 1
        self.simulate(name, path, capped)

    def simulate(self, name, path, capped):
        self.n_run += 1
        args = [path] + ([self.cap] if capped else []) + ["-o", os.path.join(self.work, "run.lst")]
        if self.n_run % 3 == 0:
            self.n_h5 += 1
            args += ["--h5", os.path.join(self.work, "run.h5")]
        result = self.process(name, args, RUN_TIMEOUT)
        if result is None:
            if capped:
                self.failures.append(f"{name}: a run capped at 0.01 s did not end within {RUN_TIMEOUT} s")
            else:
                self.long_runs.append(name)
                self.simulate(name, path, True)
            return
        status, err = result
        key = f"{status}{' capped' if capped else ''}"
        self.run_status[key] = self.run_status.get(key, 0) + 1
        if status not in (0, 3):
            self.failures.append(f"{name}: the run of a deck that --check accepted ended with status "
                                 f"{status}: hsri2d {' '.join(args)}\n{err}")
        elif status == 3 and "numerical failure" not in err:
            self.failures.append(f"{name}: status 3 without 'numerical failure'\n{err}")


def main():
    exe, work, decks = sys.argv[1], sys.argv[2], sys.argv[3:]
    exe = os.path.abspath(exe)
    os.makedirs(work, exist_ok=True)
    start = time.monotonic()
    fuzz = Fuzz(exe, work)
    rnd = random.Random(SEED)
    bases = []
    for deck in decks:
        with open(deck, encoding="ascii") as f:
            bases.append((os.path.splitext(os.path.basename(deck))[0], f.read().splitlines()))
    for name, data in cases(bases[0][1], rnd):
        fuzz.deck(name, data)
    for base_name, base_lines in bases:
        for k in range(TEXT_MUTATIONS_PER_DECK):
            fuzz.deck(f"{base_name}_text_{k}", mutate(base_lines, rnd))
        for k in range(VALUE_MUTATIONS_PER_DECK):
            fuzz.deck(f"{base_name}_value_{k}", mutate_values(base_lines, rnd))
    elapsed = time.monotonic() - start
    print(f"fuzz: {fuzz.n_check} decks checked, --check statuses {dict(sorted(fuzz.check_status.items()))}")
    print(f"fuzz: {fuzz.n_run} runs ({fuzz.n_h5} with HDF5), statuses {dict(sorted(fuzz.run_status.items()))}, "
          f"{len(fuzz.long_runs)} long runs stopped at {RUN_TIMEOUT} s and run again capped"
          + (f" ({', '.join(fuzz.long_runs)})" if fuzz.long_runs else ""))
    print(f"fuzz: {elapsed:.1f} s; the slowest process that ended took {fuzz.slowest[0]:.2f} s ({fuzz.slowest[1]})")
    known = [(f, known_failure(work, f)) for f in fuzz.failures]
    known = [(f, k) for f, k in known if k is not None]
    fuzz.failures = [f for f in fuzz.failures if f not in [f for f, _ in known]]
    for f, (_, _, reason) in known:
        print(f"KNOWN FAILURE {f}\n    reported: {reason}")
    for entry in KNOWN_FAILURES if SEED == DEFAULT_SEED else ():   # found with the default seed
        if not any(k == entry for _, k in known):
            print(f"NOTE: known failure {entry[0]}* with {entry[1]!r} did not fail: remove it from KNOWN_FAILURES")
    if fuzz.check_status.get(2, 0) < 50:
        fuzz.failures.append("too few decks were rejected: the mutations are not biting")
    if fuzz.run_status.get("0", 0) + fuzz.run_status.get("0 capped", 0) < 50:
        fuzz.failures.append("too few decks ran: the simulation is hardly exercised")
    for f in fuzz.failures:
        print("FAIL", f)
    return 1 if fuzz.failures else 0


if __name__ == "__main__":
    sys.exit(main())
