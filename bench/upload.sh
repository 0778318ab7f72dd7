#!/usr/bin/env bash
# Mission upload benchmark: dolphin's MissionUploadProtocol against a simulated copter over loopback
# UDP (real-time clock), compared in the same run with the protocol floor (N + 2 COMMAND_LONG /
# COMMAND_ACK round trips on the same link) and with a pymavlink uploader (pymavlink_upload.py)
# against the same kind of simulated vehicle. Lossy links: bench/lossy.sh.
# Plain Java main (dolphin.bench.UploadBench), not JMH. See bench/README.md.
#
#   bench/upload.sh [--no-build] [--quick]
#
# --quick: 3 runs per size instead of 21 (a smoke test, a few seconds).
# Prints the summary, also in bench/target/results/upload-summary.txt; every sample is in
# upload.json and pymavlink-upload.json there. Exit status 1 if an upload failed or did not verify.
# Takes about 10 seconds on 2 cores.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

if [ "${1:-}" = "--no-build" ]; then shift; else "$bench/build.sh"; fi
echo "== mission upload: floor, dolphin and pymavlink interleaved" >&2
bench_main upload.sh UploadBench "$out" "$python" "$bench/pymavlink_upload.py" "$@"
