#!/usr/bin/env bash
# A study spread by GNU parallel over shards, interrupted and resumed from
# parallel's job log (issue 17, section 3): the first pass stops at a shard
# made to fail once (--halt soon,fail=1: the shards after it never start);
# the collect step then exits 5, and the rows are exactly those of the shards
# that succeeded; --resume runs the shards never started but not the failed
# one (collect: still 5, only its runs missing); --resume-failed reruns it;
# the collect step then merges a table equal to a local run's results.csv
# byte for byte. Skipped (77) without parallel or without the study deck.
#
#   gnu_parallel.sh HSRI2D STUDY_DECK WORK_DIRECTORY
set -u
test_name=gnu_parallel
source "$(dirname "$0")/common.sh"
shards=8 failing=3
command -v parallel >/dev/null || skip "no GNU parallel (Debian package parallel; tools/setup tries it)"
parallel --version 2>/dev/null | grep -q 'GNU parallel' || skip "$(command -v parallel) is not GNU parallel"
# parallel's own files (--will-cite's, its temporary files) stay here
export PARALLEL_HOME=$work/parallel-home
mkdir -p "$PARALLEL_HOME" || fail "cannot make $PARALLEL_HOME"

local_run
[ "$runs" -ge $failing ] || fail "the study has $runs runs: too few to fail shard $failing of a pass"
[ "$runs" -ge $shards ] || shards=$runs
results=$work/parallel
log=$work/shards.joblog

# One shard of the study; shard $failing fails the first time (a lost
# node), before it writes anything.
cat >"$work/shard.sh" <<EOF
#!/bin/sh
if [ "\$1" = $failing ] && [ ! -e "$work/failed-once" ]; then
    : >"$work/failed-once"
    echo "shard \$1: made to fail this once" >&2
    exit 1
fi
exec "$exe" --shard "\$1/$shards" --results "$results" "$deck"
EOF
chmod +x "$work/shard.sh" || fail "cannot write $work/shard.sh"

# shards_run K...: the rows in $results are exactly the runs of shards K...
shards_run() {
    local r k expected
    for ((r = 1; r <= runs; r++)); do
        k=$(((r - 1) % shards + 1))
        expected=no
        [[ " $* " == *" $k "* ]] && expected=yes
        if [ -f "$(row_file "$results" $r)" ]; then
            [ $expected = yes ] || fail "run $r has a row, and its shard $k did not run"
        else
            [ $expected = no ] || fail "run $r has no row, and its shard $k ran"
        fi
    done
}
# collect_expect STATUS: the collect step's status
collect_expect() {
    "$exe" --collect --results "$results" -o "$work/collect.lst" "$deck" 2>"$work/collect.err"
    local status=$?
    [ $status -eq "$1" ] || fail "the collect step: status $status, expected $1: $(head -c 300 "$work/collect.err")"
}
# joblog_status K: the exit values of shard K's lines in the job log (its Seq
# is K: the shards are given in order)
joblog_status() { awk -F'\t' -v k="$1" 'NR > 1 && $1 == k {print $7}' "$log" | tr '\n' ' '; }

# pass 1: one shard at a time, so that where it stops is known: shards 1 to
# $failing - 1 done, $failing failed, the rest never started
parallel --will-cite --joblog "$log" --halt soon,fail=1 -j1 "$work/shard.sh" {} ::: $(seq 1 $shards) \
    >"$work/pass1.out" 2>&1 && fail "the first pass did not stop at the failing shard"
[ "$(joblog_status $failing)" = "1 " ] || fail "the job log has no failed shard $failing: $(cat "$log")"
shards_run $(seq 1 $((failing - 1)))
collect_expect 5
echo "$test_name: pass 1 stopped at shard $failing of $shards; collect exits 5: $(head -n 1 "$work/collect.err")"

# pass 2: --resume runs the shards never started, and skips the failed one
parallel --will-cite --joblog "$log" --resume -j2 "$work/shard.sh" {} ::: $(seq 1 $shards) \
    >"$work/pass2.out" 2>&1 || fail "the --resume pass: status $?: $(head -c 300 "$work/pass2.out")"
[ "$(joblog_status $failing)" = "1 " ] || fail "--resume ran the failed shard $failing again"
shards_run $(seq 1 $shards | grep -vx $failing)
collect_expect 5
echo "$test_name: pass 2 (--resume) ran the shards never started; collect exits 5: $(head -n 1 "$work/collect.err")"

# pass 3: --resume-failed reruns the failed shard, and only it
parallel --will-cite --joblog "$log" --resume-failed -j2 "$work/shard.sh" {} ::: $(seq 1 $shards) \
    >"$work/pass3.out" 2>&1 || fail "the --resume-failed pass: status $?: $(head -c 300 "$work/pass3.out")"
[ "$(joblog_status $failing)" = "1 0 " ] || fail "--resume-failed: shard $failing's job log lines: $(joblog_status $failing)"
[ "$(awk 'NR > 1' "$log" | wc -l)" -eq $((shards + 1)) ] || fail "the job log has not $((shards + 1)) jobs: $(cat "$log")"
shards_run $(seq 1 $shards)
collect_expect 0
same_table "$results"
[ -s "$work/collect.lst" ] || fail "the collect step wrote no listing"
echo "$test_name: pass 3 (--resume-failed) reran shard $failing; the merged table is the local run's"
echo "$test_name: passed"
