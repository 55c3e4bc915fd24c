#!/usr/bin/env bash
# Fuzz the deck reader with AFL++ (issue #10, item 1). Not part of `fpm test`.
#
#   scripts/fuzz.sh [--install] [--minutes N] [--out DIR] [--resume] [--extra-seeds DIR]
#   scripts/fuzz.sh --replay DIR...      check files/folders with the plain build only
#
# Steps: (0) --install: apt-get install afl++ (Debian); (1) build fuzz/fuzz_deck.f90 with the
# reader's sources twice, into fuzz/build/: plain (-g -fcheck=all, for triage) and AFL
# (-fsanitize-coverage=trace-pc + fuzz/afl_trace_pc.c + AFL++'s runtime); (2) seeds from
# fuzz/seeds.txt, minimised with afl-cmin; (3) one afl-fuzz instance, niced, for N minutes
# (default 35); (4) summary: afl stats, and every queue/crash/hang file replayed with the plain
# build, which must end in exit 0 (valid model) or exit 1 with an "ERROR:" message.
# Exit status: 0 clean, 1 findings (crash, hang or contract violation), 2 usage/setup.
set -euo pipefail
# the whole script is one function, read before it runs (editing it mid-campaign is then safe)
main() {
cd "$(dirname "$0")/.."
root=$(pwd)

minutes=35
out=fuzz/out
install=0
resume=0
replay_only=0
replay_args=()
extra_seeds=
while [ $# -gt 0 ]; do
    case "$1" in
    --install) install=1 ;;
    --minutes) minutes=$2; shift ;;
    --out) out=$2; shift ;;
    --resume) resume=1 ;;
    --extra-seeds) extra_seeds=$2; shift ;;   # e.g. the queue of an earlier campaign
    --replay) replay_only=1; shift; replay_args=("$@"); break ;;
    -h | --help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    esac
    shift
done

build=fuzz/build
srcs="src/kinds.f90 src/errors.f90 src/sorting.f90 src/model/foundation_structure.f90
      src/model/ground_model.f90 src/model/interface_properties.f90 src/model/applied_loads.f90
      src/model/mesh_request.f90 src/model/solver_controls.f90 src/model/model.f90
      src/fe/mesh.f90 src/fe/shape_functions.f90
      src/fe/mesh_refinement.f90 src/fe/discretization.f90
      src/deck/deck_fields.f90 src/deck/deck_reader.f90 src/deck/plausibility.f90
      fuzz/fuzz_deck.f90"
fflags="-O1 -g -fcheck=all -fbacktrace"

# ---- 0. install ----------------------------------------------------------------------------
if [ $install = 1 ] && ! command -v afl-fuzz >/dev/null; then
    apt-get update && apt-get install -y afl++
fi

# ---- 1. build ------------------------------------------------------------------------------
compile() { # dir extra-flags...
    local dir=$1; shift
    mkdir -p "$dir"
    local objs=()
    for s in $srcs; do
        local o="$dir/$(basename "$s" .f90).o"
        gfortran $fflags "$@" -J "$dir" -c "$s" -o "$o"
        objs+=("$o")
    done
    echo "${objs[@]}"
}
objs=$(compile $build/plain)
gfortran $fflags $objs -o $build/plain/fuzz_deck
if [ $replay_only = 0 ]; then
    command -v afl-fuzz >/dev/null || { echo "fuzz.sh: afl-fuzz not found (use --install)" >&2; exit 2; }
    rt=/usr/lib/afl/afl-compiler-rt.o
    [ -f $rt ] || rt=$(dirname "$(readlink -f "$(command -v afl-fuzz)")")/../lib/afl/afl-compiler-rt.o
    objs=$(compile $build/afl -fsanitize-coverage=trace-pc)
    gcc -O2 -c fuzz/afl_trace_pc.c -o $build/afl/afl_trace_pc.o
    gfortran -g $objs $build/afl/afl_trace_pc.o "$rt" -o $build/afl/fuzz_deck -ldl -lpthread
fi

# ---- replay: the oracle, with the plain build -----------------------------------------------
# prints one line per violation; sets n_checked, n_ok, n_input, n_bad
replay() {
    n_checked=0; n_ok=0; n_input=0; n_bad=0
    local f rc err
    err=$(mktemp)
    while IFS= read -r -d '' f; do
        case "$(basename "$f")" in README.txt | .state | .cur_input | .synced) continue ;; esac
        n_checked=$((n_checked + 1))
        set +e
        timeout 10 $build/plain/fuzz_deck "$f" >/dev/null 2>"$err"
        rc=$?
        set -e
        if [ $rc = 0 ]; then
            n_ok=$((n_ok + 1))
        elif [ $rc = 1 ] && grep -q '^ERROR: .' "$err" && ! grep -q 'Fortran runtime' "$err"; then
            n_input=$((n_input + 1))
        else
            n_bad=$((n_bad + 1))
            echo "VIOLATION exit=$rc $f: $(grep -m1 -v '^$' "$err" || true)"
        fi
    done < <(find "$@" -type f -not -path '*/.state/*' -print0 | sort -z)
    rm -f "$err"
}
if [ $replay_only = 1 ]; then
    replay "${replay_args[@]}"
    echo "replayed $n_checked: $n_ok valid, $n_input input errors, $n_bad violations"
    [ $n_bad = 0 ]; exit
fi

# ---- 2. seeds ------------------------------------------------------------------------------
mkdir -p "$out"
campaign=$out/campaign
if [ $resume = 0 ]; then
    rm -rf "$out/seeds_all" "$out/seeds_min"
    mkdir -p "$out/seeds_all"
    grep -v '^\s*#' fuzz/seeds.txt | while read -r pat; do
        [ -n "$pat" ] || continue
        for f in $pat; do
            if [ -f "$f" ]; then cp "$f" "$out/seeds_all/$(echo "$f" | tr / _)"; fi
        done
    done
    if [ -n "$extra_seeds" ]; then
        for f in "$extra_seeds"/*; do
            if [ -f "$f" ]; then cp "$f" "$out/seeds_all/extra_$(basename "$f" | tr ':,' '__')"; fi
        done
    fi
    # afl-cmin refuses folders under /tmp; keep $out elsewhere
    afl-cmin -i "$out/seeds_all" -o "$out/seeds_min" -t 2000 -m none -- \
        $build/afl/fuzz_deck @@ >"$out/cmin.log" 2>&1
    rm -rf "$campaign"
    input="$out/seeds_min"
else
    input=-
fi

# ---- 3. campaign: one instance, niced --------------------------------------------------------
export AFL_CRASH_EXITCODE=2                # gfortran runtime errors (-fcheck=all) exit 2
export AFL_SKIP_CPUFREQ=1 AFL_NO_AFFINITY=1 AFL_NO_UI=1
export AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1
export GFORTRAN_ERROR_BACKTRACE=0          # no backtrace inside the fuzzer (speed)
echo "fuzz.sh: $(date -u '+%F %T') UTC, $minutes min, log $out/afl.log"
t0=$(date +%s)
set +e
/usr/bin/time -f '%U %S %e' -o "$out/cpu.txt" \
    nice -n 10 afl-fuzz -i "$input" -o "$campaign" -x fuzz/deck.dict -t 2000 -m none \
    -V $((minutes * 60)) -- $build/afl/fuzz_deck @@ >"$out/afl.log" 2>&1
rc=$?
set -e
[ $rc = 0 ] || { echo "fuzz.sh: afl-fuzz failed ($rc), see $out/afl.log" >&2; tail -20 "$out/afl.log" >&2; exit 2; }
unset GFORTRAN_ERROR_BACKTRACE

# ---- 4. summary ----------------------------------------------------------------------------
stats=$campaign/default/fuzzer_stats
stat() { awk -F' *: *' -v k="$1" '$1 == k {print $2}' "$stats"; }
read -r cpu_user cpu_sys wall <"$out/cpu.txt"
echo "campaign: $(date -u -d @$t0 '+%F %T') UTC, wall ${wall}s, CPU user ${cpu_user}s + sys ${cpu_sys}s"
for k in afl_version run_time execs_done execs_per_sec corpus_count corpus_found edges_found \
         total_edges bitmap_cvg saved_crashes saved_hangs stability; do
    printf '  %-14s %s\n' "$k" "$(stat $k)"
done
replay "$campaign/default/queue" "$campaign/default/crashes" "$campaign/default/hangs"
echo "replay (plain build, -fcheck=all): $n_checked inputs, $n_ok valid models," \
     "$n_input clean input errors, $n_bad violations"
crashes=$(stat saved_crashes); hangs=$(stat saved_hangs)
if [ "$crashes" != 0 ] || [ "$hangs" != 0 ] || [ $n_bad != 0 ]; then
    echo "FINDINGS: see $campaign/default/crashes and hangs"; exit 1
fi
echo "clean: zero crashes, zero hangs, every input a valid model or a clean exit 1"
}
main "$@"; exit $?
