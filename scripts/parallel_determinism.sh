#!/usr/bin/env bash
# Parallel runs give the serial run's digits: input/atlas/beam.dat (432 hard and easy beam
# cases, among them RHO 1e-6 with EPS_BAR 1e-12, whose Newton path is sensitive to the last
# bit of any input) solved once on one thread, then RUNS times on two threads; every output
# file is compared byte for byte with the one-thread run (the release build; fpm builds it):
#   bash scripts/parallel_determinism.sh [RUNS]      (default 100; about 1 s a run)
# Prints the runs that differed, and which OpenBLAS the loader picks (Debian's serial build is
# not safe to call from two threads at once: 2 to 6 of 100 runs differed with it).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-100}
# the release build of this tree (built if it is not)
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
[ -x "$bin" ] || { echo "parallel_determinism: cannot build fricon (fpm build --profile release)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SOURCE_DATE_EPOCH=1795000000
"$bin" -q --no-figures -j 1 -o "$work/serial" input/atlas/beam.dat >/dev/null 2>&1 || true
bad=0
for k in $(seq 1 "$runs"); do
    rm -rf "$work/parallel"
    "$bin" -q --no-figures -j 2 -o "$work/parallel" input/atlas/beam.dat >/dev/null 2>&1 || true
    if ! diff -rq "$work/serial" "$work/parallel" >"$work/diff.txt"; then
        bad=$((bad + 1))
        echo "run $k: $(wc -l <"$work/diff.txt") files differ, first: $(head -n1 "$work/diff.txt")"
    fi
done
echo "OpenBLAS: $(ldd "$bin" | sed -n 's/.*libopenblas.so.0 => \([^ ]*\).*/\1/p' | xargs readlink -f)"
echo "$bad of $runs two-thread runs differ from the one-thread run"
[ "$bad" -eq 0 ]
