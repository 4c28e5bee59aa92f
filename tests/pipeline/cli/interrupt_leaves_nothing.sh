#!/bin/sh
# SIGINT during `medusa run`, `medusa sweep` or `medusa report` (README): exit code 130, one line on
# stderr, and no output file or temporary file left in the working folder (for report, beside the
# store it reads). Usage: interrupt_leaves_nothing.sh <medusa> <run> <workdir> [run|sweep|report]
set -u
medusa=$1
input=$2
work=$3
command=${4:-run}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
# The large run (4,945 cells) takes about 3 s on a fast machine, three times the delay, so the signal
# arrives mid-run.
if [ "$command" = report ]; then
  # The store of the large run is written first (beside the working folder); its report takes seconds.
  mkdir -p "${work}_store" && "$medusa" run --force "$input" -o "${work}_store/large.h5" --radius 3 --quiet >/dev/null 2>&1 || exit 1
  "$medusa" report "${work}_store/large.h5" -o interrupted.html 2>stderr.txt &
elif [ "$command" = sweep ]; then
  "$medusa" sweep "$input" -o interrupted --radii 2.5:3:0.5 --threads 2 --quiet 2>stderr.txt &
else
  "$medusa" run "$input" -o interrupted.h5 --radius 3 --quiet 2>stderr.txt &
fi
pid=$!
if [ "$command" = report ]; then sleep 0.3; else sleep 1; fi
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
