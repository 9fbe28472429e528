#!/usr/bin/env bash
# The socket soak of issue 29 (tests/bench/soak.py): slices through the real libArcus, byte for byte against
# the command line, and early closes; exits 1 if any failed.
#   tests/bench/soak.sh BUILD_DIR [soak.py options: --slices N --early N --quick --seed N --out DIR ...]
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
BUILD=${1:?usage: tests/bench/soak.sh BUILD_DIR [soak.py options]}
shift
BUILD=$(cd "$BUILD" && pwd)
PY=$("$HERE/../python/venv.sh")
export MIXENGINE_CORPUS=${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}
"$HERE/../corpus/fetch.sh" "$MIXENGINE_CORPUS"
exec nice "$PY" "$HERE/soak.py" --bin "$BUILD/mixengine" "$@"
