#!/bin/bash
# Builds the stores of the persistence benchmarks with `medusa run` and runs reduction_bench and
# distance_bench on them (bench/README.md). Stores are kept in the work folder and reused.
#
# Usage: bench/run_persistence_benches.sh [BUILD_DIR] [WORK_DIR]
#   BUILD_DIR  configured with -DMEDUSA_BUILD_BENCH=ON (default: build)
#   WORK_DIR   where the synthetic runs and the stores go (default: BUILD_DIR/persbench)
# Environment: SKIP_LARGE_3D=1 leaves out bench/data/large_3d, the largest bundled run (4,945 cells,
# 11 frames; about 4 minutes in the kinetic stage on 2 cores).
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-build}
work=${2:-$build/persbench}
python=/usr/bin/python3

cmake --build "$build" --target medusa reduction_bench distance_bench -j2
medusa=$(cd "$build" && pwd)/pipeline/cli/medusa
mkdir -p "$work"

store() { # store NAME INPUT: medusa run INPUT into WORK/NAME.h5 unless it exists
  if [ ! -f "$work/$1.h5" ]; then
    echo "medusa run $2 -> $work/$1.h5"
    "$medusa" run "$2" --radius 3 -o "$work/$1.h5" -q >/dev/null
  fi
}

# The example run (251 cells, 21 frames) and the largest bundled run.
store sorting_3d "$root/examples/sorting_3d"
# The synthetic run of 10,000 cells: a jittered grid at CC3D's cell spacing, 4 frames.
if [ ! -f "$work/random_10000.csv" ]; then
  "$python" "$here/make_random_walk.py" --cells 10000 --frames 4 --seed 10000 --step 1.2 --jitter 1.5 \
    -o "$work/random_10000.csv"
fi
store random_10000 "$work/random_10000.csv"
reduction_stores="--store $work/sorting_3d.h5"
if [ "${SKIP_LARGE_3D:-0}" != 1 ]; then
  store large_3d "$root/bench/data/large_3d"
  reduction_stores="$reduction_stores --store $work/large_3d.h5"
fi
reduction_stores="$reduction_stores --store $work/random_10000.h5"

# Twenty small runs for the distance matrices: 60-120 cells, 8 frames, four sorting biases.
distance_stores=""
for i in $(seq -w 1 20); do
  if [ ! -f "$work/walk_$i.csv" ]; then
    n=$((60 + (10#$i * 7) % 61))
    bias=$(echo "0.0 0.15 0.3 0.45" | cut -d' ' -f$((10#$i % 4 + 1)))
    "$python" "$here/make_random_walk.py" --cells "$n" --frames 8 --seed "$((10#$i))" --bias "$bias" \
      -o "$work/walk_$i.csv"
  fi
  store "walk_$i" "$work/walk_$i.csv"
  distance_stores="$distance_stores --store $work/walk_$i.h5"
done

echo
echo "### reduction_bench"
# shellcheck disable=SC2086
"$build/bench/reduction_bench" $reduction_stores --per-type
echo
echo "### distance_bench"
# shellcheck disable=SC2086
"$build/bench/distance_bench" $distance_stores
