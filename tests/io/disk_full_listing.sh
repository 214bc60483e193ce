#!/usr/bin/env bash
# A disk that fills while the listing is written (simulated by a file-size
# limit, ulimit -f, with SIGXFSZ ignored as the brief's shell recipe does)
# ends with status 4 and a message, for -o FILE and for standard output
# redirected to a file; the earlier listing at -o FILE is left untouched
# and no temporary file stays behind.
#
# Usage: disk_full_listing.sh HSRI2D WORK_DIRECTORY
test_name=io_disk_full_listing
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

"$exe" -o full.lst 2>err || fail "the unlimited run failed: $(cat err)"
size=$(kib full.lst)
[ "$size" -gt 8 ] || fail "the listing is too small to sweep ($size KiB)"
echo 'the earlier listing' >earlier.lst

for n in 1 $((size / 4)) $((size / 2)) $((size - 1)); do
    cp earlier.lst out.lst
    (trap '' XFSZ; ulimit -f "$n"; exec "$exe" -o out.lst) >out 2>err
    expect_status 4 $? "-o out.lst, file size limit $n KiB"
    expect_text err 'cannot write the listing to out.lst: File too large' "-o, limit $n KiB"
    expect_text err 'out.lst: left as before' "-o, limit $n KiB"
    no_crash err
    same_content out.lst earlier.lst "-o, limit $n KiB"
    no_part_files .

    (trap '' XFSZ; ulimit -f "$n"; exec "$exe") >stdout.lst 2>err
    expect_status 4 $? "standard output to a file, file size limit $n KiB"
    expect_text err 'cannot write the listing to standard output: File too large' "stdout, limit $n KiB"
    no_crash err
done

# Just enough room: success, and the same listing.
(trap '' XFSZ; ulimit -f $((size + 1)); exec "$exe" -o out.lst) 2>err
expect_status 0 $? "-o out.lst, file size limit $((size + 1)) KiB"
same_content out.lst full.lst "the listing written with just enough room"
pass
