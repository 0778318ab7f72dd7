#!/usr/bin/env bash
# TEST DOUBLE, NOT ArduPilot SITL. It lets the SITL suite (src/test/groovy/dolphin/sitl) run its own
# code path where no ArduPilot build exists: it takes the command line the suite gives arducopter,
# arduplane or ardurover and starts one vehicle of Dolphin's own simulator (`dolphin sim`) instead:
#
#   --model quad|plane|rover -> --type copter|plane|rover
#   --sysid N            -> --first-sysid N
#   --home LAT,LON,ALT,HDG -> --home LAT,LON,ALT (the heading is dropped)
#   --serial0 udpclient:HOST:PORT -> --link udpout:HOST:PORT
#   --speedup X          -> --speedup X
#   -I N                 -> accepted and ignored (one process, no eeprom)
#   --defaults FILES     -> read for what the simulator can give: CAM1_TYPE 1..9 -> --camera all, and
#                           SCR_ENABLE 1 with scripts/smoke-plume.lua in the working directory ->
#                           --sensor SMOKE:plume:... from the Lua script's constants; the rest ignored
#
# It adds --warmup 20 (simulated seconds) so that arming is refused for a while after boot, as
# ArduPilot refuses it while its EKF settles: the suite's waits and the executor's arm retries run.
# Use: ARDUPILOT_SITL_BIN=src/test/resources/sitl/fake-arducopter.sh mvn -B -ntp verify -P sitl
# (after `mvn package`, which builds target/dolphin.jar and target/lib).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../../.." && pwd)"
args=(sim --count 1 --warmup 20)
defaults=""
while [ $# -gt 0 ]; do
  case "$1" in
    --model) case "$2" in
               quad|copter|+|x) args+=(--type copter) ;;
               plane) args+=(--type plane) ;;
               rover) args+=(--type rover) ;;
               *) echo "fake-arducopter: unsupported --model $2" >&2; exit 2 ;;
             esac; shift 2 ;;
    --sysid) args+=(--first-sysid "$2"); shift 2 ;;
    --home) IFS=, read -r lat lon alt _ <<< "$2"; args+=(--home "$lat,$lon,$alt"); shift 2 ;;
    --serial0) case "$2" in
                 udpclient:*) args+=(--link "udpout:${2#udpclient:}") ;;
                 *) echo "fake-arducopter: only --serial0 udpclient:HOST:PORT is supported, got $2" >&2; exit 2 ;;
               esac; shift 2 ;;
    --speedup) args+=(--speedup "$2"); shift 2 ;;
    --defaults) defaults="$2"; shift 2 ;;
    -I|--instance) shift 2 ;;
    *) echo "fake-arducopter: unsupported option $1" >&2; exit 2 ;;
  esac
done
if [ -n "$defaults" ]; then
  IFS=, read -ra files <<< "$defaults"
  if grep -qsE '^CAM1_TYPE[[:space:]]+[1-9]' "${files[@]}"; then args+=(--camera all); fi
  if [ -f scripts/smoke-plume.lua ] && grep -qsE '^SCR_ENABLE[[:space:]]+1' "${files[@]}"; then
    lua_constant() { sed -nE "s/^local $1 = ([-0-9.]+).*/\1/p" scripts/smoke-plume.lua; }
    args+=(--sensor "SMOKE:plume:$(lua_constant CENTRE_LAT),$(lua_constant CENTRE_LON),$(lua_constant RADIUS_M),$(lua_constant PEAK)")
  fi
fi
jar="$root/target/dolphin.jar"
if [ ! -f "$jar" ]; then
  echo "fake-arducopter: $jar is missing: run mvn package first" >&2
  exit 2
fi
exec java -cp "$jar:$root/target/lib/*" dolphin.cli.Main "${args[@]}"
