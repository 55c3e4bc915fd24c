#!/usr/bin/env bash
# What the error estimates are worth (doc/OUTPUT.md, "Error estimates"): the physical example
# decks solved on N_e = 10, 20, ..., 1280 (the deck's grading and interpolations, the MESH
# card's N_e changed, --no-estimates), and for N_e = 40, 80, 160 each key result's estimate
# (the formula of error_estimate: the meshes N_e/2 and N_e/4 of the same family, which are in
# the sequence) against its error, the reference being the first-order extrapolation
# 2 Q(1280) - Q(640). Two rules for the credited order: the observed one up to 4, and the
# shipped one (at most 1 on a UNIFORM mesh with an end of the base in contact). Writes
# output/bench/error_estimates.md. Run from the project root (about a minute on two cores).
set -euo pipefail
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
decks="beam_physical strip_footing default tank_raft plate_physical"
for d in $decks; do
    for ne in 10 20 40 80 160 320 640 1280; do
        awk -v ne="$ne" '/^MESH/ { printf "MESH      %-10s%s\n", ne, substr($0, 21); next } { print }' \
            "input/$d.dat" >"$work/${d}_$ne.dat"
    done
done
ls "$work"/*.dat | xargs -P 2 -I{} "$bin" -q --no-figures --no-estimates -o "$work/out" {} \
    >/dev/null 2>&1
python3 - "$work/out" "$decks" >output/bench/error_estimates.md <<'PY'
import json, math, sys, platform, subprocess
out, decks = sys.argv[1], sys.argv[2].split()
keys = ['settlement_max', 'differential_settlement', 'moment_sagging', 'moment_hogging',
        'pressure_near_left_end', 'pressure_near_right_end', 'pressure_near_rim',
        'pressure_centre', 'shear_force_max']
NES = [10, 20, 40, 80, 160, 320, 640, 1280]

def richardson(q1, q2, q4, p_max):
    # error_estimate::richardson, ratio 2
    d12, d24 = q2 - q1, q4 - q2
    band = 3 * max(abs(d12), abs(d24) / 2)
    if d12 == 0 or d24 == 0 or (d12 > 0) != (d24 > 0):
        return band
    p = math.log(abs(d24) / abs(d12)) / math.log(2)
    if p < 0.5 or p > 4:
        return band
    return 1.25 * abs(d12) / (2 ** min(p, p_max) - 1)

def edge_in_contact(j, beam):
    # the last interval (the right end, the rim) or, for a beam, the first is in contact
    r = j['results']
    iv = sorted([(a, b, True) for a, b in r['contact_intervals']] +
                [(a, b, False) for a, b in r['liftoff_intervals']])
    return iv[-1][2] or (beam and iv[0][2])

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
print(f'Machine: {cpu}; the numbers do not depend on it. Reference: 2 Q(1280) - Q(640)')
print('(first order; for the EDGES decks, which converge faster, it is within |Q(1280) - Q(640)|')
print('of Q(1280)). "ratio" = estimate / error: above 1 the estimate bounds the error.')
print('"observed p" credits the observed order up to 4; "shipped" credits at most 1 on a UNIFORM')
print('mesh with an end of the base in contact (error_estimate::formal_order).')
print()
print('| deck | grading | key | N_e | error | estimate, observed p | ratio | estimate, shipped | ratio |')
print('|---|---|---|---:|---:|---:|---:|---:|---:|')
low = {'observed': 0, 'shipped': 0}
high = {'observed': 0, 'shipped': 0}
count = 0
for d in decks:
    vals = {ne: json.load(open(f'{out}/{d}_{ne}.json')) for ne in NES}
    grading = grading_of(f'input/{d}.dat')
    beam = vals[40]['model'] == 'BEAM'
    for k in keys:
        if k not in vals[10]['results']:
            continue
        if any(vals[n]['results'][k] is None for n in NES):
            continue
        f = lambda n: abs(vals[n]['results'][k]) if k == 'shear_force_max' else vals[n]['results'][k]
        ref = 2 * f(1280) - f(640)
        for n in (40, 80, 160):
            err = abs(f(n) - ref)
            e_obs = richardson(f(n), f(n // 2), f(n // 4), 4.0)
            cap = 1.0 if (grading == 'UNIFORM' and edge_in_contact(vals[n], beam)) else 4.0
            e_shp = richardson(f(n), f(n // 2), f(n // 4), cap)
            r_obs = e_obs / err if err > 0 else float('inf')
            r_shp = e_shp / err if err > 0 else float('inf')
            count += 1
            for name, r in (('observed', r_obs), ('shipped', r_shp)):
                low[name] += r < 0.5
                high[name] += r > 10
            print(f'| {d} | {grading} | {k} | {n} | {err:.3g} | {e_obs:.3g} | {r_obs:.2f} | {e_shp:.3g} | {r_shp:.2f} |')
print()
print(f'Of {count} estimates: below half the error, observed p {low["observed"]}, shipped '
      f'{low["shipped"]}; above ten times the error, observed p {high["observed"]}, shipped '
      f'{high["shipped"]}.')
PY
echo "estimate_study.sh: output/bench/error_estimates.md"
