#!/usr/bin/env bash
# A listing written to a pipe whose reader has gone (hsri2d | head) is an
# output error (issue 14, item 12): status 4, never death by SIGPIPE (141);
# a message on standard error; the HDF5 file withdrawn (no .part left, the
# earlier file at its name untouched); and the run ends as soon as a write
# fails, not at TMAX.
#
# Usage: closed_pipe.sh HSRI2D WORK_DIRECTORY
test_name=io_closed_pipe
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

"$exe" -o /dev/null --h5 run.h5 2>err || fail "the earlier run failed: $(cat err)"
cp run.h5 earlier.h5

closed() { # listing_name args...
    local name=$1 status
    shift
    # head reads the first line and exits: the listing (some 480 kB) cannot
    # all go into the pipe's buffer, so a later write finds no reader
    "$exe" "$@" --h5 run.h5 2>err | head -n 1 >/dev/null
    status=${PIPESTATUS[0]}
    expect_status 4 "$status" "$* | head"
    expect_text err "cannot write the listing to $name: Broken pipe" "$* | head"
    expect_text err 'run.h5: left as before; the partial output was removed' "$* | head"
    no_crash err
    same_content run.h5 earlier.h5 "$* | head"
    no_part_files .
}
closed 'standard output'
closed 'standard output' -o -
closed /dev/stdout -o /dev/stdout

# The run stops at the first failed write: 100 s of simulated time (some
# 90 s of computing in a Debug build, 20 s in Release) end within a second.
time_deck long.deck 100.0 0.0005
start=$(date +%s)
timeout 150 "$exe" @default long.deck 2>err | head -n 1 >/dev/null
status=${PIPESTATUS[0]}
expect_status 4 "$status" "a long run | head"
elapsed=$(($(date +%s) - start))
[ "$elapsed" -le 10 ] || fail "a long run | head took $elapsed s to notice the closed pipe"
expect_text err 'cannot write the listing to standard output: Broken pipe' "a long run | head"
pass
