# Shared by tests/cluster/*.sh (sourced): the arguments, skip and fail, and
# the local run of the study whose table the spread runs must give.
#
#   TEST.sh HSRI2D STUDY_DECK WORK_DIRECTORY
# Sets exe, deck, work (absolute), here (tests/cluster), root (the source tree).

fail() { echo "$test_name: FAIL: $*" >&2; exit 1; }
skip() { echo "$test_name: skipped: $*" >&2; exit 77; }

[ $# -eq 3 ] || { echo "usage: $0 HSRI2D STUDY_DECK WORK_DIRECTORY" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
[ -x "$1" ] || fail "no executable $1"
exe=$(realpath "$1")
[ -f "$2" ] || skip "the study deck $2 does not exist (yet)"
deck=$(realpath "$2")
rm -rf "$3" && mkdir -p "$3" || fail "cannot make the work directory $3"
work=$(realpath "$3")

# The study in one process on this machine: local/results.csv is the table
# every spread of the study must reproduce byte for byte.
local_run() {
    runs=$("$exe" --study-size "$deck" 2>"$work/size.err") || fail "$exe --study-size: $(head -c 300 "$work/size.err")"
    [[ $runs =~ ^[0-9]+$ ]] && [ "$runs" -ge 1 ] || fail "$exe --study-size printed '$runs', not a number of runs"
    "$exe" --results "$work/local" "$deck" >"$work/local.lst" 2>"$work/local.err" ||
        fail "the local run: status $?: $(head -c 300 "$work/local.err")"
    [ -s "$work/local/results.csv" ] || fail "the local run wrote no $work/local/results.csv"
    echo "$test_name: the study has $runs runs; the local run's table has $(wc -l <"$work/local/results.csv") lines"
}

# same_table DIR: DIR/results.csv is the local run's, byte for byte
same_table() {
    [ -f "$1/results.csv" ] || fail "no $1/results.csv"
    cmp "$work/local/results.csv" "$1/results.csv" ||
        fail "$1/results.csv differs from the local run's table (diff $work/local/results.csv $1/results.csv)"
}

# row_file R: the path of run R's row in the results directory $1
row_file() { printf '%s/runs/%06d.row' "$1" "$2"; }
