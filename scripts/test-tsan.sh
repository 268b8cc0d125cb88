#!/usr/bin/env bash
# Builds the engine, the runner and every suite that needs no window and starts threads with
# ThreadSanitizer (clang, into build-tsan/) and runs them: the ASan + UBSan stage's suites but the
# nine marked THREADLESS in tests/CMakeLists.txt (shapes, hulls, GJK/EPA, shape pairs, ray casts,
# meshes, the broad phase, mesh import, the worker tuner: single-threaded code). The build sets the default of
# WorldSettings::threads to 4 (SIMCORE_DEFAULT_THREADS), so every world the suites make, in code or
# from a scene file without "threads", steps its parallel stages on a pool of 3 workers and the
# caller; test_threads also runs 2 and 4 threads against 1 bit for bit. The first report ends the
# run and fails it. Left out: the editor (not built here; its suites run in the Release stage) and
# the long stability suite (label long: minutes in Release, far longer here).
#   ./scripts/test-tsan.sh [CTEST ARGS...]     e.g. -R test_threads
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${INTERPLAY_TSAN_BUILD:-$root/build-tsan}"
"$root/scripts/install-deps.sh"
# -O1 keeps the build and the instrumented run quick; line tables make reports name file:line.
# The runtime keeps its own operator new and delete, so the allocation counter
# (tests/support/allocation_counter.cpp) counts through the runtime's allocation hook here.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    -DSIMCORE_DEFAULT_THREADS=4 -DINTERPLAY_BENCH=OFF -DINTERPLAY_EDITOR=OFF -DINTERPLAY_THREADLESS_SUITES=OFF >/dev/null
cmake --build "$build"
export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan.supp"
# Qt Test's crash handler forks a debugger from the signal handler, which deadlocks in the sanitizer's
# fork hook after a report; the report itself already has the stacks.
export QTEST_DISABLE_STACK_DUMP=1
# One suite per core, as in test.sh (which sets this for every stage).
export CTEST_PARALLEL_LEVEL="${CTEST_PARALLEL_LEVEL:-$(nproc)}"
if [ $# -gt 0 ]; then
    exec ctest --test-dir "$build" --output-on-failure --timeout 900 "$@"
fi
exec ctest --test-dir "$build" --output-on-failure --timeout 900 -LE long
