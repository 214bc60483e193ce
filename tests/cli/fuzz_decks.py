#!/usr/bin/env python3
"""Feed hsri2d malformed decks of every kind and check that each ends with a
clear deck or input/output error - exit status 2 or 4 and a message on
standard error - and never with a Fortran runtime error, a backtrace, a
signal or a hang.

usage: fuzz_decks.py HSRI2D DEFAULT_DECK WORKDIR
"""
import os
import random
import subprocess
import sys

FORBIDDEN = ("Fortran runtime", "Backtrace", "Error termination", "ERROR STOP",
             "Segmentation", "Program received", "SIGSEGV")


def cases(base_lines, rnd):
    """Yield (name, bytes) pairs: fixed hostile inputs, then random mutations."""
    base = "\n".join(base_lines) + "\n"
    yield "empty", b""
    yield "newlines_only", b"\n\n\n"
    yield "binary", bytes(rnd.randrange(256) for _ in range(4096))
    yield "nul_bytes", b"*TIME\n\0\0\0\0\n"
    yield "one_huge_line", b"*TIME\n" + b"9" * 1_000_000 + b"\n"
    yield "many_groups", ("*TITLE\nx\n" * 5000).encode()
    yield "truncated_mid_card", base.encode()[: len(base) // 2 + 7]
    yield "no_final_newline", base.rstrip("\n").encode()
    yield "crlf", base.replace("\n", "\r\n").encode()
    yield "utf8", base.replace("DEFAULT", "DÉFAUT").encode("utf-8")
    yield "nan_inf", base.replace("0.2 ", "NaN ").replace("386.", "Inf ").encode()
    yield "huge_numbers", base.replace("0.0001", "9.9E+99").encode()
    yield "tiny_step", base.replace("0.0001", "1.0E-30").encode()
    yield "header_only", b"*SEGMENTS\n*JOINTS\n*INITIAL\n"
    yield "stars", b"*\n**\n* \n"
    for k in range(120):
        lines = list(base_lines)
        for _ in range(rnd.randint(1, 6)):
            i = rnd.randrange(len(lines))
            op = rnd.randrange(6)
            line = lines[i]
            if op == 0 and line:
                j = rnd.randrange(len(line))
                line = line[:j] + chr(rnd.randrange(32, 127)) + line[j + 1:]
            elif op == 1:
                line = line[: rnd.randrange(len(line) + 1)]
            elif op == 2:
                line = " " * rnd.randint(1, 15) + line
            elif op == 3:
                line = line + " " * rnd.randint(0, 20) + "".join(
                    rnd.choice("0123456789.-+E ") for _ in range(rnd.randint(1, 30)))
            elif op == 4:
                lines.insert(i, line)
            else:
                del lines[i]
                continue
            lines[i] = line
        yield f"mutation_{k}", ("\n".join(lines) + "\n").encode("latin-1", "replace")


def main():
    exe, deck, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    with open(deck, encoding="ascii") as f:
        base_lines = f.read().splitlines()
    rnd = random.Random(20261122)
    failures = []
    outcomes = {0: 0, 2: 0, 4: 0}
    for name, data in cases(base_lines, rnd):
        path = os.path.join(work, name + ".deck")
        with open(path, "wb") as f:
            f.write(data)
        try:
            p = subprocess.run([exe, "--check", path], capture_output=True, timeout=60)
        except subprocess.TimeoutExpired:
            failures.append(f"{name}: no answer within 60 s")
            continue
        err = p.stderr.decode("latin-1")
        if p.returncode not in (0, 2, 4):
            failures.append(f"{name}: exit status {p.returncode}\n{err}")
        elif p.returncode != 0 and not err.strip():
            failures.append(f"{name}: exit status {p.returncode} without a message")
        for bad in FORBIDDEN:
            if bad in err:
                failures.append(f"{name}: '{bad}' reached the user\n{err}")
        outcomes[p.returncode] = outcomes.get(p.returncode, 0) + 1
    print(f"fuzz: {sum(outcomes.values())} decks, outcomes by exit status: {outcomes}")
    if outcomes.get(2, 0) < 50:
        failures.append("too few decks were rejected: the mutations are not biting")
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
