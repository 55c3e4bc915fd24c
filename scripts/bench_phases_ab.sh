#!/usr/bin/env bash
# Time per phase before and after a change, in one run: example/bench_phases (the time of
# each phase of one case, plate and beam, at several N_e; output/bench/phases.md) built with
# `fpm build --profile release` from a reference commit, checked out in a temporary
# `git worktree`, and from the current tree (the working tree, uncommitted changes included),
# the two run alternately REPS times (reference first in odd rounds, current first in even
# ones), each as
#     OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 bench_phases OUTDIR [N_e ...]
# from the project root, so that both read the same decks (input/plate_nondim.dat,
# input/beam_nondim.dat). Each cell is the least over the REPS runs of bench_phases' own
# least over its repetitions, in processor milliseconds (from each run's phases.dat).
#
#   bash scripts/bench_phases_ab.sh REF_REV [REPS [N_e ...]]
#
# REF_REV: any commit name git knows (e.g. the merge-base with main: `git merge-base HEAD
# main`); REPS: default 3; N_e: default bench_phases' own (20 50 100 200 500 1000; one run
# of both builds then takes about 1 to 2 minutes on two cores). Writes
# output/bench/phases_ab.md (also printed), only when every run succeeded; the worktree is
# removed at the end, also on an error or an interrupt.
set -euo pipefail
if [ $# -lt 1 ] || [[ $1 == -* ]]; then
    echo "usage: bash scripts/bench_phases_ab.sh REF_REV [REPS [N_e ...]]" >&2
    exit 1
fi
ref=$1
reps=${2:-3}
shift
[ $# -ge 1 ] && shift
meshes=("$@")
[[ $reps =~ ^[1-9][0-9]*$ ]] || { echo "bench_phases_ab: REPS must be a whole number" >&2; exit 1; }
cd "$(dirname "$0")/.."
root=$PWD
# shellcheck source=scripts/bench_binaries.sh
source scripts/bench_binaries.sh
work=$(mktemp -d "${TMPDIR:-/tmp}/bench_phases_ab.XXXXXX")
cleanup() {
    remove_reference_tree "$work/ref_tree"
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
add_reference_tree bench_phases_ab "$ref" "$work/ref_tree" || exit 1
ref_commit=$(git -C "$work/ref_tree" rev-parse --short HEAD)
release_executable bench_phases_ab "$work/ref_tree" --example bench_phases || exit 1
ref_bin=$executable
release_executable bench_phases_ab "$root" --example bench_phases || exit 1
cur_bin=$executable
dirty=''
[ -n "$(git status --porcelain --untracked-files=no)" ] && dirty=' + uncommitted changes'
cur_commit="$(git rev-parse --short HEAD)$dirty"

# one run of one build; its phases.dat kept as $work/TAG_K.dat
run() {
    local tag=$1 bin=$2 k=$3
    if ! OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 "$bin" "$work/$tag" ${meshes[@]+"${meshes[@]}"} \
        >"$work/log" 2>&1; then
        echo "bench_phases_ab: $bin failed:" >&2
        tail -n 20 "$work/log" >&2
        exit 1
    fi
    mv "$work/$tag/phases.dat" "$work/${tag}_$k.dat"
    rm -rf "${work:?}/$tag"
}

started=$(date -u '+%Y-%m-%d %H:%M UTC')
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for k in $(seq "$reps"); do
    echo "bench_phases_ab: round $k of $reps" >&2
    if [ $((k % 2)) -eq 1 ]; then
        run ref "$ref_bin" "$k"
        run cur "$cur_bin" "$k"
    else
        run cur "$cur_bin" "$k"
        run ref "$ref_bin" "$k"
    fi
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

# phases.dat: per case a header "# TITLE: N_e, then s per phase (P1, P2, ...), total" and
# rows "N_e t1 ... t10 total" in seconds ('?' where a phase is not positive)
table() {
    awk -v ref="$ref_commit" -v cur="$cur_commit" '
    FNR == 1 { blk = 0; tag = (FILENAME ~ /\/ref_[0-9]+\.dat$/) ? "ref" : "cur" }
    /^# / {
        blk++
        head = $0
        sub(/^# /, "", head)
        title[blk] = head
        sub(/: N_e, then.*/, "", title[blk])
        list = head
        sub(/.*per phase \(/, "", list)
        sub(/\), total$/, "", list)
        if (!(blk in phases)) phases[blk] = list
        else if (phases[blk] != list) bad = "the two builds time different phases"
        if (blk > nblk) nblk = blk
        next
    }
    NF > 1 && blk > 0 {
        ne = $1
        if (!((blk, ne) in seen)) { seen[blk, ne] = 1; nne[blk]++; mesh[blk, nne[blk]] = ne }
        ncol = NF - 1
        for (c = 2; c <= NF; c++) {
            if ($c == "?") continue
            key = tag SUBSEP blk SUBSEP ne SUBSEP (c - 1)
            if (!(key in t) || $c + 0 < t[key]) t[key] = $c + 0
        }
    }
    function ms(tag, b, ne, c,   key, v) {
        key = tag SUBSEP b SUBSEP ne SUBSEP c
        if (!(key in t)) return "?"
        v = 1000 * t[key]
        if (v < 10) return sprintf(v < 1 ? "%.3f" : "%.2f", v)
        return sprintf(v < 100 ? "%.1f" : "%.0f", v)
    }
    function ratio(b, ne, c,   kr, kc) {
        kr = "ref" SUBSEP b SUBSEP ne SUBSEP c
        kc = "cur" SUBSEP b SUBSEP ne SUBSEP c
        if (!(kr in t) || !(kc in t) || t[kr] <= 0) return "-"
        return sprintf("%.2f", t[kc] / t[kr])
    }
    END {
        if (bad != "") { print "bench_phases_ab: " bad > "/dev/stderr"; exit 1 }
        for (b = 1; b <= nblk; b++) {
            n = split(phases[b], name, ", ")
            name[n + 1] = "**total**"
            last = mesh[b, nne[b]]
            printf "## %s\n\n", title[b]
            printf "| N_e | before (%s) ms | after (%s) ms | after / before |\n", ref, cur
            print "|---:|---:|---:|---:|"
            for (i = 1; i <= nne[b]; i++) {
                ne = mesh[b, i]
                printf "| %s | %s | %s | %s |\n", ne, ms("ref", b, ne, ncol), \
                    ms("cur", b, ne, ncol), ratio(b, ne, ncol)
            }
            print ""
            printf "| phase | before ms, N_e %s | after ms, N_e %s |", last, last
            for (i = 1; i <= nne[b]; i++) printf " after / before, N_e %s |", mesh[b, i]
            printf "\n|---|---:|---:|"
            for (i = 1; i <= nne[b]; i++) printf "---:|"
            print ""
            for (c = 1; c <= ncol; c++) {
                printf "| %s | %s | %s |", name[c], ms("ref", b, last, c), ms("cur", b, last, c)
                for (i = 1; i <= nne[b]; i++) printf " %s |", ratio(b, mesh[b, i], c)
                print ""
            }
            print ""
        }
    }' "$work"/ref_*.dat "$work"/cur_*.dat
}

md=$work/phases_ab.md
{
    echo "# Time per phase, before and after (bench_phases, both builds in one run)"
    echo
    echo "Command: \`bash scripts/bench_phases_ab.sh $ref $reps${meshes[*]+ ${meshes[*]}}\`."
    echo "Before: \`$ref_commit\` (committed $(git log -1 --format=%cs "$ref_commit"));" \
        "after: \`$cur_commit\` (the current tree)."
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 |
        sed 's/^ //'); run started $started; load average (1, 5, 15 min) $load_before before," \
        "$load_after after."
    echo "Both builds \`fpm build --profile release\`, run alternately in $reps rounds on one"
    echo "thread (\`OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1\`); each time is the least over the"
    echo "$reps rounds of bench_phases' least over its own repetitions (processor time, ms;"
    echo "phases below about 1 ms are at the timer's noise). Phases: example/bench_phases.f90 and"
    echo "output/bench/phases.md; ? = never positive (the one phase obtained as a difference)."
    echo
    table
} >"$md"
mkdir -p output/bench
cp "$md" output/bench/.phases_ab.md.tmp
mv -f output/bench/.phases_ab.md.tmp output/bench/phases_ab.md
cat output/bench/phases_ab.md
