#!/usr/bin/env python3
"""Does ADAPT pay? From one run of example/work_precision (its two tables), for each ADAPT
family at tol 1e-3 and 1e-4: the true error of its final mesh (plate: the larger of the
relative errors of W(0) and Sigma_z(0); beam: of W(0) and max |M|, Sigma_z(0) being singular
under the point load), its time (the whole adaptation), and the time each fixed family needs
to reach the same error (log-log interpolation along its rows, first crossing; '-' where its
rows never reach it), the cheapest of them named. Usage:
    python3 scripts/adapt_pays.py DIR > output/bench/adapt_pays.md
with DIR holding work_precision_{plate,beam}.txt."""
import math
import sys

TOLS = {1.0e-2: 0, 3.0e-3: 1, 1.0e-3: 2, 3.0e-4: 3, 1.0e-4: 4}   # row order of tol_list
COLS = {'plate': (4, 5), 'beam': (4, 7)}   # err_W0 and err_Sz0 / err_Mmax columns


def rows_of(path, cols, extent=False):
    """Per family its rows (N_e, time, compared error[, contact extent error])."""
    fam = {}
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        f = line.split()
        if f[2] == 'failed' or (len(f) > 3 and f[3] == 'failed'):
            continue
        err = max(float(f[cols[0]]), float(f[cols[1]]))
        row = (int(f[1]), float(f[3]), err) + ((float(f[8]),) if extent else ())
        fam.setdefault(f[0], []).append(row)
    return fam


def guarantee(out):
    """Every ADAPT run of the study (all five tols): how many end with the compared error,
    or the contact extent's (absolute, in t, as ADAPT's key), above their tol."""
    tols = sorted(TOLS, key=TOLS.get)
    lines, n, above = [], 0, []
    for case in ('plate', 'beam'):
        fam = rows_of(f'{out}/work_precision_{case}.txt', COLS[case], extent=True)
        for name in [k for k in fam if 'ADAPT' in k]:
            for (ne, _, e, ext), tol in zip(fam[name], tols):
                n += 1
                if e > tol:
                    above.append(f'{case} {name} tol {tol:.0e}: error {e:.2e}')
                if ext > tol:
                    above.append(f'{case} {name} tol {tol:.0e}: contact extent {ext:.2e}')
    lines.append(f'ADAPT runs in this study: {n} (tol 1e-2 ... 1e-4); true errors above tol'
                 f' (compared error, or the contact extent in t): '
                 + ('; '.join(above) if above else 'none') + '.')
    return lines


def reference_floor(path, case):
    """The larger relative uncertainty of the run's reference of the two compared quantities:
    an error below it is not resolved."""
    names = {'plate': ('W(0)', 'Sigma_z(0)'), 'beam': ('W(0)', 'max|M|')}[case]
    floor = 0.0
    for line in open(path):
        f = line[1:].split()
        if line.startswith('#') and len(f) >= 4 and f[0] in names and f[2] == 'uncertainty':
            floor = max(floor, float(f[3]) / abs(float(f[1])))
    return floor


def time_to_reach(rows, target):
    """Time from which the family stays at or below target: after its last row above
    target, log-log interpolated into the row before (a lucky dip of an erratic family
    followed by larger errors does not count: a user could not know where it lies)."""
    above = [k for k, (_, _, e) in enumerate(rows) if e > target]
    if not above:
        return rows[0][1]
    k = above[-1] + 1
    if k >= len(rows):
        return extrapolated(rows, target)
    (_, t0, e0), (_, t, e) = rows[k - 1], rows[k]
    if e <= 0 or e0 == e:
        return t
    s = (math.log(target) - math.log(e0)) / (math.log(e) - math.log(e0))
    return math.exp(math.log(t0) + s * (math.log(t) - math.log(t0)))


def extrapolated(rows, target):
    """Beyond the last row: error and time as powers of N_e from the last two rows (None
    when the error did not fall between them); returned negative to mark it."""
    (n0, t0, e0), (n1, t1, e1) = rows[-2], rows[-1]
    if not (0 < e1 < e0 and t1 > 0 and t0 > 0):
        return None
    p = math.log(e0 / e1) / math.log(n1 / n0)
    q = math.log(t1 / t0) / math.log(n1 / n0)
    n = n1 * (e1 / target) ** (1.0 / p)
    return -t1 * (n / n1) ** q


def main():
    out = sys.argv[1]
    print('# Does ADAPT pay? (scripts/adapt_pays.py on one run of example/work_precision)')
    print()
    print('Error: plate max(err W(0), err Sigma_z(0)), beam max(err W(0), err max|M|), relative'
          ' to the run\'s reference. "cheapest fixed": the fixed discretisation that reaches'
          ' the same error in the least time and stays there (after its last row above the error,'
          ' log-log interpolated into the row before); where none of its rows'
          ' reaches it, each would need more than its last row\'s time, the least of which is'
          ' given as a bound, unless it is extrapolated (error and time as powers of N_e from the'
          ' family\'s last two rows; its last row, which has not reached the error, and that row\'s'
          ' time are given with it: ADAPT / that time bounds the ratio from rows alone).'
          ' Fixed-mesh times are one solve without estimates; ADAPT\'s are'
          ' the whole adaptation, its estimate solves included. The fixed families run on to'
          ' N_e = 1280, and beyond while above the smallest ADAPT error (at most 13000 unknowns).'
          ' "<= tol": the true error of ADAPT\'s result is at most its tol (ADAPT\'s guarantee);'
          ' an error marked * is below the reference\'s own relative uncertainty (max of the two'
          ' quantities, given under the table): the ratios at that error compare against an'
          ' error the reference does not resolve.')
    print()
    print('| case | ADAPT family | tol | N_e | error | <= tol | time [s] | same interpolation,'
          ' UNIFORM | its time [s] | ADAPT / it | cheapest UNIFORM | its time [s] | ADAPT / it'
          ' | cheapest fixed | its time [s] | ADAPT / it |')
    print('|---|---|---:|---:|---:|---|---:|---|---:|---:|---|---:|---:|---|---:|---:|')
    floors = {}
    for case in ('plate', 'beam'):
        path = f'{out}/work_precision_{case}.txt'
        floors[case] = reference_floor(path, case)
        fam = rows_of(path, COLS[case])
        fixed = {k: v for k, v in fam.items() if 'ADAPT' not in k}
        for name in [k for k in fam if 'ADAPT' in k]:
            for tol in (1.0e-3, 1.0e-4):
                ne, t, e = fam[name][TOLS[tol]]
                cells = []
                same = name.replace('ADAPT', 'UNIFORM')
                for pool in ({same: fixed[same]},
                             {k: v for k, v in fixed.items() if 'UNIFORM' in k}, fixed):
                    best, tbest = '-', None
                    for fname, rows in pool.items():
                        tf = time_to_reach(rows, e)
                        if tf is not None and (tbest is None or abs(tf) < abs(tbest)):
                            best, tbest = fname, tf
                    if tbest is None:   # no row reaches e: each family needs more than its last
                        tlast = min(rows[-1][1] for rows in pool.values())
                        cells += ['none reached', f'> {tlast:.2e}', f'< {t / tlast:.1f}']
                        continue
                    mark = ''
                    if tbest < 0:   # its last row, above the error, already took this long
                        n_last, t_last = pool[best][-1][0], pool[best][-1][1]
                        mark = f' (extrapolated; N_e {n_last}: {t_last:.2g} s)'
                    cells += [best + mark, f'{abs(tbest):.2e}', f'{t / abs(tbest):.2g}']
                star = '*' if e < floors[case] else ''
                ok = 'yes' if e <= tol else '**NO**'
                print(f'| {case} | {name} | {tol:.0e} | {ne} | {e:.2e}{star} | {ok} | {t:.2e} | '
                      + ' | '.join(cells) + ' |')
    print()
    print('Reference uncertainty (relative, the larger of the two compared quantities): '
          + ', '.join(f'{c} {f:.1e}' for c, f in floors.items()) + '.')
    print()
    for line in guarantee(out):
        print(line)


if __name__ == '__main__':
    main()
