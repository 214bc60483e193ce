"""hsri2d --refine, the convergence check for a user's own deck (issue 16,
section 2; docs/usage.md, "Is my step small enough?").

Usage: refine_checks.py HSRI2D DECK_DIRECTORY TEST_DECK_DIRECTORY WORK_DIRECTORY

- The body-only deck (RK4 at DT = 1e-4 s): every row "ok" and the verdict
  "converged"; status 0; nothing written into the working directory.
- The default deck with a 100 g pulse (tests/runs/pulse_100g.deck) at the
  same DT: rows marked "TOO COARSE" (the seat's hip force and the hip's
  angles move by more than 1 % and 0.1 deg at DT/2) and the verdict "NOT
  CONVERGED"; status 0 (a verdict, not an error).
- Dormand-Prince (the body-only deck with NINT = 3): the refined setting is
  RTOL/100.
- -o FILE writes the table to FILE; --refine with --h5, or with --check, is a
  usage error (status 1).
"""
import os
import subprocess
import sys

exe, decks, test_decks, work = sys.argv[1:5]
decks = os.path.abspath(decks)
test_decks = os.path.abspath(test_decks)
os.makedirs(work, exist_ok=True)
os.chdir(work)
for name in os.listdir("."):
    os.remove(name)
failures = []


def fail(message):
    failures.append(message)
    print("refine_checks: FAIL: " + message)


def run(*args):
    return subprocess.run([exe, *args], capture_output=True, text=True, timeout=600)


p = run("--refine", os.path.join(decks, "body_only.deck"))
if p.returncode != 0:
    fail(f"body_only: status {p.returncode}: {p.stderr[:300]}")
rows = [line for line in p.stdout.splitlines() if line.rstrip().endswith(("ok", "TOO COARSE"))]
if len(rows) < 10 or any(r.rstrip().endswith("TOO COARSE") for r in rows):
    fail(f"body_only: expected only ok rows: {p.stdout[:2000]}")
if "verdict: converged" not in p.stdout or "DT 5.0E-05 s" not in p.stdout:
    fail(f"body_only: no converged verdict against DT/2: {p.stdout[-600:]}")
if os.listdir("."):
    fail(f"--refine wrote files: {os.listdir('.')}")

p = run("--refine", os.path.join(decks, "default.deck"), os.path.join(test_decks, "pulse_100g.deck"))
if p.returncode != 0:
    fail(f"100 g: status {p.returncode}: {p.stderr[:300]}")
coarse = [line for line in p.stdout.splitlines() if line.rstrip().endswith("TOO COARSE")]
if not any("hip, " in line for line in coarse) or "verdict: NOT CONVERGED" not in p.stdout:
    fail(f"100 g: the coarse hip angles and the verdict are missing: {p.stdout[-2500:]}")
if "head HIC15" not in p.stdout or "CPU time:" not in p.stdout:
    fail(f"100 g: no HIC15 row or CPU times: {p.stdout[:800]}")

with open("dopri.deck", "w") as f:
    f.write("*OPTIONS\n           1         0         1         1         2         3\n")
p = run("--refine", os.path.join(decks, "body_only.deck"), "dopri.deck")
if p.returncode != 0 or "RTOL 1.0E-09" not in p.stdout or "verdict: converged" not in p.stdout:
    fail(f"Dormand-Prince: RTOL/100 expected, converged: {p.returncode} {p.stdout[:400]} {p.stderr[:300]}")
os.remove("dopri.deck")

p = run("--refine", "-o", "table.txt", os.path.join(decks, "body_only.deck"))
if p.returncode != 0 or p.stdout or not os.path.exists("table.txt") or \
        "verdict: converged" not in open("table.txt").read():
    fail(f"-o: the table not in the file: {p.returncode} {p.stdout[:200]} {p.stderr[:200]}")
for extra in (["--h5", "x.h5"], ["--check"]):
    p = run("--refine", *extra, os.path.join(decks, "body_only.deck"))
    if p.returncode != 1 or "usage error" not in p.stderr:
        fail(f"--refine {' '.join(extra)}: expected a usage error, got {p.returncode}: {p.stderr[:300]}")
if os.path.exists("x.h5"):
    fail("--refine --h5 wrote the HDF5 file")

if failures:
    sys.exit(1)
print("refine_checks: all checks passed")
