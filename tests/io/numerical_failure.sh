#!/usr/bin/env bash
# A numerical failure (status 3) still delivers the listing and the HDF5
# file, up to the failure, at their targets (no temporary file left).
#
# Usage: numerical_failure.sh HSRI2D WORK_DIRECTORY
test_name=io_numerical_failure
. "$(dirname "$0")/lib.sh"
exe=$1
start_work "$2"

# Cubic stops of 1e12 with a 2 ms RK4 step: the integration diverges at 0.07 s
# (the energy balance is let go on, so that the divergence ends the run).
{
    printf '*OPTIONS\n           1         3         1         2         3         2\n'
    printf '*TIME\n         0.2     0.002     0.002   1.0E-06        10   1.0E-07   1.0E-09\n'
    printf '*NUMERICS\n%40s\n*RESTRAINTS\n' CONTINUE
    for j in 1 2 3 4 5 6 7; do
        printf '%2dCUBIC        1.0E+12   1.0E+12   1.0E+12   1.0E+12\n' $j
    done
} >blowup.deck
echo 'the earlier listing' >out.lst
"$exe" @default blowup.deck -o out.lst --h5 out.h5 >out 2>err
expect_status 3 $? "the diverging run"
expect_text err 'numerical failure' "the diverging run"
no_crash err
expect_text out.lst 'integration stopped after t =' "the delivered listing"
[ -s out.h5 ] || fail "out.h5 was not delivered"
no_part_files .
pass
