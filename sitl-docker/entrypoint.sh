#!/bin/sh
# Starts one SITL vehicle. Settings from the environment (compose.yaml sets them per service):
#   VEHICLE   copter or plane (default copter)
#   SYSID     its MAVLink system id; --sysid sets MAV_SYSID on current ArduPilot and SYSID_THISMAV on
#             older releases, so no parameter file needs editing
#   INSTANCE  SITL instance (-I): TCP ports 5760 + 10 x INSTANCE and up; eeprom per container anyway
#   HOME_LOCATION LAT,LON,ALT,HEADING (altitude above mean sea level)
#   GCS       where SERIAL0 sends MAVLink over UDP, HOST:PORT (default host.docker.internal:14559)
#   SPEEDUP   simulation speed (default 1)
# Extra arguments are passed to the binary, e.g. --serial1 udpclient:host.docker.internal:14550.
set -eu
case "${VEHICLE:-copter}" in
  copter) bin=arducopter; model=quad; parm=copter.parm ;;
  plane) bin=arduplane; model=plane; parm=plane.parm ;;
  *) echo "entrypoint: VEHICLE must be copter or plane, got $VEHICLE" >&2; exit 2 ;;
esac
exec "/opt/sitl/bin/$bin" --model "$model" -I "${INSTANCE:-0}" --sysid "${SYSID:-1}" \
  --home "${HOME_LOCATION:-40.444233,-7.375234,820,0}" --speedup "${SPEEDUP:-1}" \
  --defaults "/opt/sitl/params/$parm" --serial0 "udpclient:${GCS:-host.docker.internal:14559}" "$@"
