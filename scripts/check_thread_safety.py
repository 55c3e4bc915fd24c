#!/usr/bin/env python3
"""Code that runs on several threads at once calls no function whose result is a deferred-length
character (`character(len=:), allocatable`).

gfortran (12, and 11) keeps the length of such a result in a static variable of the caller, one
per call site, even with -fopenmp: two threads at the same call site overwrite each other's
length, and a text comes out empty or cut (seen: an empty key in a sweep's JSON, 2 of 2925
files). The cases of a sweep run in parallel (driver/analysis_driver); their files are written
inside one critical section, but the solve, the key results, the warnings and the design checks
run outside it. This check lists every function with a deferred-length character result and
fails where one is referenced from the rooms that run outside the critical section.

It also fails on an INQUIRE by file name (`inquire (file=...)`) in those rooms and in output/
(whose writers run inside the critical section while the other threads run): gfortran's
INQUIRE by name waits for the lock of every open unit, so it waited for another thread's
unit held through a gnuplot's answer, and a sweep's figures stopped using the second core
(1000 cases: 2.0 times as fast on two threads before, 1.0 with one such INQUIRE).

Usage: python3 scripts/check_thread_safety.py [SRC_DIR]   (default: the project's src/)
"""
import os
import re
import sys

# folders and files whose code runs on several threads at once (doc/ARCHITECTURE.md)
PARALLEL_FOLDERS = ['gsl', 'linalg', 'model', 'fe', 'halfspace', 'contact', 'results', 'quality']
PARALLEL_FILES = ['deck/plausibility.f90', 'output/figure_renderer.f90',
                  'output/temporary_cleanup.f90']

FUNC = re.compile(r'^\s*(?:(?:pure|elemental|recursive|impure|module)\s+)*function\s+(\w+)\s*\('
                  r'[^)]*\)\s*(?:result\s*\(\s*(\w+)\s*\))?', re.I)
DEFERRED = re.compile(r'character\s*\(\s*len\s*=\s*:\s*\)\s*,\s*allocatable\s*::\s*([\w\s,]+)', re.I)
END_FUNC = re.compile(r'^\s*end\s+function', re.I)
RENAME = re.compile(r'(\w+)\s*=>\s*(\w+)')
INQUIRE_FILE = re.compile(r'\binquire\s*\(\s*file\s*=', re.I)
# folders whose code runs while a sweep's threads run (the writers: inside the critical section)
SWEEP_FOLDERS = PARALLEL_FOLDERS + ['output']


def sources(src):
    for folder, _, files in os.walk(src):
        for f in files:
            if f.endswith('.f90'):
                yield os.path.join(folder, f)


def code_lines(path):
    """The file's lines without comments and strings (so names in texts do not count)."""
    out = []
    for line in open(path, encoding='utf-8'):
        line = re.sub(r"'[^']*'|\"[^\"]*\"", "''", line)
        out.append(line.split('!')[0])
    return out


def deferred_functions(src):
    names = set()
    for path in sources(src):
        current = None
        for line in code_lines(path):
            m = FUNC.match(line)
            if m:
                current = (m.group(2) or m.group(1)).lower(), m.group(1).lower()
                continue
            if current and END_FUNC.match(line):
                current = None
                continue
            d = DEFERRED.search(line)
            if current and d:
                declared = [v.strip().lower() for v in d.group(1).split(',')]
                if current[0] in declared:
                    names.add(current[1])
    return names


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', 'src')
    names = deferred_functions(src)
    bad = 0
    for path in sorted(sources(src)):
        rel = os.path.relpath(path, src).replace(os.sep, '/')
        if rel.split('/')[0] in SWEEP_FOLDERS or rel in PARALLEL_FILES:
            for k, line in enumerate(code_lines(path), 1):
                if INQUIRE_FILE.search(line):
                    print(f'{rel}:{k}: INQUIRE by file name (waits for every open unit)')
                    bad += 1
        if rel.split('/')[0] not in PARALLEL_FOLDERS and rel not in PARALLEL_FILES:
            continue
        lines = code_lines(path)
        local = set(names)
        for line in lines:          # use ..., only: local => remote
            for a, b in RENAME.findall(line):
                if b.lower() in names:
                    local.add(a.lower())
        for line in lines:          # a variable of the same name (an array) is not the function
            if '::' in line and not re.match(r'^\s*(use|public|private)\b', line, re.I):
                for v in re.findall(r'(\w+)\s*(?:\(|=|,|$)', line.split('::', 1)[1]):
                    local.discard(v.lower())
        for k, line in enumerate(lines, 1):
            if FUNC.match(line):
                continue
            for name in local:
                if re.search(r'(?<![\w%])' + name + r'\s*\(', line, re.I) and \
                        not re.match(r'^\s*(use|public|private)\b', line, re.I):
                    print(f'{rel}:{k}: calls {name} (a deferred-length character result)')
                    bad += 1
    print(f'{len(names)} functions with deferred-length character results; '
          f'{bad} calls or INQUIREs by name from code that runs on several threads')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
