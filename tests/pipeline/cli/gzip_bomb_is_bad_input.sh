#!/bin/sh
# A 2.5 MB .csv.gz whose second line is 2.5 GB of digits (250 gzip members of 10 MB each: readers
# see one stream), read under a 1 GB address-space limit: medusa stops at the 1 MiB line cap with
# exit 3 and one line naming the file and line, instead of growing the line to the limit and ending
# "out of memory". Usage: gzip_bomb_is_bad_input.sh <medusa> <workdir>
set -u
medusa=$1
work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
/usr/bin/python3 - <<'PY' || exit 1
import gzip
member = gzip.compress(b"7" * 10_000_000, compresslevel=9)
with open("bomb.csv.gz", "wb") as f:
    f.write(gzip.compress(b"mcs,cell_id,type_id,xCOM,yCOM,zCOM\n"))
    for _ in range(250):
        f.write(member)
PY
echo "bomb.csv.gz: $(wc -c <bomb.csv.gz) bytes"
(ulimit -v 1000000; exec "$medusa" run bomb.csv.gz -o bomb.h5 --radius 3 --threads 1 >stdout.txt 2>stderr.txt)
code=$?
cat stderr.txt
status=0
if [ "$code" -ne 3 ]; then
  echo "exit code $code, expected 3"
  status=1
fi
if [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q 'bomb.csv.gz:2: line longer than 1 MiB' stderr.txt; then
  echo "stderr is not one line naming bomb.csv.gz:2 and the 1 MiB cap"
  status=1
fi
exit $status
