#!/usr/bin/env python3
"""Every field name the program looks up by name is a field of the card table.

usage: check_field_names.py HSRI2D SRC_DIR

The builders read a card's fields by name (c1_input/deck_fields: card_value,
group_value, ...), the validators ask whether a card gave one (model_origin:
field_given, group_field_given, card_key), and both name them in messages
(model_origin: field_where and the field lists of problem, problem_at,
located and warning). A misspelled name is a
defect of the program that no deck can show: the accessors then return NaN,
-huge or .false. and the message names no columns (issue 14, item 29). Tests
that run the builders only see the names on the paths they take, so this
check reads the source instead: it finds every such call in SRC_DIR, works
out the names it can pass - a literal, an element of a character parameter
array or array constructor, a concatenation of those, a dummy argument
resolved through the calls of its procedure in the same file, a local
variable through its assignments - and checks each against the card table
that `HSRI2D --deck-format` prints (the table itself, as docs/deck-format.md
shows it). It costs nothing at run time and sees every call, taken or not.

A name with its group (the accessors) must be a field of that group (of one
of the groups the group argument can be); a name in a message's field list,
whose group is the card's, must be a field of some group. An expression the
check cannot resolve is an error too: write it so that it can be.
"""
import glob
import os
import re
import subprocess
import sys

# accessor: (index of the group argument, index of the name argument; -1: the last)
GROUP_AND_NAME = {
    "card_value": (1, 3), "card_int": (1, 3), "card_given": (1, 3),
    "group_value": (1, 2), "group_int": (1, 2), "group_given": (1, 2),
    "default_value": (1, 2), "field_number": (1, 2), "field_where": (1, 2),
    # the validators' origin (c1_input/model_origin)
    "field_given": (1, 3), "group_field_given": (1, 2), "card_key": (1, 3),
}
# procedures with a blank-separated list of field names: (group argument or None, list argument)
FIELD_LISTS = {"problem": (None, 4), "located": (None, 3), "problem_at": (2, 4), "field_list": (1, 2),
               "warning": (None, 4)}
# where these are defined the names are dummies of every caller: not checked there
DEFINITIONS = {"deck_fields.f90", "model_origin.f90"}
HELPERS = {"field_where", "field_list", "located", "problem", "problem_at"}
MAX_DEPTH = 6


class Unresolved(Exception):
    pass


def card_table(exe):
    """{group name: set of field names} from the generated documentation."""
    text = subprocess.run([exe, "--deck-format"], check=True, capture_output=True, text=True).stdout
    table, group = {}, None
    for line in text.splitlines():
        m = re.match(r"## \\\*(\w+)", line)
        if m:
            group = m.group(1)
            table[group] = set()
            continue
        m = re.match(r"\| (\d+-\d+) \| (\w+) \|", line)
        if m and group and m.group(2) != "index":
            table[group].add(m.group(2))
    return table


def group_constants(src):
    """{g_constant: group name} from the card table's source."""
    text = open(os.path.join(src, "c1_input", "deck_cards.f90")).read()
    return dict(re.findall(r"t\((g_\w+)\)%name = '(\w+)'", text))


def strip_comment(line):
    out, quote = [], None
    for ch in line:
        if quote:
            out.append(ch)
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
            out.append(ch)
        elif ch == "!":
            break
        else:
            out.append(ch)
    return "".join(out)


def statements(path):
    """The file's statements, continuation lines joined, comments removed."""
    result, current = [], ""
    for raw in open(path, encoding="utf-8", errors="replace"):
        line = strip_comment(raw.rstrip("\n")).rstrip()
        stripped = line.lstrip()
        if current and stripped.startswith("&"):
            stripped = stripped[1:]
        if stripped.endswith("&"):
            current += stripped[:-1]
            continue
        current += stripped
        if current.strip():
            result.append(current.strip())
        current = ""
    return result


def split_args(text):
    """Top-level comma-separated parts of an argument list."""
    parts, depth, quote, cur = [], 0, None, ""
    for ch in text:
        if quote:
            cur += ch
            if ch == quote:
                quote = None
            continue
        if ch in "'\"":
            quote = ch
        elif ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(cur.strip())
            cur = ""
            continue
        cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


def calls(stmt, name):
    """The argument lists of every call of `name` in a statement."""
    found = []
    for m in re.finditer(r"(?<![\w%])" + name + r"\s*\(", stmt, re.IGNORECASE):
        i, depth, quote = m.end(), 1, None
        j = i
        while j < len(stmt) and depth:
            ch = stmt[j]
            if quote:
                if ch == quote:
                    quote = None
            elif ch in "'\"":
                quote = ch
            elif ch == "(":
                depth += 1
            elif ch == ")":
                depth -= 1
            j += 1
        found.append(split_args(stmt[i:j - 1]))
    return found


class Scope:
    def __init__(self, kind, name, dummies, parent):
        self.kind, self.name, self.dummies, self.parent = kind, name, dummies, parent
        self.stmts = []

    def chain(self):
        s = self
        while s:
            yield s
            s = s.parent


class SourceFile:
    def __init__(self, path, parameters):
        self.path = path
        self.parameters = parameters      # character parameter arrays of every file
        self.scopes, self.where = [], []  # scopes; the scope of every statement
        stack = []
        for stmt in statements(path):
            m = re.match(r"(?:(?:pure|elemental|recursive|impure|module)\s+)*(?:[\w()=:,\s*]*\s)?"
                         r"(subroutine|function)\s+(\w+)\s*\(([^)]*)\)", stmt, re.IGNORECASE)
            if m and not stmt.lower().startswith("end"):
                scope = Scope(m.group(1).lower(), m.group(2).lower(),
                              [a.strip().lower() for a in m.group(3).split(",") if a.strip()],
                              stack[-1] if stack else None)
                self.scopes.append(scope)
                stack.append(scope)
                scope.stmts.append(stmt)
                self.where.append((stmt, scope))
                continue
            if re.match(r"end\s+(subroutine|function)\b", stmt, re.IGNORECASE) and stack:
                stack.pop()
                continue
            if stack:
                stack[-1].stmts.append(stmt)
            self.where.append((stmt, stack[-1] if stack else None))

    def procedure(self, name):
        for s in self.scopes:
            if s.name == name:
                return s
        return None

    def call_sites(self, proc):
        """(actual arguments, calling scope) of every call of proc in the file
        (a subroutine: its CALL statements; a function: every reference)."""
        target = self.procedure(proc)
        for stmt, scope in self.where:
            if re.search(r"(subroutine|function)\s+" + proc + r"\s*\(", stmt, re.IGNORECASE):
                continue
            if target is not None and target.kind == "subroutine":
                m = re.search(r"\bcall\s+" + proc + r"\s*\(", stmt, re.IGNORECASE)
                if not m:
                    continue
                yield from ((args, scope) for args in calls(stmt[m.start():], proc)[:1])
                continue
            for args in calls(stmt, proc):
                yield args, scope

    def assignments(self, var, scope):
        """Right-hand sides assigned to var in scope."""
        rhs = []
        for stmt in scope.stmts:
            m = re.match(r"(?:if\s*\(.*\)\s*)?" + var + r"\s*=\s*(.+)$", stmt, re.IGNORECASE)
            if m and not re.match(r".*::", stmt):
                rhs.append(m.group(1).strip())
        return rhs

    def local_parameter(self, name, scope, global_too=True):
        for s in scope.chain() if scope else []:
            for stmt in s.stmts:
                m = re.match(r"character\s*\(len=[^)]*\)\s*,\s*parameter\s*::(.*)$", stmt, re.IGNORECASE)
                if m:
                    for decl in split_args(m.group(1)):
                        d = re.match(r"(\w+)\s*(?:\([^)]*\))?\s*=\s*(.+)$", decl)
                        if d and d.group(1).lower() == name:
                            return d.group(2)
        return self.parameters.get(name) if global_too else None


def parameter_arrays(src):
    """{name: array constructor text} of every character parameter array."""
    found = {}
    for path in glob.glob(os.path.join(src, "**", "*.f90"), recursive=True):
        for stmt in statements(path):
            m = re.match(r"character\s*\(len=[^)]*\)\s*,\s*parameter\s*::(.*)$", stmt, re.IGNORECASE)
            if not m:
                continue
            for decl in split_args(m.group(1)):
                d = re.match(r"(\w+)\s*\([^)]*\)\s*=\s*(\[.+\])$", decl)
                if d:
                    found[d.group(1).lower()] = d.group(2)
    return found


def constructor_elements(text):
    inner = text.strip()[1:-1]
    if "::" in inner:
        inner = inner.split("::", 1)[1]
    return [e for e in split_args(inner)]


def evaluate(f, expr, scope, depth=0):
    """The set of strings an expression can hold."""
    expr = expr.strip()
    if depth > MAX_DEPTH:
        raise Unresolved(expr)
    parts = split_concat(expr)
    if len(parts) > 1:
        results = {""}
        for p in parts:
            results = {a + b for a in results for b in evaluate(f, p, scope, depth + 1)}
        return results
    m = re.fullmatch(r"'([^']*)'", expr)
    if m:
        return {m.group(1)}
    m = re.fullmatch(r"(?:trim|adjustl)\s*\((.*)\)", expr, re.IGNORECASE)
    if m:
        return {s.strip() for s in evaluate(f, m.group(1), scope, depth + 1)}
    if expr.startswith("["):
        out = set()
        for e in constructor_elements(expr):
            out |= evaluate(f, e, scope, depth + 1)
        return out
    m = re.fullmatch(r"(\w+)\s*(\(.*\))?", expr)
    if not m:
        raise Unresolved(expr)
    name = m.group(1).lower()
    # a parameter array of the procedure or its host (an element of it: any element)
    array = f.local_parameter(name, scope, global_too=False)
    if array is not None:
        return {s.strip() for s in evaluate(f, array, scope, depth + 1)}
    # a function of the file: what its result is assigned
    proc = f.procedure(name)
    if proc is not None and m.group(2) is not None and name not in proc.dummies:
        result = re.search(r"result\s*\(\s*(\w+)\s*\)", proc.stmts[0], re.IGNORECASE)
        var = result.group(1).lower() if result else name
        return evaluate(f, var, proc, depth + 1)
    # a dummy of an enclosing procedure: its actual arguments
    for s in scope.chain() if scope else []:
        if name in s.dummies:
            k = s.dummies.index(name)
            out, seen = set(), False
            for args, caller in f.call_sites(s.name):
                if k < len(args):
                    seen = True
                    a = args[k]
                    a = re.sub(r"^\w+\s*=\s*", "", a) if re.match(r"^\w+\s*=[^=]", a) else a
                    out |= evaluate(f, a, caller, depth + 1)
            if not seen:
                raise Unresolved(expr + " (a dummy of " + s.name + " that no call in the file passes)")
            return out
        # a local variable of this scope: its assignments
        rhs = f.assignments(name, s)
        if rhs:
            out = set()
            for r in rhs:
                # v = v//x: the tokens of x
                r_parts = [p for p in split_concat(r) if p.strip().lower() != name]
                out |= {"".join(t) for t in product_strings(f, r_parts, s, depth)}
            return out
    array = f.parameters.get(name)
    if array is not None:
        return {s.strip() for s in evaluate(f, array, scope, depth + 1)}
    raise Unresolved(expr)


def product_strings(f, parts, scope, depth):
    results = [""]
    for p in parts:
        results = [a + b for a in results for b in evaluate(f, p, scope, depth + 1)]
    return [[r] for r in results]


def split_concat(expr):
    parts, depth, quote, cur, i = [], 0, None, "", 0
    while i < len(expr):
        ch = expr[i]
        if quote:
            cur += ch
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
            cur += ch
        elif ch in "([":
            depth += 1
            cur += ch
        elif ch in ")]":
            depth -= 1
            cur += ch
        elif expr.startswith("//", i) and depth == 0:
            parts.append(cur)
            cur = ""
            i += 2
            continue
        else:
            cur += ch
        i += 1
    parts.append(cur)
    return [p.strip() for p in parts]


def groups_of(f, expr, scope, constants, depth=0):
    expr = expr.strip()
    if expr in constants:
        return {constants[expr]}
    if depth > MAX_DEPTH or not re.fullmatch(r"\w+", expr):
        raise Unresolved(expr)
    name = expr.lower()
    for s in scope.chain() if scope else []:
        if name in s.dummies:
            k = s.dummies.index(name)
            out = set()
            for args, caller in f.call_sites(s.name):
                if k < len(args):
                    out |= groups_of(f, args[k], caller, constants, depth + 1)
            if not out:
                raise Unresolved(expr)
            return out
        rhs = f.assignments(name, s)
        if rhs:
            out = set()
            for r in rhs:
                out |= groups_of(f, r, s, constants, depth + 1)
            return out
    raise Unresolved(expr)


def main():
    exe, src = sys.argv[1], sys.argv[2]
    table = card_table(exe)
    constants = group_constants(src)
    all_fields = set().union(*table.values())
    parameters = parameter_arrays(src)
    problems, checked = [], 0
    for path in sorted(glob.glob(os.path.join(src, "**", "*.f90"), recursive=True)):
        if os.path.basename(path) in DEFINITIONS:
            continue
        f = SourceFile(path, parameters)
        rel = os.path.relpath(path, src)
        for stmt, scope in f.where:
            if scope is not None and any(s.name in HELPERS for s in scope.chain()):
                continue
            for proc, (g_arg, n_arg) in GROUP_AND_NAME.items():
                for args in calls(stmt, proc):
                    if re.match(r"(?:\w+\s+)*function\s+" + proc, stmt, re.IGNORECASE):
                        continue
                    if len(args) <= max(g_arg, n_arg):
                        continue
                    try:
                        groups = groups_of(f, args[g_arg], scope, constants)
                        names = evaluate(f, args[n_arg], scope)
                    except Unresolved as e:
                        problems.append(f"{rel}: {proc}(...{args[n_arg]}): cannot tell the name or group ({e})")
                        continue
                    for n in names:
                        checked += 1
                        if not any(n in table.get(g, set()) for g in groups):
                            problems.append(f"{rel}: {proc}(..., {args[g_arg]}, ..., {args[n_arg]}): "
                                            f"no field {n!r} in *{'/*'.join(sorted(groups))}")
            for proc, (g_arg, l_arg) in FIELD_LISTS.items():
                for args in calls(stmt, proc):
                    if re.match(r"(?:\w+\s+)*(subroutine|function)\s+" + proc, stmt, re.IGNORECASE):
                        continue
                    if scope is not None and scope.name in ("field_list",) and proc == "field_where":
                        continue
                    if len(args) <= l_arg or args[l_arg].startswith(("fields", "names")) and scope and \
                            scope.name in ("problem", "problem_at", "located", "field_list"):
                        continue
                    try:
                        lists = evaluate(f, args[l_arg], scope)
                        groups = groups_of(f, args[g_arg], scope, constants) if g_arg is not None else None
                    except Unresolved as e:
                        problems.append(f"{rel}: {proc}(..., {args[l_arg]}): cannot tell the field names ({e})")
                        continue
                    for text in lists:
                        for n in text.split():
                            checked += 1
                            known = (any(n in table.get(g, set()) for g in groups) if groups else n in all_fields)
                            if not known:
                                problems.append(f"{rel}: {proc}(..., {args[l_arg]}): no field {n!r} in "
                                                + (f"*{'/*'.join(sorted(groups))}" if groups else "the card table"))
    for p in problems:
        print("FAIL: " + p)
    print(f"{checked} field names checked, {len(problems)} problems")
    return 1 if problems or checked < 100 else 0


if __name__ == "__main__":
    sys.exit(main())
