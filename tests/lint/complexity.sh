#!/usr/bin/env bash
# Runs the complexity check with lizard from the test venv (tests/python/venv.sh installs it).
#   tests/lint/complexity.sh [--max-ccn N] PATH...   fails listing every function above CCN N (20)
#   tests/lint/complexity.sh --self-test             the check's own tests (pytest, fixtures)
# Both are ctest tests (tests/CMakeLists.txt), so `make test` runs them.
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
PY=$("$HERE/../python/venv.sh")
if [ "${1:-}" = "--self-test" ]; then
  cd "$HERE"
  exec "$PY" -m pytest -q -p no:cacheprovider test_complexity_check.py
fi
exec "$PY" "$HERE/complexity_check.py" "$@"
