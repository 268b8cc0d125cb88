#!/bin/sh
# Wall time of the accuracy benchmark (interplay-bench-accuracy, its full grid) against
# interplay-sweep over the same ten reference scenes (saved by --save-scenes) at the sweep's default
# grid, each scene for the simulated time the benchmark gives it. The two alternate, ROUNDS times,
# so that the machine's load falls on both alike; prints each round, the load around it, and the
# medians as a Markdown table.
# usage: bench/accuracy/time_against_sweep.sh BUILD_DIR [ROUNDS] [SWEEP OPTIONS...]
set -eu
build=$(cd "$1" && pwd)
rounds=${2:-3}
shift $(( $# < 2 ? $# : 2 ))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bench/interplay-bench-accuracy" --save-scenes "$work/scenes" > "$work/scenes.txt"

now() { date +%s.%N; }
load() { cut -d' ' -f1 /proc/loadavg; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "| round | benchmark s | sweep s | sweep / benchmark | load before | load after |"
echo "|--:|--:|--:|--:|--:|--:|"
for round in $(seq "$rounds"); do
    before=$(load)
    start=$(now)
    "$build/bench/interplay-bench-accuracy" --out "$work/bench" > /dev/null 2>&1
    bench=$(echo "$(now) - $start" | bc)
    start=$(now)
    while read -r file seconds; do
        rm -rf "$work/sweep"
        "$build/app/interplay-sweep" "$work/scenes/$file" --seconds "$seconds" --out "$work/sweep" "$@" > /dev/null 2>&1
    done < "$work/scenes.txt"
    sweep=$(echo "$(now) - $start" | bc)
    echo "$bench" >> "$work/bench.txt"
    echo "$sweep" >> "$work/sweep.txt"
    printf '| %d | %.1f | %.1f | %.2f | %s | %s |\n' "$round" "$bench" "$sweep" "$(echo "$sweep / $bench" | bc -l)" "$before" "$(load)"
done
bench=$(median < "$work/bench.txt")
sweep=$(median < "$work/sweep.txt")
printf '| median | %.1f | %.1f | %.2f | | |\n' "$bench" "$sweep" "$(echo "$sweep / $bench" | bc -l)"
