#!/usr/bin/env bash
# Flies a Dolphin script on several ArduCopter SITL, each behind a simulated SiK radio pair
# (harness/sik_radio.py), or all behind one ground radio (MULTIPOINT=1), and keeps what happened.
# Runs SITL, never builds it; SITL, the radios and dolphin share a network namespace that has only
# loopback (unshare -n, as root): SITL listens on every interface.
#
#   harness/sitl-radio-fleet.sh SCRIPT RESULTS_DIR [dolphin run options...]
#
# Environment:
#   ARDUPILOT   (required) an ArduPilot checkout built with ./waf configure --board sitl && ./waf copter
#   VEHICLES    copters, system ids 1..N, instances 0..N-1, homes 10 m apart eastwards (default 4)
#   PROFILE     the radios' --profile: sik, worse or clear (default sik)
#   PTYS        how many of the ground radios (the first ones) are pseudo-terminals that dolphin opens
#               as serial:LINK:57600; the others are UDP ground sides (default 1)
#   MULTIPOINT  1: one ground radio for every vehicle (sik_radio.py with one --vehicle-port each),
#               one link; a pseudo-terminal if PTYS > 0 (default 0)
#   SPEEDUP     SITL's --speedup (default 1: the radios run in real time, so anything faster
#               multiplies the telemetry each radio carries)
#   LIMIT       seconds before dolphin is stopped (default 3600)
#
# SITL starts with Tools/autotest/default_params/copter.parm and SERIAL0_BAUD 57 (the vehicle's radio
# port at 57600); --serial0 udpclient to its vehicle radio. Dolphin starts once every radio is ready,
# with --status plain. RESULTS_DIR gets dolphin.out (its output), dolphin.rc, dolphin.seconds (wall
# time), command.txt, radio-N.log (harness/relay_log_summary.py reads them) and sitl-N.log.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,24p' "$0"; exit 2; }
script=$(realpath "$1") results=$2
shift 2
ap=${ARDUPILOT:?set ARDUPILOT to an ArduPilot checkout built for SITL}
repo=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$ap/build/sitl/bin/arducopter" ] || { echo "no $ap/build/sitl/bin/arducopter" >&2; exit 1; }
[ -f "$repo/target/dolphin.jar" ] || { echo "build first: mvn -o -B -DskipTests package" >&2; exit 1; }
bash "$repo/harness/venv.sh"
mkdir -p "$results"
results=$(cd "$results" && pwd)

unshare -n bash -s "$ap" "$repo" "$script" "$results" "${VEHICLES:-4}" "${PROFILE:-sik}" "${PTYS:-1}" \
    "${MULTIPOINT:-0}" "${SPEEDUP:-1}" "${LIMIT:-3600}" "$@" <<'NS'
set -uo pipefail
ap=$1 repo=$2 script=$3 results=$4 vehicles=$5 profile=$6 ptys=$7 multipoint=$8 speedup=$9 limit=${10}
shift 10   # the rest: dolphin run's options
ip link set lo up
python=$repo/.venv/bin/python
pids=()
stop() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done; wait 2>/dev/null; }
trap stop EXIT
printf 'SERIAL0_BAUD 57\n' > "$results/radio-port.parm"

# start a radio and wait for its "ready" line; $1 names it, the rest are sik_radio.py's options
radio() {
  local name=$1; shift
  "$python" "$repo/harness/sik_radio.py" --profile "$profile" --log "$results/$name.log" "$@" \
      > "$results/$name.out" 2> "$results/$name.err" &
  pids+=($!)
  for _ in $(seq 100); do grep -q '^ready' "$results/$name.out" && break; sleep 0.1; done
  head -n 1 "$results/$name.out"
}

links=()
if [ "$multipoint" = 1 ]; then
  ports=()
  for i in $(seq 1 "$vehicles"); do ports+=(--vehicle-port $((14540 + 10 * i))); done
  if [ "$ptys" -gt 0 ]; then
    radio radio-1 "${ports[@]}" --seed 1 --gcs-pty "$results/sik-1"
    links+=(--link "serial:$results/sik-1:57600")
  else
    radio radio-1 "${ports[@]}" --seed 1 --gcs-port 14541
    links+=(--link udpin:127.0.0.1:14541)
  fi
else
  for i in $(seq 1 "$vehicles"); do
    if [ "$i" -le "$ptys" ]; then
      radio "radio-$i" --vehicle-port $((14540 + 10 * i)) --seed "$i" --gcs-pty "$results/sik-$i"
      links+=(--link "serial:$results/sik-$i:57600")
    else
      radio "radio-$i" --vehicle-port $((14540 + 10 * i)) --seed "$i" --gcs-port $((14541 + 10 * i))
      links+=(--link "udpin:127.0.0.1:$((14541 + 10 * i))")
    fi
  done
fi

for i in $(seq 1 "$vehicles"); do
  mkdir -p "$results/sitl-$i"
  lon=$(awk -v i="$i" 'BEGIN { printf "%.7f", -7.375234 + (i - 1) * 10 / (111320 * cos(40.444233 * 3.14159265 / 180)) }')
  (cd "$results/sitl-$i" && exec "$ap/build/sitl/bin/arducopter" --model + -I $((i - 1)) --sysid "$i" \
      --home "40.444233,$lon,820,0" --speedup "$speedup" \
      --defaults "$ap/Tools/autotest/default_params/copter.parm,$results/radio-port.parm" \
      --serial0 "udpclient:127.0.0.1:$((14540 + 10 * i))" > "$results/sitl-$i.log" 2>&1) &
  pids+=($!)
done

cmd=("$repo/dolphin" run "$script" --status plain "${links[@]}" "$@")
echo "SITL ${vehicles} x ArduCopter $(git -C "$ap" rev-parse --short=12 HEAD 2>/dev/null), --speedup $speedup;" \
     "radios: profile $profile, multipoint $multipoint, $ptys pty ground side(s)" > "$results/command.txt"
echo "${cmd[*]}" >> "$results/command.txt"
cat "$results/command.txt"
start=$(date +%s.%N)
timeout --signal=INT --kill-after=30 "$limit" "${cmd[@]}" > "$results/dolphin.out" 2>&1
rc=$?
end=$(date +%s.%N)
echo "$rc" > "$results/dolphin.rc"
awk -v s="$start" -v e="$end" 'BEGIN { printf "%.1f\n", e - s }' > "$results/dolphin.seconds"
echo "dolphin exit $rc after $(cat "$results/dolphin.seconds") s"
NS
