#!/bin/sh
# Memory exhaustion while reading is a bad input (exit 3) whose one line names the input and its
# size, not an internal error (exit 1, "out of memory"): a valid CSV of 3 million rows (1,000 cells
# over 3,000 frames, about 450 MB once read) under a 150 MB address-space limit.
# Usage: out_of_memory_is_bad_input.sh <medusa> <workdir>
set -u
medusa=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
/usr/bin/python3 - <<'PY' || exit 1
import gzip
with gzip.open("many_rows.csv.gz", "wt", compresslevel=1) as f:
    f.write("mcs,cell_id,type_id,xCOM,yCOM,zCOM\n")
    for frame in range(3000):
        f.write("".join(f"{frame},{c},1,{c % 10}.5,{c // 10 % 10}.5,{c // 100}.5\n" for c in range(1, 1001)))
PY
echo "many_rows.csv.gz: $(wc -c <many_rows.csv.gz) bytes"
(ulimit -v 150000; exec "$medusa" run many_rows.csv.gz -o many_rows.h5 --radius 3 --threads 1 >stdout.txt 2>stderr.txt)
code=$?
cat stderr.txt
status=0
if [ "$code" -ne 3 ]; then
  echo "exit code $code, expected 3"
  status=1
fi
if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q 'many_rows.csv.gz: out of memory while reading it (.* MB on disk)' stderr.txt; then
  echo "stderr is not one line naming the input, the memory and its size"
  status=1
fi
if [ -n "$(ls | grep -v -e '^stderr.txt$' -e '^stdout.txt$' -e '^many_rows.csv.gz$')" ]; then
  echo "files left behind: $(ls)"
  status=1
fi
exit $status
