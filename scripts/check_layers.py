#!/usr/bin/env python3
"""The layers of src/ (doc/ARCHITECTURE.md): a module may use modules of its own folder and
of the folders listed before it, never of a later one. Prints every back-edge (file, the
module it uses, both folders) and exits 1 if there is one.
Usage: python3 scripts/check_layers.py [SRC_DIR]   (default: the project's src/)
"""
import pathlib, re, sys

# from the bottom up; each folder may use itself and everything before it
LAYERS = ['.', 'gsl', 'linalg', 'model', 'fe', 'halfspace', 'contact', 'deck', 'results',
          'quality', 'output', 'driver']

def main():
    root = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else \
        pathlib.Path(__file__).resolve().parent.parent / 'src'
    folder_of = {}
    uses = {}
    for path in sorted(root.rglob('*.f90')):
        folder = path.parent.relative_to(root).as_posix()
        text = path.read_text()
        m = re.search(r'^\s*module\s+(\w+)\s*$', text, re.M | re.I)
        if not m:
            continue
        name = m.group(1).lower()
        folder_of[name] = folder
        uses[name] = (path, {u.lower() for u in re.findall(r'^\s*use\s+(\w+)', text, re.M | re.I)})
    unknown = sorted({f for f in folder_of.values() if f not in LAYERS})
    if unknown:
        print('folders not in the layer list:', ', '.join(unknown))
        return 1
    bad = 0
    for name, (path, used) in sorted(uses.items()):
        level = LAYERS.index(folder_of[name])
        for u in sorted(used):
            if u in folder_of and LAYERS.index(folder_of[u]) > level:
                print(f'{path.relative_to(root)}: {name} ({folder_of[name]}) uses '
                      f'{u} ({folder_of[u]})')
                bad += 1
    print(f'{len(uses)} modules in {len(LAYERS)} layers, {bad} back-edges')
    return 1 if bad else 0

if __name__ == '__main__':
    sys.exit(main())
