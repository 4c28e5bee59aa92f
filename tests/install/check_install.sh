#!/bin/sh
# Tests of `cmake --install` (label `install`), one step per ctest:
#   check_install.sh install  <build dir> <work dir>           install into <work dir>/prefix
#   check_install.sh run      <work dir>                       the installed medusa on the installed example
#   check_install.sh consumer <work dir> <consumer source> <version>   find_package(medusa) in a new project
#   check_install.sh python   <work dir> <python dir>          /usr/bin/python3 imports the installed module
set -eu
step=$1
case $step in
install)
  build=$2 work=$3
  rm -rf "$work"
  mkdir -p "$work"
  cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
  prefix=$work/prefix
  for f in bin/medusa lib/cmake/medusa/medusaConfig.cmake lib/cmake/medusa/medusaConfigVersion.cmake \
           include/medusa/core/version.h include/medusa/medusa/store_reader.h include/medusa/kinetic/observer.h \
           share/doc/medusa/README.md share/doc/medusa/docs/FORMAT.md share/medusa/examples/sorting_3d/cells.csv.gz; do
    test -e "$prefix/$f" || { echo "not installed: $f" >&2; exit 1; }
  done
  # libkinetic's internal headers stay internal.
  if test -e "$prefix/include/medusa/kinetic/certificate_polynomials.h"; then
    echo "an internal header was installed" >&2; exit 1
  fi
  echo "installed into $prefix"
  ;;
run)
  work=$2
  prefix=$work/prefix
  cd "$work"
  rm -f x.h5 sorting_3d.h5
  "$prefix/bin/medusa" run "$prefix/share/medusa/examples/sorting_3d" -o x.h5 --quiet >run.log
  test -s x.h5 || { echo "no store x.h5" >&2; exit 1; }
  # Without an argument the installed binary runs the installed example (not the source tree's).
  mkdir -p default && cd default
  "$prefix/bin/medusa" run --quiet >/dev/null
  "$prefix/bin/medusa" info sorting_3d.h5 | grep -q "^  $prefix/share/medusa/examples/sorting_3d/" ||
    { echo "medusa run without an argument did not read the installed example" >&2; exit 1; }
  echo "ok"
  ;;
consumer)
  work=$2 source=$3 version=$4
  rm -rf "$work/consumer"
  cmake -S "$source" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >"$work/consumer.log"
  cmake --build "$work/consumer" >>"$work/consumer.log"
  out=$("$work/consumer/read_store" "$work/x.h5")
  echo "$out"
  expected_cells=$("$work/prefix/bin/medusa" info "$work/x.h5" | sed -n 's/^medusa cells: //p')
  echo "$out" | grep -q "^medusa $version\$" || { echo "wrong version" >&2; exit 1; }
  echo "$out" | grep -q "^store version $version, 251 trajectories, $expected_cells medusa cells\$" ||
    { echo "the consumer does not read the store as medusa info does" >&2; exit 1; }
  echo "ok"
  ;;
python)
  work=$2 pythondir=$3
  prefix=$work/prefix
  test -d "$prefix/$pythondir" || { echo "no $pythondir under the prefix" >&2; exit 1; }
  # The module's folder is on /usr/bin/python3's default path for the prefixes /usr/local and /usr.
  /usr/bin/python3 -c "import sys; assert '/usr/local/$pythondir' in sys.path and '/usr/$pythondir' in sys.path, sys.path" ||
    { echo "/usr/bin/python3 does not look in <prefix>/$pythondir" >&2; exit 1; }
  # The installed module (not the build tree's) reads the store of the installed medusa; its diagrams
  # have as many points as `medusa barcode` lists.
  expected=$("$prefix/bin/medusa" barcode "$work/x.h5" --format csv | grep -c ',all,forward,' || true)
  cd "$work"
  PYTHONPATH=$prefix/$pythondir /usr/bin/python3 - "$prefix" "$work/x.h5" "$expected" <<'PY'
import sys
import medusa
prefix, store, expected = sys.argv[1], sys.argv[2], int(sys.argv[3])
assert medusa.__file__.startswith(prefix + "/"), f"imported {medusa.__file__}, not the installed module"
s = medusa.open(store)
points = sum(len(a) for a in s.diagrams().values())
assert expected > 0 and points == expected, f"{points} points, medusa barcode lists {expected}"
assert len(s.classes(type=1, dim=1)) > 0
print(f"imported {medusa.__file__}: {points} points")
PY
  echo "ok"
  ;;
esac
