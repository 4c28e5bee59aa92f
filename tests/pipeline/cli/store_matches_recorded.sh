#!/usr/bin/env bash
# `medusa run` on a bundled run with its defaults (radius auto; a periodic run on the torus) must write
# a store, diagrams CSV and summary whose datasets, attributes and text equal the recorded digests
# (store_digest.py), so that a change of the kinetic engine that alters one event, one medusa cell or
# one diagram point fails here.
# Usage: store_matches_recorded.sh MEDUSA INPUT WORKDIR RECORDED
# MEDUSA_UPDATE_ENGINE_CONTRACT=1 writes RECORDED instead (scripts/update-engine-contract).
set -euo pipefail
medusa=$1 input=$2 work=$3 recorded=$4
here=$(cd "$(dirname "$0")" && pwd)
python=${MEDUSA_PYTHON:-/usr/bin/python3}
rm -rf "$work"
mkdir -p "$work"
"$medusa" run --force -q "$input" -o "$work/store.h5" >"$work/summary.txt"
outputs=("$work/store.h5" "$work/store.diagrams.csv" "$work/summary.txt")
if [ -n "${MEDUSA_UPDATE_ENGINE_CONTRACT:-}" ]; then
  {
    echo "# Digests of the store of \`medusa run $(basename "$input")\` (tests/pipeline/cli/store_digest.py)."
    echo "# Written by scripts/update-engine-contract; regenerate only with a proof that the old store was wrong."
    "$python" "$here/store_digest.py" "${outputs[@]}"
  } >"$recorded"
  echo "wrote $recorded"
else
  "$python" "$here/store_digest.py" "${outputs[@]}" --check "$recorded"
fi
