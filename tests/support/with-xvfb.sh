#!/usr/bin/env bash
# Runs a command on an X server of its own (Xvfb, 1280x1024, 24 bits) and stops the server after.
# The server picks a free display number itself (-displayfd), so windowed suites can run side by
# side: `xvfb-run -a` picks one by looking for lock files and two starting at once can pick the same.
#   with-xvfb.sh COMMAND [ARGS...]
set -uo pipefail
[ $# -gt 0 ] || { echo "usage: with-xvfb.sh COMMAND [ARGS...]" >&2; exit 2; }
dir="$(mktemp -d)"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" 2>"$dir/log" &
server=$!
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$dir"' EXIT
# The server writes its display number once it accepts connections.
for _ in $(seq 200); do
    grep -q '^[0-9]' "$dir/display" 2>/dev/null && break
    kill -0 "$server" 2>/dev/null || break
    sleep 0.05
done
display="$(grep -m1 '^[0-9]' "$dir/display" 2>/dev/null)"
if [ -z "$display" ]; then
    echo "with-xvfb.sh: Xvfb did not start; its log:" >&2
    cat "$dir/log" >&2
    exit 1
fi
DISPLAY=":$display" "$@"
