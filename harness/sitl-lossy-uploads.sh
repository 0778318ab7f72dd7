#!/usr/bin/env bash
# Mission uploads to ArduCopter SITL through a seeded lossy relay on loopback: MAVProxy's `wp load`
# and `wp ftpload` against ours (item protocol and FTP), each verified by a lossless download. With
# --link radio, through the SiK radio model instead (bench/radio.sh runs it so, with fences and rally
# points too).
# Runs SITL, never builds it; everything inside a network namespace of its own (SITL listens on every
# interface), so nothing is reachable from outside. Needs root (unshare -n).
#
#   harness/sitl-lossy-uploads.sh [RESULTS_DIR] [options of harness/sitl_lossy_uploads.py]
#
# RESULTS_DIR defaults to target/sitl-lossy/DATE-TIME.
#
# Environment: ARDUPILOT (the source tree, with build/sitl/bin/arducopter; default
# /root/ardupilot-sitl/ardupilot), MAVPROXY (mavproxy.py of a venv with MAVProxy 1.8.71, default
# the one on PATH), PYTHON (with pymavlink; default the project's .venv). Our rows need
# bench/build.sh first (bench/target/classes and the main jar); without them pass
# --tools mavproxy-wp,mavproxy-ftp.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ardupilot="${ARDUPILOT:-/root/ardupilot-sitl/ardupilot}"
mavproxy="${MAVPROXY:-mavproxy.py}"
python="${PYTHON:-$root/.venv/bin/python}"
results="${1:-$root/target/sitl-lossy/$(date -u +%Y%m%d-%H%M%S)}"
shift || true
mkdir -p "$results"
results="$(cd "$results" && pwd)"
commit="$(git -C "$ardupilot" rev-parse --short=7 HEAD 2>/dev/null || echo unknown)"
cp="$root/bench/target/classes:$root/target/dolphin.jar:$root/target/lib/*"
ours="java -cp $cp dolphin.bench.SitlUploads"
echo "results in $results" >&2
exec unshare -n bash -c 'ip link set lo up && exec "$@"' namespace \
    "$python" "$root/harness/sitl_lossy_uploads.py" --sitl "$ardupilot/build/sitl/bin/arducopter" \
    --defaults "$ardupilot/Tools/autotest/default_params/copter.parm" --commit "$commit" --results "$results" \
    --mavproxy "$mavproxy" --ours "$ours" "$@"
