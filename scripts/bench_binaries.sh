# Sourced by the scripts that compare two builds of fricon (bench_ab.sh, bench_threads.sh,
# bench_phases_ab.sh, same_results.sh).
#
#   two_binaries SCRIPT_NAME BEFORE_BIN AFTER_BIN
# sets `before` and `after` to the absolute paths of the two executables, resolved from the
# caller's folder (call it before changing folder), or stops with a message.
#
#   add_reference_tree SCRIPT_NAME REV DIR
# checks out commit REV (any name git knows) into DIR as a detached `git worktree` of the
# repository of the current folder, or returns 1 with a message; remove_reference_tree DIR
# removes it again (call it from the caller's EXIT trap, so that an error or an interrupt
# removes it too).
#
#   release_executable SCRIPT_NAME TREE [FPM_RUN_OPTION...]
# builds the fpm project in TREE with `fpm build --profile release` and sets `executable` to
# the absolute path of what `fpm run --profile release [FPM_RUN_OPTION...]` runs there
# (the program fricon, or e.g. `--example bench_phases`), or returns 1 with fpm's messages.
two_binaries() {
    local name=$1 bin
    before=$(readlink -f "$2")
    after=$(readlink -f "$3")
    for bin in "$before" "$after"; do
        [ -x "$bin" ] || { echo "$name: not an executable: $bin" >&2; exit 1; }
    done
}

add_reference_tree() {
    local name=$1 rev=$2 dir=$3 commit
    commit=$(git rev-parse --verify --quiet "$rev^{commit}") \
        || { echo "$name: not a commit: $rev" >&2; return 1; }
    git worktree add --detach --quiet "$dir" "$commit" \
        || { echo "$name: cannot check out $rev into $dir" >&2; return 1; }
}

remove_reference_tree() {
    local dir=$1
    [ -d "$dir" ] || return 0
    git worktree remove --force "$dir" 2>/dev/null || rm -rf "$dir"
    git worktree prune 2>/dev/null || true
}

release_executable() {
    local name=$1 tree=$2 log rel
    shift 2
    log=$(mktemp)
    if ! (cd "$tree" && fpm build --profile release) >"$log" 2>&1; then
        echo "$name: fpm build --profile release failed in $tree:" >&2
        tail -n 30 "$log" >&2
        rm -f "$log"
        return 1
    fi
    rm -f "$log"
    rel=$(cd "$tree" && fpm run --profile release "$@" --runner echo 2>/dev/null | tail -n 1)
    executable=$(cd "$tree" && readlink -f "$rel")
    [ -n "$rel" ] && [ -f "$executable" ] && [ -x "$executable" ] \
        || { echo "$name: no executable from fpm run --profile release $* in $tree" >&2; return 1; }
}
