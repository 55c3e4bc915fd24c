#!/usr/bin/env bash
# What the error estimates are worth on the physical example decks (doc/OUTPUT.md, "Error
# estimates"): each deck solved on N_e = 40, 80, 160 with its estimates (the program's own:
# the refined solve, error_estimate) and on N_e = 640, 1280 without, all with the deck's
# grading and interpolations (the MESH card's N_e changed); each key result's estimate
# against its error, the reference being the first-order extrapolation 2 Q(1280) - Q(640).
# The broad reference set with extrapolated and held-out cases is
# example/estimate_effectivity.f90; this study is the shipped decks. Writes
# output/bench/error_estimates.md. Run from the project root (a few minutes on two cores).
set -euo pipefail
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
decks="beam_physical strip_footing default tank_raft plate_physical"
for d in $decks; do
    for ne in 40 80 160 640 1280; do
        awk -v ne="$ne" '/^MESH/ { printf "MESH      %-10s%s\n", ne, substr($0, 21); next } { print }' \
            "input/$d.dat" >"$work/${d}_$ne.dat"
    done
done
ls "$work"/*_{40,80,160}.dat | xargs -P 2 -I{} "$bin" -q --no-figures -o "$work/out" {} \
    >/dev/null 2>&1
ls "$work"/*_{640,1280}.dat | xargs -P 2 -I{} "$bin" -q --no-figures --no-estimates \
    -o "$work/out" {} >/dev/null 2>&1
python3 - "$work/out" "$decks" >output/bench/error_estimates.md <<'PY'
import json, sys
out, decks = sys.argv[1], sys.argv[2].split()
keys = ['settlement_max', 'differential_settlement', 'contact_extent_t', 'moment_sagging',
        'moment_hogging', 'pressure_near_left_end', 'pressure_near_right_end',
        'pressure_near_rim', 'pressure_centre', 'shear_force_max']
NES = [40, 80, 160, 640, 1280]

def grading_of(path):
    for line in open(path):
        if line.startswith('MESH'):
            return line[20:30].strip() or 'UNIFORM'
    return 'UNIFORM'

cpu = 'unknown'
try:
    for line in open('/proc/cpuinfo'):
        if line.startswith('model name'):
            cpu = line.split(':', 1)[1].strip(); break
except OSError:
    pass
print('# Error estimates against their errors (scripts/estimate_study.sh)')
print()
print(f'Machine: {cpu}; the numbers do not depend on it. Estimates: the program\'s own (the case')
print('re-solved on its mesh with every element cut in two and with every other node removed;')
print('doc/OUTPUT.md, "Error estimates"). Reference: 2 Q(1280) - Q(640) (first order; for the')
print('EDGES decks, which converge faster, it is within |Q(1280) - Q(640)| of Q(1280)), with')
print('|Q(1280) - Q(640)| as its bar: a result enters the counts only where that bar is at most')
print('a fifth of its error (marked "ref" otherwise). "ratio" = estimate / error.')
print()
print('| deck | grading | key | N_e | value | error | estimate | ratio |')
print('|---|---|---|---:|---:|---:|---:|---:|')
ratios = []
for d in decks:
    vals = {ne: json.load(open(f'{out}/{d}_{ne}.json')) for ne in NES}
    grading = grading_of(f'input/{d}.dat')
    for k in keys:
        if any(vals[n]['results'].get(k) is None for n in NES):
            continue
        f = lambda n: abs(vals[n]['results'][k]) if k == 'shear_force_max' else vals[n]['results'][k]
        ref = 2 * f(1280) - f(640)
        bar = abs(f(1280) - f(640))
        for n in (40, 80, 160):
            est = (vals[n].get('errors') or {}).get(k)
            if est is None:
                continue
            err = abs(f(n) - ref)
            if err <= 1e-10 * abs(ref):
                continue
            r = est / err
            good = bar <= 0.2 * err
            if good:
                ratios.append(r)
            mark = '' if good else ' ref'
            print(f'| {d} | {grading} | {k} | {n} | {f(n):.6g} | {err:.3g} | {est:.3g} | {r:.2f}{mark} |')
print()
n = len(ratios)
if n:
    s = sorted(ratios)
    print(f'Of {n} estimates with a reference good to a fifth of the error: median ratio '
          f'{s[n // 2]:.2f}, {sum(r < 0.2 for r in s)} below 0.2, {sum(r < 0.5 for r in s)} below 0.5, '
          f'{sum(0.5 <= r <= 5 for r in s)} in [0.5, 5] ({100 * sum(0.5 <= r <= 5 for r in s) / n:.0f} %), '
          f'{sum(r > 10 for r in s)} above 10.')
PY
echo "estimate_study.sh: output/bench/error_estimates.md"
