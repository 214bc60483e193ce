#!/usr/bin/env bash
# An output that is one of the run's inputs is refused with status 1 before
# anything is written: the listing or the HDF5 file naming an input deck or
# the CSV pulse file (by inode, through a symbolic link, by another spelling
# of the path), -o and --h5 naming one file, standard output redirected to
# the HDF5 file or appended to a deck, and the same for a deck read from
# standard input (-): -o or --h5 naming the file on standard input
# (/dev/stdin, /dev/fd/0, /proc/self/fd/0), standard output appended to it,
# and standard input a pipe that -o would write back into. The inputs stay
# as they were and no output file is created.
#
# Usage: output_is_input.sh HSRI2D WORK_DIRECTORY
test_name=io_output_is_input
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

"$exe" --default-deck >in.deck || fail "cannot write the default deck"
printf 't,xddot\n0,0\n0.05,-20\n0.1,-20\n0.15,0\n0.3,0\n' >pulse.csv
printf '*PULSEFILE\npulse.csv\n' >csv.deck
mkdir sub
ln -s in.deck link.deck
cp in.deck in.copy
cp pulse.csv pulse.copy
"$exe" @default csv.deck -o check.lst 2>err || fail "the CSV deck does not run: $(cat err)"
rm -f check.lst

refused() { # regex args...
    local regex=$1
    shift
    "$exe" "$@" >out 2>err
    expect_status 1 $? "$*"
    expect_text err "$regex" "$*"
    no_crash err
    same_content in.deck in.copy "$*"
    same_content pulse.csv pulse.copy "$*"
    no_part_files .
    [ ! -e out.h5 ] && [ ! -e out.lst ] || fail "$*: an output was created"
}

refused 'the listing file in.deck is the input deck in.deck' in.deck -o in.deck
refused 'the HDF5 file in.deck is the input deck in.deck' in.deck --h5 in.deck
refused 'the listing file .*in.deck is the input deck' in.deck -o "$PWD/in.deck"
refused 'the listing file sub/../in.deck is the input deck' in.deck -o sub/../in.deck
refused 'the listing file link.deck is the input deck in.deck' in.deck -o link.deck
refused 'the HDF5 file in.deck is the input deck link.deck' link.deck --h5 in.deck
refused 'the listing file pulse.csv is the pulse file pulse.csv' @default csv.deck -o pulse.csv
refused 'the HDF5 file pulse.csv is the pulse file pulse.csv' @default csv.deck --h5 pulse.csv
refused 'the listing file csv.deck is the input deck csv.deck' @default csv.deck -o csv.deck
refused '-o and --h5 name the same file' -o out.x --h5 out.x
refused '-o and --h5 name the same file' -o sub/../out.x --h5 out.x
[ ! -e out.x ] || fail "out.x was created"

# Standard output redirected to the HDF5 file.
"$exe" --h5 out.h5 >out.h5 2>err
expect_status 1 $? "--h5 out.h5 >out.h5"
expect_text err 'standard output is the HDF5 file out.h5' "--h5 out.h5 >out.h5"
no_part_files .
rm -f out.h5

# Standard output appended to the deck it reads.
"$exe" in.deck >>in.deck 2>err
expect_status 1 $? "in.deck >>in.deck"
expect_text err 'standard output is the input deck in.deck' "in.deck >>in.deck"
same_content in.deck in.copy "in.deck >>in.deck"

# A deck read from standard input (issue 14, item 8): refused as for a named
# deck, the deck untouched.
stdin_refused() { # regex args... (standard input: in.deck)
    local regex=$1
    shift
    "$exe" "$@" <in.deck >out 2>err
    expect_status 1 $? "$* <in.deck"
    expect_text err "$regex" "$* <in.deck"
    no_crash err
    same_content in.deck in.copy "$* <in.deck"
    no_part_files .
}
for name in /dev/stdin /dev/fd/0 /proc/self/fd/0; do
    stdin_refused "the listing file $name is the input deck \(standard input\); refusing" - -o "$name"
    stdin_refused "the HDF5 file $name is the input deck \(standard input\); refusing" - --h5 "$name" -o out.lst
    stdin_refused "the listing file $name is the input deck \(standard input\)" @default - -o "$name"
done
[ ! -e out.lst ] || fail "out.lst was created"

# Standard output appended to the deck read from standard input.
"$exe" - <in.deck >>in.deck 2>err
expect_status 1 $? "- <in.deck >>in.deck"
expect_text err 'standard output is the input deck \(standard input\); refusing' "- <in.deck >>in.deck"
same_content in.deck in.copy "- <in.deck >>in.deck"

# Standard input a pipe: -o /dev/stdin would write into the pipe the deck
# came through (nobody reads it: the run would block once it is full).
cat in.deck | timeout 60 "$exe" - -o /dev/stdin >out 2>err
expect_status 1 "${PIPESTATUS[1]}" "cat in.deck | - -o /dev/stdin"
expect_text err 'the listing file /dev/stdin is the input deck \(standard input\)' "a pipe on standard input"

pass
