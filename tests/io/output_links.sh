#!/usr/bin/env bash
# Outputs named through symbolic links and hard links (docs/usage.md,
# "Output files"): the file a link points to is written and the link stays,
# also when it points to nothing yet (issue 14, item 11), through chains of
# links and relative targets; -o and --h5 naming one file through a link
# that points to nothing yet are refused; a link into a missing directory
# or a loop of links is an input/output error; the new file keeps the
# permission bits of the one it replaces; other hard links keep the old
# contents; a regular file reached through /dev/stdout (">> log") is added
# to, not overwritten from its start.
#
# Usage: output_links.sh HSRI2D WORK_DIRECTORY
test_name=io_output_links
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

# A short run: 11 print records of the default deck.
time_deck short.deck 0.05 0.005
"$exe" @default short.deck -o reference.lst --h5 reference.h5 2>err || fail "the reference run failed: $(cat err)"

run_ok() { # what args...
    local what=$1
    shift
    "$exe" @default short.deck "$@" >out 2>err
    expect_status 0 $? "$what"
    no_crash err
    no_part_files .
}

is_link_to() { # link target what
    [ -L "$1" ] || fail "$3: $1 is no longer a symbolic link"
    [ "$(readlink "$1")" = "$2" ] || fail "$3: $1 now points to $(readlink "$1"), not $2"
}

# An existing file through a link: the file replaced, the link kept.
echo 'the old listing' >real.lst
ln -s real.lst link.lst
run_ok "-o link.lst (to real.lst)" -o link.lst
is_link_to link.lst real.lst "-o link.lst"
same_content real.lst reference.lst "-o link.lst"

# A link that points to nothing yet: the file created where it points.
ln -s new.lst dangling.lst
run_ok "-o dangling.lst (to new.lst, absent)" -o dangling.lst
is_link_to dangling.lst new.lst "-o dangling.lst"
[ -f new.lst ] || fail "-o dangling.lst: new.lst was not written"
same_content new.lst reference.lst "-o dangling.lst"

ln -s new.h5 dangling.h5
run_ok "--h5 dangling.h5 (to new.h5, absent)" -o x.lst --h5 dangling.h5
is_link_to dangling.h5 new.h5 "--h5 dangling.h5"
[ -f new.h5 ] || fail "--h5 dangling.h5: new.h5 was not written"
cmp -s new.h5 reference.h5 || fail "--h5 dangling.h5: new.h5 differs from the reference run's file"

# A relative target is taken from the link's directory; a chain of links
# that point to nothing yet is followed to its end.
mkdir links targets
ln -s ../targets/far.lst links/rel.lst
run_ok "-o links/rel.lst (to ../targets/far.lst)" -o links/rel.lst
is_link_to links/rel.lst ../targets/far.lst "-o links/rel.lst"
same_content targets/far.lst reference.lst "-o links/rel.lst"
ln -s chain2.lst chain1.lst
ln -s "$PWD/targets/chain3.lst" chain2.lst
run_ok "-o chain1.lst (to chain2.lst to .../chain3.lst)" -o chain1.lst
is_link_to chain1.lst chain2.lst "-o chain1.lst"
is_link_to chain2.lst "$PWD/targets/chain3.lst" "-o chain1.lst"
same_content targets/chain3.lst reference.lst "-o chain1.lst"
no_part_files links
no_part_files targets

# -o and --h5 naming one file, one of them through a link to nothing yet.
ln -s x2.lst xl.lst
"$exe" @default short.deck -o x2.lst --h5 xl.lst >out 2>err
expect_status 1 $? "-o x2.lst --h5 xl.lst (to x2.lst, absent)"
expect_text err '-o and --h5 name the same file: x2.lst and xl.lst' "-o x2.lst --h5 xl.lst"
[ ! -e x2.lst ] || fail "-o x2.lst --h5 xl.lst: x2.lst was created"
is_link_to xl.lst x2.lst "-o x2.lst --h5 xl.lst"
no_part_files .

# A link into a missing directory, a loop of links: status 4, links kept.
ln -s nodir/x.lst lost.lst
"$exe" @default short.deck -o lost.lst >out 2>err
expect_status 4 $? "-o lost.lst (to nodir/x.lst)"
expect_text err 'cannot write the listing to lost.lst: No such file or directory \(directory nodir\)' "-o lost.lst"
is_link_to lost.lst nodir/x.lst "-o lost.lst"
ln -s loop.lst loop.lst
"$exe" @default short.deck -o loop.lst >out 2>err
expect_status 4 $? "-o loop.lst (a loop)"
expect_text err 'cannot write the listing to loop.lst: Too many levels of symbolic links' "-o loop.lst"
is_link_to loop.lst loop.lst "-o loop.lst"
no_part_files .

# Permission bits kept; other hard links keep the old contents.
echo 'the old listing' >kept.lst
chmod 640 kept.lst
ln kept.lst hard.lst
run_ok "-o kept.lst (mode 640, a second hard link)" -o kept.lst
[ "$(stat -c %a kept.lst)" = 640 ] || fail "-o kept.lst: mode $(stat -c %a kept.lst), expected 640"
same_content kept.lst reference.lst "-o kept.lst"
[ "$(cat hard.lst)" = 'the old listing' ] || fail "-o kept.lst: the other hard link hard.lst changed"
chmod 604 real.lst
run_ok "-o link.lst (to real.lst, mode 604)" -o link.lst
[ "$(stat -c %a real.lst)" = 604 ] || fail "-o link.lst: real.lst has mode $(stat -c %a real.lst), expected 604"

# /dev/stdout is written in place; a log appended to (>>) keeps its start.
echo 'the start of the log' >log
"$exe" @default short.deck -o /dev/stdout >>log 2>err
expect_status 0 $? "-o /dev/stdout >>log"
[ "$(head -n 1 log)" = 'the start of the log' ] || fail "-o /dev/stdout >>log: the log's first line was overwritten"
tail -n +2 log >log.tail
same_content log.tail reference.lst "-o /dev/stdout >>log"
pass
