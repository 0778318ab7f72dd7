#!/usr/bin/env bash
# Lossy-link upload benchmark: at 0, 5, 10, 20 and 30 % loss both ways, 10, 100 and 500 items, our
# upload over the item protocol and over MAVLink FTP against a pymavlink uploader that does what
# MAVProxy's `wp load` does (mavproxy_wpload.py, its own process and simulated vehicle, same loss
# and seed), every upload verified against the simulated vehicle's stored list. Real UDP on
# 127.0.0.1, real time. Plain Java main (dolphin.bench.LossyUploadBench). See bench/README.md.
#
#   bench/lossy.sh [--no-build] [--quick] [--lossless] [--baseline REV | --baseline-jar JAR] [--rounds N] [--cell-seconds S] [--deadline S]
#
# --quick: 3 lossless rounds, lossy 10 and 100 items only, at most 2 rounds a cell, reference deadline 20 s
#   (under 2 minutes).
# --lossless: only the lossless rounds (with --baseline, the before/after check alone; about a minute).
# --baseline REV: also builds the main project at git revision REV (once, in bench/target/baseline-REV)
#   and compares its lossless uploads with this tree's, each in a JVM of its own (UploadServer);
#   --baseline-jar JAR: the same with a jar already built (its runtime classpath in JAR's lib/).
# Prints the summary, also in bench/target/results/lossy-summary.txt; every upload is in lossy.json
# there. Exit status 1 if one of our uploads did not verify. A full run takes about 10 minutes on 2 cores.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if [ "${1:-}" = "--no-build" ]; then shift; else "$bench/build.sh"; fi
args=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--baseline" ]; then
    base="$bench/target/baseline-$2"
    if [ ! -e "$base/target/dolphin.jar" ]; then
      echo "== building the baseline $2 in $base" >&2
      rm -rf "$base" && mkdir -p "$base"
      git -C "$root" archive "$2" | tar -x -C "$base"
      cp -r "$root/.venv" "$base/"
      (cd "$base" && mvn -B -q -ntp -DskipTests package)
    fi
    args+=(--baseline-jar "$base/target/dolphin.jar")
    shift 2
  else
    args+=("$1")
    shift
  fi
done
echo "== lossy-link uploads: ours (item protocol, FTP) and the wp load reference, 0-30 % loss" >&2
bench_main lossy.sh LossyUploadBench "$out" "$python" "$bench/mavproxy_wpload.py" ${args[@]+"${args[@]}"}
