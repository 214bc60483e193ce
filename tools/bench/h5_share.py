#!/usr/bin/env python3
"""The HDF5 file's share of a whole run (docs/performance.md, "The HDF5 file's cost").

    tools/bench/h5_share.py EXE[,EXE...] ROUNDS DECK [LISTING]

For each round and each program: `EXE DECK -o LISTING` (default /dev/null), then
`EXE DECK -o LISTING --h5 FILE` (a fresh FILE in a temporary directory); CPU time
(user + system) of each child from getrusage; prints the medians and the share.
"""
import os
import statistics
import subprocess
import sys
import tempfile


def cpu_ms(args):
    p = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit(f"h5_share: {' '.join(args)} failed")
    return (ru.ru_utime + ru.ru_stime) * 1000.0, ru.ru_stime * 1000.0


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    exes, rounds, deck = sys.argv[1].split(','), int(sys.argv[2]), sys.argv[3]
    listing = sys.argv[4] if len(sys.argv) > 4 else '/dev/null'
    with tempfile.TemporaryDirectory() as work:
        h5 = os.path.join(work, 'out.h5')
        res = {(e, h): [] for e in exes for h in (False, True)}
        for _ in range(rounds):
            for e in exes:
                res[(e, False)].append(cpu_ms([e, deck, '-o', listing]))
                if os.path.exists(h5):
                    os.remove(h5)
                res[(e, True)].append(cpu_ms([e, deck, '-o', listing, '--h5', h5]))
    for e in exes:
        a = statistics.median(t for t, _ in res[(e, False)])
        b = statistics.median(t for t, _ in res[(e, True)])
        sa = statistics.median(s for _, s in res[(e, False)])
        sb = statistics.median(s for _, s in res[(e, True)])
        print(f"{e}: without --h5 {a:.1f} ms (system {sa:.1f}), with {b:.1f} ms (system {sb:.1f}): "
              f"+{b - a:.1f} ms, {100 * (b - a) / a:.0f} % of the run without, {100 * (b - a) / b:.0f} % of the run with")


if __name__ == '__main__':
    main()
