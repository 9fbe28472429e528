#!/usr/bin/env bash
# Times single stages in-process (tests/bench/micro/*_bench.cpp, built with the tests into
# BUILD_DIR/tests/bench/micro/): slicing an 832k-triangle mesh, loading an 832k-triangle binary STL,
# evaluating Cura's fdmprinter formulas. Prints one line per run with wall and CPU milliseconds; no
# thresholds (tests contain none: speed is measured here). Part of tests/bench/run.sh.
#   tests/bench/micro.sh BUILD_DIR [REPEAT]      (REPEAT runs of each, default 3)
set -euo pipefail
BUILD=$(cd "${1:?usage: tests/bench/micro.sh BUILD_DIR [REPEAT]}" && pwd)
REPEAT=${2:-3}
DIR=$BUILD/tests/bench/micro
echo "micro benchmarks, $REPEAT runs each, $(nproc) cores"
for bench in slice_sphere mesh_load formula_eval; do
  exe=$DIR/${bench}_bench
  [ -x "$exe" ] || { echo "micro.sh: $exe not built (cmake --build $BUILD)" >&2; exit 1; }
  for _ in $(seq "$REPEAT"); do "$exe"; done
done
