# Sourced by the benchmark scripts (upload.sh, lossy.sh, fleet.sh): their paths, and the run of a
# benchmark's plain Java main on this tree's build (or DOLPHIN_JAR's) and the benchmarks' classes.
set -euo pipefail
bench="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$bench")"
out="$bench/target/results"
jar="${DOLPHIN_JAR:-$root/target/dolphin.jar}"
python="$root/.venv/bin/python"

# bench_main SCRIPT CLASS ARGS...: checks that the builds are there, then runs dolphin.bench.CLASS ARGS.
# The simulator and the runtime log at INFO ("Flight plan received" per upload): kept out of the summaries.
bench_main() {
  local script="$1" class="$2"
  shift 2
  for f in "$jar" "$python" "$bench/target/classes/dolphin/bench/$class.class"; do
    [ -e "$f" ] || { echo "bench/$script: missing $f (run without --no-build)" >&2; exit 1; }
  done
  mkdir -p "$out"
  java -Dorg.slf4j.simpleLogger.defaultLogLevel=warn -cp "$bench/target/classes:$bench/target/lib/*:$jar:$root/target/lib/*" \
    "dolphin.bench.$class" "$@"
}
