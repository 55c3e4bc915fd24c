#!/usr/bin/env bash
# The fixed cost of a small case over time: on a shared or virtual machine the speed of the
# case's own work drifts by a third from one minute to the next (output/bench/fixed_cost.md),
# so one run of bench_fixed_cost.sh says little about how often a target is met. This script
# repeats the small rows of that table (a do-nothing program linked like fricon; the N_e = 10
# and 40 plate without figure and estimates, in a folder of 500 files of another deck) in
# rounds spread over MINUTES, and prints one line per round: the time, the load average and the
# median wall time of REPS runs of each row for each build (the builds alternate run by run).
# The last lines give, per build and row, the median of the rounds' medians and the share of
# rounds at or below the issue's 6 ms.
#
#   bash scripts/bench_fixed_cost_series.sh BIN [BIN2] [MINUTES [INTERVAL_S [REPS]]]
#
# Defaults: 40 minutes, a round every 120 s, 20 runs per row and build. Writes the table to
# standard output (markdown).
set -euo pipefail
export SOURCE_DATE_EPOCH=${SOURCE_DATE_EPOCH:-1700000000}
bins=()
nums=()
for arg in "$@"; do
    if [[ $arg =~ ^[0-9]+$ ]]; then nums+=("$arg"); else bins+=("$(readlink -f "$arg")"); fi
done
[ ${#bins[@]} -ge 1 ] && [ ${#bins[@]} -le 2 ] || {
    echo "usage: bash scripts/bench_fixed_cost_series.sh BIN [BIN2] [MINUTES [INTERVAL_S [REPS]]]" >&2
    exit 1
}
minutes=${nums[0]:-40}
interval=${nums[1]:-120}
reps=${nums[2]:-20}
for bin in "${bins[@]}"; do
    [ -x "$bin" ] || { echo "bench_fixed_cost_series: not an executable: $bin" >&2; exit 1; }
done
command -v perl >/dev/null || { echo "bench_fixed_cost_series: perl is needed" >&2; exit 1; }
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# the programs and decks of bench_fixed_cost.sh
libs=$(sed -n 's/^link *= *\[\(.*\)\]/\1/p' fpm.toml | tr ',' '\n' | tr -d '" ' | sed 's/^/-l/')
printf 'program noop\nend program noop\n' >"$work/noop.f90"
# shellcheck disable=SC2086
gfortran -O2 -fopenmp -o "$work/noop" "$work/noop.f90" -Wl,--no-as-needed $libs
for ne in 10 40; do
    sed "s/^MESH      20 /MESH      $(printf '%-3s' "$ne")/" input/plate_nondim.dat \
        >"$work/plate$ne.dat"
    grep -q "^MESH      $ne " "$work/plate$ne.dat"
done
for k in "${!bins[@]}"; do
    mkdir -p "$work/out_$k"
    for i in $(seq -w 1 100); do
        for ext in txt dat gp csv json; do printf 'other\n' >"$work/out_$k/other_$i.$ext"; done
    done
done

# median_ms COMMAND...: the median wall time [ms] of REPS runs of COMMAND for each build, one
# line each, the builds alternating run by run; in COMMAND @BIN@ stands for the build and @OUT@
# for its folder (as in bench_fixed_cost.sh)
median_ms() {
    perl -MTime::HiRes=time -e '
        my ($reps, $nb, @rest) = @ARGV;
        my @bins = @rest[0 .. $nb - 1];
        my @cmd = @rest[$nb .. $#rest];
        my @t = map { [] } @bins;
        open(my $saved, ">&", \*STDOUT) or die;
        open(STDOUT, ">", "/dev/null") or die;
        for my $r (1 .. $reps) {
            for my $k (0 .. $nb - 1) {
                my @c = map { my $x = $_; $x =~ s/\@BIN\@/$bins[$k]/g;
                              $x =~ s/\@OUT\@/$ENV{WORK}\/out_$k/g; $x } @cmd;
                my $t0 = time;
                system(@c) == 0 or die "bench_fixed_cost_series: @c failed\n";
                push @{$t[$k]}, 1000 * (time - $t0);
            }
        }
        open(STDOUT, ">&", $saved) or die;
        for my $k (0 .. $nb - 1) {
            my @s = sort { $a <=> $b } @{$t[$k]};
            my $n = @s;
            my $m = $n % 2 ? $s[($n - 1) / 2] : ($s[$n / 2 - 1] + $s[$n / 2]) / 2;
            printf "%.2f\n", $m;
        }' "$reps" "${#bins[@]}" "${bins[@]}" "$@"
}
export WORK=$work

echo "# The fixed cost of a small case over time (scripts/bench_fixed_cost_series.sh)"
echo
for k in "${!bins[@]}"; do echo "Build $((k + 1)): \`${bins[$k]}\`, $(ldd "${bins[$k]}" | grep -c '=>') shared libraries."; done
echo
echo "Machine: $(nproc) cores, $(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1)."
echo "Each cell: the median wall time of $reps runs [ms]; a round every $interval s for $minutes minutes."
echo
header="| time (UTC) | load average |"
rule="|---|---:|"
for row in noop 10 40; do
    for k in "${!bins[@]}"; do
        case $row in noop) name="do-nothing";; *) name="N_e = $row";; esac
        header="$header $name, build $((k + 1)) |"
        rule="$rule---:|"
    done
done
echo "$header"
echo "$rule"
end=$(( $(date +%s) + 60 * minutes ))
: >"$work/rounds"
while :; do
    start=$(date +%s)
    line="| $(date -u +%H:%M) | $(cut -d' ' -f1 /proc/loadavg) |"
    vals=()
    # the do-nothing program is the same for every build: it runs once in each build's slot
    while read -r v; do vals+=("$v"); done < <(median_ms "$work/noop")
    for ne in 10 40; do
        while read -r v; do vals+=("$v"); done < <(median_ms @BIN@ -q --no-figures \
            --no-estimates -o @OUT@ "$work/plate$ne.dat")
    done
    for v in "${vals[@]}"; do line="$line $v |"; done
    echo "$line"
    echo "${vals[*]}" >>"$work/rounds"
    [ "$(date +%s)" -ge "$end" ] && break
    sleep $(( interval - ($(date +%s) - start) > 0 ? interval - ($(date +%s) - start) : 0 ))
done
echo
echo "Over the rounds (the median of the rounds' medians; rounds at or below 6 ms):"
echo
perl -e '
    my $nb = shift;
    my @rows;
    while (<>) { push @rows, [split] }
    my $n = @rows;
    for my $i (0 .. $#{$rows[0]}) {
        my @a = sort { $a <=> $b } map { $_->[$i] } @rows;
        my $med = $n % 2 ? $a[($n - 1) / 2] : ($a[$n / 2 - 1] + $a[$n / 2]) / 2;
        my $le = grep { $_ <= 6.0 } @a;
        my $row = $i < $nb ? "do-nothing" : ($i < 2 * $nb ? "N_e = 10" : "N_e = 40");
        printf "- %s, build %d: %.2f ms; %d of %d rounds at or below 6 ms\n", $row,
            $i % $nb + 1, $med, $le, $n;
    }' "${#bins[@]}" "$work/rounds"
