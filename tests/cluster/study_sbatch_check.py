"""tools/study-sbatch without Slurm: the script it writes (its #SBATCH lines,
the shard command a task runs, the collect command), the task count asked
of hsri2d --study-size, and its refusals (clear messages, no traceback).

  study_sbatch_check.py TOOL WORK_DIRECTORY
"""
import os
import shutil
import stat
import subprocess
import sys

tool, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def run(*args, env=None):
    return subprocess.run([sys.executable, tool, *args], capture_output=True, text=True, cwd=work, env=env)


# a stand-in hsri2d that prints its arguments, and answers --study-size
stub = os.path.join(work, "stub_hsri2d")
with open(stub, "w") as f:
    f.write('#!/bin/sh\n[ "$1" = --study-size ] && { echo 7; exit 0; }\necho "$@"\n')
os.chmod(stub, os.stat(stub).st_mode | stat.S_IXUSR)
deck = os.path.join(work, "study.deck")
with open(deck, "w") as f:
    f.write("*STUDY\n")
results = os.path.join(work, "results dir")   # a space: quoted in the script

done = run("--deck", "study.deck", "--results", "results dir", "--tasks", "20", "--hsri2d", stub,
           "--partition", "short", "--time", "1-00:30:00", "--cpus-per-task", "3", "--max-running", "5",
           "-o", "a.sbatch")
check(done.returncode == 0, f"the script: status {done.returncode}: {done.stderr}")
text = open(os.path.join(work, "a.sbatch")).read() if done.returncode == 0 else ""
lines = text.splitlines()
for expected in ["#!/bin/sh", "#SBATCH --array=1-20%5", "#SBATCH --partition=short", "#SBATCH --time=1-00:30:00",
                 "#SBATCH --cpus-per-task=3", "#SBATCH --ntasks=1",
                 f"#SBATCH --output={results}/slurm/%x-%A_%a.out"]:
    check(expected in lines, f"no line '{expected}' in the script:\n{text}")
check(os.path.isdir(os.path.join(results, "slurm")), "the directory of Slurm's output files was not made")
check(f"--collect --results '{results}' -o '{results}/study.lst' {deck}" in text,
      f"no collect command in the script:\n{text}")
check("--dependency=afterok:$jobid" in text, "no dependent collect job in the script's header")
# #SBATCH lines come before the first command (sbatch reads no further)
first_command = next((i for i, line in enumerate(lines) if line and not line.startswith("#")), len(lines))
check(all(not line.startswith("#SBATCH") for line in lines[first_command:]), "an #SBATCH line after a command")

# task 4's command, as Slurm would run it
env = dict(os.environ, SLURM_ARRAY_TASK_ID="4")
task = subprocess.run(["sh", os.path.join(work, "a.sbatch")], capture_output=True, text=True, env=env)
check(task.returncode == 0, f"task 4: status {task.returncode}: {task.stderr}")
check(task.stdout.strip() == f"--jobs 3 --shard 4/20 --results {results} {deck}",
      f"task 4 ran hsri2d {task.stdout.strip()}")

# without --tasks: one task per run (--study-size); the script on standard output
done = run("--deck", deck, "--results", results, "--hsri2d", stub)
check(done.returncode == 0 and "#SBATCH --array=1-7" in done.stdout.splitlines(),
      f"without --tasks: status {done.returncode}, {done.stdout[:300]} {done.stderr}")
check("--jobs" not in done.stdout, "--jobs without --cpus-per-task")

# refusals: status 2 (argument errors) or 1, a message naming the problem, no traceback
for args, says in [(["--deck", deck, "--results", results, "--tasks", "0"], "positive integer"),
                   (["--deck", deck, "--results", results, "--tasks", "2", "--time", "soon"], "time limit"),
                   (["--deck", "none.deck", "--results", results, "--tasks", "2"], "cannot find the study deck"),
                   (["--deck", deck, "--results", results, "--tasks", "2", "-o", deck], "not overwritten"),
                   (["--deck", deck, "--results", results, "--tasks", "2", "--job-name", "a b"], "job name"),
                   (["--deck", deck, "--results", results, "--hsri2d", os.path.join(work, "none")], "cannot run"),
                   (["--results", results, "--tasks", "2"], "--deck")]:
    done = run(*args)
    check(done.returncode in (1, 2) and says in done.stderr and "Traceback" not in done.stderr,
          f"{' '.join(args)}: status {done.returncode}, {done.stderr.strip()[:300]}")
check(open(deck).read() == "*STUDY\n", "the deck was overwritten")

# --help documents every option
done = run("--help")
for option in ["--deck", "--results", "--tasks", "--hsri2d", "--partition", "--time", "--cpus-per-task",
               "--max-running", "--submit", "afterok", "--shard K/N", "--collect"]:
    check(option in done.stdout, f"--help does not mention {option}")

for message in failures:
    print("study_sbatch: FAIL:", message, file=sys.stderr)
print(f"study_sbatch: {'failed' if failures else 'passed'}")
sys.exit(1 if failures else 0)
