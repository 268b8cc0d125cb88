#!/usr/bin/env bash
# Builds the engine and test_threads with ThreadSanitizer (clang, into build-tsan/) and runs it: the
# suite steps the benchmark and jointed scenes with 2 and 4 worker threads, so every parallel stage
# runs under the sanitizer. The first report ends the run and fails it. The other engine suites
# step with the default of one thread, where there is nothing for it to find; they run under
# ASan + UBSan (scripts/test-sanitizers.sh).
#   ./scripts/test-tsan.sh [CTEST ARGS...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${INTERPLAY_TSAN_BUILD:-$root/build-tsan}"
"$root/scripts/install-deps.sh"
# -O1 keeps the build and the instrumented run quick; line tables make reports name file:line.
# The suite's allocation counter (tests/support/allocation_counter.cpp) replaces operator new and
# delete, as the TSan runtime also does: the linker takes the counter's (it comes first), which
# allocate with malloc and free, and those the runtime still watches. No precompiled header: it
# serves one suite here, and building it costs more than it saves.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread -Wl,--allow-multiple-definition" \
    -DINTERPLAY_BENCH=OFF -DINTERPLAY_EDITOR=OFF -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON >/dev/null
cmake --build "$build" --target test_threads
export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan.supp"
# Qt Test's crash handler forks a debugger from the signal handler, which deadlocks in the sanitizer's
# fork hook after a report; the report itself already has the stacks.
export QTEST_DISABLE_STACK_DUMP=1
exec ctest --test-dir "$build" --output-on-failure --timeout 900 -R '^test_threads$' "$@"
