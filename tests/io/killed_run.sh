#!/usr/bin/env bash
# A run killed midway leaves its partial outputs under their temporary
# names, TARGET.XXXXXX.part, the HDF5 one readable up to its last flush,
# and the earlier outputs at the targets untouched.
#
# Usage: killed_run.sh HSRI2D WORK_DIRECTORY
# Exit status: 0 pass, 1 fail, 77 skipped (h5dump not installed).
test_name=io_killed_run
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"
command -v h5dump >/dev/null 2>&1 || skip "h5dump not found (package hdf5-tools)"

"$exe" -o out.lst --h5 out.h5 2>err || fail "the earlier run failed: $(cat err)"
cp out.lst earlier.lst
cp out.h5 earlier.h5

# Long enough to be killed midway: 2 s of simulated time, a record every
# 0.5 ms (4001 records, some 3.5 MB of HDF5, flushed every 50 records).
time_deck long.deck 2.0 0.0005
"$exe" @default long.deck -o out.lst --h5 out.h5 >out 2>err &
pid=$!

# Kill it once its HDF5 file holds a few hundred flushed records (2 MB:
# at least two flushes of 50 records whatever the number of series).
tries=0
while :; do
    part=$(find . -maxdepth 1 -name 'out.h5.??????.part' | head -n 1)
    if [ -n "$part" ] && [ "$(wc -c <"$part")" -gt 2000000 ]; then break; fi
    kill -0 $pid 2>/dev/null || fail "the run ended before it could be killed (no growing out.h5.XXXXXX.part)"
    tries=$((tries + 1))
    [ $tries -le 3000 ] || { kill -KILL $pid; fail "out.h5.XXXXXX.part did not grow within 30 s"; }
    sleep 0.01
done
kill -KILL $pid
wait $pid 2>/dev/null

same_content out.h5 earlier.h5 "the killed run"
same_content out.lst earlier.lst "the killed run"
[ "$(find . -maxdepth 1 -name 'out.h5.??????.part' | wc -l)" -eq 1 ] || fail "not one out.h5.XXXXXX.part"
[ "$(find . -maxdepth 1 -name 'out.lst.??????.part' | wc -l)" -eq 1 ] || fail "not one out.lst.XXXXXX.part"

h5dump -H "$part" >/dev/null 2>&1 || fail "h5dump cannot open $part"
rows=$(h5dump -H -d /time "$part" 2>/dev/null | sed -n 's/.*DATASPACE *SIMPLE { ( *\([0-9]*\) ).*/\1/p' | head -n 1)
[ -n "$rows" ] && [ "$rows" -ge 100 ] || fail "/time in $part has '${rows}' rows, expected at least 100"
# The first 100 times: 0, 0.0005, 0.001, ...
h5dump -y -w 0 -m %.17g -d /time -s 0 -c 100 -o times.txt "$part" >/dev/null 2>&1 || fail "cannot read /time in $part"
tr ', ' '\n\n' <times.txt | awk 'NF { k++; want = (k - 1) * 0.0005
    if ($1 - want > 1e-9 || want - $1 > 1e-9) { bad++; if (bad <= 3) printf "row %d: %s, expected %g\n", k, $1, want } }
    END { exit (k != 100 || bad > 0) }' >&2 || fail "wrong times in $part"
h5dump -d /input/deck "$part" 2>/dev/null | grep -q 'TIME' || fail "/input/deck missing from $part"
echo "$test_name: the killed run left $part with $rows rows"
rm -f ./*.part
pass
