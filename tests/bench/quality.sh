#!/usr/bin/env bash
# MixEngine against CuraEngine 4.13, one run: layers, filament, time, print quality, slice time per model;
# pictures of a few layers in out/quality/ (see compare_quality.py).
#   tests/bench/quality.sh BUILD_DIR [--cases cube20,knot2] [--out-dir DIR] [--cached]
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=${1:?usage: tests/bench/quality.sh BUILD_DIR [compare_quality.py options]}
shift
BUILD=$(cd "$BUILD" && pwd)
PY=$("$HERE/../python/venv.sh")
export MIXENGINE_CORPUS=${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}
"$HERE/../corpus/fetch.sh" "$MIXENGINE_CORPUS"
export MIXENGINE_BIN=$BUILD/mixengine
exec "$PY" "$HERE/compare_quality.py" --bin "$BUILD/mixengine" "$@"
