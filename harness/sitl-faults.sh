#!/usr/bin/env bash
# Flies a watched survey on real ArduPilot SITL while harness/fault_injector.py injects one fault
# mid-survey, and keeps what happened in src/test/resources/sitl-recordings: NAME.tlog (dolphin's
# --tlog), NAME.out (dolphin's output, each line prefixed with the wall clock it was read at) and
# NAME.faults.txt (the injector's log: what it did, and what the vehicle said and did, on the same clock),
# NAME.sitl.txt (the first 100 lines of SITL's console, less its start-up lines) and, for an outage,
# NAME.relay.txt (the relay's marks and the transfer messages it passed).
# Like harness/record-sitl.sh, everything runs in a network namespace that has only loopback (unshare -n,
# as root): SITL listens on every interface.
#
#   harness/sitl-faults.sh SCENARIO [VEHICLE] [NAME]
#
# SCENARIO  motor, gps, pause, stall or outage (fault_injector.py --fault; outage puts
#           harness/lossy_relay.py between SITL and dolphin and drops everything for 30 s)
# VEHICLE   copter (default), plane or rover: binary, --model, parameters and script below
# NAME      recording name (default VEHICLE-fault-SCENARIO)
#
# ARDUPILOT (required) is an ArduPilot checkout built with ./waf configure --board sitl; this
# repository builds none. SITL runs at --speedup 5, home 40.444233,-7.375234,820; dolphin starts
# 15 s after SITL and is stopped after 420 s at most; the injector after 460 s at most.
# Environment: AFTER_SEQ (inject once MISSION_CURRENT seq >= N), HOLD (pause, s), WIND (stall, m/s),
# OUTAGE (s), STALL_LIMIT (dolphin run --stall-limit for the stall scenario, default 30).
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,22p' "$0"; exit 2; }
scenario=$1 vehicle=${2:-copter}
name=${3:-$vehicle-fault-$scenario}
ap=${ARDUPILOT:?set ARDUPILOT to an ArduPilot checkout built for SITL}
repo=$(cd "$(dirname "$0")/.." && pwd)
out="$repo/src/test/resources/sitl-recordings"
case $vehicle in
  copter) binary=$ap/build/sitl/bin/arducopter model=+ defaults=$ap/Tools/autotest/default_params/copter.parm
          script=$repo/src/test/resources/sitl/faults-survey.dolphin after=${AFTER_SEQ:-4} ;;
  plane)  binary=$ap/build/sitl/bin/arduplane model=plane defaults=$ap/Tools/autotest/models/plane.parm
          script=$repo/src/test/resources/sitl/plane-faults-survey.dolphin after=${AFTER_SEQ:-4} ;;
  rover)  binary=$ap/build/sitl/bin/ardurover model=rover defaults=$ap/Tools/autotest/default_params/rover.parm
          script=$repo/src/test/resources/sitl/rover-faults-survey.dolphin after=${AFTER_SEQ:-4} ;;
  *) echo "unknown vehicle $vehicle" >&2; exit 2 ;;
esac
extra=()
[ "$scenario" = stall ] && extra=(--stall-limit "${STALL_LIMIT:-30}")
[ -x "$binary" ] || { echo "no $binary" >&2; exit 1; }
bash "$repo/harness/venv.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "$name: $scenario on $vehicle, injected after MISSION_CURRENT seq $after; dolphin run ${extra[*]:-}"

unshare -n bash -s "$binary" "$model" "$defaults" "$script" "$scenario" "$vehicle" "$after" "$work" "$out/$name" \
    "$repo" "${extra[@]}" <<'NS'
set -uo pipefail
binary=$1 model=$2 defaults=$3 script=$4 scenario=$5 vehicle=$6 after=$7 work=$8 target=$9 repo=${10}
shift 10   # the rest: dolphin run's extra options
ip link set lo up
gcs_port=14570 sitl_port=14570 injector_port=14590
cd "$work"
rm -f "$target.tlog" "$target.out" "$target.faults.txt" "$target.sitl.txt" "$target.relay.txt"
if [ "$scenario" = outage ]; then
  # SITL -> relay (14571) -> dolphin (14570); the injector tells the relay when, through a FIFO that the
  # shell also holds open, so the relay never sees its end
  sitl_port=14571
  mkfifo relay.ctl
  exec 3<>relay.ctl
  "$repo/.venv/bin/python" "$repo/harness/lossy_relay.py" --vehicle-port $sitl_port --gcs-port $gcs_port \
      --control --log relay.log <&3 > relay.out 2>&1 &
  relay=$!
fi
"$binary" --model "$model" --speedup 5 --defaults "$defaults" -I30 --sysid 1 \
    --home 40.444233,-7.375234,820,0 --serial0 "udpclient:127.0.0.1:$sitl_port" \
    --serial1 "udpclient:127.0.0.1:$injector_port" > sitl.log 2>&1 &
sitl=$!
"$repo/.venv/bin/python" "$repo/harness/fault_injector.py" --link "udpin:127.0.0.1:$injector_port" \
    --fault "$scenario" --vehicle "$vehicle" --after-seq "$after" --hold "${HOLD:-15}" --wind-speed "${WIND:-30}" \
    --outage "${OUTAGE:-30}" --relay-control "$work/relay.ctl" --timeout 460 --log "$target.faults.txt" &
injector=$!
sleep 15
cd "$repo"
# dolphin's output, each line prefixed with the wall clock it was read at (the tlog's and the log's clock)
timeout 420 ./dolphin run "$script" --status plain --link "udpin:127.0.0.1:$gcs_port" --tlog "$target.tlog" "$@" 2>&1 |
  while IFS= read -r line; do printf '%s %s\n' "$(date +%H:%M:%S.%3N)" "$line"; done > "$target.out"
echo "dolphin exit ${PIPESTATUS[0]}" >> "$target.out"
sleep 5   # the vehicle's last words after dolphin ended, for the injector's log
kill "$injector" 2>/dev/null; wait "$injector" 2>/dev/null
kill "$sitl" 2>/dev/null; wait "$sitl" 2>/dev/null
# SITL's console, where ArduPilot prints what an INTERNAL_ERROR was (e.g. "SCurve::calculate_track ...")
grep -v '^Waiting for\|^bind port\|^Serial port\|^Home: \|^Starting\|^Smoothing\|^Loaded' "$work/sitl.log" |
  head -100 > "$target.sitl.txt"
if [ "$scenario" = outage ]; then
  echo quit >&3; wait "$relay" 2>/dev/null   # quit, not kill: the relay then writes out its log
  grep -v '^[0-9.]* drop' "$work/relay.log" > "$target.relay.txt" || true   # the marks, not each drop
  echo "relay: $(grep -c ' drop ' "$work/relay.log") datagrams dropped" >> "$target.relay.txt"
fi
exit 0
NS
echo "recorded $out/$name.tlog ($(stat -c %s "$out/$name.tlog") bytes), $name.out, $name.faults.txt, $name.sitl.txt"
tail -3 "$out/$name.out"
