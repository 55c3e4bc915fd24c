#!/usr/bin/env bash
# Same results before and after a change: every deck of input/ and input/paper/, and the
# built-in default case (fricon with no deck), solved by the release build of a reference
# commit and by the release build of the current tree (the working tree, uncommitted changes
# included); every output file and the console output compared byte for byte.
#
#   bash scripts/same_results.sh [--figures] [REF_REV [DECK...]]
#
# REF_REV: any commit name git knows (default: the merge-base of HEAD with main; HEAD compares
# the working tree with its last commit). DECK...: other decks instead of the default list,
# e.g. test/data/malformed/*.dat for the error paths (the word `default` names the built-in
# case). --figures: gnuplot runs too and the PNG files are
# compared byte for byte as well (gnuplot's PNG of the same script and data is the same bytes
# on one machine); without it, --no-figures: the figure scripts (.gp, the templates embedded)
# and their data are compared, which is all a figure is drawn from.
#
# Steps: REF_REV checked out in a temporary `git worktree`; both trees built with
# `fpm build --profile release` (scripts/bench_binaries.sh); each case run by each build
# from the project root (the same deck files), as
#     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 fricon --progress -j 1 --no-figures -o OUT DECK
# where OUT is the same path for both builds (a run's folder is moved aside before the other
# build runs), so that no output carries a path that differs between them. One case at a
# time (-j 1) and one BLAS thread, so that the console lines come in one order; --progress so
# that the progress lines are compared too. Compared for each case: the exit status (must be
# equal; non-zero in both is counted), standard output, standard error and every file of OUT
# (report .txt, .dat, .csv, .json, .gp, .html, the sweep summary and overlay; a file present in one
# folder only is a difference).
#
# Filter (applied to every compared file): only the progress lines of standard error carry
# measured times, `fricon: 3 of 6 done (NAME), 0.4 s elapsed, about 0.8 s left`; their
# "N s elapsed" and "about N s left" become "T s elapsed" and "about T s left". Found by
# running every deck twice with the same build and diffing (the outputs' run time is fixed by
# SOURCE_DATE_EPOCH, exported below; the deck identity in the JSON and the output folder
# on standard output, are the same in both runs by construction). The size announcement of a
# large case ("about 12.0 s and 0.3 GB (rough estimates)") is a formula of the case's size,
# not a measurement: it is compared.
#
# Prints one line per case (same, or DIFFERENT with the first differing file and line and the
# two lines) and a count; the reference worktree and all outputs are removed at the end, also
# on an error or an interrupt. Exit status 0 when every case is the same, 1 otherwise, 2 on a
# usage or build error. About a minute on two shared cores (30 to 90 s, most of it the
# reference's release build; the runs take about 10 s, --figures adds about 30 s).
set -uo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
figures=--no-figures
if [ "${1:-}" = --figures ]; then
    figures=''
    shift
fi
case "${1:-}" in
-h | --help | -*)
    echo "usage: bash scripts/same_results.sh [--figures] [REF_REV [DECK...]]" >&2
    exit 2
    ;;
esac
root=$(cd "$(dirname "$0")/.." && pwd) || exit 2
ref=''
if [ $# -ge 1 ]; then
    ref=$1
    shift
fi
# decks named from the caller's folder; the runs are made from the project root, with the
# path relative to it for a deck inside it
cases=()
for deck in "$@"; do
    if [ "$deck" != default ] && [ -f "$deck" ]; then
        deck=$(readlink -f "$deck")
        deck=${deck#"$root"/}
    fi
    cases+=("$deck")
done
cd "$root" || exit 2
# shellcheck source=scripts/bench_binaries.sh
source scripts/bench_binaries.sh
if [ -z "$ref" ]; then
    ref=$(git merge-base HEAD main) || { echo "same_results: no merge-base with main" >&2; exit 2; }
fi
[ ${#cases[@]} -eq 0 ] && cases=(default input/*.dat input/paper/*.dat)
for deck in "${cases[@]}"; do
    [ "$deck" = default ] || [ -f "$deck" ] || { echo "same_results: no deck $deck" >&2; exit 2; }
done

work=$(mktemp -d "${TMPDIR:-/tmp}/same_results.XXXXXX")
cleanup() {
    remove_reference_tree "$work/ref_tree"
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP
add_reference_tree same_results "$ref" "$work/ref_tree" || exit 2
ref_commit=$(git -C "$work/ref_tree" rev-parse --short HEAD)
echo "same_results: building the reference $ref ($ref_commit) and the current tree" \
    "(release profile)"
release_executable same_results "$work/ref_tree" || exit 2
ref_bin=$executable
release_executable same_results "$root" || exit 2
cur_bin=$executable
dirty=''
[ -n "$(git status --porcelain --untracked-files=no)" ] && dirty=' + uncommitted changes'
echo "reference: $ref_commit  $(git log -1 --format=%s "$ref_commit" | cut -c1-70)"
echo "current:   $(git rev-parse --short HEAD)$dirty"
echo

# run TAG BIN ID DECK: the case's outputs and console in $work/TAG/ID; the run itself writes
# to $work/run/ID, the same path for both builds
run() {
    local tag=$1 bin=$2 id=$3 deck=$4 status=0 args
    local dir=$work/run/$id
    mkdir -p "$dir" "$work/$tag"
    args=(--progress -j 1 $figures -o "$dir/out")
    [ "$deck" = default ] || args+=("$deck")
    OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 "$bin" "${args[@]}" \
        >"$dir/stdout" 2>"$dir/stderr" </dev/null || status=$?
    echo "$status" >"$dir/status"
    mv "$dir" "$work/$tag/$id"
}

# the timing filter of the header
filtered() {
    sed -E -e 's/[0-9.*]+ s elapsed/T s elapsed/g' \
        -e 's/about [0-9.*]+ s left/about T s left/g' "$1"
}

# first_difference FILE_A FILE_B LABEL: empty when the filtered files are equal; else LABEL,
# the first differing line and the two lines
first_difference() {
    local a=$1 b=$2 label=$3 at n
    if [[ $label == *.png ]]; then
        cmp -s "$a" "$b" || echo "$label: $(cmp "$a" "$b" 2>&1 | sed 's/.*: //')"
        return 0
    fi
    filtered "$a" >"$work/a"
    filtered "$b" >"$work/b"
    cmp -s "$work/a" "$work/b" && return 0
    at=$(cmp "$work/a" "$work/b" 2>&1 | grep -o 'line [0-9]*' | head -n 1)
    n=${at#line }
    if [ -z "$n" ]; then
        echo "$label differs"
        return 0
    fi
    # the two lines from 40 characters before their first difference
    A=$(sed -n "${n}p" "$work/a") B=$(sed -n "${n}p" "$work/b") awk -v label="$label" \
        -v n="$n" 'BEGIN {
        a = ENVIRON["A"]; b = ENVIRON["B"]; c = 1
        while (c <= length(a) && substr(a, c, 1) == substr(b, c, 1)) c++
        from = c > 40 ? c - 40 : 1
        cut = from > 1 ? "..." : ""
        printf "%s line %d, column %d\n", label, n, c
        printf "             reference: %s%s\n", cut, substr(a, from, 100)
        printf "             current:   %s%s\n", cut, substr(b, from, 100) }'
}

# compare_case ID: the first difference of the two runs of one case (empty: the same)
compare_case() {
    local a=$work/ref/$1 b=$work/cur/$1 f d
    if [ "$(cat "$a/status")" != "$(cat "$b/status")" ]; then
        echo "exit status $(cat "$a/status") (reference) and $(cat "$b/status") (current)"
        return
    fi
    for f in stdout stderr; do
        d=$(first_difference "$a/$f" "$b/$f" "standard ${f#std}")
        [ -n "$d" ] && { echo "$d"; return; }
    done
    (cd "$a" && find . -path ./out/\* -type f | sort) >"$work/list_a"
    (cd "$b" && find . -path ./out/\* -type f | sort) >"$work/list_b"
    f=$(comm -23 "$work/list_a" "$work/list_b" | head -n 1)
    [ -n "$f" ] && { echo "${f#./out/} written by the reference only"; return; }
    f=$(comm -13 "$work/list_a" "$work/list_b" | head -n 1)
    [ -n "$f" ] && { echo "${f#./out/} written by the current tree only"; return; }
    while read -r f; do
        d=$(first_difference "$a/$f" "$b/$f" "${f#./out/}")
        [ -n "$d" ] && { echo "$d"; return; }
    done <"$work/list_a"
}

n_same=0
n_different=0
n_failed_both=0
for deck in "${cases[@]}"; do
    id=${deck//\//_}
    run ref "$ref_bin" "$id" "$deck"
    run cur "$cur_bin" "$id" "$deck"
    label=$deck
    [ "$deck" = default ] && label='(default: fricon with no deck)'
    d=$(compare_case "$id")
    if [ -z "$d" ]; then
        n_same=$((n_same + 1))
        status=$(cat "$work/ref/$id/status")
        note=''
        if [ "$status" != 0 ]; then
            n_failed_both=$((n_failed_both + 1))
            note="  (exit status $status in both)"
        fi
        echo "same       $label$note"
    else
        n_different=$((n_different + 1))
        echo "DIFFERENT  $label: $d"
    fi
    rm -rf "${work:?}/ref/$id" "${work:?}/cur/$id"
done
echo
echo "same_results: ${#cases[@]} cases: $n_same same, $n_different DIFFERENT;" \
    "$n_failed_both of the same ended with the same non-zero exit status in both builds" \
    "(reference $ref_commit, current $(git rev-parse --short HEAD)$dirty; ${SECONDS} s)"
[ "$n_different" -eq 0 ]
