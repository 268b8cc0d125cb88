#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer (clang, into build-asan/)
# and runs every ctest test under them; a sanitizer report fails the test that caused it.
#   ./scripts/test-sanitizers.sh [CTEST ARGS...]     e.g. -R test_scene_io
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
source "$root/scripts/sanitizer-build.sh"
configure_asan_build
cmake --build "$asan_build"
ctest --test-dir "$asan_build" --output-on-failure --timeout 900 "$@"
