#!/usr/bin/env python3
"""Check that the stand-in refuses what pFUnit 4.14 refuses (test pfunit_lite_refuses).

    check_refusals.py --pfproc PFPROC --work DIR [--pfunit PFUNIT_DIR
                      --cmake CMAKE --fc COMPILER [--flag FLAG]...] EXAMPLE.pf...

Each example (tests/funit_lite/refused/*.pf) holds one construct that real
pFUnit 4.14 cannot build, between the comment lines `! >>>` and `! <<<`, and
says in its header what pfunit_lite must answer (`! expect: <text>`) and how
the construct is written instead (`! fixed: <line>`, one or more lines). For
each example:

  1. pfproc.py refuses it: exit status 1 and one message
     `<file>:<line>: error: ...<text>...`, <line> being the construct's first
     line (the first one after `! >>>` that is not a comment);
  2. pfproc.py accepts the control, the same file with the construct replaced
     by the fixed lines (written as <module>.pf under --work), so the refusal
     is about that construct and nothing else;
  3. with --pfunit (CMake passes it when it found pFUnit): real pFUnit
     fails to build the example and builds the control, each a test program
     of its own made by add_pfunit_ctest in a small CMake project under
     --work, its .pf compiled with the flags the tests are compiled with
     (--flag), and linked: some constructs fail only there.

Exit status 0 when every example behaves so; the reasons otherwise.
"""

import argparse
import os
import re
import subprocess
import sys


def parse_example(path):
    """(lines, expected text, fixed lines, first and last index of the
    construct's marked range) of an example."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    expect = [l[len("! expect:"):].strip() for l in lines if l.startswith("! expect:")]
    fixed = [l[len("! fixed: "):] for l in lines if l.startswith("! fixed: ")]
    marks = [i for i, l in enumerate(lines) if l.strip() in ("! >>>", "! <<<")]
    if len(expect) != 1 or not fixed or len(marks) != 2:
        raise ValueError(f"{path}: needs one '! expect:', '! fixed:' lines and one '! >>>' ... '! <<<' range")
    return lines, expect[0], fixed, marks[0], marks[1]


def first_code_line(lines, start, end):
    """1-based number of the first line in (start, end) that is not a comment."""
    for i in range(start + 1, end):
        if lines[i].strip() and not lines[i].lstrip().startswith("!"):
            return i + 1
    raise ValueError("empty '! >>>' ... '! <<<' range")


def run(command, cwd):
    return subprocess.run(command, cwd=cwd, capture_output=True, text=True)


def cmake_list(items):
    return " ".join('"' + item.replace("\\", "/").replace('"', '\\"') + '"' for item in items)


def pfunit_project(programs, args):
    """Write and configure a CMake project with one add_pfunit_ctest program
    per (name, .pf file); returns its build directory."""
    source = os.path.join(args.work, "pfunit")
    build = os.path.join(source, "build")
    os.makedirs(source, exist_ok=True)
    text = ["cmake_minimum_required(VERSION 3.24)",
            "project(pfunit_refusals LANGUAGES Fortran)",
            "find_package(PFUNIT REQUIRED)",
            "enable_testing()"]
    for name, pf in programs:
        # Each .pf in a directory of its own (an example and its control may
        # share a name); an absolute path is taken as one in the build tree.
        directory = os.path.join(source, name)
        os.makedirs(directory, exist_ok=True)
        copy = os.path.join(directory, os.path.basename(pf))
        with open(pf, encoding="utf-8") as f, open(copy, "w", encoding="utf-8") as g:
            g.write(f.read())
        f90 = os.path.splitext(copy)[0] + ".F90"
        text += [f"add_pfunit_ctest({name} TEST_SOURCES {cmake_list([copy])})",
                 f"set_target_properties({name} PROPERTIES EXCLUDE_FROM_ALL TRUE)",
                 f"set_source_files_properties({cmake_list([f90])} PROPERTIES COMPILE_OPTIONS {cmake_list([';'.join(args.flag)])})"]
    with open(os.path.join(source, "CMakeLists.txt"), "w", encoding="utf-8") as f:
        f.write("\n".join(text) + "\n")
    done = run([args.cmake, "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Debug",
                f"-DCMAKE_Fortran_COMPILER={args.fc}", f"-DPFUNIT_DIR={args.pfunit}"], args.work)
    if done.returncode != 0:
        raise ValueError("the CMake project with pFUnit did not configure:\n" + done.stdout + done.stderr)
    return build


def pfunit_builds(build, name, args):
    """(True, '') when real pFUnit builds the program `name`, else (False, the first error)."""
    done = run([args.cmake, "--build", build, "--target", name], args.work)
    if done.returncode == 0:
        return True, ""
    output = (done.stdout + done.stderr).splitlines()
    errors = [l.strip() for l in output if re.search(r"Error|error:|undefined reference", l)]
    return False, errors[0] if errors else "(no message)"


def check(example, args):
    """The reasons `example` does not behave as stages 1 and 2 say; the
    control's path is added to args.controls."""
    problems = []
    name = os.path.basename(example)
    lines, expect, fixed, start, end = parse_example(example)
    line = first_code_line(lines, start, end)

    done = run([sys.executable, args.pfproc, "module", example, os.path.join(args.work, name + ".F90")], args.work)
    message = done.stderr.strip()
    pattern = re.escape(f"{example}:{line}: error: ") + ".*" + re.escape(expect)
    if done.returncode != 1 or len(message.splitlines()) != 1 or not re.match(pattern, message):
        problems.append(f"pfproc.py should refuse it at line {line} with '{expect}'; "
                        f"exit status {done.returncode}, said: {message or '(nothing)'}")

    control_lines = lines[:start] + fixed + lines[end + 1:]
    module = next((m.group(1) for m in (re.match(r"\s*module\s+(\w+)\s*$", l, re.IGNORECASE)
                                        for l in control_lines) if m), None)
    if module is None:
        return problems + ["its control (with the fixed lines) has no module statement"]
    control = os.path.join(args.work, module + ".pf")
    with open(control, "w", encoding="utf-8") as f:
        f.write("\n".join(control_lines) + "\n")
    done = run([sys.executable, args.pfproc, "module", control, control + ".F90"], args.work)
    if done.returncode != 0:
        problems.append(f"pfproc.py should accept its control {control}; said: {done.stderr.strip()}")
    args.controls[example] = control
    return problems


def check_pfunit(examples, args):
    """Stage 3: {example: reasons} where real pFUnit does not agree."""
    programs = []
    for k, example in enumerate(examples):
        programs += [(f"example_{k}", example), (f"control_{k}", args.controls[example])]
    build = pfunit_project(programs, args)
    problems = {}
    for k, example in enumerate(examples):
        found = []
        built, why = pfunit_builds(build, f"example_{k}", args)
        if built:
            found.append("pFUnit 4.14 builds it: the stand-in refuses what pFUnit accepts")
        else:
            args.pfunit_errors[example] = why
        built, why = pfunit_builds(build, f"control_{k}", args)
        if not built:
            found.append(f"pFUnit 4.14 does not build its control {args.controls[example]}: {why}")
        problems[example] = found
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pfproc", required=True, help="tools/pfunit_lite/pfproc.py")
    parser.add_argument("--work", required=True, help="a directory for the generated files")
    parser.add_argument("--pfunit", metavar="PFUNIT_DIR",
                        help="pFUnit's CMake package directory, to check that pFUnit refuses the examples too")
    parser.add_argument("--cmake", default="cmake", help="cmake (with --pfunit)")
    parser.add_argument("--fc", help="the Fortran compiler (with --pfunit)")
    parser.add_argument("--flag", action="append", default=[], help="a compiler flag for the .pf (with --pfunit)")
    parser.add_argument("examples", nargs="+")
    args = parser.parse_args()
    if args.pfunit and not args.fc:
        parser.error("--pfunit needs --fc")
    args.work = os.path.abspath(args.work)
    os.makedirs(args.work, exist_ok=True)
    args.pfproc = os.path.abspath(args.pfproc)
    args.controls = {}
    args.pfunit_errors = {}

    examples = [os.path.abspath(example) for example in args.examples]
    problems = {}
    for example in examples:
        try:
            problems[example] = check(example, args)
        except (OSError, ValueError) as error:
            problems[example] = [str(error)]
    if args.pfunit:
        try:
            for example, found in check_pfunit([e for e in examples if e in args.controls], args).items():
                problems[example] += found
        except (OSError, ValueError) as error:
            print(f"FAIL: {error}")
            return 1

    failed = 0
    for example in examples:
        name = os.path.basename(example)
        for problem in problems[example]:
            print(f"FAIL {name}: {problem}")
        if not problems[example]:
            print(f"ok   {name}")
            if args.pfunit:
                print(f"       pFUnit 4.14 fails on it too ({args.pfunit_errors[example]}) and builds its control")
        failed += bool(problems[example])
    print(f"{len(examples) - failed} of {len(examples)} refusals as expected")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
