#!/usr/bin/env bash
# Every deck of input/ and input/paper/ solved by the release build (-O3), which the test
# suite (a debug build) never runs: optimised code can fail where debug code does not (a
# segmentation fault in build_system was seen once in a release build only). Each deck must
# end with exit status 0; the outputs go to a temporary folder. With the argument debug, the
# same decks through the debug build that README's `fpm run` uses (runtime checks on: an
# ADAPT deck's report once stopped it with a character-length error the suite did not reach).
#   bash scripts/release_smoke.sh [release|debug]
set -uo pipefail
cd "$(dirname "$0")/.."
profile=${1:-release}
fpm build --profile "$profile" >/dev/null || exit 1
bin=$(fpm run --profile "$profile" --runner echo 2>/dev/null | tail -n 1)
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
echo "$profile smoke: $failed deck(s) failed"
[ "$failed" -eq 0 ]
