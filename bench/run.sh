#!/usr/bin/env bash
# The benchmarks (bench/README.md): the codec throughput benchmark (dolphin.mavlink.codec, JMH, one
# thread, against pymavlink's parser on the same bytes), then the mission upload benchmark
# (bench/upload.sh: dolphin's uploader against the protocol floor and a pymavlink uploader), the
# lossy-link upload benchmark (bench/lossy.sh: 0-30 % loss against a pymavlink wp load reference),
# then the fleet-scale benchmark (bench/fleet.sh: 50, 250 and 1000 simulated vehicles).
#
#   bench/run.sh [--no-build] [JMH options...]
#   BENCH=codec bench/run.sh ...     # only the codec benchmark; BENCH=upload, lossy or fleet: only that one
#
# Builds the main project (its jar, runtime classpath and .venv with the pinned pymavlink) and
# this benchmark project, writes the mixed stream to bench/target/results/stream.bin, runs the
# JMH benchmarks on it (1 fork, 3 x 1 s warm-up, 5 x 1 s measurement unless JMH options say
# otherwise, e.g. `bench/run.sh -wi 5 -i 10`), runs pymavlink_parse.py on the same file with the
# project's venv Python, and prints the summary (also in bench/target/results/summary.txt).
# DOLPHIN_JAR=path/to/dolphin.jar measures that jar instead of target/dolphin.jar (before/after).
# Takes about 1.5 minutes on 2 cores once Maven's cache is warm, plus about 10 seconds for the upload
# benchmark, 10 minutes for the lossy links and 4 for the fleet.
set -euo pipefail
bench="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$bench")"
out="$bench/target/results"
frames=10000   # CodecBenchmark.FRAMES
which="${BENCH:-all}"

if [ "${1:-}" = "--no-build" ]; then shift; else "$bench/build.sh"; fi
if [ "$which" = upload ] || [ "$which" = lossy ] || [ "$which" = fleet ]; then
  exec "$bench/$which.sh" --no-build
fi
for f in "${DOLPHIN_JAR:-$root/target/dolphin.jar}" "$root/.venv/bin/python" "$bench/target/classes/META-INF/BenchmarkList"; do
  [ -e "$f" ] || { echo "bench/run.sh: missing $f (run without --no-build)" >&2; exit 1; }
done

# DOLPHIN_JAR: measure another build of the main jar (e.g. an older commit's) with the same benchmarks.
jar="${DOLPHIN_JAR:-$root/target/dolphin.jar}"
cp="$bench/target/classes:$bench/target/lib/*:$jar:$root/target/lib/*"
py="$root/.venv/bin/python"
mkdir -p "$out"

echo "== writing the stream" >&2
java -cp "$cp" dolphin.bench.MixedStream "$out/stream.bin" "$frames" | tee "$out/stream.txt" >&2

echo "== JMH: the codec" >&2
java -cp "$cp" org.openjdk.jmh.Main 'dolphin.bench.CodecBenchmark' -p file="$out/stream.bin" \
  -rf json -rff "$out/jmh.json" "$@" > "$out/jmh.txt"
sed -n '/^Benchmark /,$p' "$out/jmh.txt" >&2

echo "== pymavlink on the same bytes" >&2
"$py" "$bench/pymavlink_parse.py" "$out/stream.bin" --frames "$frames" --repeat 20 --json > "$out/pymavlink.json"

"$py" - "$out" "$jar" <<'PY' | tee "$out/summary.txt"
import json, os, platform, sys, datetime
out = sys.argv[1]
jmh = {r["benchmark"].rsplit(".", 1)[1]: r for r in json.load(open(os.path.join(out, "jmh.json")))}
py = json.load(open(os.path.join(out, "pymavlink.json")))
stream = open(os.path.join(out, "stream.txt")).read().strip()

def java(name):
    r = jmh[name]["primaryMetric"]
    iters = [x for fork in r["rawData"] for x in fork]
    return r["score"], r["scoreError"], max(iters)

def fmt(x):
    return f"{x:12,.0f}"

cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.processor())
print(f"codec benchmark, {datetime.date.today().isoformat()}, {cpu}, {os.cpu_count()} cores, "
      f"Java {jmh['framingStream']['vmVersion']}, Python {py['python']}, pymavlink {py['pymavlink']}")
print(f"codec: {sys.argv[2]}")
print(stream)
print(f"pymavlink: checksum {py['crc']}; native parser: {py['native_parser']}")
print()
print(f"{'frames/s, one thread':32s} {'mean (JMH)':>12s}  {'+-error':>12s}  {'best iter.':>12s}")
for name, label in [("framingStream", "Java framing, stream"), ("framingDatagrams", "Java framing, datagrams"),
                    ("decodeStream", "Java framing+decode, stream"), ("decodeDatagrams", "Java framing+decode, datagrams"),
                    ("write", "Java FrameWriter.write")]:
    if name in jmh:
        s, e, b = java(name)
        print(f"{label:32s} {fmt(s)}  {fmt(e)}  {fmt(b)}")
for mode in ("stream", "datagrams"):
    r = py[mode]
    print(f"{'pymavlink parse_buffer, ' + mode:32s} {fmt(r['median'])}  {'(median)':>12s}  {fmt(r['best'])}")
print()
print("ratio to pymavlink on the same bytes (pymavlink always decodes: like for like is framing+decode)")
print(f"{'':32s} {'mean/median':>12s}  {'best/best':>12s}")
ok = True
for jname, mode, label in [("decodeStream", "stream", "framing+decode, stream"), ("decodeDatagrams", "datagrams", "framing+decode, datagrams"),
                           ("framingStream", "stream", "framing only, stream"), ("framingDatagrams", "datagrams", "framing only, datagrams")]:
    s, _, b = java(jname)
    print(f"{label:32s} {s / py[mode]['median']:10.1f} x  {b / py[mode]['best']:10.1f} x")
print()
targets = [("framing, stream >= 3 M frames/s", java("framingStream")[0] >= 3e6),
           ("framing+decode, stream >= 3 M frames/s", java("decodeStream")[0] >= 3e6),
           ("framing+decode, stream >= 25 x pymavlink", java("decodeStream")[0] / py["stream"]["median"] >= 25)]
for label, met in targets:
    print(f"target {label:42s} {'met' if met else 'MISSED'}")
PY

if [ "$which" = all ]; then
  echo >&2
  "$bench/upload.sh" --no-build
  echo >&2
  "$bench/lossy.sh" --no-build
  echo >&2
  "$bench/fleet.sh" --no-build
fi
