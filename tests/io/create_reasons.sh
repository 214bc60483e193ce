#!/usr/bin/env bash
# An output file that cannot be created is refused with status 4 and a
# message that says why: the directory does not exist, the target is a
# directory, the directory is not writable (not testable as root).
#
# Usage: create_reasons.sh HSRI2D WORK_DIRECTORY
test_name=io_create_reasons
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"
mkdir adir

fails() { # regex args...
    local regex=$1
    shift
    "$exe" "$@" >out 2>err
    expect_status 4 $? "$*"
    expect_text err "$regex" "$*"
    no_crash err
    no_part_files .
    no_part_files adir
}

fails 'cannot create HDF5 file missing/x.h5: No such file or directory \(directory missing\)' --h5 missing/x.h5
fails 'cannot write the listing to missing/x.lst: No such file or directory \(directory missing\)' -o missing/x.lst
fails 'cannot create HDF5 file adir: it is a directory' --h5 adir
fails 'cannot write the listing to adir: it is a directory' -o adir
fails 'cannot create HDF5 file adir/: it is a directory' --h5 adir/
fails 'cannot create HDF5 file /dev/null: not a regular file' --h5 /dev/null
touch afile
fails 'cannot create HDF5 file afile/x.h5: Not a directory \(directory afile\)' --h5 afile/x.h5

if [ "$(id -u)" -ne 0 ]; then
    mkdir ro && chmod 555 ro
    fails 'cannot create HDF5 file ro/x.h5: Permission denied \(directory ro\)' --h5 ro/x.h5
    chmod 755 ro
else
    echo "$test_name: running as root: the permission case is not tested"
fi
pass
