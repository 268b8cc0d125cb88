# Sourced by test-sanitizers.sh and fuzz.sh: the one sanitizer build both use (build-asan/), so
# whichever runs second finds it built. clang, AddressSanitizer + UndefinedBehaviorSanitizer on every
# target, libFuzzer targets on top; the benchmarks and the editor are left out (the editor's suites
# run in the Release stage).
#   INTERPLAY_ASAN_BUILD=DIR   build directory (default: build-asan/ in the source tree)

asan_build="${INTERPLAY_ASAN_BUILD:-$root/build-asan}"

configure_asan_build() {
    # -O1 keeps the build and the instrumented run quick; line tables make reports name file:line.
    cmake -S "$root" -B "$asan_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
        -DINTERPLAY_SANITIZE=ON -DINTERPLAY_FUZZ=ON -DINTERPLAY_BENCH=OFF -DINTERPLAY_EDITOR=OFF >/dev/null
}

# Every sanitizer report is fatal (the build also compiles with -fno-sanitize-recover=all).
# intercept_strndup=0: Debian 12's libxkbcommon-x11 (under Qt's xcb platform, so in every GUI test)
# strndup()s X atom names that are not NUL-terminated, which the interceptor reports as an overflow;
# no Interplay code calls strndup.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=0:intercept_strndup=0"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
if [ -z "${ASAN_SYMBOLIZER_PATH:-}" ] && command -v llvm-symbolizer >/dev/null; then
    export ASAN_SYMBOLIZER_PATH="$(command -v llvm-symbolizer)"
fi
