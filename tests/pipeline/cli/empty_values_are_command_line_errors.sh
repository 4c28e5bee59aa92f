#!/bin/sh
# An empty option value is a command-line error (exit 2, one line naming the option), not a default:
# `--radius ''` is no radius and `--time ""` no time (CLI11 alone reads "" as 0).
# Usage: empty_values_are_command_line_errors.sh <medusa> <small run csv> <store> <workdir>
set -u
medusa=$1
input=$2
store=$3
cd "$4" || exit 1
status=0
check() { # <option> <command...>
  option=$1
  shift
  "$@" >stdout.txt 2>stderr.txt
  code=$?
  echo "$*: exit $code: $(cat stderr.txt)"
  if [ "$code" -ne 2 ] || [ "$(wc -l <stderr.txt)" -ne 1 ] || ! grep -q -- "$option" stderr.txt; then
    echo "expected exit 2 and one line naming $option"
    status=1
  fi
}
check --radius "$medusa" run "$input" -o empty_radius.h5 --radius ''
check --time "$medusa" at "$store" --time '' -o empty_time.csv
check --time "$medusa" at "$store" --time ' ' -o empty_time.csv
if [ -e empty_radius.h5 ] || [ -e empty_time.csv ]; then
  echo "an output was written"
  status=1
fi
exit $status
