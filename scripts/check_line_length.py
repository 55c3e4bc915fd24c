#!/usr/bin/env python3
"""Source lines of at most 100 characters (../shared/STYLE.md, as doc/ARCHITECTURE.md cites it):
every .f90 and .c file under src/, app/, test/ and example/ of ROOT (default: the project).
Characters, not bytes (a UTF-8 '²' is one). Prints each longer line as FILE:LINE: LENGTH and
exits 1 if there is one, else 0.

    python3 scripts/check_line_length.py [ROOT]
"""
import os
import sys

LIMIT = 100
FOLDERS = ('src', 'app', 'test', 'example')


def long_lines(root):
    """(path, line number, length) of every line over LIMIT characters."""
    found = []
    for folder in FOLDERS:
        for base, _, names in sorted(os.walk(os.path.join(root, folder))):
            for name in sorted(names):
                if not name.endswith(('.f90', '.c')):
                    continue
                path = os.path.join(base, name)
                with open(path, encoding='utf-8') as source:
                    for number, line in enumerate(source, 1):
                        length = len(line.rstrip('\n'))
                        if length > LIMIT:
                            found.append((os.path.relpath(path, root), number, length))
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..')
    found = long_lines(root)
    for path, number, length in found:
        print(f'{path}:{number}: {length} characters (at most {LIMIT})')
    print(f'{len(found)} lines over {LIMIT} characters')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
