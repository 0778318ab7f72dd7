#!/usr/bin/env bash
# Records copter-smoke-plume.tlog: ArduCopter SITL (a binary you built from ArduPilot's sources; this
# repository builds none) with src/test/resources/lua/smoke-plume.lua in the scripts/ folder of its
# working directory, SCR_ENABLE 1 and CAM1_TYPE 1 added to the given parameter file, and
# harness/smoke_session.py as the ground station (camera and gimbal discovery, a flight over the
# plume, RTL). SITL listens on every network interface, so everything runs in a network namespace
# that has only loopback (unshare -n, as root).
#
#   harness/record-smoke-plume.sh ARDUCOPTER COPTER_PARM [TLOG]
#
# ARDUCOPTER  build/sitl/bin/arducopter    COPTER_PARM  Tools/autotest/default_params/copter.parm
# TLOG        default src/test/resources/sitl-recordings/copter-smoke-plume.tlog
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,12p' "$0"; exit 2; }
binary=$(realpath "$1") defaults=$(realpath "$2")
repo=$(cd "$(dirname "$0")/.." && pwd)
tlog=$(realpath -m "${3:-$repo/src/test/resources/sitl-recordings/copter-smoke-plume.tlog}")
"$repo/harness/venv.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/scripts"
cp "$repo/src/test/resources/lua/smoke-plume.lua" "$work/scripts/"
{ cat "$defaults"; echo "SCR_ENABLE 1"; echo "CAM1_TYPE 1"; } > "$work/copter-smoke.parm"

unshare -n bash -s "$binary" "$work" "$tlog" "$repo" <<'NS'
set -uo pipefail
binary=$1 work=$2 tlog=$3 repo=$4
ip link set lo up
port=14570
cd "$work"
"$binary" --model + --speedup 5 --defaults copter-smoke.parm -I30 --sysid 1 \
    --home 40.444233,-7.375234,820,0 --serial0 "udpclient:127.0.0.1:$port" > sitl.log 2>&1 &
sitl=$!
"$repo/.venv/bin/python" "$repo/harness/smoke_session.py" "$port" --fly --tlog "$tlog"
kill "$sitl" 2>/dev/null
wait "$sitl" 2>/dev/null
exit 0
NS
echo "recorded $tlog ($(stat -c %s "$tlog") bytes)"
