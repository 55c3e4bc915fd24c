#!/usr/bin/env bash
# Every deck of input/ and input/paper/ solved by the release build (-O3), which the test
# suite (a debug build) never runs: optimised code can fail where debug code does not (a
# segmentation fault in build_system was seen once in a release build only). Each deck must
# end with exit status 0; the outputs go to a temporary folder.
#   bash scripts/release_smoke.sh
set -uo pipefail
cd "$(dirname "$0")/.."
fpm build --profile release >/dev/null || exit 1
bin=$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for deck in input/*.dat input/paper/*.dat; do
    "$bin" -q --no-figures -o "$tmp/out" "$deck" >"$tmp/log" 2>&1
    status=$?
    if [ "$status" -ne 0 ]; then
        echo "FAILED $deck: exit status $status"
        tail -n 5 "$tmp/log"
        failed=$((failed + 1))
    else
        echo "ok     $deck"
    fi
done
echo "release smoke: $failed deck(s) failed"
[ "$failed" -eq 0 ]
