#!/usr/bin/env python3
"""How many dummy arguments of src/'s public procedures are documented, per folder and overall.

Counted: every module procedure that is public (named in a `public ::` statement, or in a
module without a bare `private` statement), including a separate module procedure declared
by its `module subroutine`/`module function` interface in the parent module. Not counted:
interface bodies of external libraries (LAPACK, GSL's bind(C) functions: the library documents
them), abstract interfaces, private procedures, internal procedures and submodules (their
arguments are declared in the parent's interface).

An argument is documented when its declaration statement has a trailing `!!` comment on one
of its lines, or when a comment block directly above the declaration starts with `!>`, or is
a block of `!!` lines that does not continue the previous line's trailing `!!` comment and does
not follow the procedure's own statement (there `!!` documents the procedure, FORD's rule). A
declaration of several arguments documents all of them.

Usage: python3 scripts/doc_coverage.py [--list] [SRC_DIR]   (default: the project's src/)
  --list   also print every undocumented argument (file:line procedure argument)
"""
import pathlib, re, sys
from collections import defaultdict

PROC_RE = re.compile(
    r'^(?:(?:pure|elemental|impure|recursive|module|non_recursive)\s+|'
    r'(?:real|integer|logical|complex|character|type|class)\s*(?:\([^)]*\))?\s*)*'
    r'(subroutine|function)\s+(\w+)\s*(\(([^)]*)\))?', re.I)
END_PROC_RE = re.compile(r'^end\s*(subroutine|function)\b', re.I)
END_BARE_RE = re.compile(r'^end\s*$', re.I)


def split_comment(line):
    """(code, comment) of one line; a `!` inside a string is code."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in '\'"':
            quote = ch
        elif ch == '!':
            return line[:i], line[i:]
    return line, ''


def statements(lines):
    """Join continuation lines: a list of (first line index, last line index, code, comments)."""
    out = []
    i = 0
    while i < len(lines):
        code, comment = split_comment(lines[i])
        first = i
        comments = [comment]
        code = code.rstrip()
        while code.endswith('&') and i + 1 < len(lines):
            i += 1
            nxt, c = split_comment(lines[i])
            comments.append(c)
            code = code[:-1] + ' ' + nxt.strip().lstrip('&')
            code = code.rstrip()
        out.append((first, i, code.strip(), comments))
        i += 1
    return out


def entity_names(decl):
    """Names declared after `::`, at the top parenthesis level."""
    rest = decl.split('::', 1)[1]
    names, depth, cur = [], 0, ''
    for ch in rest:
        if ch in '([':
            depth += 1
        elif ch in ')]':
            depth -= 1
        if ch == ',' and depth == 0:
            names.append(cur)
            cur = ''
        else:
            cur += ch
    names.append(cur)
    out = []
    for n in names:
        m = re.match(r'\s*(\w+)', n)
        if m:
            out.append(m.group(1).lower())
    return out


def above_documents(lines, first, header_line):
    """A comment block directly above line `first` documents it (see the module header)."""
    j = first - 1
    block = []
    while j >= 0 and lines[j].strip().startswith('!'):
        block.insert(0, lines[j].strip())
        j -= 1
    if not block:
        return False
    if block[0].startswith('!>'):
        return True
    if not block[0].startswith('!!'):
        return False
    if j < 0 or j == header_line:
        return False
    _, comment = split_comment(lines[j])
    return not comment.startswith('!!')


def is_declaration(code):
    return '::' in code and not re.match(r'^(use|public|private|procedure|generic)\b', code,
                                         re.I)


def procedure_args(lines, stmts, k, header_line):
    """Dummy arguments of the procedure whose statement is stmts[k]: {name: (line, doc)}."""
    m = PROC_RE.match(stmts[k][2])
    args = [a.strip().lower() for a in (m.group(4) or '').split(',') if a.strip()]
    found = {}
    depth = 0
    for first, last, code, comments in stmts[k + 1:]:
        low = code.lower()
        if depth == 0 and (re.match(r'^contains\b', low) or END_PROC_RE.match(low)
                           or END_BARE_RE.match(low)):
            break
        if re.match(r'^(abstract\s+)?interface\b', low) or re.match(r'^type\s*(,|::)', low):
            depth += 1
        elif re.match(r'^end\s*(interface|type)\b', low):
            depth -= 1
        if depth or not is_declaration(code):
            continue
        doc = any(c.startswith('!!') for c in comments) or \
            above_documents(lines, first, header_line)
        for name in entity_names(code):
            if name in args and name not in found:
                found[name] = (first + 1, doc)
    return [(a,) + found.get(a, (stmts[k][0] + 1, False)) for a in args]


def module_procedures(path):
    """(procedure, [(arg, line, documented)]) for every public procedure of one file."""
    lines = path.read_text().splitlines()
    stmts = statements(lines)
    if not stmts or not any(re.match(r'^module\s+\w+\s*$', s[2], re.I) for s in stmts):
        return []
    default_public = not any(re.match(r'^private\s*$', s[2], re.I) for s in stmts)
    public = set()
    for s in stmts:
        m = re.match(r'^public\s*(::)?\s*(.*)$', s[2], re.I)
        if m and m.group(2):
            public |= {n.strip().lower() for n in m.group(2).split(',')}
    result = []
    in_contains = False
    depth = 0          # procedures open inside the module's contains part
    iface = None       # kind of the interface block open in the specification part
    for k, (first, last, code, comments) in enumerate(stmts):
        low = code.lower()
        if re.match(r'^contains\b', low) and depth == 0 and iface is None:
            in_contains = True
            continue
        if not in_contains:
            m = re.match(r'^(abstract\s+)?interface\b', low)
            if m:
                iface = 'abstract' if m.group(1) else 'plain'
                continue
            if re.match(r'^end\s*interface\b', low):
                iface = None
                continue
            # separate module procedures: `module subroutine` bodies of a plain interface
            if iface == 'plain' and re.match(r'^(\w+\s+)*module\s+(subroutine|function)\b',
                                             low):
                m = PROC_RE.match(code)
                name = m.group(2).lower()
                if name in public or default_public:
                    result.append((name, procedure_args(lines, stmts, k, first)))
            continue
        m = PROC_RE.match(code)
        if m and not low.startswith('end'):
            depth += 1
            name = m.group(2).lower()
            if depth == 1 and (name in public or default_public):
                result.append((name, procedure_args(lines, stmts, k, first)))
        elif END_PROC_RE.match(low) or (END_BARE_RE.match(low) and depth > 0):
            depth -= 1
    return result


def main():
    argv = [a for a in sys.argv[1:] if a != '--list']
    listing = '--list' in sys.argv[1:]
    root = pathlib.Path(argv[0]) if argv else \
        pathlib.Path(__file__).resolve().parent.parent / 'src'
    totals = defaultdict(lambda: [0, 0, 0])     # folder -> procedures, arguments, documented
    missing = []
    for path in sorted(root.rglob('*.f90')):
        folder = path.parent.relative_to(root).as_posix()
        folder = 'src' if folder == '.' else 'src/' + folder
        for proc, args in module_procedures(path):
            totals[folder][0] += 1
            for arg, line, doc in args:
                totals[folder][1] += 1
                totals[folder][2] += doc
                if not doc:
                    missing.append(f'{path.relative_to(root.parent)}:{line}: {proc} {arg}')
    print(f'{"folder":16s} {"procedures":>10s} {"arguments":>10s} {"documented":>10s} '
          f'{"fraction":>8s}')
    all_ = [0, 0, 0]
    for folder in sorted(totals):
        p, a, d = totals[folder]
        all_ = [all_[0] + p, all_[1] + a, all_[2] + d]
        print(f'{folder:16s} {p:10d} {a:10d} {d:10d} {d / max(a, 1):8.1%}')
    p, a, d = all_
    print(f'{"overall":16s} {p:10d} {a:10d} {d:10d} {d / max(a, 1):8.1%}')
    if listing:
        print('\n'.join(missing))
    return 0


if __name__ == '__main__':
    sys.exit(main())
