#!/bin/sh
# SIGINT or SIGTERM while `medusa report` computes its radius sweep (README): exit code 130, the last
# line on stderr "medusa: interrupted; ...", no report and no temporary file left, nothing new beside
# the store. Usage: interrupted_report_sweep_leaves_nothing.sh <medusa> <run> <workdir> INT|TERM
set -u
medusa=$1
input=$2
work=$3
signal=${4:-INT}
rm -rf "$work" "${work}_store" && mkdir -p "$work" "${work}_store" && cd "$work" || exit 1
# The large run (4,945 cells): each radius of its sweep takes seconds, so the signal arrives mid-sweep.
"$medusa" run --force "$input" -o "${work}_store/large.h5" --radius 3 --quiet >/dev/null 2>&1 || exit 1
before=$(ls "${work}_store")
"$medusa" report "${work}_store/large.h5" -o interrupted.html --threads 2 2>stderr.txt &
pid=$!
# Wait until the sweep has started (its first progress line), at most 300 s.
tries=0
until grep -q 'radius sweep of' stderr.txt 2>/dev/null; do
  tries=$((tries + 1))
  if [ "$tries" -gt 3000 ] || ! kill -0 "$pid" 2>/dev/null; then
    echo "the report did not start its radius sweep"
    cat stderr.txt
    exit 1
  fi
  sleep 0.1
done
sleep 1
kill -"$signal" "$pid"
wait "$pid"
code=$?
cat stderr.txt
if [ "$code" -ne 130 ]; then
  echo "exit code $code, expected 130"
  exit 1
fi
if ! tail -n 1 stderr.txt | grep -q '^medusa: interrupted'; then
  echo "the last line on stderr is not 'medusa: interrupted...'"
  exit 1
fi
left=$(ls | grep -v '^stderr.txt$')
if [ -n "$left" ]; then
  echo "files left behind: $left"
  exit 1
fi
if [ "$(ls "${work}_store")" != "$before" ]; then
  echo "files left beside the store: $(ls "${work}_store")"
  exit 1
fi
echo "interrupted cleanly during the radius sweep"
