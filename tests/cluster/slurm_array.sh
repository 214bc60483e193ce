#!/usr/bin/env bash
# A study spread over a Slurm job array, for real (issue 17, section 3): a
# one-node Slurm from Debian's packages (slurmctld, slurmd, slurm-client,
# munge) with its own munge key and socket and its own slurm.conf, on free
# ports, in a temporary directory; tools/study-sbatch --submit submits a
# 20-task array of the study and the dependent collect job; the test polls
# squeue until both are gone, checks every task and the collect job
# completed, runs the collect step again by hand, and compares the merged
# table with a local run's results.csv byte for byte. The daemons are
# stopped by their PIDs on every exit (a trap). Skipped (77) where the
# packages are not installed, the study deck does not exist, or the daemons
# cannot start here.
#
#   slurm_array.sh HSRI2D STUDY_DECK WORK_DIRECTORY
#
# HSRI2D_CLUSTER_TIMEOUT: seconds to wait for the jobs (default 300).
set -u
test_name=slurm_array
source "$(dirname "$0")/common.sh"
tasks=20
timeout=${HSRI2D_CLUSTER_TIMEOUT:-300}

for c in munged slurmctld slurmd sbatch squeue scontrol sinfo scancel; do
    command -v $c >/dev/null ||
        skip "no $c: install Debian's slurmctld slurmd slurm-client munge (tools/setup tries: docs/modification.md)"
done
# Not only root: run as nobody, the daemons (SlurmUser and SlurmdUser the
# current user) ran its jobs too.

# A job's environment comes from sbatch's: nothing of an enclosing Slurm job
while IFS='=' read -r name _; do
    case $name in SLURM_* | SBATCH_* | SALLOC_* | SRUN_*) unset "$name" ;; esac
done < <(env)

# The daemons' files: a short path (the munge socket's must fit in 108 bytes),
# every directory searchable by all (munged insists)
cluster=$(mktemp -d /tmp/hsri2d-slurm.XXXXXX) || fail "cannot make a temporary directory"
chmod 755 "$cluster"
export SLURM_CONF=$cluster/slurm.conf
pids=() ids=()

# stop PID...: SIGTERM, then SIGKILL after 15 s
stop() {
    local pid n
    for pid in "$@"; do kill "$pid" 2>/dev/null; done
    for pid in "$@"; do
        for ((n = 0; n < 150; n++)); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -0 "$pid" 2>/dev/null && { echo "$test_name: PID $pid ignored SIGTERM: killed" >&2; kill -KILL "$pid"; }
        wait "$pid" 2>/dev/null
    done
}
cleanup() {
    local status=$?
    trap - EXIT INT TERM
    if [ ${#ids[@]} -gt 0 ] && [ -n "${ctld_pid:-}" ] && kill -0 "$ctld_pid" 2>/dev/null; then
        # jobs still queued or running (a timeout): cancelled before slurmd stops
        scancel "${ids[@]}" 2>/dev/null
        for ((n = 0; n < 100; n++)); do
            [ -z "$(squeue -h -o %i -j "$(IFS=,; echo "${ids[*]}")" 2>/dev/null)" ] && break
            sleep 0.1
        done
    fi
    # this cluster's slurmstepd outlive their jobs by a moment: waited for
    # (10 s), then killed by PID. They are found by the slurm.conf their
    # environment names, which only root can read (slurmstepd is not
    # dumpable); for others, by their sockets in slurmd's spool directory,
    # which go a moment before they do.
    local steps=() pid
    for ((n = 0; n < 100; n++)); do
        steps=()
        for pid in $(cd /proc && echo [0-9]*); do
            [ "$(cat /proc/$pid/comm 2>/dev/null)" = slurmstepd ] &&
                { tr "\\0" "\\n" </proc/$pid/environ; } 2>/dev/null | grep -qx "SLURM_CONF=$SLURM_CONF" && steps+=($pid)
        done
        [ ${#steps[@]} -eq 0 ] && ! compgen -G "$cluster/spool/localhost_*" >/dev/null && break
        sleep 0.1
    done
    if [ ${#steps[@]} -gt 0 ]; then
        echo "$test_name: slurmstepd ${steps[*]} still there after 10 s: killed" >&2
        kill -KILL "${steps[@]}"
    fi
    # slurmd, then slurmctld, then munged: each stopped by the PID this test started
    local i
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do stop "${pids[i]}"; done
    if [ $status -ne 0 ] && [ $status -ne 77 ]; then
        cp -r "$cluster/log" "$work/daemon-logs" 2>/dev/null &&
            echo "$test_name: the daemons' logs are in $work/daemon-logs" >&2
    fi
    rm -rf "$cluster"
    exit $status
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# tail_logs: the end of the daemons' logs, for a message
tail_logs() { tail -n 5 "$cluster"/log/*.log "$cluster"/log/*.out 2>/dev/null | head -c 3000; }

local_run

# munge: its own key and socket
mkdir -p "$cluster/munge" "$cluster/log" "$cluster/state" "$cluster/spool" || fail "cannot fill $cluster"
key=$cluster/munge/munge.key
if command -v mungekey >/dev/null; then
    mungekey -c -k "$key" || fail "mungekey could not make a key"
else
    head -c 1024 /dev/urandom >"$key" && chmod 400 "$key" || fail "cannot make a munge key"
fi
socket=$cluster/munge/socket
munged -F --key-file="$key" --socket="$socket" --pid-file="$cluster/munge/munged.pid" \
    --seed-file="$cluster/munge/munged.seed" --log-file="$cluster/log/munged.log" \
    >"$cluster/log/munged.out" 2>&1 &
pids+=($!)
for ((n = 0; n < 50; n++)); do [ -S "$socket" ] && break; sleep 0.1; done
munge -n -S "$socket" 2>/dev/null | unmunge -S "$socket" >/dev/null 2>&1 ||
    skip "munged does not start here: $(tail_logs)"

# two free TCP ports, for slurmctld and slurmd
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s:
    x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])') || fail "cannot find two free ports"

user=$(id -un)
cat >"$SLURM_CONF" <<EOF
# a one-node Slurm for tests/cluster/slurm_array.sh
ClusterName=hsri2dtest
SlurmctldHost=localhost
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
# start the next array tasks at once, not 3 s after a task ends
SchedulerParameters=batch_sched_delay=0
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
# the node is what slurm.conf says, whatever the hardware's sockets and cores
SlurmdParameters=config_overrides
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -D -f "$SLURM_CONF" >"$cluster/log/slurmctld.out" 2>&1 &
ctld_pid=$!
pids+=($ctld_pid)
slurmd -D -N localhost -f "$SLURM_CONF" >"$cluster/log/slurmd.out" 2>&1 &
pids+=($!)
state=''
for ((n = 0; n < 300; n++)); do
    state=$(sinfo -h -n localhost -o %t 2>/dev/null)
    [ "$state" = idle ] && break
    for pid in "${pids[@]}"; do
        kill -0 "$pid" 2>/dev/null || skip "a Slurm daemon (PID $pid) stopped at its start: $(tail_logs)"
    done
    sleep 0.1
done
[ "$state" = idle ] || skip "the node is not idle 30 s after the daemons started (state '$state'): $(tail_logs)"
echo "$test_name: a one-node Slurm $(sinfo -V | cut -d' ' -f2) is up (slurmctld port $ctld_port, slurmd port $slurmd_port)"

# the array and its collect job, by the tool
results=$work/slurm
cd "$work" || fail "cannot enter $work"
"$root/tools/study-sbatch" --deck "$deck" --results "$results" --tasks $tasks --hsri2d "$exe" \
    --partition test --time 10:00 -o "$work/study.sbatch" || fail "tools/study-sbatch could not write the script"
grep -q -- "^#SBATCH --array=1-$tasks\$" "$work/study.sbatch" || fail "study.sbatch: no --array=1-$tasks"
submitted=$("$root/tools/study-sbatch" --deck "$deck" --results "$results" --tasks $tasks --hsri2d "$exe" \
    --partition test --time 10:00 --submit) || fail "tools/study-sbatch --submit failed"
read -r _ array_id _ collect_id <<<"$submitted"
[[ $array_id =~ ^[0-9]+$ && $collect_id =~ ^[0-9]+$ ]] || fail "tools/study-sbatch --submit printed '$submitted'"
ids=("$array_id" "$collect_id")
echo "$test_name: submitted the array $array_id ($tasks tasks) and the collect job $collect_id"

# poll squeue until neither is queued, running or completing
SECONDS=0
while :; do
    left=$(squeue -h -o %i -t PD,R,CG,CF,S -j "$array_id,$collect_id" 2>/dev/null | wc -l)
    [ "$left" -eq 0 ] && break
    [ $SECONDS -lt "$timeout" ] || fail "$left jobs still queued or running after $timeout s:
$(squeue -j "$array_id,$collect_id"; sinfo; tail_logs)"
    sleep 1
done
echo "$test_name: the jobs left the queue in $SECONDS s"

# every task and the collect job completed with status 0 (slurmctld keeps
# finished jobs' records for MinJobAge, 300 s)
states=$(scontrol -o show job "$array_id" | sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/\1 \2 \3/p' | sort -n)
[ "$(grep -c ' COMPLETED 0:0$' <<<"$states")" -eq $tasks ] ||
    fail "not every one of the $tasks tasks completed with status 0:
$states
$(tail -n 3 "$results"/slurm/*.out | head -c 3000)"
collect_state=$(scontrol -o show job "$collect_id" | grep -o 'JobState=[A-Z_]* .*ExitCode=[0-9:]*' | sed 's/ .* / /')
[ "$collect_state" = "JobState=COMPLETED ExitCode=0:0" ] ||
    fail "the collect job: $collect_state: $(cat "$results"/slurm/*collect*.out | head -c 2000)"
[ -s "$results/study.lst" ] || fail "the collect job wrote no listing $results/study.lst"
same_table "$results"
echo "$test_name: the $tasks tasks and the collect job completed; results.csv is the local run's"

# the collect step by hand gives the same table again
rm "$results/results.csv"
"$exe" --collect --results "$results" -o "$work/collect.lst" "$deck" 2>"$work/collect.err" ||
    fail "$exe --collect: status $?: $(head -c 300 "$work/collect.err")"
same_table "$results"
cmp -s "$results/study.lst" "$work/collect.lst" || fail "the collect job's listing differs from a second collect's"
echo "$test_name: passed"
