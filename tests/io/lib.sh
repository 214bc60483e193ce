# Helpers shared by the tests in tests/io (sourced by bash, not run).
#
# Each test is a bash script: test_name is set before sourcing, the
# work directory is emptied by start_work, fail ends the test.

set -u

fail() {
    echo "$test_name: FAIL: $*" >&2
    exit 1
}

skip() {
    echo "$test_name: skipped: $*" >&2
    exit 77
}

pass() {
    echo "$test_name: PASS"
    exit 0
}

# start_work DIR: an empty work directory, made current.
start_work() {
    rm -rf "$1" && mkdir -p "$1" && cd "$1" || fail "cannot set up $1"
}

# no_crash FILE...: nothing in FILE says that the program crashed or that a
# Fortran runtime error or backtrace reached the user.
no_crash() {
    local f
    for f in "$@"; do
        if grep -E 'Fortran runtime|Backtrace|Error termination|ERROR STOP|Segmentation|Program received|core dumped' \
            "$f" >/dev/null 2>&1; then
            fail "a crash or runtime error reached the user ($f):
$(cat "$f")"
        fi
    done
}

# expect_status WANT GOT WHAT: the exit status, with a word for a signal.
expect_status() {
    if [ "$2" -ne "$1" ]; then
        if [ "$2" -gt 128 ]; then
            fail "$3: killed by signal $(($2 - 128)) (status $2), expected status $1"
        fi
        fail "$3: exit status $2, expected $1"
    fi
}

# expect_text FILE REGEX WHAT: FILE holds a line matching the extended REGEX.
expect_text() {
    grep -E -- "$2" "$1" >/dev/null 2>&1 || fail "$3: expected /$2/ in:
$(cat "$1" 2>/dev/null)"
}

# no_part_files DIR: no temporary output file (*.part) is left in DIR.
no_part_files() {
    local left
    left=$(find "$1" -maxdepth 1 -name '*.part' | head -n 5)
    [ -z "$left" ] || fail "temporary files left: $left"
}

# same_file_content A B WHAT
same_content() {
    cmp -s "$1" "$2" || fail "$3: $1 changed"
}

# A deck replacing *TIME of the default deck: run to TMAX seconds, a record
# every DTPRINT seconds (RK4, DT = 0.0001 s).
time_deck() { # file tmax dtprint
    printf '*TIME\n%12s%10s%10s   1.0E-06        10   1.0E-07   1.0E-09\n' "$2" 0.0001 "$3" >"$1"
}

# Size of a file in 1024-byte blocks (the unit of bash's ulimit -f), rounded down.
kib() {
    echo $(($(wc -c <"$1") / 1024))
}
