#!/usr/bin/env bash
# Hard-case atlas (issue 8): input/atlas/beam.dat and plate.dat sweep rho 1e-6 ... 1e6,
# zeta 0.001 ... 0.5, f 0, 0.6, 2, eps_bar 1e-12, 1e-6, 0.1, nu_f 0, 0.5 (432 cases each, N_e
# 20). Writes output/atlas/: the summaries, atlas.md (outcomes by reason, the failures) and
# atlas.png (per model and f: outcome and linear solves over the rho-zeta plane; each point
# aggregates eps_bar and nu_f: the worst outcome and the most solves). The beam carries
# H = 0.3 V: with f = 0 it must slide (status 2, "sliding"); every other case is well posed
# and must solve. Run from the project root: bash scripts/atlas.sh
set -uo pipefail
cd "$(dirname "$0")/.."
fpm build >/dev/null
bin=$(fpm run --runner echo 2>/dev/null | tail -n 1)
out=output/atlas
mkdir -p "$out"
for m in beam plate; do
    "$bin" -q --no-figures --no-estimates -o "$out/run" "input/atlas/$m.dat" >/dev/null 2>"$out/$m.stderr"
    cp "$out/run/${m}_summary.csv" "$out/${m}_summary.csv"
done
rm -rf "$out/run"
python3 - "$out" <<'PY'
import csv, sys, math, collections
out = sys.argv[1]
lines = ['# Hard-case atlas', '', 'Cases: rho 1e-6 ... 1e6 (6), zeta 0.001 ... 0.5 (4), f 0, 0.6, 2,',
         'eps_bar 1e-12, 1e-6, 0.1, nu_f 0, 0.5; N_e 20, P1, Newton. Beam: central load with',
         'H = 0.3 V (f = 0 must slide); plate: disk load r <= 0.1 a.', '']
for m in ['beam', 'plate']:
    rows = list(csv.DictReader(open(f'{out}/{m}_summary.csv')))
    par = lambda r: dict(kv.split('=') for kv in r['parameters'].split(': ')[1].split())
    count = collections.Counter(); fails = []; solves = []
    grid = {}
    for r in rows:
        p = par(r); st = int(r['status']); msg = r['message']
        f = float(p['F']); expect_slide = (m == 'beam' and f * 1.0 < 0.3)
        if st == 0:
            kind = 'solved' if not expect_slide else 'WRONG: solved although it slides'
            solves.append(int(r['linear_solves']))
        elif 'sliding' in msg:
            kind = 'status 2, sliding (true)' if expect_slide else 'WRONG: sliding'
        else:
            kind = 'FAILED (well posed): ' + msg.split(':')[0][:60]
            fails.append((p, msg))
        count[kind] += 1
        key = (p['F'], float(p['RHO']), float(p['ZETA']))
        bad = 2 if kind.startswith(('FAILED', 'WRONG')) else (1 if st else 0)
        old = grid.get(key, (0, 0))
        grid[key] = (max(old[0], bad), max(old[1], int(r['linear_solves']) if st == 0 else 0))
    lines += [f'## {m}: {len(rows)} cases', '']
    lines += [f'| outcome | cases |', '|---|---|'] + [f'| {k} | {v} |' for k, v in sorted(count.items())]
    if solves:
        solves.sort()
        lines += ['', f'Linear solves of the solved cases: median {solves[len(solves)//2]}, '
                  f'90th percentile {solves[int(0.9*len(solves))]}, max {solves[-1]}.']
    if fails:
        lines += ['', 'Well-posed cases that failed (rho, zeta, f, eps_bar, nu_f: message):', '']
        for p, msg in fails[:40]:
            lines.append(f"- {p['RHO']} {p['ZETA']} {p['F']} {p['EPS_BAR']} {p['NU_F']}: {msg[:150]}")
    lines.append('')
    with open(f'{out}/{m}_map.dat', 'w') as g:
        for fval in ['0.0', '0.6', '2.0']:
            for (fv, rho, zeta), (bad, ns) in sorted(grid.items()):
                if fv == fval: g.write(f'{math.log10(rho)} {zeta} {bad} {ns}\n')
            g.write('\n\n')
open(f'{out}/atlas.md', 'w').write('\n'.join(lines) + '\n')
print('\n'.join(lines))
PY
cat >"$out/atlas.gp" <<GP
set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced
set output '$out/atlas.png'
set multiplot layout 2,3 title "Hard-case atlas: green solved, blue status 2 for the true reason (sliding), red failed;\nmarker size: linear solves; each point is the worst of eps_bar x nu_f" font 'Sans,13'
set logscale y; set xrange [-6.8:6.8]; set yrange [0.0006:0.9]; set grid
set xlabel 'log10 rho'; set ylabel 'zeta = h/l or h/a'
set palette defined (0 '#2ca02c', 1 '#1f77b4', 2 '#d62728'); set cbrange [0:2]; unset colorbox
set key off
fs = '0 0.6 2'
do for [m in 'beam plate'] {
  do for [i = 0:2] {
    set title sprintf('%s, f = %s', m, word(fs, i + 1))
    plot '$out/'.m.'_map.dat' index i u 1:2:(1 + sqrt(\$4)/1.5):3 w p pt 7 ps variable lc palette
  }
}
unset multiplot
GP
gnuplot "$out/atlas.gp" && echo "atlas.sh: $out/atlas.md, $out/atlas.png"
