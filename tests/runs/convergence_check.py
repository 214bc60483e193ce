#!/usr/bin/env python3
"""tools/convergence --quick, a smoke test (issue 15 section 3): on a belted
and an unbelted deck it runs, prints its tables (the reference and its own
convergence, the fixed-step errors and orders, Dormand-Prince's table, the
peaks under RK4 with each belt section, the targets, the summary) with
finite figures, leaves nothing behind in its temporary directory nor beside
the decks, exits 0 or, with --check, 1 exactly when a target fails; a step
list the deck cannot take and a missing hsri2d are the tool's own failures
(status 2); killed, it ends its runs and removes its directory. Whether the targets pass is not checked: that is the tool's
measurement, not a test.

Usage: convergence_check.py HSRI2D TOOL DECKS WORKDIR
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time

NAME = "convergence"


def fail(message):
    print(f"{NAME}: FAIL: {message}")
    sys.exit(1)


hsri2d, tool, decks, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
tmp = os.path.join(work, "tmp")
os.makedirs(tmp)
env = dict(os.environ, TMPDIR=tmp)
belted, unbelted = os.path.join(decks, "sled_belted.deck"), os.path.join(decks, "body_only.deck")


def snapshot(folder):
    return sorted((e.name, e.stat().st_size, e.stat().st_mtime_ns) for e in os.scandir(folder))


def tool_run(*args):
    return subprocess.run([sys.executable, tool, "--hsri2d", hsri2d, *args], capture_output=True, text=True, env=env)


before = snapshot(decks)
p = tool_run("--quick", "--check", "--jobs", "2", belted, unbelted)
out = p.stdout
if p.returncode not in (0, 1):
    fail(f"--quick --check: status {p.returncode}\n{p.stderr}\n{out}")
if snapshot(decks) != before:
    fail("the decks' directory changed")
if os.listdir(tmp):
    fail(f"left behind in its temporary directory: {os.listdir(tmp)}")
if re.search(r"\bnan\b|\binf\b", out, re.IGNORECASE):
    fail(f"a figure is not finite:\n{out}")

sections = out.split("\n=== ")
if len(sections) != 4 or not sections[1].startswith("decks/sled_belted.deck") \
        or not sections[2].startswith("decks/body_only.deck") or not sections[3].startswith("summary"):
    fail(f"expected a section per deck and the summary, got {[s.splitlines()[0] for s in sections]}\n{out}")
number = r"[0-9.]+e[-+][0-9]+"
for deck, section, n_targets, belts in ((belted, sections[1], 15, True), (unbelted, sections[2], 12, False)):
    label = os.path.basename(deck)
    if not re.search(rf"reference: RK4 at dt = 6\.25e-06 s .*\|r\(1\.25e-05\) - r\(6\.25e-06\)\| = {number} deg",
                     section) or not re.search(r"estimated error of the reference [0-9.]+e[-+][0-9]+ deg", section):
        fail(f"{label}: no reference with its own convergence\n{section}")
    for dt in ("0.0004", "0.0002", "0.0001"):
        if not re.search(rf"^\s+{dt}\s+{number}[~!EWC]*\s+{number}[~!EWC]*\s+{number}[~!EWC]*\s", section, re.MULTILINE):
            fail(f"{label}: no row of three errors at dt = {dt}\n{section}")
    if not re.search(r"^\s+order\s+(-|[-0-9.]+) \(\d pts\)", section, re.MULTILINE):
        fail(f"{label}: no observed orders\n{section}")
    for rtol in ("1e-04", "1e-05", "1e-06", "1e-07", "1e-12"):
        if not re.search(rf"^\s+{rtol}\s+{number}[~!EWC]*\s+\S+ t=[0-9.]+\s+\d+\s+\d+\s+\d+\s+[0-9.]+ %\s+{number}\s+\S",
                         section, re.MULTILINE):
            fail(f"{label}: no Dormand-Prince row at RTOL {rtol}\n{section}")
    if not re.search(r"slope of log\(error\) vs log\(RTOL\): \S+; p in error ~ evaluations\^-p: \S+", section):
        fail(f"{label}: no Dormand-Prince slopes\n{section}")
    header = re.search(r"^\s+dt \(s\)\s+HIC15\s+head \(g\)\s+chest \(g\)(.*)$", section, re.MULTILINE)
    if not header or (header.group(1).split() == ["lap", "(lb)", "torso2", "(lb)", "torso3", "(lb)"]) != belts:
        fail(f"{label}: the peaks' table has not HIC15, head, chest{' and the three belt sections' if belts else ''}"
             f"\n{section}")
    targets = re.findall(r"^  (\S.*?)\s{2,}(\S.*?)\s+(PASS|FAIL)$", section.split("\ntargets")[-1], re.MULTILINE)
    if len(targets) != n_targets:
        fail(f"{label}: {len(targets)} targets, expected {n_targets}\n{section}")
# body_only's Dormand-Prince steps at RTOL 1e-4 and 1e-5 are fewer than 1.5 a print interval (bound by the
# print times): both marked C and left out of the slope
for rtol in ("1e-04", "1e-05"):
    if not re.search(rf"^\s+{rtol}\s+{number}C\s", sections[2], re.MULTILINE):
        fail(f"body_only.deck: the row at RTOL {rtol} is not marked C\n{sections[2]}")
if not re.search(r"^\s+1e-06\s+[0-9.]+e[-+][0-9]+\s", sections[2], re.MULTILINE) or "(C: fewer than 1.5 steps a print interval" not in sections[2]:
    fail(f"body_only.deck: RTOL 1e-6 marked C, or no note of C\n{sections[2]}")
summary = sections[3]
for label in ("decks/sled_belted.deck", "decks/body_only.deck"):
    row = re.search(rf"^  {re.escape(label)}(( +\S+)+)$", summary, re.MULTILINE)
    if not row or len(row.group(1).split()) != 12:
        fail(f"no summary row of 12 figures for {label}\n{summary}")
failed = out.count("   FAIL\n")
if (p.returncode == 1) != (failed > 0):
    fail(f"--check: status {p.returncode} with {failed} targets failed")

# without --check: status 0 whatever the targets (a smaller measurement)
p = tool_run("--dt", "4e-4,2e-4", "--ref-dt", "2.5e-5", "--rtol", "1e-4,1e-5", unbelted)
if p.returncode != 0 or "\ntargets" not in p.stdout:
    fail(f"without --check: status {p.returncode}, expected 0 and the targets\n{p.stderr}\n{p.stdout}")

# the tool's own failures: status 2, with a message
p = tool_run("--dt", "3e-4,1.5e-4", unbelted)
if p.returncode != 2 or "is not a whole multiple of dt = 0.0003 s" not in p.stderr:
    fail(f"a step TMAX is no multiple of: status {p.returncode}, expected 2 and a message\n{p.stderr}")
p = subprocess.run([sys.executable, tool, "--hsri2d", os.path.join(work, "missing"), unbelted],
                   capture_output=True, text=True, env=env)
if p.returncode != 2 or "no hsri2d program at" not in p.stderr:
    fail(f"a missing hsri2d: status {p.returncode}, expected 2 and a message\n{p.stderr}")
if os.listdir(tmp):
    fail(f"left behind in its temporary directory: {os.listdir(tmp)}")

# killed (SIGTERM) while its runs are under way: it ends them, removes its
# directory and says so, status 128 + 15
p = subprocess.Popen([sys.executable, tool, "--hsri2d", hsri2d, "--quick", belted], env=env,
                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
deadline = time.monotonic() + 60
while not any(name.endswith(".deck") for _, _, names in os.walk(tmp) for name in names):
    if p.poll() is not None or time.monotonic() > deadline:
        fail(f"no run started (status {p.poll()})")
    time.sleep(0.05)
p.send_signal(signal.SIGTERM)
_, err = p.communicate(timeout=60)
if p.returncode != 128 + signal.SIGTERM or "stopped by SIGTERM" not in err:
    fail(f"killed: status {p.returncode}, expected {128 + signal.SIGTERM} and a message\n{err}")
# the processes' command lines from /proc (no ps: procps is not in a minimal Debian)
left = []
for pid in filter(str.isdigit, os.listdir("/proc")):
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            args = f.read().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        continue
    if tmp in args:
        left.append(args)
if left:
    fail(f"killed: runs left behind\n{left}")
if os.listdir(tmp):
    fail(f"killed: left behind in its temporary directory: {os.listdir(tmp)}")
print(f"{NAME}: ok")
