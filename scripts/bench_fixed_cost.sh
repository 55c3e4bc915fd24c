#!/usr/bin/env bash
# The fixed cost of a run: what a whole fricon process costs around its case, measured as the
# user runs it (release build, dynamically linked, no OMP_*/OPENBLAS_* variables). The median
# wall time of REPS runs of: an empty process, a do-nothing program linked like fricon, `fricon
# --version`, a deck refused for an input error, the N_e = 10, 20, 40 plate without figure and
# estimates, N_e = 10 with estimates, N_e = 10 with its figure (each in an output folder that
# holds 500 files of another deck), and the 1000-case sweep bench/sweep_1000.dat with and
# without figures on 1 and 2 threads (-j). With two builds, every measurement alternates
# between them run by run, so that both columns come from the same minutes of the machine.
#
#   bash scripts/bench_fixed_cost.sh [BIN [AFTER_BIN]] [REPS]
#
# BIN: a fricon executable (default: the release build of this checkout); AFTER_BIN: a second
# one (e.g. release builds of two commits copied out of build/). REPS (default 20) is the
# number of runs of each small measurement; the sweeps run 3 times without figures and once
# with (about 90 s a run before they used both cores; SWEEPS=no leaves the sweeps out, for a
# quick look). Where valgrind is installed, the instructions of --version, the input error and
# the N_e = 10, 20, 40 cases are counted too (callgrind; INSTRUCTIONS=no leaves them out):
# unlike the times, they do not depend on what else the machine runs. Writes
# output/bench/fixed_cost.md.
set -euo pipefail
# one run time for the runs compared, so that their outputs can be the same bytes (the
# run's date and time are stamped on the outputs: src/run_identity.f90)
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
reps=20
bins=()
for arg in "$@"; do
    if [[ $arg =~ ^[0-9]+$ ]]; then reps=$arg; else bins+=("$arg"); fi
done
if [ ${#bins[@]} -eq 2 ]; then
    # shellcheck source=scripts/bench_binaries.sh
    source "$(dirname "$0")/bench_binaries.sh"
    two_binaries bench_fixed_cost "${bins[0]}" "${bins[1]}"  # before changing folder
    bins=("$before" "$after")
    tags=(before after)
elif [ ${#bins[@]} -eq 1 ]; then
    bins=("$(readlink -f "${bins[0]}")")
    tags=(fricon)
elif [ ${#bins[@]} -eq 0 ]; then
    tags=(fricon)
else
    echo "usage: bash scripts/bench_fixed_cost.sh [BIN [AFTER_BIN]] [REPS]" >&2
    exit 1
fi
cd "$(dirname "$0")/.."
if [ ${#bins[@]} -eq 0 ]; then
    fpm build --profile release >/dev/null
    bins=("$(readlink -f "$(fpm run --profile release --runner echo 2>/dev/null | tail -n 1)")")
fi
for bin in "${bins[@]}"; do
    [ -x "$bin" ] || { echo "bench_fixed_cost: not an executable: $bin" >&2; exit 1; }
done
command -v perl >/dev/null || { echo "bench_fixed_cost: perl is needed (the timer)" >&2; exit 1; }
out=output/bench
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
nb=${#bins[@]}

# --- the programs and decks measured --------------------------------------------------------
printf 'int main(void) { return 0; }\n' >"$work/empty.c"
gcc -O2 -o "$work/empty" "$work/empty.c"
# the libraries fricon links (fpm.toml's link list, in its order), each loaded even though
# nothing calls it
libs=$(sed -n 's/^link *= *\[\(.*\)\]/\1/p' fpm.toml | tr ',' '\n' | tr -d '" ' | sed 's/^/-l/')
[ -n "$libs" ] || { echo "bench_fixed_cost: no link list in fpm.toml" >&2; exit 1; }
printf 'program noop\nend program noop\n' >"$work/noop.f90"
# shellcheck disable=SC2086
gfortran -O2 -fopenmp -o "$work/noop" "$work/noop.f90" -Wl,--no-as-needed $libs
for ne in 10 20 40; do
    sed "s/^MESH      20 /MESH      $(printf '%-3s' "$ne")/" input/plate_nondim.dat \
        >"$work/plate$ne.dat"
    grep -q "^MESH      $ne " "$work/plate$ne.dat"
done
# Poisson's ratio 0.62 is out of range: read, checked, refused with exit status 1
sed 's/^NONDIM    0.01      0.1       0.3 /NONDIM    0.01      0.1       0.62/' \
    input/plate_nondim.dat >"$work/bad.dat"
grep -q '0\.62' "$work/bad.dat"
# each build writes into its own folder, which holds 500 files of another deck (100 cases)
for t in "${tags[@]}"; do
    mkdir -p "$work/out_$t"
    for i in $(seq -w 1 100); do
        printf '= report\n' >"$work/out_$t/other_$i.txt"
        printf '# data\n' >"$work/out_$t/other_$i.dat"
        printf '# figure\n' >"$work/out_$t/other_$i.gp"
        printf 'x [m]\n' >"$work/out_$t/other_$i.csv"
        printf '{\n  "deck_file": "/elsewhere/other.dat"\n}\n' >"$work/out_$t/other_$i.json"
    done
done

# --- the timer ------------------------------------------------------------------------------
# measure FRESH EXPECTED_STATUS REPS COMMAND...: prints, for each build (one line), the median
# and the least wall time [ms] and the mean processor time (user + system) [ms]. In COMMAND, @BIN@ stands for the build and @OUT@ for its folder;
# the runs alternate between the builds; FRESH=1 empties the folder before each run (not
# timed). A run that exits with another status than EXPECTED_STATUS stops the benchmark.
measure() {
    local fresh=$1 expected=$2 n=$3
    shift 3
    perl -MTime::HiRes=time -MFile::Path=remove_tree -e '
        my ($fresh, $expected, $reps, $nb, @rest) = @ARGV;
        my @bins = splice(@rest, 0, $nb);
        my @outs = splice(@rest, 0, $nb);
        my (@t, @u);
        for my $r (1 .. $reps) {
            for my $k (0 .. $nb - 1) {
                my @cmd = map { my $w = $_; $w =~ s/\@BIN\@/$bins[$k]/g;
                                $w =~ s/\@OUT\@/$outs[$k]/g; $w } @rest;
                if ($fresh) { remove_tree($outs[$k]); mkdir $outs[$k]; }
                my $t0 = time;
                my @c0 = times;
                my $pid = fork;
                if ($pid == 0) {
                    open STDOUT, ">", "/dev/null";
                    open STDERR, ">", "/dev/null";
                    exec @cmd or exit 127;
                }
                waitpid($pid, 0);
                my $dt = (time - $t0) * 1000;
                my @c1 = times;
                my $status = $? >> 8;
                die "bench_fixed_cost: exit status $status (expected $expected): @cmd\n"
                    if $status != $expected;
                push @{$t[$k]}, $dt;
                $u[$k] += ($c1[2] + $c1[3] - $c0[2] - $c0[3]) * 1000 / $reps;
            }
        }
        # (times() counts in clock ticks: the processor time is the mean over the runs)
        for my $k (0 .. $nb - 1) {
            my @s = sort { $a <=> $b } @{$t[$k]};
            my $median = @s % 2 ? $s[$#s / 2] : ($s[@s / 2 - 1] + $s[@s / 2]) / 2;
            printf "%.6f %.6f %.6f\n", $median, $s[0], $u[$k];
        }' "$fresh" "$expected" "$n" "$nb" "${bins[@]}" \
        "${tags[@]/#/$work/out_}" "$@"
}
rows=()      # "label|target|ms of each build"
row() {      # row LABEL TARGET MEASURE-ARGUMENTS...
    local label=$1 target=$2
    shift 2
    local ms
    ms=$(measure "$@" | tr '\n' '|')
    rows+=("$label|$target|$ms")
    echo "  $label: ${ms//|/  |  } (median, least, processor ms)" >&2
}

echo "bench_fixed_cost: ${bins[*]}, $reps runs each" >&2
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
lean=(-q --no-figures --no-estimates -o @OUT@)
row 'an empty process (C, `return 0`)' '' 0 0 "$reps" "$work/empty"
row 'a do-nothing program linked like fricon' '' 0 0 "$reps" "$work/noop"
row '`fricon --version`' '' 0 0 "$reps" @BIN@ --version
row 'a deck with an input error (read, check, refuse)' '&le; 5' 0 1 "$reps" @BIN@ \
    "${lean[@]}" "$work/bad.dat"
for ne in 10 20 40; do
    row "N_e = $ne without figure and estimates" '&le; 6' 0 0 "$reps" @BIN@ "${lean[@]}" \
        "$work/plate$ne.dat"
done
row 'N_e = 10 with error estimates' '' 0 0 "$reps" @BIN@ -q --no-figures -o @OUT@ \
    "$work/plate10.dat"
row 'N_e = 10 with its figure' '' 0 0 "$reps" @BIN@ -q --no-estimates -o @OUT@ \
    "$work/plate10.dat"
# --- instructions: the same count on a busy machine as on an idle one --------------------
# valgrind's callgrind counts the instructions of the whole process (the loader, the
# libraries' start, the run, the exit); the same build, deck and environment give the same
# count to a few hundred in millions (OpenBLAS's idle worker thread), whatever else runs
count_rows=()    # "label|count of each build"
count_row() {    # count_row LABEL EXPECTED_STATUS COMMAND...
    local label=$1 expected=$2 line=$1 k status words
    shift 2
    for ((k = 0; k < nb; k++)); do
        words=("${@//@BIN@/${bins[$k]}}")
        words=("${words[@]//@OUT@/$work/out_${tags[$k]}}")
        status=0
        valgrind --tool=callgrind --callgrind-out-file=/dev/null "${words[@]}" >/dev/null \
            2>"$work/callgrind.txt" || status=$?
        if [ "$status" -ne "$expected" ]; then
            echo "bench_fixed_cost: exit status $status under valgrind (expected $expected)" >&2
            exit 1
        fi
        line="$line|$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/callgrind.txt")"
    done
    count_rows+=("$line")
    echo "  $line (instructions)" >&2
}
if [ "${INSTRUCTIONS:-yes}" != no ] && command -v valgrind >/dev/null; then
    count_row '`fricon --version`' 0 @BIN@ --version
    count_row 'a deck with an input error' 1 @BIN@ "${lean[@]}" "$work/bad.dat"
    for ne in 10 20 40; do
        count_row "N_e = $ne without figure and estimates" 0 @BIN@ "${lean[@]}" \
            "$work/plate$ne.dat"
    done
fi
sweep_rows=()
summaries_differ=()
sweep_kinds=(no yes)
[ "${SWEEPS:-yes}" = no ] && sweep_kinds=()
for figures in "${sweep_kinds[@]}"; do
    for jobs in 1 2; do
        flags=(-q -j "$jobs" -o @OUT@)
        n=3
        if [ "$figures" = no ]; then flags+=(--no-figures); else n=1; fi
        load=$(cut -d' ' -f1 /proc/loadavg)
        ms=$(measure 1 0 "$n" @BIN@ "${flags[@]}" bench/sweep_1000.dat | tr '\n' '|')
        sweep_rows+=("$figures|$jobs|$load|$ms")
        echo "  sweep, figures $figures, -j $jobs: ${ms//|/ ms  }" >&2
        # the summaries of the builds (the last run of each) must agree; where they do not,
        # the table says so and the differing rows are kept beside it
        if [ "$nb" -eq 2 ] && ! cmp -s "$work/out_before/sweep_1000_summary.csv" \
            "$work/out_after/sweep_1000_summary.csv"; then
            echo "bench_fixed_cost: the two builds' sweep summaries differ" >&2
            diff "$work/out_before/sweep_1000_summary.csv" "$work/out_after/sweep_1000_summary.csv" \
                >"$work/summary_diff_${figures}_j$jobs.txt" || true
            summaries_differ+=("figures $figures, -j $jobs")
        fi
    done
done

# --- the table ------------------------------------------------------------------------------
{
    echo "# The fixed cost of a run"
    echo
    echo "Command: \`bash scripts/bench_fixed_cost.sh${*:+ $*}\` ($(date -u '+%Y-%m-%d %H:%M UTC'))."
    for k in "${!bins[@]}"; do
        echo "Build ${tags[$k]}: \`${bins[$k]}\`, $(ldd "${bins[$k]}" | grep -c '=>') shared libraries."
    done
    echo
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load average before the runs $load_before, after $(cut -d' ' -f1-3 /proc/loadavg) (other programs' load counts: the machine may be shared). \`lscpu\`:"
    echo
    echo '```'
    lscpu | grep -E '^(Architecture|CPU\(s\)|Model name|Thread|Core|Socket|CPU max MHz|BogoMIPS|Hypervisor|Virtualization|L[123])' || true
    echo '```'
    echo
    echo "Whole processes, as the user runs them: median wall time of $reps runs (the sweeps: of 3"
    echo "runs without figures, one run with). With two builds the runs alternate between them."
    echo "The plate is input/plate_nondim.dat (point load) with MESH N_e; each run writes into a"
    echo "folder that holds 500 files of another deck; the input error is its Poisson ratio 0.62."
    echo
    echo "Each cell: the median wall time, in brackets the least of the runs and the mean"
    echo "processor time (user + system, all threads and child processes) [ms]."
    echo
    header="| | target [ms] |"
    rule="|---|---|"
    for t in "${tags[@]}"; do header="$header $t: median (least; processor) [ms] |"; rule="$rule---:|"; done
    echo "$header"
    echo "$rule"
    for r in "${rows[@]}"; do
        IFS='|' read -r -a f <<<"$r"
        line="| ${f[0]} | ${f[1]} |"
        for ((k = 0; k < nb; k++)); do
            read -r med least cpu <<<"${f[$((k + 2))]}"
            line="$line $(printf '%.1f (%.1f; %.1f)' "$med" "$least" "$cpu") |"
        done
        echo "$line"
    done
    echo
    if [ ${#count_rows[@]} -gt 0 ]; then
        echo "Instructions of the whole process, counted by valgrind's callgrind (millions; the"
        echo "same on a busy machine as on an idle one, so that builds compare whatever the load):"
        echo
        header="| |"
        rule="|---|"
        for t in "${tags[@]}"; do header="$header $t [M] |"; rule="$rule---:|"; done
        [ "$nb" -eq 2 ] && { header="$header after / before |"; rule="$rule---:|"; }
        echo "$header"
        echo "$rule"
        for r in "${count_rows[@]}"; do
            IFS='|' read -r -a f <<<"$r"
            line="| ${f[0]} |"
            for ((k = 0; k < nb; k++)); do
                line="$line $(awk -v n="${f[$((k + 1))]}" 'BEGIN { printf "%.2f", n / 1e6 }') |"
            done
            [ "$nb" -eq 2 ] && line="$line $(awk -v a="${f[1]}" -v b="${f[2]}" 'BEGIN { printf "%.3f", b / a }') |"
            echo "$line"
        done
        echo
    fi
    if [ ${#sweep_rows[@]} -eq 4 ]; then
        echo "The sweep bench/sweep_1000.dat (1000 NONDIM plates, N_e = 10, with error estimates):"
        echo
        echo "(wall time: the median of the runs; processor time: user + system of all threads and"
        echo "gnuplots, mean of the runs; load: the 1-minute load average when the measurement began)"
        echo
        header="| figures | -j | load |"
        rule="|---|---|---:|"
        for t in "${tags[@]}"; do
            header="$header $t wall [s] | $t [cases/s] | $t processor [s] |"
            rule="$rule---:|---:|---:|"
        done
        echo "$header"
        echo "$rule"
        for r in "${sweep_rows[@]}"; do
            IFS='|' read -r -a f <<<"$r"
            line="| ${f[0]} | ${f[1]} | ${f[2]} |"
            for ((k = 0; k < nb; k++)); do
                read -r med least cpu <<<"${f[$((k + 3))]}"
                line="$line $(awk -v ms="$med" -v c="$cpu" 'BEGIN { printf "%.2f | %.0f | %.2f", ms / 1000, 1e6 / ms, c / 1000 }') |"
            done
            echo "$line"
        done
        echo
        for ((k = 0; k < nb; k++)); do
            wall() { echo "${sweep_rows[$1]}" | cut -d'|' -f$((k + 4)) | cut -d' ' -f1; }
            awk -v t="${tags[$k]}" -v a="$(wall 2)" -v b="$(wall 3)" -v c="$(wall 1)" \
                'BEGIN { printf "%s: with figures, 2 threads %.2f times as fast as 1 (target: at least 1.8); without figures on 2 threads %.0f cases/s (target: at least 1000).\n", t, a / b, 1e6 / c }'
            echo
        done
        if [ ${#summaries_differ[@]} -gt 0 ]; then
            echo "The two builds' sweep summaries DIFFER (${summaries_differ[*]}): output/bench/fixed_cost_summary_diff_*.txt."
        elif [ "$nb" -eq 2 ]; then
            echo "The two builds' sweep summaries are identical in each sweep."
        fi
    fi
} >"$work/fixed_cost.md"
mv "$work/fixed_cost.md" "$out/fixed_cost.md"
rm -f "$out"/fixed_cost_summary_diff_*.txt
for f in "$work"/summary_diff_*.txt; do
    [ -e "$f" ] && mv "$f" "$out/fixed_cost_${f##*/}"
done
cat "$out/fixed_cost.md"
