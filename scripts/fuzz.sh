#!/usr/bin/env bash
# Short libFuzzer runs of the fuzz targets in fuzz/ (built with clang, ASan + UBSan, into
# build-asan/), all at once (one core each). A crash, a hang (an input over 10 s), a leak or an
# allocation beyond 2 GB fails the run; the input that did it is saved in build-asan/fuzz-artifacts/
# and should be added to tests/data/fuzz/TARGET/ as a regression input (ctest replays that folder).
#   ./scripts/fuzz.sh [SECONDS]     seconds per target (default 60, or $FUZZ_SECONDS)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-${FUZZ_SECONDS:-60}}"
targets=(scene_load scene_step mesh_import)
max_len=16384

"$root/scripts/install-deps.sh"
source "$root/scripts/sanitizer-build.sh"
configure_asan_build
cmake --build "$asan_build" --target "${targets[@]/#/fuzz_}"

# Seeds: the committed corpus, the regression inputs, and the demo scenes small enough to be fuzzed
# whole. The corpus the fuzzer grows stays in the build directory.
seeds="$asan_build/fuzz-seeds"
rm -rf "$seeds" && mkdir -p "$seeds"
find "$root/scenes" -name '*.json' -size -${max_len}c -exec cp {} "$seeds/" \;
mkdir -p "$asan_build/fuzz-artifacts"

pids=()
for t in "${targets[@]}"; do
    mkdir -p "$asan_build/fuzz-corpus/$t"
    # The scene targets start from scenes with the scene dictionary; the importer from mesh files.
    if [ "$t" = mesh_import ]; then
        inputs=(-max_len=$max_len "$asan_build/fuzz-corpus/$t" "$root/tests/data/fuzz/$t" "$root/tests/data/meshes"
                "$root/tests/data/meshes/hostile")
    else
        inputs=(-max_len=$max_len -dict="$root/fuzz/scene.dict" "$asan_build/fuzz-corpus/$t" "$root/fuzz/corpus"
                "$root/tests/data/fuzz/$t" "$seeds")
    fi
    "$asan_build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
        -use_value_profile=1 -print_final_stats=1 -artifact_prefix="$asan_build/fuzz-artifacts/$t-" "${inputs[@]}" \
        >"$asan_build/fuzz-$t.log" 2>&1 &
    pids+=($!)
done

passed=0 failed=0
for i in "${!targets[@]}"; do
    t="${targets[$i]}"
    log="$asan_build/fuzz-$t.log"
    if wait "${pids[$i]}"; then
        passed=$((passed + 1))
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
        corpus=$(ls "$asan_build/fuzz-corpus/$t" | wc -l)
        echo "fuzz_$t: ${runs:-?} inputs in ${seconds} s, no failure (corpus: $corpus inputs)"
    else
        failed=$((failed + 1))
        echo "fuzz_$t: FAILED; the end of its log ($log):"
        tail -n 60 "$log"
        for a in "$asan_build/fuzz-artifacts/$t-"*; do
            [ -e "$a" ] && echo "fuzz_$t: reproducer $a: add it to tests/data/fuzz/$t/ once fixed"
        done
    fi
done
echo "fuzz: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
