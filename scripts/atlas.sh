#!/usr/bin/env bash
# Hard-case atlas (issue 8): input/atlas/beam.dat and plate.dat sweep rho 1e-6 ... 1e6,
# zeta 0.001 ... 0.5, f 0, 0.6, 2, eps_bar 1e-12, 1e-6, 0.1, nu_f 0, 0.5 (432 cases each, N_e
# 20). Writes output/atlas/: the summaries, atlas.md (outcomes by reason, the failures) and
# atlas.png (per model and f: outcome and linear solves over the rho-zeta plane; each point
# aggregates eps_bar and nu_f: the worst outcome and the most solves). The beam carries
# H = 0.3 V: with f = 0 it must slide (status 2, "sliding"); every other case is well posed
# and must solve. The edges (atlas_edges.png, same atlas.md): beam_utilisation.dat (H/(fV)
# from 0.5 to 2: sliding exactly when above 1), beam_eccentric.dat (a load 0.05 l from the
# end: the contact shrinks to a small zone) and plate_meshes.dat (soft to stiff plates), both
# on meshes up to N_e = 2000 (a few minutes on two cores).
# Run from the project root: bash scripts/atlas.sh
set -uo pipefail
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
out=output/atlas
mkdir -p "$out"
for m in beam plate beam_utilisation beam_eccentric plate_meshes; do
    "$bin" -q --no-figures --no-estimates -o "$out/run" "input/atlas/$m.dat" >/dev/null 2>"$out/$m.stderr"
    cp "$out/run/${m}_summary.csv" "$out/${m}_summary.csv"
done
rm -rf "$out/run"
python3 - "$out" "$bin" <<'PY'
import csv, sys, math, collections, os, subprocess, tempfile
out = sys.argv[1]
fricon = os.path.abspath(sys.argv[2])

def finer(m, p, ne=80):
    # A failed well-posed case re-solved alone on N_e = ne (the atlas decks use 20): tells a
    # failure of the method from a mesh too coarse for the case (doc/CHOICES.md).
    cards = []
    for line in open(f'input/atlas/{m}.dat'):
        name = line[:10].strip()
        if name == 'SWEEP' or line.startswith('*'):
            continue
        fields = [line[10 + 10*i:20 + 10*i].strip() for i in range(7)]
        if name == 'NONDIM':
            fields[0], fields[1], fields[3] = p['RHO'], p['ZETA'], p['NU_F']
        elif name == 'FRICTION':
            fields[0], fields[1] = p['F'], p['EPS_BAR']
        elif name == 'MESH':
            fields[0] = str(ne)
        if name in ('NONDIM', 'FRICTION', 'MESH'):
            line = f'{name:<10}' + ''.join(f'{v:<10}' for v in fields).rstrip() + '\n'
        cards.append(line)
    with tempfile.TemporaryDirectory() as tmp:
        deck = os.path.join(tmp, 'finer.dat')
        open(deck, 'w').writelines(cards)
        st = subprocess.run([fricon, '-q', '--no-figures', '--no-estimates', '-o',
                             os.path.join(tmp, 'out'), deck], capture_output=True).returncode
    return f'on N_e = {ne}: ' + ('solved' if st == 0 else f'status {st}')

def cases(name):
    rows = list(csv.DictReader(l for l in open(f'{out}/{name}_summary.csv') if not l.startswith('#')))
    for r in rows:
        r['p'] = dict(kv.split('=') for kv in r['parameters'].split(': ')[1].split())
    return rows

def edges(out):
    # The edges of the atlas: expected outcome from statics (sliding iff H > f V), every
    # other case must solve; tables and the data of atlas_edges.png.
    md = ['## Edges: utilisation, a small contact zone, meshes to N_e = 2000', '']
    rows = cases('beam_utilisation')
    md += ['Beam, central load with H = 0.3 V, rho 1e-4 ... 1e6, zeta 0.01 and 0.1, eps_bar 1e-12',
           'and 1e-6, N_e 40: outcome against the utilisation H/(fV) (statics: sliding iff > 1).', '',
           '| f | H/(fV) | cases | solved | status 2, sliding | other failures | max linear solves |',
           '|---|---|---|---|---|---|---|']
    with open(f'{out}/utilisation.dat', 'w') as g:
        for f in sorted({r['p']['F'] for r in rows}, key=float):
            sel = [r for r in rows if r['p']['F'] == f]
            u = math.inf if float(f) == 0 else 0.3 / float(f)
            ok = [r for r in sel if r['status'] == '0']
            sl = [r for r in sel if r['status'] != '0' and 'sliding' in r['message']]
            bad = len(sel) - len(ok) - len(sl)
            wrong = (u > 1 and len(ok) > 0) or (u <= 1 and len(sl) > 0)
            ns = max([int(r['linear_solves']) for r in ok], default=0)
            md.append(f'| {f} | {u:.3g} | {len(sel)} | {len(ok)} | {len(sl)} | {bad}{" WRONG" if wrong else ""} | {ns} |')
            for r in sel:
                st = 0 if r['status'] == '0' else (1 if 'sliding' in r['message'] else 2)
                g.write(f"{min(u, 2.5)} {math.log10(float(r['p']['RHO']))} {st} "
                        f"{int(r['linear_solves']) if st == 0 else 0}\n")
    for name, text, key in [('beam_eccentric', 'Beam, vertical load 0.05 l from the end (contact '
                             'shrinking to about 0.15 l), rho 1e-4 ... 1e6, f 0 and 0.6', 'contact_length'),
                            ('plate_meshes', 'Plate, disk load r <= 0.1 a, rho 1e-6 ... 1e3, '
                             'f 0 and 0.6', 'contact_extent_t')]:
        rows = cases(name)
        md += ['', text + ': by mesh.', '',
               '| N_e | cases | solved | failed | median / max linear solves | contact extent (min ... max) |',
               '|---|---|---|---|---|---|']
        nes = sorted({int(r['p']['NE']) for r in rows})
        for ne in nes:
            sel = [r for r in rows if int(r['p']['NE']) == ne]
            ok = [r for r in sel if r['status'] == '0']
            ns = sorted(int(r['linear_solves']) for r in ok)
            ext = [float(r[key]) for r in ok if r[key]]
            md.append(f'| {ne} | {len(sel)} | {len(ok)} | {len(sel) - len(ok)} | '
                      f'{ns[len(ns)//2] if ns else "-"} / {ns[-1] if ns else "-"} | '
                      f'{min(ext):.4f} ... {max(ext):.4f} |' if ext else f'| {ne} | {len(sel)} | 0 | {len(sel)} | - | - |')
        for r in rows:
            if r['status'] != '0':
                md.append(f"- FAILED {r['parameters']}: {r['message'][:120]}")
        with open(f'{out}/{name}.dat', 'w') as g:
            for rho in sorted({r['p']['RHO'] for r in rows}, key=float):
                for f in sorted({r['p']['F'] for r in rows}, key=float):
                    for r in sorted([r for r in rows if r['p']['RHO'] == rho and r['p']['F'] == f],
                                    key=lambda r: int(r['p']['NE'])):
                        g.write(f"{r['p']['NE']} {r[key] or 'nan'} {r['linear_solves'] if r['status'] == '0' else 'nan'} "
                                f"{rho} {f}\n")
                    g.write('\n\n')
    md.append('')
    return md
lines = ['# Hard-case atlas', '', 'Cases: rho 1e-6 ... 1e6 (6), zeta 0.001 ... 0.5 (4), f 0, 0.6, 2,',
         'eps_bar 1e-12, 1e-6, 0.1, nu_f 0, 0.5; N_e 20, P1, Newton. Beam: central load with',
         'H = 0.3 V (f = 0 must slide); plate: disk load r <= 0.1 a.', '']
for m in ['beam', 'plate']:
    rows = list(csv.DictReader(l for l in open(f'{out}/{m}_summary.csv') if not l.startswith('#')))
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
    # solved on a finer mesh than the deck's: fricon's warning (doc/CHOICES.md, very soft beams)
    refined = [l.split(': ', 2)[1].split(' (')[0] + ': ' + l.split('): ', 1)[1].split(':')[0]
               for l in open(f'{out}/{m}.stderr') if 'mesh refined from' in l]
    if refined:
        lines += ['', f'Solved on a mesh refined by fricon (friction not resolved pointwise on '
                  f'N_e = 20; doc/CHOICES.md): {len(refined)}', '']
        lines += [f'- {r}' for r in refined]
    if solves:
        solves.sort()
        lines += ['', f'Linear solves of the solved cases: median {solves[len(solves)//2]}, '
                  f'90th percentile {solves[int(0.9*len(solves))]}, max {solves[-1]}.']
    if fails:
        lines += ['', 'Well-posed cases that failed (rho, zeta, f, eps_bar, nu_f: message):', '']
        for p, msg in fails[:40]:
            lines.append(f"- {p['RHO']} {p['ZETA']} {p['F']} {p['EPS_BAR']} {p['NU_F']}: {msg[:150]}"
                         f" ({finer(m, p)})")
    lines.append('')
    with open(f'{out}/{m}_map.dat', 'w') as g:
        for fval in ['0.0', '0.6', '2.0']:
            for (fv, rho, zeta), (bad, ns) in sorted(grid.items()):
                if fv == fval: g.write(f'{math.log10(rho)} {zeta} {bad} {ns}\n')
            g.write('\n\n')
lines += edges(out)
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
cat >"$out/atlas_edges.gp" <<GP
set terminal pngcairo size 1600,1000 font 'Sans,11' noenhanced
set output '$out/atlas_edges.png'
set multiplot layout 2,3 title "Hard-case atlas, edges: utilisation up to and beyond 1, a small contact zone, meshes to N_e = 2000; solid lines f = 0, dashed f = 0.6" font 'Sans,13'
set grid
set palette defined (0 '#2ca02c', 1 '#1f77b4', 2 '#d62728'); set cbrange [0:2]; unset colorbox
set title 'beam, H = 0.3 V: green solved, blue sliding (status 2), red failed'
set xlabel 'utilisation H/(f V)  (f = 0 drawn at 2.5)'; set ylabel 'log10 rho'
set xrange [0.3:2.7]; set yrange [-4.8:6.8]; set key off
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dt 2 lc 'black'
plot '$out/utilisation.dat' u 1:2:(1 + sqrt(\$4)/1.5):3 w p pt 7 ps variable lc palette
unset arrow 1
set xrange [*:*]; set yrange [*:*]; set logscale x; set key top right font 'Sans,9'
rhos = '1e-4 1e-2 1 1e2 1e4 1e6'
set title 'beam, load 0.05 l from the end: contact length'
set xlabel 'N_e'; set ylabel 'contact length / l'
plot for [i = 0:11] '$out/beam_eccentric.dat' index i u 1:2 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(rhos, i/2 + 1) : '')
set title 'beam, load 0.05 l from the end: linear solves'
set ylabel 'linear solves of the case'
plot for [i = 0:11] '$out/beam_eccentric.dat' index i u 1:3 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(rhos, i/2 + 1) : '')
prhos = '1e-6 1e-3 1 1e3'
set title 'plate, disk load: contact extent'
set ylabel 'contact extent r/a'
plot for [i = 0:7] '$out/plate_meshes.dat' index i u 1:2 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(prhos, i/2 + 1) : '')
set title 'plate, disk load: linear solves (failures: missing points)'
set ylabel 'linear solves of the case'
plot for [i = 0:7] '$out/plate_meshes.dat' index i u 1:3 w lp lt (i/2 + 1) pt 7 dt i%2+1 title (i % 2 == 0 ? 'rho '.word(prhos, i/2 + 1) : '')
unset multiplot
GP
gnuplot "$out/atlas.gp" && gnuplot "$out/atlas_edges.gp" && \
    echo "atlas.sh: $out/atlas.md, $out/atlas.png, $out/atlas_edges.png"
