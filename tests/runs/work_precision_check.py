#!/usr/bin/env python3
"""tools/work-precision --quick, a smoke test (issue 16 sections 1 and 3): on
the belted sled it runs, writes work-precision.md with the deck's table (every
setting measured, the belt column, the reference's own difference, the
cheapest accurate setting, the recommended default, the time to accuracy) and
its plot (a PNG the doc names; without matplotlib, --no-plots and no PNG),
prints the time-to-accuracy ratio against the body alone with the target's
verdict, and leaves nothing in its temporary directory nor beside the decks.
A missing hsri2d and a deck hsri2d refuses are the tool's own failures (status
2) and leave the earlier doc as it was. Whether the figures are good is not
checked: that is the tool's measurement, not a test.

Usage: work_precision_check.py HSRI2D TOOL DECKS WORKDIR
"""
import os
import re
import shutil
import subprocess
import sys

NAME = "work_precision"


def fail(message):
    print(f"{NAME}: FAIL: {message}")
    sys.exit(1)


hsri2d, tool, decks, work = sys.argv[1:5]

# the choice of the cheapest: CPU times within CPU_TIE of the least are a tie,
# broken by the fewest evaluations (the tool as a module: no run)
import importlib.machinery
import importlib.util
import types
loader = importlib.machinery.SourceFileLoader("work_precision_tool", tool)
wp = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
loader.exec_module(wp)
fake = lambda cpu, evals: types.SimpleNamespace(cpu_median=cpu, fig={"evaluations": evals})
a, b, c = fake(0.0840, 4996), fake(0.0836, 5535), fake(0.0700, 9000)
if wp.least_cost([a, b]) is not a:
    fail("CPU times 0.5 % apart: the fewer evaluations should win")
if wp.least_cost([a, b, c]) is not c:
    fail("a CPU time 17 % below the others should win whatever its evaluations")
if wp.least_cost([]) is not None:
    fail("no candidate: None")
# 20 % apart but within the rounds' spreads: a tie
d = types.SimpleNamespace(cpu_median=0.0825, fig={"evaluations": 4996}, cpu=[0.060, 0.065, 0.08, 0.0825, 0.09, 0.10, 0.11])
e = types.SimpleNamespace(cpu_median=0.0679, fig={"evaluations": 5535}, cpu=[0.060, 0.062, 0.065, 0.0679, 0.08, 0.09, 0.095])
if wp.least_cost([d, e]) is not d:
    fail("medians apart by less than the rounds' spreads: the fewer evaluations should win")
shutil.rmtree(work, ignore_errors=True)
tmp, out = os.path.join(work, "tmp"), os.path.join(work, "out")
os.makedirs(tmp)
env = dict(os.environ, TMPDIR=tmp)
deck = os.path.join(decks, "sled_belted.deck")
try:
    import matplotlib  # noqa: F401
    plots = []
except ImportError:
    plots = ["--no-plots"]


def snapshot(folder):
    return sorted((e.name, e.stat().st_size, e.stat().st_mtime_ns) for e in os.scandir(folder))


def tool_run(*args, program=hsri2d):
    return subprocess.run([sys.executable, tool, "--hsri2d", program, "--out", out, *plots, *args],
                          capture_output=True, text=True, env=env)


before = snapshot(decks)
p = tool_run("--quick", deck)
if p.returncode != 0:
    fail(f"--quick: status {p.returncode}\n{p.stderr}\n{p.stdout}")
if snapshot(decks) != before:
    fail("the decks' directory changed")
if os.listdir(tmp):
    fail(f"left behind in its temporary directory: {os.listdir(tmp)}")
if re.search(r"\bnan\b|\binf\b", p.stdout, re.IGNORECASE):
    fail(f"a figure is not finite:\n{p.stdout}")

# standard output: the deck's settings and the time to accuracy against the body alone
settings = ["Adams-Moulton DT 0.00025 s, CTOL 1e-06", "RK4 DT 0.00025 s", "Adams-Moulton DT 0.0001 s, CTOL 1e-06",
            "RK4 DT 0.0001 s", "Dormand-Prince RTOL 1e-04", "Dormand-Prince RTOL 1e-06",
            "Dormand-Prince RTOL 1e-05 (deck)"]
for s in settings:
    if not re.search(rf"^  {re.escape(s)} +[0-9.]+ +\d+ +\d+ +\d+ +\d+ +\d+ +[0-9.]+ +[0-9.]+  (yes|no)$",
                     p.stdout, re.MULTILINE):
        fail(f"no row of figures for {s}\n{p.stdout}")
m = re.search(r"time to accuracy \(section 3\): (.+?), ([0-9.]+) ms / body alone ([0-9.]+) ms = ([0-9.]+) "
              r"\(target 1: (PASS|FAIL)\)", p.stdout)
if not m:
    fail(f"no time to accuracy with its ratio and verdict\n{p.stdout}")
cpu, bench, ratio = float(m.group(2)), float(m.group(3)), float(m.group(4))
if not (cpu > 0 and bench > 0 and abs(ratio - cpu / bench) <= 0.01 * ratio + 0.01):
    fail(f"the ratio {ratio} is not {cpu} ms / {bench} ms")
if (m.group(5) == "PASS") != (ratio <= 1.0):
    fail(f"the verdict {m.group(5)} does not follow from the ratio {ratio} and the target 1")

# the doc: the command at its top, the summary, the deck's table, its plot
path = os.path.join(out, "work-precision.md")
if not os.path.exists(path):
    fail(f"no {path}")
with open(path, encoding="utf-8") as f:
    doc = f.read()
if "\ntools/work-precision\n" not in doc.split("## ")[0]:
    fail(f"the doc does not begin with the command that regenerates it\n{doc[:600]}")
if not re.search(r"^\| decks/sled_belted\.deck \| .+ \| [0-9.]+ \| [0-9.]+ \| 1 (PASS|FAIL) \|$", doc, re.MULTILINE):
    fail("no summary row for the deck")
table = [line for line in doc.splitlines() if line.startswith(("| Adams-Moulton", "| RK4", "| Dormand-Prince"))]
if len(table) != len(settings) or "belts %" not in doc or "its difference from RTOL 1e-08" not in doc:
    fail(f"expected the deck's table of {len(settings)} settings with belts and the reference's check\n{doc}")
for what in ("cheapest accurate:", "recommended default:", "time to accuracy (section 3):"):
    if "- " + what not in doc:
        fail(f"the doc lacks '{what}'")
png = os.path.join(out, "img", "work-precision-sled_belted.png")
if not plots:
    if "(img/work-precision-sled_belted.png)" not in doc:
        fail("the doc does not show the plot")
    if not os.path.exists(png):
        fail(f"no plot {png}")
    with open(png, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            fail(f"{png} is not a PNG")
if [n for n in os.listdir(out) + os.listdir(os.path.join(out, "img")) if n.endswith(".part") or ".part." in n]:
    fail("a temporary output is left behind")

# the tool's own failures: status 2, and the earlier doc is kept as it was
kept = snapshot(out)
p = tool_run("--quick", deck, program=os.path.join(work, "missing"))
if p.returncode != 2 or "no hsri2d program at" not in p.stderr:
    fail(f"a missing hsri2d: status {p.returncode}, expected 2 and a message\n{p.stderr}")
bad = os.path.join(work, "bad.deck")
with open(bad, "w") as f:
    f.write("*TITLE\nBAD\n*NOSUCHGROUP\n")
p = tool_run("--quick", bad)
if p.returncode != 2 or "hsri2d refused" not in p.stderr:
    fail(f"a deck hsri2d refuses: status {p.returncode}, expected 2 and a message\n{p.stderr}")
if snapshot(out) != kept:
    fail("a failed run of the tool changed the earlier doc or plots")
if os.listdir(tmp):
    fail(f"left behind in its temporary directory: {os.listdir(tmp)}")
print(f"{NAME}: ok")
