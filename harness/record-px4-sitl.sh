#!/usr/bin/env bash
# Records a flight of real PX4 SITL (its built-in simulator, SIH) for the simulated PX4 vehicles'
# conformance: starts the px4 binary of a px4_sitl_default build you made from PX4's sources (this
# repository builds none), flies a Dolphin script against it with `dolphin run --tlog`, and keeps the
# tlog and dolphin's output in src/test/resources/sitl-recordings. PX4 listens on every network
# interface, so everything runs in a network namespace that has only loopback (unshare -n, as root).
#
#   harness/record-px4-sitl.sh NAME BINARY MODEL SCRIPT [SETTLE_S] [TIMEOUT_S] [PARAM=VALUE ...]
#
# NAME      recording name (NAME.tlog, NAME.out)      BINARY    build/px4_sitl_default/bin/px4
# MODEL     SIH's model: quadx, airplane, standard_vtol
# SCRIPT    the .dolphin script to fly                SETTLE_S  real seconds between PX4's start and
#                                                               dolphin's (0: "at boot"; default 10)
# TIMEOUT_S real seconds after which dolphin is stopped (default 240)
# PARAM=VALUE parameters PX4 sets at boot (PX4_PARAM_ variables), e.g. SIM_BAT_DRAIN=500
# PX4 runs at speed factor 4 (PX4_SIM_SPEED_FACTOR), instance 0 (system id 1), home at
# 40.444233,-7.375234,820; dolphin talks to it first on its UDP port 18570 (udpout).
set -euo pipefail
[ $# -ge 4 ] || { sed -n '2,17p' "$0"; exit 2; }
name=$1 binary=$(realpath "$2") model=$3 script=$(realpath "$4")
settle=${5:-10} timeout_s=${6:-240}
shift $(( $# < 6 ? $# : 6 ))
params=("$@")
etc="$(dirname "$binary")/../etc"
[ -d "$etc" ] || { echo "no ROMFS at $etc: BINARY must be build/px4_sitl_default/bin/px4" >&2; exit 2; }
repo=$(cd "$(dirname "$0")/.." && pwd)
out="$repo/src/test/resources/sitl-recordings"
mkdir -p "$out"
work=$(mktemp -d)
# rm -rf does not follow the links PX4 makes in its working directory (etc, test_data)
trap 'rm -rf "$work"' EXIT

unshare -n bash -s "$binary" "$(realpath "$etc")" "$model" "$script" "$settle" "$timeout_s" "$work" "$out/$name" "$repo" "${params[@]}" <<'NS'
set -uo pipefail
binary=$1 etc=$2 model=$3 script=$4 settle=$5 timeout_s=$6 work=$7 target=$8 repo=$9
shift 9
ip link set lo up
cd "$work"
for p in "$@"; do export "PX4_PARAM_$p"; done
PX4_SIM_MODEL="sihsim_$model" PX4_SIMULATOR=sihsim PX4_SIM_SPEED_FACTOR=4 \
    PX4_HOME_LAT=40.444233 PX4_HOME_LON=-7.375234 PX4_HOME_ALT=820 \
    "$binary" -i 0 -d "$etc" > px4.log 2>&1 &
px4=$!
sleep "$settle"
cd "$repo"
timeout "$timeout_s" ./dolphin run "$script" --status plain --link udpout:127.0.0.1:18570 \
    --tlog "$target.tlog" > "$target.out" 2>&1
echo "dolphin exit $?" >> "$target.out"
kill "$px4" 2>/dev/null
wait "$px4" 2>/dev/null
exit 0
NS
echo "recorded $out/$name.tlog ($(stat -c %s "$out/$name.tlog") bytes); dolphin's output in $out/$name.out"
