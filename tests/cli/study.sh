#!/usr/bin/env bash
# A study (report C.8; docs/modification.md) as a user runs one: the same
# table and listing in one process and on two worker processes; a study
# stopped part-way resumes and redoes only what is missing; a slice per
# shard and the collect step give the same table; the collect step names
# missing runs (exit 5); one invalid variation is a row, not the study's
# end; a study whose every run is invalid exits 5 with the table; the
# listing of a kept run marks the varied cards; bad study cards are deck
# errors at their card and field.
#
# Usage: study.sh HSRI2D DECKS_DIR STUDY_DECKS_DIR WORK_DIRECTORY
test_name=cli_study
. "$(dirname "$0")/../io/lib.sh"
exe=$1
decks=$2
studies=$3
start_work "$4"
base=$decks/sled_belted.deck

# one process, then two workers: the same bytes
"$exe" --results one "$base" "$studies/oat.deck" >one.lst 2>err || fail "the study failed: $(cat err)"
no_crash err one.lst
expect_text one/results.csv '^run,status,loadtable_2_force,belts_1_phiprime,joints_1_omega,hic15,belt_f,undesired,clip3ms,meets_limits,t_end,reason$' "the table's header"
[ "$(wc -l <one/results.csv)" -eq 8 ] || fail "OAT of 3 + 2 + 1 values and the base: 7 runs expected:
$(cat one/results.csv)"
expect_text one/results.csv '^1,completed,2500,55,70,' "run 1 is the deck itself"
expect_text one/results.csv '^2,completed,1500,55,70,' "run 2 varies the lap belt alone"
expect_text one/results.csv '^6,completed,2500,70,70,' "run 6 varies the lap anchor alone"
expect_text one/results.csv '^7,invalid,2500,55,300,,,,,no,0,".*OMEGA = 300 deg must be less than BOMEGA = 210 deg"$' "an invalid variation is a row with its reason"
expect_text one.lst 'SUMMARY  7 of 7 runs have a result: 6 completed, 0 ended by an end test, 0 failed, 1 invalid' "the listing's summary"
"$exe" --jobs 2 --results two "$base" "$studies/oat.deck" >two.lst 2>err || fail "the study on two workers failed: $(cat err)"
cmp -s one/results.csv two/results.csv || fail "--jobs 2 gave another table:
$(diff one/results.csv two/results.csv)"
cmp -s one.lst two.lst || fail "--jobs 2 gave another listing"

# the table read back by a CSV reader
if command -v python3 >/dev/null; then
    python3 - one/results.csv <<'EOF' || fail "the table is not read by Python's csv module as written"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 7 and rows[6]["status"] == "invalid" and float(rows[1]["loadtable_2_force"]) == 1500.0
EOF
fi

# stopped part-way: rows 2 and 5 missing; the collect step says so, the
# study resumes and redoes those two only (the other rows keep their times)
cp -r one part
rm part/runs/000002.row part/runs/000005.row part/results.csv
touch -d '2001-01-01' part/runs/000001.row
"$exe" --collect --results part "$base" "$studies/oat.deck" >/dev/null 2>err
expect_status 5 $? "--collect with runs missing"
expect_text err 'the study has 2 run\(s\) without a result in part: run 2, run 5' "--collect names the missing runs"
no_crash err
"$exe" --results part "$base" "$studies/oat.deck" >part.lst 2>err || fail "the resumed study failed: $(cat err)"
cmp -s one/results.csv part/results.csv || fail "the resumed study gave another table"
[ "$(date -d @"$(stat -c %Y part/runs/000001.row)" +%Y)" = 2001 ] || fail "the resumed study ran run 1 again"

# two shards and the collect step: the same table
"$exe" --shard 2/2 --results shards "$base" "$studies/oat.deck" >out 2>err || fail "shard 2/2 failed: $(cat err)"
[ ! -s out ] || fail "a shard wrote a listing"
[ ! -e shards/results.csv ] || fail "a shard wrote the table"
"$exe" --shard 1/2 --results shards "$base" "$studies/oat.deck" >/dev/null 2>err || fail "shard 1/2 failed"
"$exe" --collect --results shards "$base" "$studies/oat.deck" >shards.lst 2>err || fail "collect failed: $(cat err)"
cmp -s one/results.csv shards/results.csv || fail "the shards' merged table differs"
[ "$("$exe" --study-size "$base" "$studies/oat.deck")" = 7 ] || fail "--study-size"

# a results directory of another study is refused, never mixed
"$exe" --results one "$base" "$studies/grid.deck" >/dev/null 2>err
expect_status 1 $? "another study's directory"
expect_text err 'one holds the results of another study' "another study's directory"

# every run invalid: exit 5, the table written all the same
"$exe" --results bad "$base" "$studies/all_invalid.deck" >bad.lst 2>err
expect_status 5 $? "a study whose every run is invalid"
expect_text err 'every run of the study failed or was invalid' "every run invalid"
[ "$(grep -c ',invalid,' bad/results.csv)" -eq 2 ] || fail "the invalid runs' rows"
no_crash err bad.lst

# bad study cards: deck errors at their card and field
printf '*STUDY\n    RANDOM        10\n*VARY\n 1 BELTS             1 SLOPE           1.        2.\n' >bad_cards.deck
"$exe" "$base" bad_cards.deck >/dev/null 2>err
expect_status 2 $? "bad study cards"
expect_text err 'bad_cards.deck:2: \*STUDY card 1, field SEED \(columns 23-32\): METHOD RANDOM draws at random: give a SEED' "a seed missing"
expect_text err 'bad_cards.deck:4: \*VARY card 1, fields GROUP \(columns 3-17\), CARD \(columns 18-22\) and FIELD \(columns 23-32\): \*BELTS has no field SLOPE; its fields are: H, LENGTH, PHI, LPRIME, PHIPRIME, SLACK' "a field that does not exist"
printf '*STUDY\n      GRID\n*VARY\n 1 BELTS             1 SLACK\n*VALUES\n 1       0.1      -0.5\n' >bad_value.deck
"$exe" "$base" bad_value.deck >/dev/null 2>err
expect_status 2 $? "a value outside its field's range"
expect_text err 'bad_value.deck:6: \*VALUES card 1, field V2 \(columns 13-22\): value -0.5 is outside the range of \*BELTS 1 SLACK' "a value outside its field's range"
printf '*STUDY\n      GRID\n*VARY\n 1 BELTS             1 SLACK      0.1       0.2         2\n*CRITERIA\n     HIC15         2\n' >bad_occupant.deck
"$exe" "$base" bad_occupant.deck >/dev/null 2>err
expect_status 2 $? "a criterion of an occupant the model does not have"
expect_text err 'bad_occupant.deck:6: \*CRITERIA card 1, field OCC \(columns 13-22\): the deck.s model has 1 occupant\(s\); there is no occupant 2' "a criterion's occupant"
printf '*STUDY\n      GRID\n*VARY\n 1 SEATS             1 K\n' >bad_group.deck
"$exe" "$base" bad_group.deck >/dev/null 2>err
expect_status 2 $? "a group that does not exist"
expect_text err 'bad_group.deck:4: \*VARY card 1, field GROUP \(columns 3-17\): found "SEATS"' "a group that does not exist"
no_crash err
"$exe" - <"$studies/oat.deck" >/dev/null 2>err
expect_status 2 $? "a study on standard input alone"
cat "$base" "$studies/oat.deck" | "$exe" - >/dev/null 2>err
expect_status 1 $? "a study on standard input"
expect_text err 'a study deck \(\*STUDY, report C.8\) is run from regular files' "a study on standard input"
"$exe" --refine "$decks/study_restraint.deck" >/dev/null 2>err
expect_status 1 $? "--refine on a study deck"
expect_text err 'nor by --refine or --outputs' "--refine on a study deck"

# progress on standard error only when it is a terminal (script(1) gives one)
"$exe" --results quiet "$base" "$studies/lhs.deck" -o /dev/null 2>err || fail "the hypercube failed: $(cat err)"
[ ! -s err ] || fail "progress written where standard error is not a terminal: $(cat err)"
if command -v script >/dev/null; then
    script -qec "$exe --jobs 2 --results tty $base $studies/lhs.deck -o /dev/null" /dev/null >tty.out 2>&1 \
        || fail "the study on a terminal failed: $(cat tty.out)"
    expect_text tty.out 'hsri2d: study: 4 of 4 runs done, 0 failed, 0 remaining' "progress on a terminal"
fi

# a run the program cannot vouch for carries its warning in its row
"$exe" --results coarse "$base" "$studies/coarse_step.deck" >coarse.lst 2>err || fail "the coarse study failed: $(cat err)"
expect_text coarse/results.csv '^1,completed,2,0.0025,.*"warning: .*DT = 0.0025 s \(\*TIME\) is too large for this deck' "the row's warning"
expect_text coarse.lst 'warning: .*is too large for this deck' "the listing's warning"

# ENSEMBLE: the deck, then seeded perturbations within the field's range;
# the listing's statistics of each criterion; the same seed, the same runs
"$exe" --results ens "$base" "$studies/ensemble.deck" >ens.lst 2>err || fail "the ensemble failed: $(cat err)"
[ "$(wc -l <ens/results.csv)" -eq 6 ] || fail "ENSEMBLE RUNS 5: 5 rows expected"
expect_text ens/results.csv '^1,completed,2500,55,' "the ensemble's run 1 is the deck"
[ "$(cut -d, -f4 ens/results.csv | sort -u | wc -l)" -eq 6 ] || fail "the anchor angle (no LOW, HIGH) was not perturbed:
$(cat ens/results.csv)"
expect_text ens.lst '^   hic15 +5 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+$' "the ensemble's statistics"
"$exe" --results ens2 "$base" "$studies/ensemble.deck" >/dev/null 2>err || fail "the ensemble again failed"
cmp -s ens/results.csv ens2/results.csv || fail "the same seed gave other runs"
"$exe" --results lhs "$base" "$studies/lhs.deck" >/dev/null 2>err || fail "the hypercube failed: $(cat err)"
python3 - lhs/results.csv <<'EOF' || fail "LHS: not one run per stratum"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 4
for col, lo, hi in (("loadtable_2_force", 1500, 3500), ("belts_1_phiprime", 40, 70)):
    strata = sorted(int((float(r[col]) - lo) / (hi - lo) * 4) for r in rows)
    assert strata == [0, 1, 2, 3], (col, strata)
EOF

# a kept run's listing marks the cards the study set; its HDF5 file holds the
# same numbers, bit for bit, as the variation's deck run by a process of its own
sed "s/^       OAT\$/       OAT$(printf '%58s' '')BOTH/" "$studies/oat.deck" >keep.deck
"$exe" --results keep "$base" keep.deck >/dev/null 2>err || fail "the study keeping listings failed: $(cat err)"
[ -s keep/runs/000002.lst ] || fail "KEEP BOTH wrote no listing of run 2"
[ -s keep/runs/000002.h5 ] || fail "KEEP BOTH wrote no HDF5 file of run 2"
expect_text keep/runs/000002.lst '^ +[0-9]+  V  .*sled_belted.deck:131 +1 +1\. +1500$' "run 2's listing marks the varied card"
expect_text keep/runs/000002.lst 'V = card with a field the study set for this run' "the mark is explained"
sed '131s/^ 1        1\.     2500\.$/ 1        1.      1500/' "$base" >variation.deck
cmp -s "$base" variation.deck && fail "the variation deck was not made"
"$exe" variation.deck --h5 variation.h5 -o variation.lst 2>err || fail "the variation's own run failed: $(cat err)"
if python3 -c 'import h5py' 2>/dev/null; then
    python3 - keep/runs/000002.h5 variation.h5 <<'EOF' || fail "a study's run and the same deck's own process differ"
import sys
import h5py
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
names = []
a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
assert len(names) > 20
for n in names:
    if n == "input/deck":
        continue
    x, y = a[n][()], b[n][()]
    assert x.shape == y.shape and (x.tobytes() == y.tobytes()), n
EOF
fi
no_part_files keep/runs

# the table in HDF5 (/study), the same numbers as results.csv
"$exe" --collect --results one --h5 one.h5 "$base" "$studies/oat.deck" >/dev/null 2>err || fail "--collect --h5 failed: $(cat err)"
if python3 -c 'import h5py' 2>/dev/null; then
    python3 - one.h5 one/results.csv <<'EOF' || fail "/study differs from results.csv"
import csv, math, sys
import h5py
f = h5py.File(sys.argv[1], "r")
rows = list(csv.DictReader(open(sys.argv[2])))
st = f["study"]
assert list(st["run"][:]) == [float(r["run"]) for r in rows]
assert list(st["status"][:]) == [1, 1, 1, 1, 1, 1, 4]
cols = [c.decode() if isinstance(c, bytes) else c for c in st["criteria"].attrs["columns"]]
for i, r in enumerate(rows):
    for j, c in enumerate(cols):
        v = st["criteria"][i, j]
        assert (math.isnan(v) and r[c] == "") or v == float(r[c]), (i, c, v, r[c])
    assert list(st["values"][i]) == [float(r["loadtable_2_force"]), float(r["belts_1_phiprime"]), float(r["joints_1_omega"])]
assert len(f["input/deck"]) > 100
EOF
fi

# an output never overwrites an input
cp "$base" base_copy.deck
"$exe" --results over -o base_copy.deck base_copy.deck "$studies/oat.deck" >/dev/null 2>err
expect_status 1 $? "a listing over the deck"
expect_text err 'refusing to overwrite it' "a listing over the deck"
same_content "$base" base_copy.deck "a listing over the deck"
pass
