# Sourced by the before/after benchmark scripts (bench_ab.sh, bench_threads.sh):
#   two_binaries SCRIPT_NAME BEFORE_BIN AFTER_BIN
# sets `before` and `after` to the absolute paths of the two executables, resolved from the
# caller's folder (call it before changing folder), or stops with a message.
two_binaries() {
    local name=$1 bin
    before=$(readlink -f "$2")
    after=$(readlink -f "$3")
    for bin in "$before" "$after"; do
        [ -x "$bin" ] || { echo "$name: not an executable: $bin" >&2; exit 1; }
    done
}
