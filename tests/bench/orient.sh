#!/usr/bin/env bash
# Benchmarks the dual-nozzle orientation pass (tests/bench/bench_orient.py; prints, asserts nothing).
#   tests/bench/orient.sh BUILD_DIR [bench_orient.py options]
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=${1:?usage: tests/bench/orient.sh BUILD_DIR [bench_orient.py options]}
shift
BUILD=$(cd "$BUILD" && pwd)
PY=$("$HERE/../python/venv.sh")
export MIXENGINE_CORPUS=${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}
"$HERE/../corpus/fetch.sh" "$MIXENGINE_CORPUS"
exec "$PY" "$HERE/bench_orient.py" --bin "$BUILD/mixengine" "$@"
