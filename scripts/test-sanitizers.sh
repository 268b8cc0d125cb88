#!/usr/bin/env bash
# Builds the engine, runner, tests and fuzz targets with ASan + UBSan (clang, into build-asan/)
# and runs the engine's and the runner's suites under them; a sanitizer report fails the test that
# caused it.
#   ./scripts/test-sanitizers.sh [CTEST ARGS...]     e.g. -R test_scene_io
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
source "$root/scripts/sanitizer-build.sh"
configure_asan_build
cmake --build "$asan_build"
if [ $# -gt 0 ]; then
    exec ctest --test-dir "$asan_build" --output-on-failure --timeout 900 "$@"
fi
# The editor is not part of this build (the CI time budget: it is half of the compile); its suites
# run in the Release stage. The long stability case (label long) would take many minutes here.
exec ctest --test-dir "$asan_build" --output-on-failure --timeout 900 -LE long
