#!/bin/sh
# SIGINT during `medusa run` or `medusa sweep` (README): exit code 130, one line on stderr, and no
# output file or temporary file left in the working folder.
# Usage: interrupt_leaves_nothing.sh <medusa> <run> <workdir> [run|sweep]
set -u
medusa=$1
input=$2
work=$3
command=${4:-run}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
# The large run (4,945 cells) takes far longer than the delay, so the signal arrives mid-run.
if [ "$command" = sweep ]; then
  "$medusa" sweep "$input" -o interrupted --radii 2.5:3:0.5 --threads 2 --quiet 2>stderr.txt &
else
  "$medusa" run "$input" -o interrupted.h5 --radius 3 --quiet 2>stderr.txt &
fi
pid=$!
sleep 2
kill -INT "$pid"
wait "$pid"
code=$?
cat stderr.txt
if [ "$code" -ne 130 ]; then
  echo "exit code $code, expected 130"
  exit 1
fi
if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q '^medusa: ' stderr.txt; then
  echo "stderr is not one line 'medusa: <message>'"
  exit 1
fi
left=$(ls | grep -v '^stderr.txt$')
if [ -n "$left" ]; then
  echo "files left behind: $left"
  exit 1
fi
echo "interrupted cleanly"
