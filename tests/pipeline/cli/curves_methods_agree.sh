#!/bin/sh
# `medusa curves` by one coned reduction (docs/MATH.md §6.8) writes the same CSV, byte for byte, as the
# per-batch recomputation of docs/MATH.md §6.6 (hidden `--method reference`), with and without
# --frames-only (FRAMES_TOO=no: every batch only, the frames being a subset of those rows).
# Usage: curves_methods_agree.sh <medusa> <workdir> <store.h5> | <input> <run options...>
set -u
medusa=$1
work=$2
input=$3
shift 3
mkdir -p "$work" && cd "$work" || exit 1
case "$input" in
  *.h5) store=$input ;;
  *)
    store=$(basename "$input" | sed 's/[.].*//')_agree.h5
    "$medusa" run --force "$input" -o "$store" --quiet "$@" >/dev/null || { echo "medusa run failed"; exit 1; }
    ;;
esac
name=$(basename "$store" .h5)
modes='"" --frames-only'
[ "${FRAMES_TOO:-yes}" = no ] && modes='""'
eval "set -- $modes"
for frames in "$@"; do
  "$medusa" curves "$store" -o "$name.fast" $frames >/dev/null || { echo "curves failed"; exit 1; }
  "$medusa" curves "$store" -o "$name.reference" --method reference $frames >/dev/null ||
    { echo "curves --method reference failed"; exit 1; }
  rows=$(($(wc -l <"$name.fast.curves.csv") - 1))
  if [ "$rows" -lt 3 ]; then
    echo "only $rows rows: nothing compared"
    exit 1
  fi
  if ! cmp "$name.fast.curves.csv" "$name.reference.curves.csv"; then
    diff "$name.fast.curves.csv" "$name.reference.curves.csv" | head -5
    exit 1
  fi
  echo "$store ${frames:-every batch}: $rows rows identical"
done
