#!/bin/sh
# A store that cannot be written (here a file size limit, as a full disk would do): `medusa run` exits
# with the store error's code 5 (README) and one line on stderr naming the store, and leaves no output
# or temporary file, with the store written on the engine's thread (--threads 1) or beside it
# (--threads 2). It used to end in a segfault inside HDF5's exit handler after the message.
# Usage: store_write_failure_leaves_nothing.sh <medusa> <run> <workdir>
set -u
medusa=$1
input=$2
work=$3
status=0
for threads in 1 2; do
  rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
  # Writes past 64 KiB fail with EFBIG instead of killing the process (SIGXFSZ ignored, inherited).
  (trap '' XFSZ; ulimit -f 64; exec "$medusa" run "$input" -o full.h5 --radius 3 --quiet --threads "$threads" \
     >stdout.txt 2>stderr.txt)
  code=$?
  echo "--threads $threads: exit code $code"
  cat stderr.txt
  if [ "$code" -ne 5 ]; then
    echo "exit code $code, expected 5 (store error)"
    status=1
  fi
  if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q '^medusa: store .*full.h5' stderr.txt; then
    echo "stderr is not one line 'medusa: store <path>: ...'"
    status=1
  fi
  left=$(ls | grep -v -e '^stderr.txt$' -e '^stdout.txt$')
  if [ -n "$left" ]; then
    echo "files left behind: $left"
    status=1
  fi
done
exit $status
