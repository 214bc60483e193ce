#!/usr/bin/env python3
"""Print the names pFUnit's `funit` module makes public, one per line, sorted,
from the funit.mod gfortran wrote when pFUnit was built (a gzip-compressed text
file): the names of its generic interfaces and of its symbol tree. pfproc.py's
FUNIT_NAMES is this list; regenerate it when the pFUnit version changes:

    tools/pfunit_lite/funit_names.py PREFIX/PFUNIT-4.14/include/funit.mod

Standard library only.
"""
import gzip
import re
import sys


def top_level_blocks(text):
    """(start, end) of each top-level parenthesised block, quotes respected."""
    blocks, depth, start, quoted = [], 0, 0, False
    for i, c in enumerate(text):
        if c == "'":
            quoted = not quoted
        if quoted:
            continue
        if c == "(":
            if depth == 0:
                start = i
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                blocks.append((start, i))
    return blocks


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 1
    with gzip.open(argv[1], "rt", encoding="ascii", errors="replace") as f:
        text = f.read()
    blocks = top_level_blocks(text)
    if not blocks:
        print(f"funit_names.py: {argv[1]} does not look like a gfortran module file", file=sys.stderr)
        return 1
    start, end = blocks[-1]
    symtree = re.findall(r"'([a-z_0-9]+)' [01] \d+", text[start:end + 1])
    generics = re.findall(r"\('([a-z_0-9]+)' '[a-z_0-9]+'", text)
    for name in sorted(set(symtree) | set(generics)):
        print(name)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
