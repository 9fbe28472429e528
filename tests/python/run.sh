#!/usr/bin/env bash
# Runs the Python end-to-end tests against a built binary.
#   tests/python/run.sh BUILD_DIR [pytest args...]
# Sets up the venv (tests/python/venv.sh), fetches the corpus (tests/corpus/fetch.sh), then runs
# pytest -q tests/python with MIXENGINE_BIN=BUILD_DIR/mixengine. Exits with pytest's exit code.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REPO=$(cd "$HERE/../.." && pwd)
BUILD=${1:?usage: tests/python/run.sh BUILD_DIR [pytest args...]}
shift
BUILD=$(cd "$BUILD" && pwd)

PY=$("$HERE/venv.sh")
export MIXENGINE_CORPUS=${MIXENGINE_CORPUS:-$HOME/.cache/mixengine-corpus}
"$HERE/../corpus/fetch.sh" "$MIXENGINE_CORPUS"
export MIXENGINE_BIN=$BUILD/mixengine
cd "$REPO"
# MIXENGINE_PYTESTS: which tests (default: all of tests/python), e.g. tests/sanitize/run.sh runs the socket ones.
exec "$PY" -m pytest -q -p no:cacheprovider ${MIXENGINE_PYTESTS:-tests/python} "$@"
