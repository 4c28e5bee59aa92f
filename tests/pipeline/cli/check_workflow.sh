#!/bin/sh
# examples/Snakefile on three small runs (the 3-frame CSVs): `snakemake --cores 2` runs medusa on each
# in parallel, compares them and plots each store; the comparison names all three runs.
# Usage: check_workflow.sh <medusa> <examples folder> <tests/data/cli folder> <workdir>
set -eu
medusa=$1
examples=$2
data=$3
work=$4
rm -rf "$work" && mkdir -p "$work/runs"
cp "$data/cells_3frames.csv.gz" "$work/runs/sorting_3d.csv.gz"
cp "$data/sorting_3d_seed2_3frames.csv.gz" "$work/runs/sorting_3d_seed2.csv.gz"
cp "$data/nosorting_3d_3frames.csv.gz" "$work/runs/nosorting_3d.csv.gz"
cd "$work"
/usr/bin/snakemake -s "$examples/Snakefile" --cores 2 --config runs=runs medusa="$medusa" out=results
for f in compare.distances.csv compare.heatmap.svg compare.dendrogram.svg \
         stores/sorting_3d.h5 stores/sorting_3d_seed2.h5 stores/nosorting_3d.h5 \
         plots/sorting_3d.barcodes.png plots/sorting_3d.betti.png plots/nosorting_3d.betti.png; do
  if [ ! -s "results/$f" ]; then
    echo "missing or empty: results/$f"
    exit 1
  fi
done
header=$(head -n 1 results/compare.distances.csv)
echo "distance matrix header: $header"
if [ "$header" != "run,nosorting_3d,sorting_3d,sorting_3d_seed2" ]; then
  echo "unexpected header"
  exit 1
fi
if [ "$(wc -l < results/compare.distances.csv)" -ne 4 ]; then
  echo "expected 3 rows"
  exit 1
fi
# plot_store.py without a diagrams CSV next to the store: it asks `medusa barcode --format csv`.
mkdir -p alone
cp results/stores/sorting_3d.h5 alone/
/usr/bin/python3 "$examples/plot_store.py" alone/sorting_3d.h5 --medusa "$medusa"
for f in alone/sorting_3d.barcodes.png alone/sorting_3d.betti.png; do
  if [ ! -s "$f" ]; then
    echo "missing or empty: $f"
    exit 1
  fi
done
echo ok
