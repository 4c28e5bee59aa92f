#!/bin/sh
# An input that cannot be read within an address-space limit is a bad input (exit 3) told in one line
# naming the file, not an internal error (exit 1, "out of memory"), and leaves nothing behind.
#   bomb:      a 2.5 MB .csv.gz whose second line is 2.5 GB of digits (250 gzip members of 10 MB each:
#              readers see one stream) under 1 GB: medusa stops at the 1 MiB line cap, naming the line.
#   many_rows: a valid CSV of 3 million rows (1,000 cells over 3,000 frames, about 450 MB once read)
#              under 150 MB: the line names the input and its size on disk.
# Usage: memory_limited_input_is_bad_input.sh <medusa> <workdir> bomb|many_rows
set -u
medusa=$1
work=$2
case=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
case $case in
  bomb) limit=1000000; expected='bomb.csv.gz:2: line longer than 1 MiB' ;;
  many_rows) limit=150000; expected='many_rows.csv.gz: out of memory while reading it (.* MB on disk)' ;;
  *) echo "unknown case $case"; exit 1 ;;
esac
/usr/bin/python3 - "$case" <<'PY' || exit 1
import gzip
import sys
header = "mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"
if sys.argv[1] == "bomb":
    member = gzip.compress(b"7" * 10_000_000, compresslevel=9)
    with open("bomb.csv.gz", "wb") as f:
        f.write(gzip.compress(header.encode()))
        for _ in range(250):
            f.write(member)
else:
    with gzip.open("many_rows.csv.gz", "wt", compresslevel=1) as f:
        f.write(header)
        for frame in range(3000):
            f.write("".join(f"{frame},{c},1,{c % 10}.5,{c // 10 % 10}.5,{c // 100}.5\n" for c in range(1, 1001)))
PY
input=$case.csv.gz
echo "$input: $(wc -c <"$input") bytes"
(ulimit -v $limit; exec "$medusa" run "$input" -o "$case.h5" --radius 3 --threads 1 >stdout.txt 2>stderr.txt)
code=$?
cat stderr.txt
status=0
if [ "$code" -ne 3 ]; then
  echo "exit code $code, expected 3"
  status=1
fi
if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q "$expected" stderr.txt; then
  echo "stderr is not one line matching: $expected"
  status=1
fi
if [ -n "$(ls | grep -v -e '^stderr.txt$' -e '^stdout.txt$' -e "^$input\$")" ]; then
  echo "files left behind: $(ls)"
  status=1
fi
exit $status
