#!/usr/bin/env bash
# "Nothing is allocated inside the step loop" (docs/architecture.md), shown
# by counting: the calls of malloc and realloc (a preloaded counter,
# malloc_count.c) of runs of the default deck that differ only in their
# step count (DT, or the tolerances for Dormand-Prince) must be the same, up to a few
# events' worth; an allocation per step would add one for each of the
# 500 or more extra steps. With Table 5's limits (the joint reactions at
# every accepted step, issue 14 item 31) and without, under each
# integrator.
#
#   no_step_allocations.sh HSRI2D DECK_DIRECTORY COUNTER_LIBRARY WORK_DIRECTORY
set -u
exe=$(realpath "$1") decks=$(realpath "$2") counter=$(realpath "$3") work=$4
test_name=runs_no_step_allocations
fail() { echo "$test_name: FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work" || fail "cannot set up $work"

# a card: the index in columns 1-2, then fields of ten columns
card() { local index=$1; shift; printf '%2s' "$index"; printf '%10s' "$@"; printf '\n'; }

# count NINT DT TOL LIMITS: the allocations and steps of a 0.05 s run (TOL:
# RTOL and ATOL), in $allocations and $steps
count() {
    {
        echo '*OPTIONS'; card '' 1 3 1 2 3 "$1"
        echo '*TIME'; card '' 0.05 "$2" 0.01 '' '' "$3" "$3"
        if [ "$4" = yes ]; then
            # limits the run does not reach: checked at every step, never an event
            echo '*INJURY'; card 4 '' '' 9000.; card 7 '' 9000.; card 9 90000.
        fi
    } >changes.deck
    rm -f count
    rm -rf mme
    # (with MME=yes, an ISO-MME data set: the belts' tensions sampled at every
    # accepted step for its 10 kHz channels)
    MALLOC_COUNT_FILE=$PWD/count LD_PRELOAD=$counter "$exe" "$decks/default.deck" changes.deck -o run.lst \
        ${MME:+--mme mme} \
        2>stderr.txt || fail "NINT $1, DT $2, RTOL $3: status $?: $(head -c 300 stderr.txt)"
    [ -s count ] || { echo "$test_name: skipped: the counter did not report (LD_PRELOAD ignored?)" >&2; exit 77; }
    allocations=$(cat count)
    steps=$(sed -n 's/^  accepted steps *//p' run.lst)
}

for limits in yes no mme; do
    MME=
    if [ $limits = mme ]; then MME=yes limits=no; fi
    for nint in 1 2 3; do
        if [ -n "$MME" ] && [ $nint != 1 ]; then continue; fi
        if [ $nint = 3 ]; then
            count $nint 0.0001 1e-6 $limits
        else
            count $nint 0.0001 '' $limits
        fi
        few=$allocations steps_few=$steps
        if [ $nint = 3 ]; then
            count $nint 0.0001 1e-12 $limits
        else
            count $nint 0.000025 '' $limits
        fi
        many=$allocations steps_many=$steps
        extra=$((steps_many - steps_few))
        echo "limits $limits${MME:+ (--mme)}, NINT $nint: $few allocations in $steps_few steps, $many in $steps_many"
        [ "$extra" -ge 500 ] || fail "limits $limits, NINT $nint: only $extra more steps: the test tests nothing"
        diff=$((many - few))
        [ ${diff#-} -lt $((extra / 10)) ] ||
            fail "limits $limits, NINT $nint: $diff more allocations for $extra more steps"
    done
done
echo "$test_name: PASS"
