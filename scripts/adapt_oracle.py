#!/usr/bin/env python3
"""A bound on what a better stop decision could give ADAPT. From one run of
example/work_precision: for each ADAPT family and target error T (1e-3, 1e-4), the cheapest of
its runs (tol 1e-2 ... 1e-4) whose true error is at or below T (an ADAPT that knew its true
error would stop there, on the meshes it makes), against the time the cheapest uniform and
the cheapest fixed family need to reach T (scripts/adapt_pays.py's time_to_reach). Usage:
    python3 scripts/adapt_oracle.py DIR
with DIR holding work_precision_{plate,beam}.txt."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from adapt_pays import COLS, rows_of, time_to_reach   # noqa: E402

TOL_LIST = [1.0e-2, 3.0e-3, 1.0e-3, 3.0e-4, 1.0e-4]   # row order of the ADAPT families


def cheapest(pool, target):
    best, tbest = None, None
    for name, rows in pool.items():
        t = time_to_reach(rows, target)
        if t is not None and (tbest is None or abs(t) < abs(tbest)):
            best, tbest = name, t
    return best, tbest


def main():
    out = sys.argv[1]
    print('| case | ADAPT family | target | cheapest ADAPT run at or below it | N_e | its time [s]'
          ' | cheapest UNIFORM to the target | its time [s] | ADAPT / it'
          ' | cheapest fixed | its time [s] | ADAPT / it |')
    print('|---|---|---:|---|---:|---:|---|---:|---:|---|---:|---:|')
    for case in ('plate', 'beam'):
        fam = rows_of(f'{out}/work_precision_{case}.txt', COLS[case])
        fixed = {k: v for k, v in fam.items() if 'ADAPT' not in k}
        uniform = {k: v for k, v in fixed.items() if 'UNIFORM' in k}
        for name in [k for k in fam if 'ADAPT' in k]:
            for target in (1.0e-3, 1.0e-4):
                runs = [(t, tol, ne) for (ne, t, e), tol in zip(fam[name], TOL_LIST)
                        if e <= target]
                if not runs:
                    print(f'| {case} | {name} | {target:.0e} | none | | | | | | | | |')
                    continue
                t, tol, ne = min(runs)
                cells = []
                for pool in (uniform, fixed):
                    best, tb = cheapest(pool, target)
                    if tb is None:
                        cells += ['none reached', '', '']
                        continue
                    mark = ' (extrapolated)' if tb < 0 else ''
                    cells += [best + mark, f'{abs(tb):.2e}', f'{t / abs(tb):.1f}']
                print(f'| {case} | {name} | {target:.0e} | tol {tol:.0e} | {ne} | {t:.2e} | '
                      + ' | '.join(cells) + ' |')


if __name__ == '__main__':
    main()
