#!/usr/bin/env bash
# A stand-in for hsri2d's study command line, for developing the cluster
# scripts before the study lands (issue 17, section 3). NOT a test and not
# registered: tests/cluster/*.sh run against the real hsri2d. It keeps the
# contract trivially: the study's size is the deck's line "RUNS n" (23 when
# there is none); run r's row is "r,value,status" computed from r.
#
#   fake_hsri2d.sh --study-size DECK
#   fake_hsri2d.sh --results DIR [--shard K/N | --collect] [--jobs N] [-o FILE] DECK
set -u
results='' shard='' collect=no listing='' deck='' size_only=no
while [ $# -gt 0 ]; do
    case $1 in
        --results) results=$2; shift 2 ;;
        --shard) shard=$2; shift 2 ;;
        --collect) collect=yes; shift ;;
        --jobs) shift 2 ;;
        -o) listing=$2; shift 2 ;;
        --study-size) size_only=yes; shift ;;
        -*) echo "fake_hsri2d: unknown option $1" >&2; exit 2 ;;
        *) deck=$1; shift ;;
    esac
done
[ -r "$deck" ] || { echo "fake_hsri2d: cannot read the deck '$deck'" >&2; exit 2; }
runs=$(sed -n 's/^RUNS *\([0-9]*\).*/\1/p' "$deck" | head -n 1)
runs=${runs:-23}
if [ $size_only = yes ]; then echo "$runs"; exit 0; fi
[ -n "$results" ] || { echo "fake_hsri2d: a study needs --results DIR" >&2; exit 2; }
mkdir -p "$results/runs" || exit 4

k=1 n=1
if [ -n "$shard" ]; then k=${shard%/*} n=${shard#*/}; fi
if [ $collect = no ]; then
    for ((r = 1; r <= runs; r++)); do
        [ $(((r - 1) % n)) -eq $((k - 1)) ] || continue
        row=$(printf '%s/runs/%06d.row' "$results" $r)
        [ -f "$row" ] && continue
        status=completed
        [ $((r % 7)) -eq 0 ] && status=failed
        printf '%d,%d.%03d,%s\n' $r $((r * r % 97)) $((r * 37 % 1000)) $status >"$row.tmp" &&
            mv "$row.tmp" "$row" || exit 4
    done
    [ -n "$shard" ] && exit 0
fi

missing=()
for ((r = 1; r <= runs; r++)); do
    [ -f "$(printf '%s/runs/%06d.row' "$results" $r)" ] || missing+=($r)
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "fake_hsri2d: ${#missing[@]} runs missing: ${missing[*]}" >&2
    exit 5
fi
{
    echo 'run,value,status'
    for ((r = 1; r <= runs; r++)); do cat "$(printf '%s/runs/%06d.row' "$results" $r)"; done
} >"$results/results.csv.tmp" && mv "$results/results.csv.tmp" "$results/results.csv" || exit 4
text="STUDY $deck: $runs runs"
if [ -n "$listing" ]; then echo "$text" >"$listing"; else echo "$text"; fi
