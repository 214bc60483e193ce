#!/usr/bin/env bash
# The listing is put in place first, then the HDF5 file (docs/usage.md,
# "Output files"): when the second rename fails, the run ends with status 4,
# the new listing is in place, what is at the HDF5 file's name stays as it
# was, the message names that file, and no temporary file is left. The
# rename is made to fail by putting a directory at the HDF5 file's name
# while the run goes on.
#
# Usage: rename_fails.sh HSRI2D WORK_DIRECTORY
test_name=io_rename_fails
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

# 3 s of simulated time: some 2 s of computing in a Debug build.
time_deck run.deck 3.0 0.01
"$exe" @default run.deck -o reference.lst 2>err || fail "the reference run failed: $(cat err)"
echo 'the earlier listing' >out.lst

"$exe" @default run.deck -o out.lst --h5 out.h5 >out 2>err &
pid=$!
deadline=$((SECONDS + 10))
until [ -n "$(find . -maxdepth 1 -name 'out.h5.??????.part')" ]; do
    kill -0 $pid 2>/dev/null || fail "the run ended before out.h5.XXXXXX.part appeared: $(cat err)"
    [ $SECONDS -lt $deadline ] || { kill -KILL $pid; fail "no out.h5.XXXXXX.part within 10 s"; }
    sleep 0.01
done
mkdir out.h5
echo 'kept' >out.h5/inside
kill -0 $pid 2>/dev/null || fail "the run ended before out.h5 became a directory: the test needs a longer run"
wait $pid
expect_status 4 $? "--h5 out.h5 become a directory"
no_crash err
expect_text err 'cannot put the new HDF5 file in place of out.h5: Is a directory' "the second rename"
grep -q 'out.lst' err && fail "the message names the listing, which was delivered: $(cat err)"
same_content out.lst reference.lst "the listing renamed first"
[ -d out.h5 ] && [ "$(cat out.h5/inside)" = kept ] || fail "out.h5 did not stay as it was"
no_part_files .
pass
