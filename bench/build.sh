#!/usr/bin/env bash
# Builds what the benchmarks need: the main project's jar, runtime classpath and .venv with the
# pinned pymavlink, then the benchmark project itself.
set -euo pipefail
bench="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
echo "== building the main project (jar, runtime classpath, .venv with pymavlink)" >&2
(cd "$(dirname "$bench")" && mvn -B -q -ntp -DskipTests package)
echo "== building the benchmarks" >&2
(cd "$bench" && mvn -B -q -ntp package)
