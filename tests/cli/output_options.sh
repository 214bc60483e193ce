#!/usr/bin/env bash
# -o and --h5 are never ignored without notice (issue 14, item 25;
# docs/usage.md, "The command line"): each may be given once; `-o -` is
# standard output and `--h5 -` an error; --default-deck, --deck-format and
# --outputs write to -o FILE; an option that would be ignored (--h5 with
# them, a deck with --default-deck, two of the modes) is an error; --check
# checks -o and --h5 against the inputs and creates nothing. --help and
# --version print on standard output whatever else is given.
#
# Usage: output_options.sh HSRI2D WORK_DIRECTORY
test_name=cli_output_options
. "$(dirname "$0")/../io/lib.sh"
exe=$1
start_work "$2"

"$exe" --default-deck >in.deck || fail "cannot print the default deck"
cp in.deck in.copy
"$exe" >stdout.lst 2>err || fail "the default run failed: $(cat err)"

# usage_error REGEX ARGS...: status 1, the message, nothing created, the
# deck untouched.
usage_error() {
    local regex=$1
    shift
    rm -f a b x.lst x.h5 ./-
    "$exe" "$@" >out 2>err
    expect_status 1 $? "$*"
    expect_text err "$regex" "$*"
    no_crash err
    [ ! -s out ] || fail "$*: wrote to standard output"
    for f in a b x.lst x.h5 -; do
        [ ! -e "$f" ] || fail "$*: created $f"
    done
    same_content in.deck in.copy "$*"
    no_part_files .
}

usage_error 'the listing file \(-o, --output\) is named twice; name it once' -o a -o b
usage_error 'the listing file \(-o, --output\) is named twice' -o a --output b
usage_error 'the HDF5 file \(--h5\) is named twice; name it once' --h5 a --h5 b
usage_error 'option --h5 needs a file: an HDF5 file cannot be written to standard output' --h5 -
usage_error '--default-deck reads no deck; "in.deck" would be ignored' --default-deck in.deck
usage_error '--deck-format reads no deck' --deck-format in.deck
usage_error '--default-deck writes no HDF5 file; --h5 would be ignored' --default-deck --h5 x.h5
usage_error '--deck-format writes no HDF5 file' --deck-format --h5 x.h5
usage_error '--outputs writes no HDF5 file' --outputs --h5 x.h5
usage_error '--outputs and --check cannot go together' --check --outputs
usage_error '--default-deck and --outputs cannot go together' --outputs --default-deck -o x.lst
usage_error 'the listing file in.deck is the input deck in.deck' --outputs in.deck -o in.deck
usage_error 'the listing file in.deck is the input deck in.deck' --check in.deck -o in.deck
usage_error 'the HDF5 file in.deck is the input deck in.deck' --check in.deck --h5 in.deck
usage_error '-o and --h5 name the same file' --check -o x.lst --h5 x.lst

# -o -: standard output, no file called "-".
rm -f ./-
"$exe" -o - >dash.lst 2>err
expect_status 0 $? "-o -"
[ ! -e ./- ] || fail "-o - created a file named -"
same_content dash.lst stdout.lst "-o -"

# The printing options write to -o FILE (atomically, like the listing).
for option in --default-deck --deck-format --outputs; do
    "$exe" $option >expected 2>err || fail "$option failed: $(cat err)"
    echo 'an earlier file' >printed
    "$exe" $option -o printed >out 2>err
    expect_status 0 $? "$option -o printed"
    [ ! -s out ] || fail "$option -o printed: wrote to standard output"
    same_content printed expected "$option -o printed"
    no_part_files .
    "$exe" $option -o - >dash 2>err
    expect_status 0 $? "$option -o -"
    same_content dash expected "$option -o -"
done
"$exe" --default-deck -o /dev/full >out 2>err
expect_status 4 $? "--default-deck -o /dev/full"
expect_text err 'cannot write the output to /dev/full: No space left on device' "--default-deck -o /dev/full"

# --check with outputs that are fine: valid, nothing created.
"$exe" --check in.deck -o new.lst --h5 new.h5 >out 2>err
expect_status 0 $? "--check in.deck -o new.lst --h5 new.h5"
expect_text out 'the deck is valid' "--check -o new.lst"
[ ! -e new.lst ] && [ ! -e new.h5 ] || fail "--check created an output"
no_part_files .

# --help and --version: standard output, whatever else is given.
for option in --help --version; do
    "$exe" $option -o x.lst --h5 x.h5 >out 2>err
    expect_status 0 $? "$option -o x.lst --h5 x.lst"
    expect_text out 'hsri2d' "$option -o x.lst"
    [ ! -e x.lst ] && [ ! -e x.h5 ] || fail "$option created a file"
done
pass
