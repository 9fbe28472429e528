#!/usr/bin/env bash
# Benchmarks MixEngine against CuraEngine 4.13 (prints a table, writes out/bench.json), after the
# in-process micro benchmarks of single stages (tests/bench/micro.sh).
#   tests/bench/run.sh BUILD_DIR [--repeat N] [--phase full|load+slice] [--models a,b] [--out FILE]
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=${1:?usage: tests/bench/run.sh BUILD_DIR [bench_slice.py options]}
shift
BUILD=$(cd "$BUILD" && pwd)
PY=$("$HERE/../python/venv.sh")
export MIXENGINE_CORPUS=${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}
"$HERE/../corpus/fetch.sh" "$MIXENGINE_CORPUS"
"$HERE/micro.sh" "$BUILD" 1                                       # single stages, in-process
"$PY" "$HERE/bench_orient.py" --bin "$BUILD/mixengine" --repeat 1  # the orientation pass (issue 7)
exec "$PY" "$HERE/bench_slice.py" --bin "$BUILD/mixengine" "$@"
