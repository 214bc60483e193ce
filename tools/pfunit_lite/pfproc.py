#!/usr/bin/env python3
"""pfunit_lite preprocessor: pFUnit test modules (.pf) to plain Fortran.

A stand-in for pFUnit's funitproc, used when no pFUnit is installed, for
the subset of pFUnit described in tests/funit_lite/README.md. The same .pf
files build unchanged under a real pFUnit.

    pfproc.py module INPUT.pf OUTPUT.F90
        Check that INPUT.pf is written as pFUnit 4.14 reads it (below), then
        write the test module with every @assert... line replaced by a call
        to the assertion of the funit module (tests/funit_lite/funit.F90)
        carrying the .pf file's name and line, followed by
        `if (anyExceptions()) return`. `#line` markers keep compiler
        messages pointing at the .pf file.

    pfproc.py driver OUTPUT.F90 INPUT.pf [INPUT.pf ...]
        Write a program that runs every @test of the given modules in file
        order, with the module's @before and @after around each, and prints
        a summary; its exit status is 1 if any test failed.

Malformed input is reported as `file:line: error: ...` with exit status 1.
So is what the stand-in could read but pFUnit 4.14's preprocessor (funitproc)
cannot, since it matches each line as a whole against a regular expression:

  - an @ directive continued with `&` (pFUnit leaves it as invalid Fortran);
  - a comment after an @ directive (pFUnit takes it for part of the
    directive: an @assert's comment swallows the location arguments);
  - an @assert whose one line, as pFUnit writes it (`  call assertX(..., &`),
    is wider than the 132 columns the tests are compiled with; likewise the
    line pFUnit writes to register a test, and the suite function's name
    (`<module>_suite`), which must be a Fortran name (63 characters at most);
  - a comment on the `module` statement (pFUnit then does not see the module);
  - a procedure named as one of the names pFUnit's funit module exports
    (FUNIT_NAMES: `starts_with`, `is`, `run`, ...), which then does not compile.

Standard library only.
"""

import argparse
import os
import re
import sys

# Supported assertions: lower-case directive -> (funit procedure, operands
# required, counted as pFUnit's preprocessor counts them).
ASSERTIONS = {
    "assertequal": ("assertEqual", 2),
    "assertnotequal": ("assertNotEqual", 2),
    "assertrelativelyequal": ("assertRelativelyEqual", 2),
    "asserttrue": ("assertTrue", 1),
    "assertfalse": ("assertFalse", 1),
    "assertlessthan": ("assertLessThan", 2),
    "assertlessthanorequal": ("assertLessThanOrEqual", 2),
    "assertgreaterthan": ("assertGreaterThan", 2),
    "assertgreaterthanorequal": ("assertGreaterThanOrEqual", 2),
    "assertexceptionraised": ("assertExceptionRaised", 0),
}

# @test options that change which tests exist or how they run; the stand-in
# cannot honour them, so it refuses them rather than ignore them.
UNSUPPORTED_TEST_OPTIONS = ("npes", "ifdef", "ifndef", "type", "cases", "testparameters")

# The names pFUnit 4.14's `funit` module makes public (its generic interfaces and
# its symbol tree, read from the funit.mod gfortran writes when pFUnit is built:
# tools/pfunit_lite/funit_names.py PREFIX/PFUNIT-4.14/include/funit.mod). A test
# module that uses funit and defines a procedure of one of these names does not
# compile under pFUnit ("Cannot change attributes of USE-associated symbol"),
# whatever the stand-in's own funit exports.
FUNIT_NAMES = frozenset((
    "abstractmatcher", "abstracttestparameter", "all_of", "allof", "any_of", "anyexceptions",
    "anyof", "array_with_size", "assertall", "assertany", "assertexceptionraised",
    "assertfalse", "assertgreaterthanorequal", "assertisnan", "assertlessthanorequal",
    "assertnone", "assertnotall", "assertnotequal", "assertrelativelyequal", "assertsameshape",
    "basetestrunner", "catch", "catchnext", "contains_string", "debuglistener", "disable",
    "empty_array", "equal_to", "every", "every_item", "expectation", "fhamcrest", "finalize",
    "funit", "get_context", "ignore_all", "initialize", "is", "isarraywithsize", "isequal",
    "isnear", "isnot", "isrelativelynear", "istrueorfalse", "listenerpointer",
    "loadtests_interface", "matchable", "matcherdescription", "namefilter", "near", "not",
    "parallelcontext", "parameterizedtestcase", "predicate", "relatively_near", "remoterunner",
    "resultprinter", "robustrunner", "run", "serialcontext", "sourcelocation", "starts_with",
    "stringcontains", "stringendswith", "stringstartswith", "stub", "subject", "taplistener",
    "test", "testannotation", "testcase", "testlistener", "testlistenervector", "testmethod",
    "testresult", "testrunner", "testsuite", "throw", "timeoutannotation", "trim_all",
    "wascalled", "wascalledonce", "whitespaceoptions", "xmlprinter",
))

PROCEDURE_RE = re.compile(
    r"\s*(?:(?:pure|impure|elemental|recursive|module)\s+)*"
    r"(?:(?:integer|real|logical|character|complex|double\s+precision|type\s*\([^)]*\)|class\s*\([^)]*\))"
    r"(?:\s*\([^)]*\))?\s+)?(?:(?:pure|impure|elemental|recursive)\s+)*"
    r"(?:subroutine|function)\s+(\w+)", re.IGNORECASE)

MODULE_RE = re.compile(r"\s*module\s+(\w+)\s*$", re.IGNORECASE)
SUBROUTINE_RE = re.compile(r"\s*subroutine\s+(\w+)\s*(\((.*)\))?\s*$", re.IGNORECASE)
KEYWORD_ARG_RE = re.compile(r"\s*[A-Za-z]\w*\s*=(?!=)")

# Longest generated line before continuation (the project allows 132).
WRAP_WIDTH = 100

# The free-form line width the tests are compiled with (cmake/compilers.cmake,
# -ffree-line-length-132), which also applies to the lines pFUnit generates.
PFUNIT_LINE_LIMIT = 132
# The longest Fortran name (F2008 3.2.2).
FORTRAN_NAME_LIMIT = 63

# How pFUnit 4.14's preprocessor recognises a test module and an assertion
# (bin/funit/pFUnitParser.py, AtBegin and AtAssert): the whole line must match.
PFUNIT_MODULE_RE = re.compile(r"\s*module\s+(\w*)\s*$", re.IGNORECASE)
PFUNIT_ASSERT_RE = re.compile(r"\s*@assert(\w+)\s*\((.*)\)\s*$", re.IGNORECASE)


class PfError(Exception):
    """Malformed .pf input, reported as file:line: error: text."""

    def __init__(self, path, line, text):
        super().__init__(f"{path}:{line}: error: {text}")


class Suite:
    """What the driver needs from one .pf file."""

    def __init__(self, path):
        self.path = path
        self.module = None
        self.tests = []  # (name, line, disabled) in file order
        self.before = None
        self.after = None


# --------------------------------------------------------------------------
# Fortran lexical helpers
# --------------------------------------------------------------------------

def strip_comment(text, quote):
    """Cut a trailing `!` comment; `quote` is the string delimiter open at
    the start of the text (or None). Returns (code, quote open at the end)."""
    i = 0
    while i < len(text):
        c = text[i]
        if quote:
            if c == quote:
                if text[i + 1:i + 2] == quote:  # doubled quote inside a string
                    i += 1
                else:
                    quote = None
        elif c in "'\"":
            quote = c
        elif c == "!":
            return text[:i], quote
        i += 1
    return text, quote


def is_blank_or_comment(line):
    stripped = line.strip()
    return not stripped or stripped.startswith("!")


def read_directive(line, path, number):
    """The text of a directive, which must stand alone on its line, as
    pFUnit 4.14 reads it: no continuation, no trailing comment."""
    code, quote = strip_comment(line, None)
    if quote:
        raise PfError(path, number, "unterminated character string in directive")
    code = code.rstrip()
    if code.endswith("&"):
        raise PfError(path, number, "an @ directive must stand on one line: pFUnit 4.14 does not join "
                                    "continuation lines (compute long arguments into a variable first)")
    if code != line.rstrip():
        raise PfError(path, number, "a comment after an @ directive: pFUnit 4.14 reads it as part of the "
                                    "directive (put the comment on a line of its own above)")
    return code.strip()


def split_arguments(text, path, line):
    """Split '(a, b, ...)' at its top-level commas, respecting strings and
    nested () and []. Nothing may follow the closing parenthesis."""
    if not text.startswith("("):
        raise PfError(path, line, "expected '(' after the assertion name")
    closing = {"(": ")", "[": "]"}
    stack, quote, args, start = [], None, [], 1
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None  # a doubled quote reopens at once: same result
            continue
        if c in "'\"":
            quote = c
        elif c in closing:
            stack.append(closing[c])
        elif c in ")]":
            if not stack or stack.pop() != c:
                raise PfError(path, line, f"unbalanced '{c}' in assertion arguments")
            if not stack:
                if text[i + 1:].strip():
                    raise PfError(path, line, f"unexpected text after the arguments: '{text[i + 1:].strip()}'")
                args.append(text[start:i])
                return arguments_list(args, path, line)
        elif c == "," and len(stack) == 1:
            args.append(text[start:i])
            start = i + 1
    raise PfError(path, line, "unbalanced '(' in assertion arguments")


def arguments_list(args, path, line):
    args = [a.strip() for a in args]
    if args == [""]:
        return []
    if any(not a for a in args):
        raise PfError(path, line, "empty argument in assertion")
    return args


def wrap(indent, statement):
    """Lines of `statement` no wider than WRAP_WIDTH. Breaks use `&` at both
    ends, which continues the text exactly, even inside strings or tokens."""
    room = max(40, WRAP_WIDTH - len(indent) - 4)
    lines, prefix = [], indent
    while len(statement) > room:
        cut = break_point(statement, room)
        lines.append(prefix + statement[:cut] + "&")
        statement = statement[cut:]
        prefix = indent + "   &"
    lines.append(prefix + statement)
    return lines


def break_point(text, room):
    """Index just after the last blank outside strings within `room`, else
    `room` itself."""
    quote, best = None, 0
    for i, c in enumerate(text[:room]):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == " " and i > 0:
            best = i + 1
    return best or room


def fortran_string(text):
    return "'" + text.replace("'", "''") + "'"


def line_marker(line, path):
    return f'#line {line} "{os.path.abspath(path)}"'


# --------------------------------------------------------------------------
# .pf parsing
# --------------------------------------------------------------------------

class Parser:
    """Reads one .pf file, producing the Fortran module text and the Suite."""

    def __init__(self, path):
        self.path = path
        self.name = os.path.basename(path)
        with open(path, encoding="utf-8") as f:
            self.lines = f.read().splitlines()
        self.suite = Suite(path)
        self.out = []
        self.pending = None  # (directive, line) waiting for its subroutine
        self.disabled = False
        self.module_line = 1

    def error(self, line, text):
        return PfError(self.path, line, text)

    def run(self):
        self.out.append(f"! Generated from {self.name} by tools/pfunit_lite/pfproc.py: do not edit.")
        self.out.append(line_marker(1, self.path))
        i = 0
        while i < len(self.lines):
            line = self.lines[i]
            if line.lstrip().startswith("@"):
                self.directive(read_directive(line, self.path, i + 1), i + 1)
                i += 1
                continue
            if not is_blank_or_comment(line):
                self.statement(line, i + 1)
            self.out.append(line)
            i += 1
        self.finish()
        return "\n".join(self.out) + "\n"

    def finish(self):
        if self.pending:
            directive, line = self.pending
            raise self.error(line, f"@{directive} is not followed by a subroutine")
        if not self.suite.module:
            raise self.error(1, "no 'module <name>' statement found")
        if not self.suite.tests:
            raise self.error(1, "no @test found")
        self.check_pfunit_registration()

    def check_pfunit_registration(self):
        """The names and lines pFUnit 4.14 writes to register the tests
        (Parser.printMakeSuite, addSimpleTestMethod) must be valid Fortran."""
        module, line = self.suite.module, self.module_line
        suite_function = module + "_suite"
        if len(suite_function) > FORTRAN_NAME_LIMIT:
            raise self.error(line, f"module name '{module}' too long: pFUnit names its suite "
                                   f"'{suite_function}', more than {FORTRAN_NAME_LIMIT} characters")
        fixtures = "".join(f", {keyword}={name}" for keyword, name
                           in (("setUp", self.suite.before), ("tearDown", self.suite.after)) if name)
        for name, number, _ in self.suite.tests:
            width = len(f"      {name}{fixtures}))")
            if width > PFUNIT_LINE_LIMIT:
                raise self.error(number, f"test name '{name}' too long: pFUnit registers it on a line of "
                                         f"{width} columns, more than {PFUNIT_LINE_LIMIT}")

    def statement(self, line, number):
        """A Fortran line: the module statement, a procedure of the module (its
        name must not be one funit exports), or the subroutine a pending
        @test, @before or @after applies to."""
        procedure = PROCEDURE_RE.match(strip_comment(line, None)[0])
        if procedure and procedure.group(1).lower() in FUNIT_NAMES:
            raise self.error(number, f"procedure '{procedure.group(1)}': pFUnit's funit module exports this "
                                     "name, so the module does not compile under pFUnit 4.14 (rename it)")
        if self.pending:
            self.subroutine(line, number)
            return
        match = MODULE_RE.match(strip_comment(line, None)[0])
        if match and not self.suite.module:
            if not PFUNIT_MODULE_RE.match(line):
                raise self.error(number, "a comment on the module statement: pFUnit 4.14 would not see the "
                                         "module (put the comment on a line of its own)")
            self.module(match.group(1), number)

    def module(self, name, number):
        stem = os.path.splitext(self.name)[0]
        if name.lower() != stem.lower():
            raise self.error(number, f"module '{name}' must be named after its file: '{stem}'")
        self.suite.module = name
        self.module_line = number

    def subroutine(self, line, number):
        directive, _ = self.pending
        match = SUBROUTINE_RE.match(strip_comment(line, None)[0])
        if not match:
            raise self.error(number, f"expected 'subroutine <name>()' after @{directive}")
        name = match.group(1)
        if match.group(3) and match.group(3).strip():
            raise self.error(number, f"@{directive} subroutine '{name}' must take no arguments "
                                     "(test-case classes are not supported)")
        if directive == "test":
            if any(t[0].lower() == name.lower() for t in self.suite.tests):
                raise self.error(number, f"test '{name}' defined twice")
            self.suite.tests.append((name, number, self.disabled))
        else:
            setattr(self.suite, directive, name)
        self.pending = None
        self.disabled = False

    def directive(self, text, number):
        match = re.match(r"@(\w+)\s*(.*)$", text, re.DOTALL)
        if not match:
            raise self.error(number, f"malformed directive '{text}'")
        name, rest = match.group(1), match.group(2)
        word = name.lower()
        if word in ASSERTIONS:
            self.assertion(word, rest, number)
            return
        if word not in ("test", "before", "after", "disable"):
            raise self.error(number, f"@{name} is not supported by pfunit_lite "
                                     "(see tests/funit_lite/README.md)")
        if word == "test":
            self.test_options(rest, number)
        elif rest:
            raise self.error(number, f"@{word} takes no arguments")
        if word == "disable":
            self.disable(number)
        else:
            self.expect_subroutine(word, number)
        # A comment line in place of the directive's line.
        self.out.append("!" + self.lines[number - 1].lstrip())

    def disable(self, number):
        if not self.pending or self.pending[0] != "test" or self.disabled:
            raise self.error(number, "@disable must stand between @test and its subroutine")
        self.disabled = True

    def expect_subroutine(self, word, number):
        if self.pending:
            raise self.error(self.pending[1], f"@{self.pending[0]} is not followed by a subroutine")
        if word in ("before", "after") and getattr(self.suite, word):
            raise self.error(number, f"second @{word} in the module")
        self.pending = (word, number)

    def test_options(self, rest, number):
        if not rest:
            return
        if not (rest.startswith("(") and rest.endswith(")")):
            raise self.error(number, "expected '@test' or '@test(options)'")
        for option in UNSUPPORTED_TEST_OPTIONS:
            if re.search(r"\b" + option + r"\s*=", rest, re.IGNORECASE):
                raise self.error(number, f"@test option '{option}' is not supported by pfunit_lite")

    def assertion(self, word, rest, number):
        if self.pending:
            directive, line = self.pending
            raise self.error(line, f"@{directive} is not followed by a subroutine")
        procedure, operands = ASSERTIONS[word]
        args = split_arguments(rest, self.path, number)
        if len(args) < operands:
            raise self.error(number, f"@{procedure} needs at least {operands} argument(s)")
        self.check_pfunit_width(number)
        location = f"location=SourceLocation({fortran_string(self.name)}, {number})"
        indent = re.match(r"\s*", self.lines[number - 1]).group(0)
        expansion = wrap(indent, f"call {procedure}(" + ", ".join(args + [location]) + ")")
        expansion.append(f"{indent}if (anyExceptions()) return")
        # Each generated line is marked as the directive's line, so that
        # compiler messages point at it; then numbering resumes after it.
        for text in expansion:
            self.out += [line_marker(number, self.path), text]
        self.out.append(line_marker(number + 1, self.path))

    def check_pfunit_width(self, number):
        """pFUnit writes an @assert line as `  call assertX(<arguments>, &`
        (pFUnitParser.py, AtAssert.action); that line must fit."""
        match = PFUNIT_ASSERT_RE.match(self.lines[number - 1])
        if not match:
            raise self.error(number, "pFUnit 4.14 would not recognise this @assert line")
        arguments = match.group(2)
        written = f"  call assert{match.group(1)}({arguments}{', ' if arguments.strip() else ''}&"
        if len(written) > PFUNIT_LINE_LIMIT:
            raise self.error(number, f"pFUnit 4.14 writes this @assert on one line of {len(written)} columns, "
                                     f"more than {PFUNIT_LINE_LIMIT} (compute long arguments into a variable first)")


def parse(path):
    parser = Parser(path)
    text = parser.run()
    return text, parser.suite


# --------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------

def driver_text(suites):
    """The program that runs every test of `suites` in order."""
    check_unique_modules(suites)
    uses = ["   use funit, only: funit_run_test, funit_skip_test, funit_finish"]
    calls = []
    for m, suite in enumerate(suites, start=1):
        suite_uses, suite_calls = suite_driver(m, suite)
        uses += suite_uses
        calls += suite_calls
    return "\n".join(["! Generated by tools/pfunit_lite/pfproc.py: do not edit.",
                      "program funit_driver"] + uses + ["   implicit none", ""] + calls
                     + ["   call funit_finish()", "end program funit_driver"]) + "\n"


def check_unique_modules(suites):
    seen = {}
    for suite in suites:
        key = suite.module.lower()
        if key in seen:
            raise PfError(suite.path, 1, f"module '{suite.module}' also defined in {seen[key]}")
        seen[key] = suite.path


def suite_driver(m, suite):
    """The use statements and calls for the m-th suite. Procedures are
    renamed on import (t<m>_<k>, b<m>, a<m>) so that modules may share names."""
    uses, calls, fixtures = [], [], ""
    for prefix, keyword, name in (("b", "before", suite.before), ("a", "after", suite.after)):
        if name:
            uses.append(f"   use {suite.module}, only: {prefix}{m} => {name}")
            fixtures += f", {keyword}={prefix}{m}"
    file_name = fortran_string(os.path.basename(suite.path))
    for k, (name, line, disabled) in enumerate(suite.tests, start=1):
        where = f"{file_name}, {line}, {fortran_string(name)}"
        if disabled:
            calls += wrap("   ", f"call funit_skip_test({where})")
        else:
            uses.append(f"   use {suite.module}, only: t{m}_{k} => {name}")
            calls += wrap("   ", f"call funit_run_test({where}, t{m}_{k}{fixtures})")
    return uses, calls


# --------------------------------------------------------------------------
# Command line
# --------------------------------------------------------------------------

def write(path, text):
    directory = os.path.dirname(path)
    if directory:
        os.makedirs(directory, exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    module = commands.add_parser("module", help="preprocess one .pf file")
    module.add_argument("input")
    module.add_argument("output")
    driver = commands.add_parser("driver", help="write the test program for .pf files")
    driver.add_argument("output")
    driver.add_argument("inputs", nargs="+")
    args = parser.parse_args(argv)
    try:
        if args.command == "module":
            text, _ = parse(args.input)
            write(args.output, text)
        else:
            write(args.output, driver_text([parse(path)[1] for path in args.inputs]))
    except PfError as error:
        print(error, file=sys.stderr)
        return 1
    except OSError as error:
        print(f"pfproc.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
