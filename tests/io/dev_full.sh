#!/usr/bin/env bash
# Output that cannot be written ends with status 4 and a message, never 0:
# the listing to /dev/full (-o), standard output to /dev/full, the other
# printing options to /dev/full. gfortran reports no write error itself,
# so this fails unless every write is checked.
#
# Usage: dev_full.sh HSRI2D WORK_DIRECTORY
test_name=io_dev_full
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

"$exe" -o /dev/full >out 2>err
expect_status 4 $? "-o /dev/full"
expect_text err 'cannot write the listing to /dev/full: No space left on device' "-o /dev/full"
no_crash err

"$exe" >/dev/full 2>err
expect_status 4 $? "standard output to /dev/full"
expect_text err 'cannot write the listing to standard output: No space left on device' "stdout to /dev/full"
no_crash err

# The HDF5 file is withdrawn when the listing fails.
"$exe" -o /dev/full --h5 run.h5 >out 2>err
expect_status 4 $? "-o /dev/full --h5 run.h5"
[ ! -e run.h5 ] || fail "run.h5 was delivered although the listing failed"
no_part_files .
no_crash err

for option in --help --version --default-deck --check; do
    "$exe" $option >/dev/full 2>err
    expect_status 4 $? "$option >/dev/full"
    expect_text err 'No space left on device' "$option >/dev/full"
    no_crash err
done
pass
