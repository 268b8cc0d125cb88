#!/usr/bin/env bash
# Installs, builds and runs every test, in four stages that each also run alone:
#   1. the ctest suites, Release (build/);
#   2. the same suites under AddressSanitizer + UndefinedBehaviorSanitizer (scripts/test-sanitizers.sh,
#      build-asan/);
#   3. those of them that start threads under ThreadSanitizer, every world on 4 threads
#      (scripts/test-tsan.sh, build-tsan/);
#   4. a short libFuzzer run of every fuzz target (scripts/fuzz.sh; FUZZ_SECONDS=N per target, default 30
#      here, 60 when fuzz.sh runs alone).
# Every stage runs even when an earlier one fails, so one run shows every failure; the exit code is
# non-zero if any stage failed.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT

"$root/scripts/build.sh" || exit 1
stage_times=("install and Release build $SECONDS s")  # each stage's wall time, for the summary

failed_stages=()
stage() {  # stage NAME COMMAND...: runs it, its output to the terminal and to $logs/NAME
    local name="$1"
    shift
    echo "== $name"
    local start=$SECONDS
    "$@" 2>&1 | tee "$logs/$name"
    local status=${PIPESTATUS[0]}
    stage_times+=("$name $((SECONDS - start)) s")
    [ "$status" -eq 0 ] || failed_stages+=("$name")
}
# The suites are independent processes, run one per core (windowed ones each on an X server of its
# own: tests/support/with-xvfb.sh); ctest reads this in every stage.
export CTEST_PARALLEL_LEVEL="${CTEST_PARALLEL_LEVEL:-$(nproc)}"
stage release ctest --test-dir "$root/build" --output-on-failure --timeout 900
stage sanitizers "$root/scripts/test-sanitizers.sh"
stage tsan "$root/scripts/test-tsan.sh"
stage fuzz "$root/scripts/fuzz.sh" "${FUZZ_SECONDS:-30}"  # 30 s per target here: the CI time budget

# ctest's "N% tests passed, F tests failed out of T" and fuzz.sh's "fuzz: P passed, F failed".
ctest_counts() {  # summed over every ctest run of the stage (the sanitizer stage has two)
    sed -n 's/.*tests passed, \([0-9]*\) tests\{0,1\} failed out of \([0-9]*\).*/\2 \1/p' "$logs/$1" |
        awk '{t += $1; f += $2} END {if (NR) print t - f, f}'
}
read -r rp rf < <(ctest_counts release; echo "0 1")
read -r ap af < <(ctest_counts sanitizers; echo "0 1")
read -r tp tf < <(ctest_counts tsan; echo "0 1")
read -r fp ff < <(sed -n 's/^fuzz: \([0-9]*\) passed, \([0-9]*\) failed.*/\1 \2/p' "$logs/fuzz"; echo "0 1")
echo "Release: $rp passed, $rf failed; ASan+UBSan: $ap passed, $af failed; TSan: $tp passed, $tf failed;" \
    "fuzz targets: $fp passed, $ff failed"
if [ ${#failed_stages[@]} -gt 0 ]; then
    echo "failed stages: ${failed_stages[*]}"
fi
printf -v times '%s, ' "${stage_times[@]}"
echo "wall time: ${times}total $SECONDS s"
echo "all: $((rp + ap + tp + fp)) passed, $((rf + af + tf + ff)) failed"
[ ${#failed_stages[@]} -eq 0 ]
