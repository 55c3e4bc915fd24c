#!/usr/bin/env bash
# Faults: SIGTERM and SIGINT (alternately) sent to fricon while one of its temporary files
# exists, in a sweep (input/sweep.dat at N_e 100 with a third friction value: 9 cases, with
# figures, about 2 s on 2 cores). The output folder is polled until a NAME.tmp appears (a
# case's report, data, JSON or script being written; a figure's being drawn), the k-th one
# in round k, then the signal is sent to fricon alone. The program must remove its temporary
# files before it ends: none may be left, and every file under its final name is complete.
# (SIGKILL cannot be caught: scripts/kill_test.sh covers it; the next run clears its .tmp.)
# Run from the project root after fpm build:
#   bash scripts/signal_test.sh [ROUNDS] [BINARY]   (default 20; writes output/bench/signal_test.txt)
set -uo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-20}
bin=${2:-$(fpm run --runner echo 2>/dev/null | tail -n 1)}
bin=$(readlink -f "$bin")
deck=$(mktemp --suffix=.dat)
sed -e 's/^SWEEP     F .*/SWEEP     F         0.0       0.5       1.0/' -e 's/^END/MESH      100\nEND/' \
    input/sweep.dat > "$deck"
log=output/bench/signal_test.txt
mkdir -p output/bench
python3 - "$bin" "$deck" "$rounds" <<'PY' | tee "$log"
import sys, os, json, time, signal, subprocess, tempfile, shutil
binary, deck, rounds = sys.argv[1], sys.argv[2], int(sys.argv[3])

def problems(d):
    bad = []
    for f in sorted(os.listdir(d)):
        p = os.path.join(d, f)
        try:
            assert not f.endswith('.tmp'), 'temporary file'
            if f.endswith('.json'):
                assert 'status' in json.load(open(p))
            elif f.endswith('.csv'):
                rows = [r for r in open(p).read().splitlines() if not r.startswith('#')]
                n = len(rows[0].split(','))
                assert len(rows) > 1 and all(len(r.split(',')) >= n for r in rows[1:])
            elif f.endswith('.txt'):
                t = open(p).read(); assert ' 8. CHECKS' in t or 'ANALYSIS FAILED' in t
            elif f.endswith('.png'):
                b = open(p, 'rb').read()
                assert b[:8] == b'\x89PNG\r\n\x1a\n' and b[-8:-4] == b'IEND'
        except Exception as e:
            bad.append('%s (%r)' % (f, e))
    return bad

print('# Signal test: %d rounds of SIGTERM or SIGINT while a .tmp of a 9-case sweep exists' % rounds)
print('# machine: %d cores; %s' % (os.cpu_count(), time.strftime('%Y-%m-%d', time.gmtime())))
bad_rounds = 0
for k in range(1, rounds + 1):
    sig = signal.SIGTERM if k % 2 else signal.SIGINT
    d = tempfile.mkdtemp()
    # SIGINT as a terminal's Ctrl-C finds it (a shell's background job inherits it ignored)
    proc = subprocess.Popen([binary, '-q', '-o', d, deck], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    seen, target = set(), None
    while proc.poll() is None and target is None:
        for f in os.listdir(d):
            if f.endswith('.tmp') and f not in seen:
                seen.add(f)
                if len(seen) == k:
                    target = f
    if target is not None:
        proc.send_signal(sig)
    rc = proc.wait()
    time.sleep(0.5)   # a gnuplot the program started may still be finishing its figure
    bad = problems(d)
    print('round %d: %s while %s existed, exit %d; %s' % (
        k, sig.name, target or '(none: the run ended first)', rc,
        'left: ' + ', '.join(bad) if bad else 'nothing left'))
    bad_rounds += 1 if bad else 0
    shutil.rmtree(d)
print('rounds leaving a temporary or incomplete file: %d' % bad_rounds)
PY
rm -f "$deck"
! grep -q 'incomplete file: [1-9]' "$log"
