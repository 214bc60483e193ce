#!/usr/bin/env bash
# A run killed before its first page of time histories (50 print records)
# leaves, under the listing's temporary name, everything known before the
# run: the run page with its warnings, the deck echo, the parameters and the
# preliminary calculations (issue 14, item 13: it used to leave an empty
# file, the text waiting in a buffer); and the HDF5 file's structure and
# deck under its own; the files at the targets untouched. Killed by
# SIGKILL, SIGTERM and SIGINT (Ctrl-C) alike. The events are in the HDF5
# file as they happen, before any flush of the records.
#
# Usage: killed_early.sh HSRI2D DECK EVENT_DECK WORK_DIRECTORY
#   DECK: a deck with an interior that gives a warning (tools/bench/interior_driver.deck)
#   EVENT_DECK: a deck with an event at 0.0473 s (decks/unbelted_driver.deck)
# Exit status: 0 pass, 1 fail, 77 skipped (h5dump not installed).
test_name=io_killed_early
. "$(dirname "$0")/lib.sh"
exe=$1
deck=$2
event_deck=$3
start_work "$4"
command -v h5dump >/dev/null 2>&1 || skip "h5dump not found (package hdf5-tools)"
# job control: a background job then takes SIGINT (a non-interactive shell
# would start it with SIGINT ignored)
set -m

echo 'the earlier listing' >out.lst
echo 'the earlier HDF5 file' >out.h5
cp out.lst earlier.lst
cp out.h5 earlier.h5
# 1000 s of simulated time (the most *TIME allows), a record every 10 s:
# the 50th record (the first page of tables) is 5 million steps, some 20 s
# of computing, away (RK4 steps growing once the body is at rest).
time_deck long.deck 1000.0 10.0

for signal in KILL TERM INT; do
    rm -f ./*.part
    "$exe" "$deck" long.deck -o out.lst --h5 out.h5 >out 2>err &
    pid=$!
    # Wait for the last line known before the run (the preliminary
    # calculations' kinetic energy), then kill.
    deadline=$((SECONDS + 10))
    while :; do
        part=$(find . -maxdepth 1 -name 'out.lst.??????.part' | head -n 1)
        if [ -n "$part" ] && grep -q 'kinetic energy: vehicle' "$part"; then break; fi
        kill -0 $pid 2>/dev/null || fail "SIG$signal: the run ended before it could be killed: $(cat err)"
        [ $SECONDS -lt $deadline ] || { kill -KILL $pid; fail "SIG$signal: the listing's first pages did not reach out.lst.XXXXXX.part within 10 s"; }
        sleep 0.01
    done
    kill -$signal $pid
    wait $pid 2>/dev/null
    status=$?
    [ $status -gt 128 ] || fail "SIG$signal: the run ended with status $status, not by the signal"

    same_content out.lst earlier.lst "SIG$signal"
    same_content out.h5 earlier.h5 "SIG$signal"
    for want in '^RUN$' '^ TITLE   INTERIOR TIMING DECK' '^ WARNING \*SURFACES surface 9' '^INPUT DECK \(C\.1\)$' \
        'long\.deck:2 ' '^PARAMETERS \(C\.1, TABLES 1-6\)$' '^PRELIMINARY CALCULATIONS \(C\.2\)$' \
        '^  kinetic energy: vehicle'; do
        expect_text "$part" "$want" "SIG$signal: the listing left"
    done
    grep -q 'TIME HISTORIES' "$part" && fail "SIG$signal: the run got to its time histories before it was killed"
    [ -z "$(tail -c 1 "$part")" ] || fail "SIG$signal: the listing left ends inside a line"
    h5part=$(find . -maxdepth 1 -name 'out.h5.??????.part' | head -n 1)
    [ -n "$h5part" ] || fail "SIG$signal: no out.h5.XXXXXX.part"
    h5dump -d /input/deck "$h5part" 2>/dev/null | grep -q 'TIME' || fail "SIG$signal: /input/deck missing from $h5part"
    h5dump -H -d /time "$h5part" >/dev/null 2>&1 || fail "SIG$signal: /time missing from $h5part"
    echo "$test_name: SIG$signal left $part ($(wc -c <"$part") bytes) and $h5part"
done
rm -f ./*.part

# The events as they happen: the unbelted driver's first undesired contact
# (t = 0.0473 s) is in the file of a run killed long before its first flush
# of records (the 50th record, t = 500 s).
"$exe" "$event_deck" long.deck -o out.lst --h5 out.h5 >out 2>err &
pid=$!
sleep 3
kill -0 $pid 2>/dev/null || fail "the event run ended before it could be killed: $(cat err)"
kill -KILL $pid
wait $pid 2>/dev/null
h5part=$(find . -maxdepth 1 -name 'out.h5.??????.part' | head -n 1)
[ -n "$h5part" ] || fail "the event run left no out.h5.XXXXXX.part"
h5dump -y -w 0 -m %.17g -d /events/time -o events.txt "$h5part" >/dev/null 2>&1 || fail "no /events/time in $h5part"
first=$(tr ', ' '\n\n' <events.txt | awk 'NF { print; exit }')
awk -v t="$first" 'BEGIN { exit !(t > 0.04 && t < 0.06) }' || fail "the first event in $h5part is at t = '$first', expected 0.0473 s"
echo "$test_name: the killed event run left $(tr ', ' '\n\n' <events.txt | grep -c .) events in $h5part, the first at t = $first s"
same_content out.lst earlier.lst "the event run"
same_content out.h5 earlier.h5 "the event run"
rm -f ./*.part
pass
