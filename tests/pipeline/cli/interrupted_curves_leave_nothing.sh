#!/bin/sh
# SIGINT or SIGTERM during `medusa curves` on a large store (README): exit code 130, one line on stderr,
# no output or temporary file left, and the command stops promptly (the bound only catches a command
# that ignores the signal until its work is done; it is no performance figure).
# Usage: interrupted_curves_leave_nothing.sh <medusa> <large_3d cells.csv.gz> <workdir>
set -u
medusa=$1
input=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
"$medusa" run "$input" -o large.h5 --quiet >/dev/null || { echo "medusa run failed"; exit 1; }
mkdir out
# The command takes about 1.5 s on large_3d's store on a fast machine: the signals come within its
# first half, at different stages of its work.
for case in "INT 0.25" "TERM 0.5" "INT 0.75"; do
  set -- $case
  signal=$1
  delay=$2
  "$medusa" curves large.h5 -o out/large >stdout.txt 2>stderr.txt &
  pid=$!
  sleep "$delay"
  if ! kill -0 "$pid" 2>/dev/null; then
    echo "curves finished before SIG$signal after $delay s: nothing interrupted"
    exit 1
  fi
  kill -"$signal" "$pid"
  sent=$(date +%s.%N)
  wait "$pid"
  code=$?
  took=$(awk -v a="$sent" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3f", b - a }')
  cat stderr.txt
  echo "SIG$signal after $delay s: exit code $code, $took s after the signal"
  if [ "$code" -ne 130 ]; then
    echo "exit code $code, expected 130"
    exit 1
  fi
  if awk -v t="$took" 'BEGIN { exit !(t > 5) }'; then
    echo "still running $took s after the signal"
    exit 1
  fi
  if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q '^medusa: ' stderr.txt; then
    echo "stderr is not one line 'medusa: <message>'"
    exit 1
  fi
  left=$(ls out)
  if [ -n "$left" ]; then
    echo "files left behind: $left"
    exit 1
  fi
done
echo "interrupted cleanly"
