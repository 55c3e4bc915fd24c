#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (issue 10):
#   bash scripts/sanitize.sh [SUITE]
# Any invalid access, use after free, overflow or undefined operation stops the run with a
# report. Leak detection is off (the GSL/OpenBLAS runtimes keep their pools to the end).
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-g -O1 -fno-omit-frame-pointer -fsanitize=address,undefined -fcheck=all -ffpe-trap=invalid,zero,overflow"
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fpm test --profile debug --flag "$flags" --link-flag "-fsanitize=address,undefined" -- "$@"
