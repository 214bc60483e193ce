#!/usr/bin/env bash
# A study of report Section D's analog (C.8; docs/analog.md, "When do they
# meet"): decks/study_analog.deck gives the same table and listing in one
# process and on two worker processes; its rows are the plain analog runs'
# figures at the same values; OAT (each run kept: its own listing and HDF5
# file), RANDOM, LHS, ENSEMBLE and OPTIMIZE (the least damping that keeps
# the occupants apart) run on an analog deck; an occupant's criterion on an
# analog deck is a deck error at its card and field.
#
# Usage: analog_study.sh HSRI2D DECKS_DIR STUDY_DECKS_DIR WORK_DIRECTORY
test_name=cli_analog_study
. "$(dirname "$0")/../io/lib.sh"
exe=$1
decks=$2
studies=$3
start_work "$4"

# the shipped study, one process and two workers: the same bytes
"$exe" --results one "$decks/study_analog.deck" >one.lst 2>err || fail "the study failed: $(cat err)"
no_crash err one.lst
expect_text one/results.csv '^run,status,analog_1_zeta,analog_1_l,meet,t_meet,sep_min,meets_limits,t_end,reason$' \
    "the table's header"
[ "$(wc -l <one/results.csv)" -eq 50 ] || fail "GRID of 7 damping ratios and 7 spacings: 49 runs expected"
expect_text one.lst 'SUMMARY  49 of 49 runs have a result: 49 completed' "the listing's summary"
"$exe" --jobs 2 --results two "$decks/study_analog.deck" >two.lst 2>err || fail "two workers failed: $(cat err)"
cmp -s one/results.csv two/results.csv || fail "--jobs 2 gave another table:
$(diff one/results.csv two/results.csv)"
cmp -s one.lst two.lst || fail "--jobs 2 gave another listing"
[ "$("$exe" --study-size "$decks/study_analog.deck")" = 49 ] || fail "--study-size"

# the rows at the shipped decks' values are those decks' plain runs: the
# report's undamped case meets (its listing's first contact), the critically
# damped one never does (its least separation)
"$exe" "$decks/analog_undamped.deck" >undamped.lst 2>err || fail "the undamped deck failed: $(cat err)"
"$exe" "$decks/analog_damped.deck" >damped.lst 2>err || fail "the damped deck failed: $(cat err)"
python3 - one/results.csv undamped.lst damped.lst <<'EOF' || fail "the study's rows differ from the plain runs"
import csv, re, sys
rows = {(float(r["analog_1_zeta"]), float(r["analog_1_l"])): r for r in csv.DictReader(open(sys.argv[1]))}
def summary(path):
    text = open(path).read()
    part = text[text.index("SUMMARY OF THE CASES"):]
    for line in part.splitlines():
        f = line.split()
        if len(f) >= 10 and f[0] == "1":
            return f
    raise SystemExit(f"no case 1 in the summary of {path}")
u, d = summary(sys.argv[2]), summary(sys.argv[3])
ru, rd = rows[(0.0, 34.0)], rows[(1.0, 34.0)]
assert u[9] == "YES" and ru["meet"] == "1", (u, ru)
# the listing's digits of the first contact
assert f"{float(ru['t_meet']):.{len(u[10].split('.')[1])}f}" == u[10], (u[10], ru["t_meet"])
assert d[9] == "NO" and rd["meet"] == "0" and rd["t_meet"] == "NaN", (d, rd)
assert f"{float(rd['sep_min']):.{len(d[-2].split('.')[1])}f}" == d[-2], (d[-2], rd["sep_min"])
EOF

# every method on an analog deck (the undamped deck, then the study's cards)
base=$decks/analog_undamped.deck
"$exe" --results oat "$base" "$studies/analog_oat.deck" >oat.lst 2>err || fail "OAT failed: $(cat err)"
no_crash err oat.lst
[ "$(wc -l <oat/results.csv)" -eq 9 ] || fail "OAT of 3 + 2 + 2 values and the deck: 8 runs expected"
expect_text oat/results.csv '^1,completed,0,34,20,1,0\.06429858' "OAT's run 1 is the deck"
expect_text oat/results.csv '^8,completed,0,34,25,1,' "OAT varies the speed (mph) alone"
expect_text oat.lst 'SUMMARY  8 of 8 runs have a result: 8 completed, 0 ended by an end test, 0 failed, 0 invalid; 3 meet the limits' \
    "OVERLAP at most 0: the runs that stay apart"
# a kept run's own listing and HDF5 file are the analog's, its varied card marked
expect_text oat/runs/000007.lst 'ANALOG OF SECTION D: CASE 1' "a kept run's listing"
expect_text oat/runs/000007.lst ' V  .*undamped\.deck:17 +15 1470\.59' "the kept listing's card holds the run's speed"
[ -s oat/runs/000007.h5 ] || fail "a kept run's HDF5 file"
"$exe" --results random "$base" "$studies/analog_random.deck" >random.lst 2>err || fail "RANDOM failed: $(cat err)"
expect_text random/results.csv '^run,status,analog_1_zeta,analog_1_l,meet,t_meet,sep_min,' "RANDOM's default criteria"
[ "$(grep -c ',completed,' random/results.csv)" -eq 6 ] || fail "RANDOM: 6 runs expected"
"$exe" --results lhs "$base" "$studies/analog_lhs.deck" >lhs.lst 2>err || fail "LHS failed: $(cat err)"
python3 - lhs/results.csv <<'EOF' || fail "LHS: not one run per stratum"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 5
for col, lo, hi in (("analog_1_zeta", 0, 1), ("analog_1_l", 30, 40)):
    assert sorted(int((float(r[col]) - lo) / (hi - lo) * 5) for r in rows) == [0, 1, 2, 3, 4], col
EOF
"$exe" --results ensemble "$base" "$studies/analog_ensemble.deck" >ensemble.lst 2>err || fail "ENSEMBLE failed: $(cat err)"
expect_text ensemble/results.csv '^1,completed,34,0\.06429858' "the ensemble's run 1 is the deck"
[ "$(grep -c ',completed,' ensemble/results.csv)" -eq 4 ] || fail "ENSEMBLE: 4 runs expected"

# OPTIMIZE: the least damper c that keeps them apart at 34 in, from the
# critically damped deck; the boundary lies at ZETA 0.26777 (docs/analog.md)
"$exe" --results optimize "$decks/analog_damped.deck" "$studies/analog_optimize.deck" >optimize.lst 2>err \
    || fail "OPTIMIZE failed: $(cat err)"
expect_text optimize.lst '^ BEST     run [0-9]+: CDAMP = 13\.0[6-9][0-9]* within the limits, at analog_1_zeta = 0\.26(78|79|80)' \
    "OPTIMIZE's least damping"

# an occupant's criterion on an analog deck: a deck error at its card and field
printf '*STUDY\n      GRID\n*VARY\n 1 ANALOG            1 ZETA             0.        1.         2\n*CRITERIA\n     HIC15\n' \
    >bad_crit.deck
"$exe" "$base" bad_crit.deck >/dev/null 2>err
expect_status 2 $? "an occupant's criterion on an analog deck"
expect_text err 'bad_crit.deck:6: \*CRITERIA card 1, field CRIT \(columns 3-12\): HIC15 is a criterion of the occupant simulation; a deck with \*ANALOG \(report Section D\) is judged by MEET, TMEET, SEPMIN, OVERLAP or CDAMP' \
    "an occupant's criterion on an analog deck"
no_crash err

# --mme on an analog deck: a usage error, nothing written (it has no channels)
"$exe" --mme mme_out "$decks/analog_undamped.deck" -o mme.lst 2>err
expect_status 1 $? "--mme on an analog deck"
expect_text err 'an analog deck \(\*ANALOG\) has no channels to write as an ISO-MME data set; --mme would be ignored' \
    "--mme on an analog deck"
[ ! -e mme_out ] || fail "--mme on an analog deck made its folder"
no_crash err
pass
