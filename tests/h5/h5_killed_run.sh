#!/bin/sh
# A run killed midway must leave a readable HDF5 file holding everything up
# to its last flush. Starts h5_writer_demo, waits until it has flushed and
# then written more without flushing, kills it with SIGKILL, and checks with
# h5dump that the file opens and that every flushed row and event is there.
#
# Usage: h5_killed_run.sh DEMO_EXECUTABLE WORK_DIRECTORY
# Exit status: 0 pass, 1 fail, 77 skipped (h5dump not installed).
set -u

demo=$1
dir=$2
n_flushed=1000      # rows flushed (not a multiple of the 64-row block)
n_unflushed=5000    # rows appended after the flush: many blocks reach HDF5
ncols=10
file=$dir/h5_killed_run.h5
marker=$dir/h5_killed_run.ready
dump=$dir/h5_killed_run.txt

fail() {
    echo "h5_killed_run: FAIL: $*" >&2
    exit 1
}

command -v h5dump >/dev/null 2>&1 || {
    echo "h5_killed_run: h5dump not found (package hdf5-tools); skipped" >&2
    exit 77
}

mkdir -p "$dir" || fail "cannot create $dir"
rm -f "$file" "$marker" "$dump"

"$demo" "$file" "$marker" $n_flushed $n_unflushed &
pid=$!

# Wait (at most 60 s) for the demo to say it is ready.
tries=0
while [ ! -e "$marker" ]; do
    if ! kill -0 $pid 2>/dev/null; then
        wait $pid
        fail "the demo exited (status $?) before it was ready"
    fi
    tries=$((tries + 1))
    if [ $tries -gt 600 ]; then
        kill -KILL $pid 2>/dev/null
        fail "the demo was not ready within 60 s"
    fi
    sleep 0.1
done

kill -KILL $pid
wait $pid 2>/dev/null
echo "h5_killed_run: demo killed after $n_flushed flushed and $n_unflushed unflushed rows"

h5dump -H "$file" >/dev/null 2>&1 || fail "h5dump cannot open $file"

# Rows in a series, as h5dump shows its shape: ( rows ) or ( rows, ncols ).
rows_of() {
    h5dump -H -d "$1" "$file" 2>/dev/null |
        sed -n 's/.*DATASPACE *SIMPLE { ( *\([0-9]*\).*/\1/p' | head -n 1
}

for name in /time /body/z; do
    rows=$(rows_of $name)
    [ -n "$rows" ] || fail "cannot read the shape of $name"
    [ "$rows" -ge $n_flushed ] || fail "$name has $rows rows, expected at least $n_flushed"
    echo "h5_killed_run: $name has $rows rows in the killed file"
done

# Every flushed value: /time (1-D) row i is i; /body/z row i column j is
# 1000*i + j.
check_values() { # name ncols
    rm -f "$dump"
    if [ "$2" -eq 1 ]; then start=0 count=$n_flushed; else start="0,0" count="$n_flushed,$2"; fi
    h5dump -y -w 0 -m %.17g -d "$1" -s "$start" -c "$count" -o "$dump" "$file" >/dev/null 2>&1 ||
        fail "h5dump cannot read the first $n_flushed rows of $1"
    tr ', ' '\n\n' <"$dump" | awk -v n=$n_flushed -v nc="$2" -v name="$1" '
        NF { k++; i = int((k - 1) / nc) + 1; j = (k - 1) % nc + 1
             want = (nc == 1) ? i : 1000 * i + j
             if ($1 + 0 != want) { bad++; if (bad <= 5) printf "%s row %d column %d: %s, expected %d\n", name, i, j, $1, want } }
        END { if (k != n * nc) { printf "%s: %d values read, expected %d\n", name, k, n * nc; exit 1 }
              exit bad > 0 }' || fail "wrong values in $1"
}
check_values /time 1
check_values /body/z $ncols

# The event written before the flush.
rm -f "$dump"
h5dump -y -w 0 -d /events/kind -s 0 -c 1 -o "$dump" "$file" >/dev/null 2>&1 ||
    fail "cannot read /events/kind"
[ "$(tr -d ' ,\n' <"$dump")" = 1 ] || fail "the flushed event is missing from /events/kind"
h5dump -d /events/text "$file" 2>/dev/null | grep -q '"event before the flush' ||
    fail "the flushed event is missing from /events/text"
h5dump -d /input/deck "$file" 2>/dev/null | grep -q '"killed-run demo deck' ||
    fail "/input/deck is missing or wrong"

rm -f "$marker" "$dump"
echo "h5_killed_run: PASS"
exit 0
