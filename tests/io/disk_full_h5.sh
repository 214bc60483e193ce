#!/usr/bin/env bash
# A disk that fills while the HDF5 file is written (a file-size limit,
# ulimit -f, with SIGXFSZ ignored), during its creation, in the middle of
# the run and when it is closed: always status 4 and a message that says
# where and why, never a crash (HDF5 1.10 used to end in a segmentation
# fault after a failed flush or close); the earlier outputs at the same
# paths are left untouched and no temporary file stays behind.
#
# Usage: disk_full_h5.sh HSRI2D DECK_DIRECTORY WORK_DIRECTORY
test_name=io_disk_full_h5
. "$(dirname "$0")/lib.sh"
exe=$1
decks=$2
start_work "$3"

# A run with a flush every 50 records mid-run (401 records) and the
# default run (41 records, nothing flushed between creation and close).
time_deck dense.deck 0.2 0.0005
"$exe" @default dense.deck -o dense.lst --h5 dense.h5 2>err || fail "the unlimited dense run failed: $(cat err)"
"$exe" -o default.lst --h5 default.h5 2>err || fail "the unlimited default run failed: $(cat err)"
dense=$(kib dense.h5)
default=$(kib default.h5)

# The earlier outputs at the paths the failing runs aim at.
"$exe" "$decks/free_fall.deck" -o out.lst --h5 out.h5 2>err || fail "the earlier run failed: $(cat err)"
cp out.lst earlier.lst
cp out.h5 earlier.h5

stages=''
# try LIMIT_KIB DECK_ARGS...: a run under a file-size limit. The listing
# goes to out.lst, or, with listing=pipe, through a pipe (not limited by
# ulimit -f): the dense run's listing outgrows its HDF5 file and, written as
# the run goes, would otherwise fill first.
listing=file
try() { # limit_kib deck_args...
    local n=$1 status
    shift
    if [ "$listing" = pipe ]; then
        (trap '' XFSZ; ulimit -f "$n"; exec "$exe" "$@" --h5 out.h5) 2>err | cat >/dev/null
        status=${PIPESTATUS[0]}
    else
        (trap '' XFSZ; ulimit -f "$n"; exec "$exe" "$@" -o out.lst --h5 out.h5) >out 2>err
        status=$?
    fi
    expect_status 4 $status "file size limit $n KiB, $*"
    no_crash err
    expect_text err '(HDF5 file out\.h5|dataset [a-z0-9_/]* in out\.h5): File too large' "limit $n KiB, $*"
    # each failure said once (issue 14, item 26: a failed flush was
    # reported by the run and again when the file was closed)
    [ -z "$(sort err | uniq -d)" ] || fail "limit $n KiB, $*: a line printed twice:
$(cat err)"
    same_content out.h5 earlier.h5 "limit $n KiB, $*"
    same_content out.lst earlier.lst "limit $n KiB, $*"
    no_part_files .
    stages="$stages $(sed -n 's/^cannot \(create\|add series\|write\|flush\|close\) .*/\1/p' err | tr ' ' _)"
}

try 1
try 8
try 20
try $((default * 3 / 4))
try $((default - 1))
listing=pipe
try $((dense / 2)) @default dense.deck
try $((dense * 3 / 4)) @default dense.deck
echo "$test_name: stages that failed:$stages"
# creation, and later: a block of rows written in the middle of the run or
# the last rows written at close (the series have no chunk cache, so both
# report the dataset being written), or a flush
case " $stages " in
    *" create "*) ;;
    *) fail "no limit made the creation fail (stages:$stages)" ;;
esac
case " $stages " in
    *" write "* | *" flush "* | *" close "*) ;;
    *) fail "no limit made a write after the creation fail (stages:$stages)" ;;
esac
pass
