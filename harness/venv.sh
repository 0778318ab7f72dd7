#!/usr/bin/env bash
# Creates (or refreshes) the project's Python venv with the pinned pymavlink, in .venv at the
# project root. Idempotent: does nothing when the venv matches harness/requirements.txt.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$root/.venv"
req="$root/harness/requirements.txt"
stamp="$venv/.requirements.sha256"
want="$(sha256sum "$req" | cut -d' ' -f1)"
if [ -x "$venv/bin/python" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
  exit 0
fi
python3 -m venv "$venv" || {
  echo "harness/venv.sh: 'python3 -m venv' failed; install Python 3 with venv (Debian: apt-get install python3-venv)" >&2
  exit 1
}
"$venv/bin/pip" install -q --disable-pip-version-check --require-hashes -r "$req"
echo "$want" > "$stamp"
