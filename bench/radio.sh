#!/usr/bin/env bash
# Uploads to ArduCopter SITL over a SiK radio pair model (harness/sik_radio.py, profiles sik and
# worse; SITL's SERIAL0 a 57600 baud port): a 100-item mission, a 14-item fence and 6 rally points,
# ours (the default path, FTP when offered, read back; and the item protocol forced) side by side
# with MAVProxy's `wp load`, `wp ftpload`, `fence load` and `rally load`, each upload verified by a
# download over a lossless SITL port. Runs SITL, never builds it; everything inside a network
# namespace of its own (harness/sitl-lossy-uploads.sh), so it needs root. See bench/README.md,
# "Uploads over a SiK radio model".
#
#   bench/radio.sh [--no-build] [--lost-version] [RESULTS_DIR] [options of harness/sitl_lossy_uploads.py]
#
# --lost-version: also ours-lost-version, our default upload from a fresh process whose discovery lost
#   the vehicle's first AUTOPILOT_VERSION (the radio model drops it).
# RESULTS_DIR defaults to bench/target/radio/DATE-TIME; each profile's run goes to a directory of its
# own in it, and RESULTS_DIR/table.md has them all. Prints that table, then the raw JSON lines.
# Defaults: 3 rounds (--rounds N). Environment: ARDUPILOT, MAVPROXY, PYTHON as
# harness/sitl-lossy-uploads.sh; PROFILES (default "sik worse"). About 20 minutes with --lost-version.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if [ "${1:-}" = "--no-build" ]; then shift; else "$bench/build.sh"; fi
tools=mavproxy-wp,mavproxy-ftp,ours-auto,ours-items
if [ "${1:-}" = "--lost-version" ]; then tools+=,ours-lost-version; shift; fi
results="$bench/target/radio/$(date -u +%Y%m%d-%H%M%S)"
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then results="$1"; shift; fi
mkdir -p "$results"
results="$(cd "$results" && pwd)"
ardupilot="${ARDUPILOT:-/root/ardupilot-sitl/ardupilot}"
for profile in ${PROFILES:-sik worse}; do
  echo "== radio profile $profile" >&2
  "$root/harness/sitl-lossy-uploads.sh" "$results/$profile" --link radio --radio-profile "$profile" \
    --kinds mission,fence,rally --tools "$tools" --rounds 3 "$@"
done
"${PYTHON:-$python}" "$root/harness/sitl_lossy_uploads.py" --results "$results" --tools "$tools" \
  --commit "$(git -C "$ardupilot" rev-parse --short=7 HEAD 2>/dev/null || echo unknown)" \
  --merge $(for profile in ${PROFILES:-sik worse}; do echo "$results/$profile"; done) >&2
cat "$results/table.md"
echo
echo '```json'
cat "$results"/*/samples.jsonl
echo '```'
