#!/usr/bin/env bash
# Installs the Debian 12 packages Interplay needs to build, run and test (run as root; uses sudo
# otherwise). Packages already present are skipped, so this is fast on a prepared machine.
set -euo pipefail

packages=(
    # build
    cmake ninja-build g++ pkg-config
    qt6-base-dev qt6-base-dev-tools qt6-declarative-dev qt6-declarative-dev-tools libqt6opengl6-dev
    libglm-dev nlohmann-json3-dev
    # run: OpenGL through Mesa, QML modules the panels import, a font
    libgl1-mesa-dri qt6-qpa-plugins fonts-dejavu-core
    qml6-module-qtquick qml6-module-qtqml-workerscript qml6-module-qtquick-controls
    qml6-module-qtquick-layouts qml6-module-qtquick-templates qml6-module-qtquick-window
    # test: a virtual X server for the OpenGL window tests
    xvfb xauth
    # benchmark: Bullet, the reference engine (benchmark only)
    libbullet-dev
    # reliability: clang with its sanitizer and libFuzzer runtimes, llvm-symbolizer for readable
    # reports (scripts/test-sanitizers.sh, scripts/fuzz.sh)
    clang libclang-rt-14-dev llvm
    # geometry import: OBJ, STL and glTF meshes (simcore's importer)
    libassimp-dev
    # distributed sweeps: the GNU parallel recipe of interplay-sweep, tested in CI
    parallel
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
