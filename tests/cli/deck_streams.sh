#!/usr/bin/env bash
# A deck read from standard input, a pipe, a FIFO or a process substitution
# gives the same listing as the same deck read from a file (docs/usage.md).
#
# usage: deck_streams.sh CASE HSRI2D DECK WORKDIR
#   CASE  stdin_pipe | stdin_slow_pipe | process_substitution | fifo |
#         stdin_empty | stdin_too_large | stdin_errors | stdin_pulse_file
#
# Where the two runs can name their deck alike, the listings are compared
# byte for byte: the file is called "(standard input)" (the name the
# listing gives standard input) or, for the FIFO, has the FIFO's path.
# A process substitution is named /dev/fd/N, so there the listings are
# compared from the parameters to the end, and by length.
set -u
case_name=$1 exe=$(realpath "$2") deck=$(realpath "$3") work=$(realpath -m "$4/$1")
rm -rf "$work"
mkdir -p "$work/file" "$work/stream"

# Failures are kept in a file: the checks also run in subshells and pipelines.
fail() {
  echo "FAIL: $*" | tee -a "$work/failures"
}

# No Fortran runtime error, backtrace or signal may reach the user.
check_clean() {
  if grep -qE 'Fortran runtime|Backtrace|Error termination|ERROR STOP|Segmentation|Program received|SIGSEGV' "$1"; then
    fail "a runtime error reached the user:"
    cat "$1"
  fi
}

# run NAME EXPECTED_STATUS COMMAND...: run in the current directory, keep
# stdout/stderr in $work/NAME.out and .err, check status and cleanliness.
run() {
  local name=$1 expected=$2
  shift 2
  "$@" >"$work/$name.out" 2>"$work/$name.err"
  local status=$?
  if [ "$status" -ne "$expected" ]; then
    fail "$name: exit status $status, expected $expected"
    cat "$work/$name.err"
  fi
  check_clean "$work/$name.err"
}

same_files() {
  if ! cmp "$1" "$2"; then
    fail "$1 and $2 differ"
    diff "$1" "$2" | head -20
  fi
}

# Listings from the parameters to the end, and their lengths, are equal.
same_but_deck_names() {
  sed -n '/^PARAMETERS (C.1/,$p' "$1" >"$1.from_parameters"
  sed -n '/^PARAMETERS (C.1/,$p' "$2" >"$2.from_parameters"
  same_files "$1.from_parameters" "$2.from_parameters"
  if [ "$(wc -l <"$1")" -ne "$(wc -l <"$2")" ]; then
    fail "$1 and $2 differ in length"
  fi
  if ! grep -q '^PARAMETERS (C.1' "$1"; then
    fail "$1 has no parameters page"
  fi
}

# The reference: the deck as a regular file named as standard input is named.
file_listing() {
  cp "$deck" "$work/file/(standard input)"
  (cd "$work/file" && run file 0 "$exe" '(standard input)' -o "$work/file.lst")
}

case $case_name in
stdin_pipe)
  file_listing
  # a different directory, which holds no file of that name
  (cd "$work/stream" && cat "$deck" | run stream 0 "$exe" - -o "$work/stream.lst")
  same_files "$work/file.lst" "$work/stream.lst"
  ;;
stdin_slow_pipe)
  # the writer pauses twice mid-card, the second time after a few bytes: a
  # momentary end of the pipe's data is not its end, and a read of several
  # bytes may find fewer than it asked for
  file_listing
  (cd "$work/stream" && {
    head -c 1000 "$deck"
    sleep 0.2
    tail -c +1001 "$deck" | head -c 7
    sleep 0.2
    tail -c +1008 "$deck"
  } | run stream 0 "$exe" - -o "$work/stream.lst")
  same_files "$work/file.lst" "$work/stream.lst"
  ;;
process_substitution)
  (cd "$work/file" && run file 0 "$exe" "$deck" -o "$work/file.lst")
  (cd "$work/stream" && run stream 0 "$exe" <(cat "$deck") -o "$work/stream.lst")
  same_but_deck_names "$work/file.lst" "$work/stream.lst"
  grep -q '^ DECK    /dev/fd/' "$work/stream.lst" || fail "the listing does not name /dev/fd/N"
  ;;
fifo)
  cp "$deck" "$work/file/in.deck"
  (cd "$work/file" && run file 0 "$exe" in.deck -o "$work/file.lst")
  mkfifo "$work/stream/in.deck"
  cat "$deck" >"$work/stream/in.deck" &
  writer=$!
  (cd "$work/stream" && run stream 0 "$exe" in.deck -o "$work/stream.lst")
  wait "$writer"
  same_files "$work/file.lst" "$work/stream.lst"
  ;;
stdin_empty)
  run empty_file 2 "$exe" - </dev/null
  run empty_pipe 2 "$exe" - < <(true)
  for r in empty_file empty_pipe; do
    grep -qx '(standard input): the deck is empty' "$work/$r.err" || fail "$r: no \"the deck is empty\""
    if grep -q 'card group' "$work/$r.err"; then fail "$r: a cascade of missing groups"; fi
  done
  ;;
stdin_too_large)
  # the 64 MiB limit holds for a stream too (one byte more: about 4 s, Debug)
  head -c $((64 * 1024 * 1024 + 1)) /dev/zero | run large 4 "$exe" --check -
  grep -q '^(standard input): cannot read: more than 64 MiB' "$work/large.err" || fail "no size limit"
  ;;
stdin_errors)
  # problems are located in "(standard input)"; a second "-" is refused
  printf '*TIME\n         abc\n' | run bad 2 "$exe" --check @default -
  grep -q '^(standard input):2: \*TIME card 1, field TMAX (columns 3-12): found "abc"' "$work/bad.err" ||
    fail "the error does not name (standard input):2"
  run twice 1 "$exe" - - </dev/null
  grep -q 'standard input (-) may be named only once' "$work/twice.err" || fail "two '-' not refused"
  ;;
stdin_pulse_file)
  # files named on the cards of a deck from standard input are relative to
  # the current directory
  printf 't, xddot\n0, 0\n0.01, -5\n0.02, 0\n' >"$work/stream/pulse.csv"
  (cd "$work/stream" && printf '*PULSEFILE\npulse.csv\n' | run pulse 0 "$exe" @default - -o "$work/pulse.lst")
  grep -q '^ PULSE   pulse.csv' "$work/pulse.lst" || fail "the listing does not use pulse.csv"
  # a file that cannot be read: an input/output error (docs/usage.md)
  (cd "$work/file" && printf '*PULSEFILE\npulse.csv\n' | run no_pulse 4 "$exe" --check @default -)
  grep -q '^(standard input):2: .*pulse file: pulse.csv: no such file' "$work/no_pulse.err" ||
    fail "a missing pulse file is not reported against (standard input)"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac

if [ -e "$work/failures" ]; then
  exit 1
fi
echo "$case_name: ok"
