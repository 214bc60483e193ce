#!/usr/bin/env bash
# tools/listdiff (issue 18): identical listings, numbers within the
# tolerances, a number beyond them, listings that differ only in a date or
# the program's version, a word changed, a missing file and a missing
# numdiff, each with its exit status (0 the same, 1 they differ, 2 trouble).
#
#   listdiff_check.sh LISTDIFF ARCHIVED.lst WORKDIR
set -uo pipefail
listdiff=$1 archived=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fails=0
expect() {   # expect STATUS PATTERN DESCRIPTION -- COMMAND...
  local want=$1 pattern=$2 what=$3
  shift 4
  local out status
  out=$("$@" 2>&1)
  status=$?
  if [ "$status" -ne "$want" ]; then
    echo "FAIL: $what: status $status, expected $want"; printf '%s\n' "$out" | head -n 8; fails=$((fails + 1))
  elif [ -n "$pattern" ] && ! printf '%s\n' "$out" | grep -q -E -- "$pattern"; then
    echo "FAIL: $what: no \"$pattern\" in:"; printf '%s\n' "$out" | head -n 8; fails=$((fails + 1))
  else
    echo "ok: $what (status $status)"
  fi
}
cp "$archived" a.lst
# a line with a number to change: the first of the deck echo's numeric cards
line=$(grep -n -m1 -E '^ +[0-9]+ +[^ ]+:[0-9]+ +[0-9]+ +[0-9]*\.[0-9]+' a.lst | cut -d: -f1)
[ -n "$line" ] || { echo "FAIL: no numeric card in $archived"; exit 1; }
number=$(sed -n "${line}p" a.lst | awk '{print $4}')
echo "changing $number on line $line"
python3 - "$number" "$line" <<'PY'
import sys
num, line = sys.argv[1], int(sys.argv[2])
rows = open("a.lst", encoding="utf-8").read().split("\n")
v = float(num)
def put(name, new):
    r = list(rows)
    i = r[line - 1].index(" " + num) + 1
    r[line - 1] = r[line - 1][:i] + new + r[line - 1][i + len(num):]
    open(name, "w", encoding="utf-8").write("\n".join(r))
put("within.lst", repr(v * (1 + 3e-7)))      # relative 3e-7 < 1e-6
put("beyond.lst", repr(v * (1 + 3e-5)))      # relative 3e-5 > 1e-6
# the same listing printed on another day, at another time, by another version
dated = [r.replace("HSRI-2D 0.1.0", "HSRI-2D 9.8.7-rc1") for r in rows]
a = list(rows); a.insert(3, " RUN     2026-11-28 01:57:15 (Sat Nov 28 01:57:15 UTC 2026)")
b = list(dated); b.insert(3, " RUN     2027-01-02 23:04:05 (Sat Jan  2 23:04:05 UTC 2027)")
open("dated_a.lst", "w", encoding="utf-8").write("\n".join(a))
open("dated_b.lst", "w", encoding="utf-8").write("\n".join(b))
r = list(rows); r[0] = r[0].replace("PAGE 1", "PAGE 9")
open("page.lst", "w", encoding="utf-8").write("\n".join(r))
r = list(rows); r[line - 1] = r[line - 1].replace("deck:", "DECK:", 1)
open("word.lst", "w", encoding="utf-8").write("\n".join(r))
PY
expect 0 ""            "identical listings"             -- "$listdiff" a.lst a.lst
expect 0 ""            "a number within the tolerances" -- "$listdiff" a.lst within.lst
expect 1 "##$line "    "a number beyond the tolerances" -- "$listdiff" a.lst beyond.lst
expect 1 ""            "-q: status only"                -- "$listdiff" -q a.lst beyond.lst
expect 0 ""            "a wider tolerance (-r 1e-4)"    -- "$listdiff" -r 1e-4 a.lst beyond.lst
expect 0 ""            "only the date and version differ" -- "$listdiff" dated_a.lst dated_b.lst
expect 1 ""            "a page number differs"          -- "$listdiff" a.lst page.lst
expect 1 ""            "a word differs"                 -- "$listdiff" a.lst word.lst
expect 2 "no such readable file" "a missing file"       -- "$listdiff" a.lst missing.lst
expect 2 "not a tolerance" "a bad tolerance"            -- "$listdiff" -r x a.lst a.lst
expect 2 "usage"       "one file only"                  -- "$listdiff" a.lst
# no numdiff on the PATH: a PATH of the other tools the script uses
mkdir -p nonumdiff
for tool in bash sed mktemp rm grep cat dirname; do
  ln -sf "$(command -v "$tool")" nonumdiff/"$tool"
done
expect 2 "needs numdiff \\(Debian package numdiff" "numdiff missing" -- \
  env -u NUMDIFF PATH="$work/nonumdiff" bash "$listdiff" a.lst a.lst
[ "$fails" -eq 0 ] && echo "listdiff: every case as expected"
exit $(( fails > 0 ))
