#!/usr/bin/env bash
# Records a flight of real ArduPilot SITL for RecordingConformanceSpec: starts a SITL binary that you
# built from ArduPilot's sources (this repository builds none), flies a Dolphin script against it with
# `dolphin run --tlog`, and keeps the tlog and dolphin's output in src/test/resources/sitl-recordings.
# SITL listens on every network interface, so everything runs in a network namespace that has only
# loopback (unshare -n, as root).
#
#   harness/record-sitl.sh NAME BINARY MODEL DEFAULTS SCRIPT [SETTLE_S] [TIMEOUT_S] [HOME]
#
# NAME      recording name (NAME.tlog, NAME.out)      BINARY    arducopter, arduplane, ardurover...
# MODEL     SITL's --model (+, plane, rover)          DEFAULTS  its parameter files (Tools/autotest/...),
#                                                               comma-separated, later ones overriding
# SCRIPT    the .dolphin script to fly                SETTLE_S  real seconds between SITL's start and
#                                                               dolphin's (0: "at boot"; default 15)
# TIMEOUT_S real seconds after which dolphin is stopped (default 240); SITL runs at --speedup 5.
# HOME      SITL's home LAT,LON,ALT (default 40.444233,-7.375234,820; ArduSub needs one at sea level)
set -euo pipefail
[ $# -ge 5 ] || { sed -n '2,18p' "$0"; exit 2; }
name=$1 binary=$(realpath "$2") model=$3 script=$(realpath "$5")
defaults=$(IFS=,; realpath -e $4 | paste -sd,)
settle=${6:-15} timeout_s=${7:-240} home=${8:-40.444233,-7.375234,820}
repo=$(cd "$(dirname "$0")/.." && pwd)
out="$repo/src/test/resources/sitl-recordings"
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

unshare -n bash -s "$binary" "$model" "$defaults" "$script" "$settle" "$timeout_s" "$work" "$out/$name" "$repo" "$home" <<'NS'
set -uo pipefail
binary=$1 model=$2 defaults=$3 script=$4 settle=$5 timeout_s=$6 work=$7 target=$8 repo=$9 home=${10}
ip link set lo up
port=14570
cd "$work"
"$binary" --model "$model" --speedup 5 --defaults "$defaults" -I30 --sysid 1 \
    --home "$home,0" --serial0 "udpclient:127.0.0.1:$port" > sitl.log 2>&1 &
sitl=$!
sleep "$settle"
cd "$repo"
timeout "$timeout_s" ./dolphin run "$script" --status plain --link "udpin:127.0.0.1:$port" \
    --tlog "$target.tlog" > "$target.out" 2>&1
echo "dolphin exit $?" >> "$target.out"
kill "$sitl" 2>/dev/null
wait "$sitl" 2>/dev/null
exit 0
NS
echo "recorded $out/$name.tlog ($(stat -c %s "$out/$name.tlog") bytes); dolphin's output in $out/$name.out"
