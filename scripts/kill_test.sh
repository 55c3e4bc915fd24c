#!/usr/bin/env bash
# Faults (issue 10): kill fricon with SIGKILL at random moments of a sweep, then check that
# no output file under its final name is partial, and that the next run leaves no temporary
# file and only complete results. Run from the project root after fpm build:
#   bash scripts/kill_test.sh [ROUNDS]      (default 20; writes output/bench/kill_test.txt)
# Complete means: every .json parses and has a status; every .csv row has the header's field
# count; every .dat has rows of one width; every .txt ends its sections (CHECKS or ANALYSIS
# FAILED); every .png ends with its IEND chunk.
set -uo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-20}
bin=$(fpm run --runner echo 2>/dev/null | tail -n 1)
dir=$(mktemp -d)
log=output/bench/kill_test.txt
mkdir -p output/bench
check_dir() { # check_dir DIR -> prints problems, returns their number
    python3 - "$1" <<'PY'
import sys, os, json, glob
d = sys.argv[1]; bad = 0
for f in sorted(os.listdir(d)):
    p = os.path.join(d, f)
    try:
        if f.endswith('.json'):
            j = json.load(open(p)); assert 'status' in j
        elif f.endswith('.csv'):
            rows = [r for r in open(p).read().splitlines() if not r.startswith('#')]
            n = len(rows[0].split(','))
            assert all(len(r.split(',')) >= n for r in rows[1:]) and len(rows) > 1
        elif f.endswith('.dat'):
            rows = [r.split() for r in open(p) if not r.startswith('#')]
            assert rows and len(set(map(len, rows))) == 1
        elif f.endswith('.txt'):
            t = open(p).read(); assert ' 8. CHECKS' in t or 'ANALYSIS FAILED' in t
        elif f.endswith('.png'):
            b = open(p, 'rb').read(); assert b[:8] == b'\x89PNG\r\n\x1a\n' and b[-8:-4] == b'IEND'
    except Exception as e:
        print('  partial or broken:', f, repr(e)); bad += 1
print('  ', len(os.listdir(d)), 'files checked,', bad, 'broken')
sys.exit(min(bad, 100))
PY
}
broken=0
{
    echo "# Kill test: $rounds rounds of SIGKILL at a random moment of input/sweep.dat (6 cases)"
    echo "# machine: $(nproc) cores; $(date -u +%Y-%m-%d)"
    for ((k = 1; k <= rounds; k++)); do
        delay=$(awk -v s=$RANDOM 'BEGIN { srand(s); printf "%.2f", 0.05 + 2.0 * rand() }')
        setsid "$bin" -q -o "$dir" input/sweep.dat >/dev/null 2>&1 &
        pid=$!
        sleep "$delay"
        kill -KILL -- -"$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        echo "round $k: killed after $delay s; $(ls "$dir" | grep -c '\.tmp$') temporary file(s) left"
        check_dir "$dir" || broken=$((broken + 1))
    done
    echo "final run in the same folder:"
    "$bin" -q -o "$dir" input/sweep.dat >/dev/null 2>&1
    echo "  exit $?; $(ls "$dir" | grep -c '\.tmp$') temporary file(s) left"
    check_dir "$dir" || broken=$((broken + 1))
    echo "rounds with a partial or broken file under its final name: $broken"
} | tee "$log"
rm -rf "$dir"
[ "$broken" -eq 0 ]
