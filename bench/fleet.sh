#!/usr/bin/env bash
# Fleet-scale benchmark: one `dolphin sim` process with 50, 250 and 1000 vehicles (250 per link,
# so four links for 1000) streaming at 4 Hz, and the runtime in the benchmark's process flying
# bench/fleet.dolphin on every vehicle, each cut at 90 % battery by its own guard. Plain Java main
# (dolphin.bench.FleetBench), real time. See bench/README.md.
#
#   bench/fleet.sh [--no-build] [--web | --flood RATE] [SIZE...]      # default sizes: 50 250 1000
#
# With --web (needs Debian's chromium), each size runs twice: without the web view, then with it
# and a page open in a headless chromium; the summary gives the ratios (issue 13). With --flood RATE,
# each size runs without, then with every vehicle sending RATE sensor readings per second; the
# summary gives the ratio of the reaction p99 (issue 21; sizes up to 250, one link).
#
# Prints the summary, also in bench/target/results/fleet-summary.txt; every reaction time is in
# fleet.json there. Exit status 1 if a run did not complete or a vehicle was not cut.
# Takes about 3 minutes on 2 cores.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if [ "${1:-}" = "--no-build" ]; then shift; else "$bench/build.sh"; fi
web=()
if [ "${1:-}" = "--web" ]; then web=(--web); shift; fi
if [ "${1:-}" = "--flood" ]; then web=(--flood "$2"); shift 2; fi
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(50 250 1000)
echo "== fleet scale: ${sizes[*]} vehicles" >&2
bench_main fleet.sh FleetBench "$out" "$bench/fleet.dolphin" "$(command -v java)" "$jar:$root/target/lib/*" "${web[@]}" "${sizes[@]}"
