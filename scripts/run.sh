#!/usr/bin/env bash
# Installs, builds and starts the editor: ./scripts/run.sh [SCENE.json]
# (no scene: the built-in default scene).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/build.sh"
exec "$root/build/app/interplay" "$@"
