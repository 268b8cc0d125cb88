#!/usr/bin/env bash
# Box3D and Interplay, each at 1 and 2 threads, on the anchor scenes, alternating within one run:
# the thread-count side of ../shared/anchors/run_anchors.sh (which runs Interplay at 1 thread only).
# It uses that script's harnesses: box3d_bench (built by run_anchors.sh, BUILD_ONLY=1 builds just
# them) and interplay_anchor.py, which writes the same scene for interplay-run.
#
# usage: bench/anchors/threads_vs_box3d.sh [INTERPLAY_RUN]   (default build/app/interplay-run)
# env:   ANCHORS=../shared/anchors (the harness sources)  ANCHORS_DIR=${TMPDIR:-/tmp}/interplay-anchors
#        SCENES="pile1k mixed1k pyramid pyramid20"  REPEATS=3
# Prints one line per run (ENGINE= THREADS= REP= and the harness's figures), then the medians.
# THREADS is what ran: interplay_anchor.py's own line says threads=1 whatever its runner adds.
# Before each 2-thread run, RT= is the core-to-core round trip in ns (interplay-bench-threads
# --round-trip, next to the runner's build folder, or $BENCH_THREADS): where the host runs the two
# virtual CPUs on cores that share no cache (350-600 ns against 70-190) neither engine gains from
# a second thread, and the table's last column gives the range.
set -uo pipefail

IRUN=$(realpath "${1:-build/app/interplay-run}")
ANCHORS=$(realpath "${ANCHORS:-$(dirname "${BASH_SOURCE[0]}")/../../../shared/anchors}")
A=${ANCHORS_DIR:-${TMPDIR:-/tmp}/interplay-anchors}
SCENES=${SCENES:-"pile1k mixed1k pyramid pyramid20"}
REPEATS=${REPEATS:-3}
BOX3D="$A/bin/box3d_bench"
[[ -x "$BOX3D" ]] || { echo "no $BOX3D: run $ANCHORS/run_anchors.sh with BUILD_ONLY=1 and BOX3D_GIT set" >&2; exit 2; }
[[ -x "$IRUN" ]] || { echo "no interplay-run at $IRUN" >&2; exit 2; }
BENCH_THREADS=${BENCH_THREADS:-$(dirname "$IRUN")/../bench/interplay-bench-threads}
[[ -x "$BENCH_THREADS" ]] || { echo "no interplay-bench-threads at $BENCH_THREADS" >&2; exit 2; }

# interplay_anchor.py runs `RUNNER scene.json --steps N`: a runner that adds --threads 2.
IRUN2="$A/bin/interplay-run-2-threads"
printf '#!/bin/sh\nexec "%s" "$@" --threads 2\n' "$IRUN" >"$IRUN2" && chmod +x "$IRUN2"

RES="$A/results/threads-$(date +%Y%m%d-%H%M%S).txt"
echo "# $(date -u '+%Y-%m-%d %H:%M UTC') $(nproc) cpus $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load before $(cut -d' ' -f1-3 /proc/loadavg)" | tee "$RES"
one() { # one ENGINE THREADS REP CMD...
    local rt="" line
    [[ $2 -gt 1 ]] && rt="RT=$("$BENCH_THREADS" --round-trip) "
    line=$("${@:4}" 2>/dev/null | grep -m1 "mean_ms=") || line="FAILED"
    echo "ENGINE=$1 THREADS=$2 REP=$3 $rt$line" | tee -a "$RES"
}
for scene in $SCENES; do
    for rep in $(seq 1 "$REPEATS"); do
        one box3d 1 "$rep" "$BOX3D" "$scene" 1
        one interplay 1 "$rep" python3 "$ANCHORS/interplay_anchor.py" "$IRUN" "$scene" "$A/scenes"
        one box3d 2 "$rep" "$BOX3D" "$scene" 2
        one interplay 2 "$rep" python3 "$ANCHORS/interplay_anchor.py" "$IRUN2" "$scene" "$A/scenes"
    done
done
echo "# load after $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$RES"
python3 - "$RES" <<'PY'
import re, statistics, sys
runs, trips = {}, {}
for line in open(sys.argv[1]):
    kv = dict(t.split("=", 1) for t in line.split() if "=" in t)
    if "mean_ms" in kv:
        runs.setdefault((kv["scene"], kv["ENGINE"], kv["THREADS"]), []).append(float(kv["mean_ms"]))
    if "RT" in kv and "scene" in kv:
        trips.setdefault(kv["scene"], []).append(int(kv["RT"]))
print("\n| scene | Box3D 1T | Box3D 2T | Interplay 1T | Interplay 2T | Interplay / Box3D, 1T | 2T | Interplay 2T / 1T speedup | round trip, ns |")
print("|---|--:|--:|--:|--:|--:|--:|--:|--:|")
for scene in dict.fromkeys(s for s, _, _ in runs):
    m = {(e, t): statistics.median(v) for (s, e, t), v in runs.items() if s == scene}
    g = lambda e, t: m.get((e, t), float("nan"))
    print(f"| {scene} | {g('box3d','1'):.3f} | {g('box3d','2'):.3f} | {g('interplay','1'):.3f} | {g('interplay','2'):.3f} | "
          f"{g('interplay','1')/g('box3d','1'):.2f} | {g('interplay','2')/g('box3d','2'):.2f} | {g('interplay','1')/g('interplay','2'):.2f} | "
          f"{min(trips.get(scene, [0]))}–{max(trips.get(scene, [0]))} |")
PY
echo "raw: $RES"
